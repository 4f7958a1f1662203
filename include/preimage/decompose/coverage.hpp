// SPDX-License-Identifier: Apache-2.0
// Coverage paths on the boustrophedon decomposition (Choset et al., 6.2.1 and 6.2.5).
//
// The cells are visited in depth-first order of the adjacency graph from the start
// cell. Inside a cell the tool runs laps along the slice (floor to ceiling) at spacing
// w = 2r, joined by boundary-following moves along the floor or ceiling; between cells it
// travels on collision-free paths planned in the trapezoidal decomposition. Every free
// point farther than r from the boundary ends up within r of the path: a lap spans the
// whole cell height, and the horizontal segment from such a point to its nearest lap
// stays in free space, hence in the cell.
#pragma once
#include <preimage/decompose/boustrophedon.hpp>

#include <optional>

namespace preimage::decompose {

struct CoverageOptions {
  double radius;                    // tool radius r; laps are 2r apart
  std::optional<Point> start;       // default: the first vertex of the first cell's floor
  std::optional<double> angle_deg;  // sweep direction; none = try candidates, keep the shortest
};

struct CoverageReport {
  // Input coordinates; every segment is certified in closed free space with exact
  // predicates before it is returned. At angles that are not quarter turns the path is
  // built in the rotated (sweep) frame; a point rounded out of free space on the way back
  // is moved a few ulps in, and a segment that rounding made graze a wall is replaced by a
  // shortest path between its ends (counted in rounding_detours).
  std::vector<Point> path;
  std::size_t rounding_detours = 0;
  double angle = 0;         // sweep direction used
  double length = 0;
  std::size_t laps = 0, turns = 0, cells = 0, critical_points = 0;
  double diameter = 0;        // Δ: diameter of the smallest disc containing the environment
  double perimeter = 0;       // P_total: boundary length, obstacles included
  double bound = 0;           // Δ²/(2r) + 4Δ(N_cp + N_ob) + 5 P_total − 4Δ
  std::vector<std::uint32_t> cell_order;  // depth-first order the cells were covered in
};

/// Throws InputError for r <= 0 or a start outside free space.
CoverageReport plan_coverage(const Environment& env, const CoverageOptions& options);

/// Diameter of the smallest enclosing disc of the points (Welzl's algorithm, in double:
/// it only enters the reported bound, never a decision).
double min_disc_diameter(std::vector<Point> pts);

}  // namespace preimage::decompose
