// SPDX-License-Identifier: Apache-2.0
// Which sweep of each cell, and in what order: a generalised travelling-salesman *path*.
//
// Each cell (a cluster) offers a few sweeps, each with an entry point, an exit point and its
// own length; exactly one sweep per cell is used, and between consecutive sweeps the robot
// travels from one's exit to the next one's entry at the cost the transit oracle gives
// (shortest collision-free path length). The walk starts at a given point, or at the first
// sweep's entry. Solved exactly by dynamic programming over subsets for up to
// kExactClusters cells. Beyond: a nearest-neighbour start improved by Or-opt and bounded
// 2-opt moves on candidate lists (the nearest cells), each move re-choosing the sweeps of the
// cells it touches, all sweeps re-chosen for the order (a layered shortest path) when no
// move is left; then iterated: a few dozen double bridges, each followed by the local
// search, the walk kept when it gets cheaper. Transit costs are settled lazily: the search runs on straight-line
// estimates (lower bounds) and true costs of the pairs its answer uses, for a few rounds;
// the cost returned is always the true cost of the walk. The lower bound reported counts
// every cell's cheapest sweep and every transit at its cheapest straight line.
#pragma once
#include <preimage/geometry/kernel.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace preimage::coverage {

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

/// transit(a, b): cost of travelling from a to b (>= the straight-line distance). Instances
/// of up to `exact_up_to` cells are solved exactly (the DP is O(2^N (4N)^2)).
SweepOrder order_sweeps(const std::vector<std::vector<Sweep>>& cells, const std::optional<Point>& start,
                        const std::function<double(const Point&, const Point&)>& transit,
                        std::size_t exact_up_to = kExactClusters);

}  // namespace preimage::coverage
