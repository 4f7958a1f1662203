// Scenes of about 10^5 vertices for the scale tests and benchmarks (issue 26): a circle, a
// star, a square with long collinear runs and an office floor plan of 65 x 65 rooms. Made
// on demand (tests/tools/large_scenes.cpp writes them for the CLI tests), never stored.
#pragma once
#include <preimage/scene/scene.hpp>

#include <string>
#include <vector>

namespace preimage::testing {

struct LargeScene {
  std::string name;   // file stem: "circle_100k"
  scene::Scene scene;  // environment, start and goal (both in free space, not in line with a vertex)
};

/// The four shapes, in this order: circle_100k, star_100k, collinear_100k, office_100k.
std::vector<LargeScene> large_scenes();

}  // namespace preimage::testing
