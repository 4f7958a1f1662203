// Random beam scenes and a CGAL Arrangement_2 oracle for the beams module (tests, benchmarks).
#pragma once
#include <preimage/beams/arrangement.hpp>
#include <preimage/scene/scene.hpp>

#include <cstdint>
#include <vector>

namespace preimage::testing {

/// A random environment (n outer vertices, `holes` obstacles) with `beams` line beams
/// (chords through random interior points), labels drawn from `labels` names, a
/// fraction of them undirected. Redraws until the beams are in general position.
scene::Scene random_beam_scene(std::size_t n, std::size_t holes, std::size_t beams, std::uint64_t seed,
                               std::size_t labels = 0, double undirected_fraction = 0.0);

/// A random sufficient scene (beams paper 5.2): a ray beam from a random vertex of every
/// obstacle in a random direction, plus `lines` chords; redrawn until every region is
/// simply connected. With `ddd` every beam is directed with a label of its own and
/// no chords are added (all beams disjoint); otherwise labels come from `labels` names
/// (indistinguishable beams) and a fraction is undirected.
scene::Scene random_sufficient_scene(std::size_t n, std::size_t holes, std::size_t lines, std::uint64_t seed, bool ddd,
                                     std::size_t labels = 3, double undirected_fraction = 0.3);

/// Free faces of CGAL's Arrangement_2 of environment edges and beams, and for each of
/// the arrangement's region sample points the CGAL face containing it (an index
/// into a face enumeration; -1 if not in a free face).
struct OracleRegions {
  std::size_t free_faces = 0;
  std::vector<long> face_of_sample;
};
OracleRegions cgal_regions(const beams::BeamArrangement& arrangement);

}  // namespace preimage::testing
