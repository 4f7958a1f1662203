// SPDX-License-Identifier: Apache-2.0
// Private to coverage: what every coverage pattern shares (coverage.cpp, morse_coverage.cpp).
#pragma once
#include <preimage/coverage/coverage.hpp>
#include <preimage/geometry/clearance.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/local_frame.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/geometry/visibility_graph.hpp>

#include "cell_sweep.hpp"

#include <cmath>

namespace preimage::coverage::detail {

/// The problem once the configuration space is built: the component covered and its indexes.
struct Planning {
  const Environment& env;                     // the workspace
  const geometry::ConfigurationSpace& cs;
  const Environment& E;                       // the component covered
  const geometry::VisibilityIndex& index;     // of E
  const geometry::VisibilityGraph& graph;     // of E
  const CoverageOptions& o;
  double w;
  std::optional<Point> start;                 // in E (the entry point when the start lies in the band)
};

/// A straight move of the path: inside E (exact walk) and, with a footprint, r from every
/// obstacle (exact).
inline bool certified(const Planning& P, const Point& a, const Point& z) {
  return P.index.visible(a, z) && (P.cs.radius() == 0 || P.cs.admits(a, z));
}

/// Certifies every segment of `path` from `certified_before` on (inside E exactly, and r
/// from every obstacle; the earlier ones the caller has certified) — a failure is a bug
/// (std::logic_error) — and sets the report's path, moves, length, transit length, rotation
/// and turns.
void finish_path(const Planning& P, Polyline path, CoverageReport& rep, std::size_t certified_before = 0);

/// Euclidean distance, for ordering laps (a choice, never a decision on geometry).
inline double planar_distance(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

/// A path grown point by point: a straight move where it is certified (inside E, r from
/// every obstacle), else the shortest path there (counted in `detours`).
struct PathBuilder {
  const Planning& P;
  Polyline path;
  std::size_t detours = 0;
  void go(const Point& z, Move move);
};

/// The report of a cell-by-cell pattern: finish_path, then the counts.
CoverageReport pattern_report(const Planning& P, Polyline path, std::size_t detours, std::size_t laps, std::size_t cells, std::size_t nodes,
                              std::vector<std::uint32_t> order);

/// 6.2.1's exhaustive walk: cells in depth-first order of the adjacency graph from `first`
/// (neighbours in their listed order), then any cell the walk did not reach, the same way.
std::vector<std::uint32_t> depth_first_order(const std::vector<std::vector<std::uint32_t>>& adj, std::uint32_t first);

/// The variable-slice patterns of 6.2.3 (spiral, concentric, spike, squarel) on the Morse
/// decomposition of E (morse_coverage.cpp).
CoverageReport plan_pattern(const Planning& P);

/// The brushfire pattern of 6.2.3 (Fig. 6.17): offset curves w apart from the obstacles,
/// and the medial axis between them, cell by cell (brushfire_coverage.cpp).
CoverageReport plan_brushfire(const Planning& P);

/// The tethered robot's pattern of 6.2.3 (Fig. 6.18): fronts of the geodesic distance from
/// the start, w apart (wavefront_coverage.cpp).
CoverageReport plan_wavefront(const Planning& P);

/// Boundary following straightened: within a run of follow moves, a point is skipped when
/// the straight segment past it is certified and no skipped point is more than w/8 off it.
void straighten_follows(const Planning& P, Polyline& path);

/// Runs of small turns one way outside laps (the chords of an arc) replaced by fewer
/// corners, each turning less than 14 degrees, where the new segments are certified.
void merge_bends(const Planning& P, Polyline& path);

/// Touch-ups stop when at most this fraction of the component's raster samples is left.
inline constexpr double kTouchUpLeft = 1e-3;

struct CoverageRaster;
/// The samples of R the tool (width w) leaves uncovered along `path`: open[id] = 1; `left`
/// of them, of which `allowed` (kTouchUpLeft of the target) may stay.
struct Uncovered {
  std::vector<char> open;
  std::size_t left = 0, allowed = 0;
};
Uncovered uncovered(const CoverageRaster& R, const Polyline& path, double w);
/// The open samples in 4-connected patches, largest first.
std::vector<std::vector<std::size_t>> patches_of(const CoverageRaster& R, const std::vector<char>& open);

/// The path made drivable by a robot with turning radius R: laps and long segments kept,
/// corners turned by certified Dubins curves, laps cut back where the turn needs room,
/// what cannot be reached skipped and counted (drivable.cpp).
void make_drivable(const Planning& P, CoverageReport& rep, double R);

}  // namespace preimage::coverage::detail
