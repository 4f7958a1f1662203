// SPDX-License-Identifier: Apache-2.0
// Coverage paths on the boustrophedon decomposition (Choset et al., 6.2.1 and 6.2.5) for a
// disc robot that a real base can drive.
//
// The robot's centre moves in the configuration space (free space eroded by its radius r,
// geometry::ConfigurationSpace); the decomposition is of that space. Inside a cell the
// tool runs laps along the slice at spacing w (the tool width, 2r by default), joined by
// boundary-following moves along the cell's floor or ceiling chain. Every cell can be swept
// four ways (from its left or right end, first lap up or down); which sweep of each cell and
// in what order is a generalised travelling-salesman path over the cells (exact for up to
// 12 cells, a local search with a lower bound beyond), with the shortest collision-free
// transit between one sweep's end and the next one's start (geometry::VisibilityGraph). The
// paper's exhaustive walk (depth-first order, transits through the trapezoids) remains
// available for comparison.
//
// Every point laps reach that is farther than w/2 from the configuration space boundary is
// within w/2 of a lap: the slice segment from it to its nearest lap stays in the cell.
// Every segment is certified before the path is returned: inside the polygonal
// configuration space with exact predicates, and at distance >= r from every obstacle
// with exact arithmetic; a failure is a bug (std::logic_error), never a printed path.
#pragma once
#include <preimage/decompose/boustrophedon.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace preimage::coverage {

// Coverage turns the cells of decompose into a robot's path (docs/architecture.md: one
// arrow, decompose -> coverage).
using decompose::BoustrophedonDecomposition;
using geometry::Environment;
using geometry::Point;

enum class CellOrder { Optimised, DepthFirst };  // GTSP over sweeps, or 6.2.1's exhaustive walk
enum class Transit { Shortest, Decomposition };  // visibility-graph shortest paths, or trapezoid midpoints
/// The pattern inside cells (6.2.1, 6.2.3): straight laps on the boustrophedon decomposition,
/// or laps along the slices of a Morse decomposition around a centre — circles (concentric,
/// or a spiral in annular cells), rays from the centre (spike: denser near it), or diamonds
/// (squarel, a spiral in annular cells).
/// Or the distance-function patterns: offset curves from the obstacles and the medial axis
/// between them (brushfire), or fronts of the geodesic distance from the start for a
/// tethered robot (wavefront).
enum class Pattern : std::uint8_t { Boustrophedon, Spiral, Concentric, Spike, Squarel, Brushfire, Wavefront };
std::string_view to_string(Pattern p);
std::optional<Pattern> parse_pattern(std::string_view s);

/// Widths giving more laps than this across the environment's bounding box are refused.
inline constexpr double kMaxLapsAcross = 1e5;

struct CoverageOptions {
  double width = 0;                  // tool width w: laps are w apart; 0 means 2 * robot_radius
  double robot_radius = 0;           // r: the robot's centre stays r away from every obstacle
  std::optional<Point> start;        // default: where the first sweep begins
  std::optional<double> angle_deg;   // sweep direction; none = try candidates, keep the cheapest (length and turns)
  CellOrder order = CellOrder::Optimised;
  Transit transit = Transit::Shortest;
  Pattern pattern = Pattern::Boustrophedon;
  std::optional<Point> centre;       // of the variable-slice patterns; default: the middle of the bounding box
  // A robot that cannot turn in place (car-like): every turn an arc of radius >= this,
  // forward, reversing only where no forward curve fits (turn_model.hpp, drivable.cpp).
  // 0: turns in place.
  double min_turn_radius = 0;
  // What a turn is worth in metres of path: a run of small turns round a corner (the
  // chords of an arc) becomes fewer corners where that adds at most this much path per
  // turn saved. 0: transits stay shortest paths, follow moves hug the boundary.
  double turn_cost = 0.1;
  // Boustrophedon with the order optimised, for a robot that turns in place: also plan
  // each direction with adjacent cells merged into monotone regions where that saves laps
  // (cell_merging.hpp), and keep the cheaper path.
  bool merge_cells = true;
};

/// What a path segment is doing (for figures and metrics); Turn: a chord of an arc a
/// curvature-limited robot drives (CoverageReport::arcs).
enum class Move : std::uint8_t { Lap, Follow, Transit, Turn };
std::string_view to_string(Move m);

/// An arc of a curvature-limited path: path points first..last lie on it (the chords are
/// the path's segments); it turns by `turn` radians (positive: left) about `centre`.
struct CoverageArc {
  Point centre;
  double radius = 0, turn = 0;
  std::size_t first = 0, last = 0;
  bool reverse = false;  // driven backwards (the heading still changes by `turn`)
};

struct CoverageReport {
  // Input coordinates, certified (see above). At angles that are not quarter turns the path
  // is built in the rotated sweep frame; points rounded out on the way back are moved a few
  // ulps in and a segment that rounding made graze a wall is replaced by a shortest path
  // (counted in rounding_detours; never at quarter turns).
  std::vector<Point> path;
  std::vector<Move> moves;  // per segment: path[i] -> path[i + 1]
  std::size_t rounding_detours = 0;
  // Points visited after the pattern, by transits, where its laps left patches uncovered
  // (a raster of the component at w/8; until at most 0.1 % of its samples is left).
  std::size_t touch_ups = 0;
  double angle = 0;          // sweep direction used
  // With a minimum turning radius: the arcs (every one certified, not only its chords: the
  // capsule around each chord that holds the arc keeps r from every obstacle), laps whose
  // ends were cut back so the turn fits in the room, and laps and points of the plan the
  // robot could not reach with its turning radius (left out; measure_coverage says what
  // that costs).
  double min_turn_radius = 0;
  std::vector<CoverageArc> arcs;
  std::size_t shortened_laps = 0, skipped = 0;
  std::size_t unreached = 0;  // uncovered places (touch-up points) no curve reaches: given up
  // Path points where the robot stops and changes its direction of travel: it drives
  // forward from the first point, backwards after the first cusp, and so on.
  std::vector<std::size_t> cusps;
  double width = 0, robot_radius = 0;
  std::size_t laps = 0, cells = 0, critical_points = 0;
  // With --angle auto: cells of the decomposition swept at the perpendicular direction
  // (decomposed again on their own there), because that needs fewer laps; `cells` counts
  // the cells swept.
  std::size_t turned_cells = 0;
  // With the order optimised: cells swept as one region with the cell before them, because
  // their union is still monotone in the sweep direction and needs fewer laps; `cells`
  // counts the regions swept.
  std::size_t merged_cells = 0;
  // Heading changes over 1 degree, and over 15 degrees; a curvature-limited path changes
  // heading only along arcs, so there each arc (a run turning one way) is one turn.
  std::size_t turns = 0, sharp_turns = 0;
  double length = 0, transit_length = 0, rotation_deg = 0;  // rotation: sum of heading changes
  // Regions in the order covered: the decomposition's cells, numbered in its order; with
  // turned cells (turned_cells), the turned cells' own cells come first, then the
  // decomposition's other cells; with merged cells (merged_cells), a region of several
  // cells is numbered where its first cell would be.
  std::vector<std::uint32_t> cell_order;
  std::vector<std::uint8_t> sweeps;       // per covered cell: 0..3 (bit 0: from the right end, bit 1: first lap down)
  bool order_optimal = false;             // exact GTSP solution (small instances)
  double order_lower_bound = 0;           // lower bound on the path length for any order and sweeps
  // The configuration space actually covered: the component holding the start.
  double target_area = 0;        // its area (polygonal, certified inside the exact one)
  double unreachable_area = 0;   // area of the other components (the robot cannot get there)
  double cspace_error = 0;       // how far the polygonal boundary may lie inside the exact one
  // Chapter's bound for the exhaustive walk: D^2/(2r) + 4D(N_cp + N_ob) + 5 P_total - 4D.
  double diameter = 0, perimeter = 0, bound = 0;
};

/// Throws InputError for a width or radius that is not positive and finite (the width may be
/// 0 when the radius is positive), a start the robot does not fit at, or a robot that fits
/// nowhere. Throws std::logic_error if a segment fails certification (a bug).
CoverageReport plan_coverage(const Environment& env, const CoverageOptions& options);

/// What boustrophedon's candidate paths (directions, cells turned or merged) are compared
/// by: the length, plus `turn_cost` per turn over 1 degree and once more per turn over 15
/// degrees, where a robot that turns in place stops.
double path_cost(const CoverageReport& report, double turn_cost);

/// Rasterised quality of a coverage path (floating point: a measurement, not a decision):
/// the target is the configuration space component the path runs in, sampled on a square
/// grid of side `cell` (default w/8, coarser where that would exceed 4 million samples); a
/// sample is covered when within w/2 of the path, and
/// covered twice when the path comes within w/2 - cell/2 of it on two separate visits (the
/// margin keeps samples exactly halfway between neighbouring laps from counting).
struct CoverageMetrics {
  double covered_fraction = 0;  // covered samples / target samples
  double overlap = 0;           // samples covered twice or more / target samples
  double efficiency = 0;        // length / (target area / w): 1 is a perfect boustrophedon without transits
  std::size_t samples = 0;
};
CoverageMetrics measure_coverage(const Environment& env, const CoverageReport& report, double cell = 0);

/// Diameter of the smallest disc containing the points (Welzl's algorithm, in double:
/// it only enters the reported bound, never a decision).
double min_disc_diameter(std::vector<Point> pts);

}  // namespace preimage::coverage
