// SPDX-License-Identifier: Apache-2.0
// Continuous paths in a beam arrangement: tracing a polyline to the word and region
// sequence it produces, a random-walk simulator (the ground truth for property tests),
// and a sample path realising any possible region sequence (beams paper, 4.1 and
// Fig. 21(b)): through every region's sample point, crossing the right beam in the
// right direction at the midpoint of a beam piece, and no other beam.
#pragma once
#include <preimage/beams/arrangement.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace preimage::beams {

/// What a body moving along a path observes.
struct Trace {
  std::vector<Symbol> word;
  std::vector<std::uint32_t> regions;  // regions visited, word.size() + 1 of them
  std::vector<ExactPoint> crossings;   // where each observation happened
};

/// Traces a polyline. Throws InputError if a vertex is not strictly inside a region,
/// or a segment touches the boundary, a landmark or a beam without crossing it
/// transversally, or passes through a beam crossing (paper, section 2 sensor model).
Trace trace_path(const BeamArrangement& arrangement, std::span<const ExactPoint> path);

struct Simulation {
  std::vector<ExactPoint> path;
  Trace trace;
};
/// A random body path of `steps` segments in free space (seeded, reproducible). It stops
/// early (fewer segments) if 10,000 random segments in a row leave no admissible one.
/// `progress`, if given, is called with the number of segments made after each one.
Simulation simulate(const BeamArrangement& arrangement, std::uint64_t seed, std::size_t steps,
                    const std::function<void(std::size_t)>& progress = {});

/// A path inside region r between two points strictly inside it (exact): the straight
/// segment if it stays inside, otherwise through the region's vertical slab cells.
std::vector<ExactPoint> route_in_region(const BeamArrangement& arrangement, std::uint32_t region, const ExactPoint& from,
                                        const ExactPoint& to);

/// The sample path of one crossing of G (paper 5.3, phase 1, step 3): from the sample
/// point of the region behind beam piece `half_edge` to the sample point of its face,
/// crossing that piece once at its midpoint and no other beam.
std::vector<ExactPoint> crossing_path(const BeamArrangement& arrangement, std::uint32_t half_edge);

/// A path in free space from p to q (both strictly inside regions), through sample
/// points and fewest beam crossings: the fixed return path that closes an open path
/// (paper, end of 5.3). Throws InputError if p or q is not strictly inside a region.
std::vector<ExactPoint> free_path(const BeamArrangement& arrangement, const ExactPoint& p, const ExactPoint& q);

/// A sample path for region sequence `regions` (k+1 regions) explaining `word` (k
/// observations). Throws std::invalid_argument if some step is not an edge of G.
std::vector<ExactPoint> sample_path(const BeamArrangement& arrangement, std::span<const std::uint32_t> regions,
                                    std::span<const Symbol> word);

}  // namespace preimage::beams
