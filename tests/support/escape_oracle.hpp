// SPDX-License-Identifier: Apache-2.0
// Brute-force shortest escape paths: the visibility graph of the local map's vertices and
// the target, Dijkstra from the target, then for every escape edge the best last leg from
// any graph node to an endpoint or to the foot of its perpendicular. O(n^3); the oracle
// the ray sweep is tested and benchmarked against.
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/tracking/local_map.hpp>

#include <random>
#include <vector>

namespace preimage::testing {

/// SDE(q^t, e) for every escape edge of `map`, in edge order (as EscapePathTree::paths).
std::vector<double> brute_force_sde(const tracking::LocalMap& map, const geometry::Point& target);

/// A point in the open free space of env, drawn uniformly from its bounding box.
geometry::Point random_free_point(const geometry::Environment& env, std::mt19937_64& rng);

}  // namespace preimage::testing
