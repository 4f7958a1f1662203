// SPDX-License-Identifier: Apache-2.0
// Brute-force shortest paths in closed free space: Dijkstra over the start, the goal and
// every vertex, an edge wherever the O(n) exact edge scan (geometry::visible) says the
// segment is free. O(n^2) visibility tests per query; the oracle for the visibility graph,
// coverage transits and planners.
#pragma once
#include <preimage/geometry/environment.hpp>

namespace preimage::testing {

/// Length of a shortest path from s to t in closed free space (infinity if none).
double brute_shortest_path(const geometry::Environment& env, const geometry::Point& s, const geometry::Point& t);

/// Distance from p to the nearest boundary edge, by scanning every edge (double).
double brute_clearance(const geometry::Environment& env, const geometry::Point& p);

}  // namespace preimage::testing
