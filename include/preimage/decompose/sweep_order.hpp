// SPDX-License-Identifier: Apache-2.0
// Which sweep of each cell, and in what order: a generalised travelling-salesman *path*.
//
// Each cell (a cluster) offers a few sweeps, each with an entry point, an exit point and its
// own length; exactly one sweep per cell is used, and between consecutive sweeps the robot
// travels from one's exit to the next one's entry at the cost the transit oracle gives
// (shortest collision-free path length). The walk starts at a given point, or at the first
// sweep's entry. Solved exactly by dynamic programming over subsets for up to
// kExactClusters cells; beyond, a greedy start improved by Or-opt and 2-opt moves over the
// cell order, each evaluated with the best sweeps for that order (a layered shortest path),
// and a lower bound from a minimum spanning tree over straight-line distances, which no
// transit can beat.
#pragma once
#include <preimage/geometry/kernel.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace preimage::decompose {

using geometry::Point;

struct Sweep {
  Point entry, exit;
  double length = 0;
};

struct SweepOrder {
  std::vector<std::uint32_t> cells;   // visiting order (cluster indices)
  std::vector<std::uint8_t> sweeps;   // chosen sweep per visited cell
  double cost = 0;                    // sweeps + transits (+ from the start)
  double lower_bound = 0;             // no order and choice of sweeps costs less
  bool optimal = false;
};

inline constexpr std::size_t kExactClusters = 12;

/// transit(a, b): cost of travelling from a to b (>= the straight-line distance).
SweepOrder order_sweeps(const std::vector<std::vector<Sweep>>& cells, const std::optional<Point>& start,
                        const std::function<double(const Point&, const Point&)>& transit);

}  // namespace preimage::decompose
