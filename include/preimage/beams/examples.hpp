// SPDX-License-Identifier: Apache-2.0
// Virtual beams from landmarks (beams paper, section 3, Fig. 6) and the paper's
// example scenes, built in code so the demo and tests need no files. The JSON copies
// in examples/beams/ are checked against these by the tests.
#pragma once
#include <preimage/scene/scene.hpp>

#include <string>

namespace preimage::beams {

enum class LandmarkModel {
  Crossing,  // Fig. 6(a): a ray beyond each landmark of every pair (robot, o_i, o_j collinear)
  North      // Fig. 6(b): a ray due north of each landmark
};

/// Replaces the scene's beams by the virtual beams of its landmarks. Crossing model:
/// the ray beyond o_j (away from o_i) is labelled "j/i" (o_j seen in front of o_i), or
/// "i~j" for both rays when `distinguishable` is false. North model: labelled after
/// the landmark. The scene must have no environment (the unbounded plane).
scene::Scene with_landmark_beams(scene::Scene landmarks, LandmarkModel model, bool directed, bool distinguishable);

scene::Scene fig1_scene();    // six beams, four obstacles, three regions; word cbabdeeefe
scene::Scene fig3b_scene();   // crossing, directed and indistinguishable beams, 8 regions
scene::Scene fig11_scene();   // ring of three regions for two bodies
scene::Scene fig13_scene();   // perfect beams b1, b2 about two obstacles (5.1, 6.1)
scene::Scene fig18_scene();   // perfect beams a, b: the commutator a b a' b' (Fig. 18)
/// n landmarks in general position (no three collinear, distinct abscissae).
scene::Scene landmark_scene(std::size_t n, std::uint64_t seed);

}  // namespace preimage::beams
