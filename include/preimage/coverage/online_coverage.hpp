// SPDX-License-Identifier: Apache-2.0
// Sensor-based coverage of an unknown environment (Choset et al., 6.2.4; Acar and Choset's
// cycle algorithm): a disc robot that does not know the map covers it while it builds the
// boustrophedon Reeb graph incrementally, and knows when it is done.
//
// Model. The robot's centre moves in the configuration space (the free space eroded by its
// radius r, geometry::ConfigurationSpace), in the sweep frame (x along the sweep direction,
// slices vertical). A simulator owns the map and offers the primitives of the text: a lap
// along the slice until contact (exact ray shooting in the configuration space polygon: the
// centre's first contact, rounded to the nearest double on the robot's side), a lap along a
// wall that runs along the slice (to the wall's end; which side the wall is on is felt by
// contact), boundary following forward or reverse with the lateral displacement tracked by
// odometry (edge by edge along the contact boundary, stopping exactly on a given slice or
// either of two), and retracing a stretch the robot has driven. After every step of
// boundary following the robot reads a ring of N range sensors from its centre against the
// workspace (ray casting in double: a measurement, plus Gaussian noise). The planner sees
// only those readings, contact and its odometry, never the map.
//
// Critical point sensing. The robot follows the boundary vertex to vertex; a critical point,
// where the boundary's normal is parallel to the sweep direction (Lemma 5.5.2), is an
// extreme of h = x along the boundary, so it is sensed where the lateral displacement
// (odometry) turns back: a vertex, or a vertical run, placed exactly on its slice. A follow
// that arrives on its stop slice at a vertex drives on (along the slice while the boundary
// runs along it, then one step) to see whether the boundary turns back there, and otherwise
// returns to the chain's point on the slice that faces the cell. The turn the boundary makes
// at the extreme gives the critical point's kind: a convex free corner ends free space
// (death ahead, birth behind), a reflex one ends an obstacle (merge, split). The ring's
// minimum (the text's method) is only compared at reflex critical points, where it should
// point back at the obstacle; at a concave corner it points at either of two walls r away,
// in a passage barely 2r wide at the far side, so it is not trusted. Sensor noise therefore
// changes no decision; `ring_disagreements` counts where the ring would have misread.
//
// Critical slices. Where walls line up across the sweep, several critical points share one
// slice and the offline Reeb graph has a node joining more than three cells. So a node is
// the piece of the slice through a sensed critical point, surveyed by the robot: from the
// critical point's run it laps up and down along the slice, sliding along walls that run
// along it (their obstacle side felt by contact), until the boundary crosses the slice. At
// every boundary point between two laps the boundary touches the slice from one side; a
// short boundary follow (lateral displacement at most w/2, then back) tells which. Per side,
// the maximal stretches of the piece free on that side, split where an obstacle touches from
// that side, are the node's ports: one per adjacent cell, left and right, bottom to top
// (birth and death one, split and merge three, a `Slice` node any other count). A cell closes
// through the port of its closing critical point's piece that holds it: above a floor's
// critical point, below a ceiling's, around an obstacle's first point, on a birth or death.
//
// The cycle algorithm (Fig. 6.23) made exact, per strip from the last lap (slice x0, floor
// point F0, ceiling point C0) towards the target slice x0 + d w: follow the floor forward to
// the target (forward phase); back across the last lap, follow the ceiling forward (the
// ceiling's boundary following of the reverse phase); a critical point sensed on either
// (on the target slice too) moves the target back to its slice. Closing phase: a lap across
// the target slice from a side without a critical point there, or from a side whose critical
// point is not a pocket's end; arriving where odometry says the other chain (or its critical
// point) crosses proves the strip clear. Hitting an obstacle instead, follow it back against
// the sweep to where it starts (a nearer critical point, or one on the target slice where
// the boundary turns back at once), the new target, and lap from there both ways along its
// slice until both laps arrive on the chains, going on from the far side of every obstacle
// that starts on the same slice. Where the floor's follow and the ceiling's end at the ends
// of two different pockets on one slice, what separates the pockets starts inside the strip:
// the robot follows on around the ceiling's pocket, back against the sweep, to it. The
// target only moves back, so the cell closes at its first critical point along the sweep
// however many the strip holds. With `cycle = false` the same simulator runs a plain raster
// scan (follow one side per strip, alternating, lap across), which misses ceiling critical
// points.
//
// Completeness relies on w <= 2r: every obstacle of the configuration space is at least 2r
// wide, so none hides between two laps. Larger widths are refused.
//
// The incremental Reeb graph (Figs. 6.20, 6.21): a node per surveyed critical slice with its
// ports, an edge when a cell is covered from a node's port to its closing critical slice;
// the robot travels (retracing its own path, shortest over what it has driven) to the
// nearest node with an unexplored port, and stops when every port is explored. Critical
// points passed over while a strip's target moved back are not registered then: every node
// closes some cell and the graph is connected, so the robot meets each again. Anything the
// graph cannot explain (a closing critical point no port of its slice holds, or whose port
// is already explored, a lap that cannot start or arrives past a chain, a boundary that
// turns back at once where no obstacle was met, a surveyed slice that joins one cell on
// each side or where the boundary does not touch it from one side) is reported as an
// inconsistency and the robot does not claim completion.
//
// Output: the path in input coordinates, certified segment by segment (inside the
// configuration space polygon exactly and r from every obstacle) like plan_coverage's.
#pragma once
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/coverage/coverage.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace preimage::coverage {

struct OnlineOptions {
  double robot_radius = 0;          // r > 0
  double width = 0;                 // tool width w, 0 < w <= 2r; 0 means 2r
  double angle_deg = 0;             // sweep direction
  std::size_t sensors = 32;         // range sensors on the ring (a multiple of 4, >= 8)
  double range = 0;                 // their maximum range; 0 means 10 r
  double noise = 0;                 // standard deviation of the Gaussian noise on each reading
  std::uint64_t seed = 1;           // of the noise
  bool cycle = true;                // false: plain raster scan (misses ceiling critical points)
  std::optional<Point> start;       // default: the middle of the configuration space's largest lap
  std::size_t max_steps = 0;        // primitive budget (0: automatic); running out is an inconsistency
};

/// A node's shape by its cells (left | right): birth 0 | 1, death 1 | 0, split 1 | 2, merge
/// 2 | 1; slice: any other count (several critical points on one critical slice).
enum class OnlineKind : std::uint8_t { Birth, Death, Split, Merge, Slice };
std::string_view to_string(OnlineKind k);

/// A sensed critical slice (the connected piece of the slice through a sensed critical
/// point, surveyed by the robot), in the order sensed.
struct OnlineNode {
  OnlineKind kind = OnlineKind::Birth;
  double x = 0, y_low = 0, y_high = 0;  // sweep frame: the piece of the slice x (y_low <= y_high)
  Point at;                             // input frame (the middle of the piece)
  std::size_t sensed_at = 0;            // path index where it was sensed
  /// Ports, one per adjacent cell: [0, left) the cells on the left (ending here), bottom to
  /// top, [left, size) those on the right (starting here), bottom to top. Per port, the
  /// edge explored through it or -1, and its interval on the slice (sweep frame).
  std::size_t left = 0;
  std::vector<int> ports;
  std::vector<std::pair<double, double>> spans;
};

/// A covered cell: an edge of the Reeb graph.
struct OnlineEdge {
  std::uint32_t from, to;      // opening node and closing node
  std::size_t laps = 0;
  std::size_t path_begin = 0, path_end = 0;  // path indices of its sweep
};

struct OnlineReport {
  std::vector<Point> path;   // input frame, certified
  std::vector<Move> moves;   // per segment
  std::vector<OnlineNode> nodes;
  std::vector<OnlineEdge> edges;
  std::vector<std::uint32_t> sensing_order;  // node ids in the order they were (re)visited as closing or found
  bool complete = false;       // every port explored and nothing inconsistent
  std::string inconsistency;   // empty unless something did not add up
  double angle = 0, width = 0, robot_radius = 0, range = 0, noise = 0;
  std::size_t sensors = 0, laps = 0, readings = 0, steps = 0;
  /// Reflex critical points (an obstacle ends) where the ring's minimum did not point back at
  /// the obstacle: the ring's own critical point sensing would have misread them.
  std::size_t ring_disagreements = 0;
  double resolution = 0;       // angular resolution of the normal estimate (pi / N), radians
  double length = 0, transit_length = 0;
  double target_area = 0;      // area of the configuration space component covered
};

/// Throws InputError for a radius or width out of range, a ring of fewer than 8 sensors or
/// not a multiple of 4, a range not above r, negative noise, a start the robot does not fit
/// at. Throws std::logic_error if a path segment fails certification (a bug).
OnlineReport plan_online_coverage(const Environment& env, const OnlineOptions& options);

/// The online graph against the offline boustrophedon Reeb graph of the same configuration
/// space component and angle: nodes matched by position (the offline critical slice within
/// `tolerance` of the sensed one) and by their cells on either side (left and right port
/// counts against cells_left and cells_right), then edges compared as multisets under the
/// matching.
struct OnlineComparison {
  bool isomorphic = false;
  std::size_t offline_nodes = 0, offline_edges = 0;
  double max_offset = 0;           // largest distance between matched critical points
  std::vector<int> offline_of;     // per online node, the offline critical slice (-1: none)
  std::string detail;              // why not, when not
};
OnlineComparison compare_with_offline(const Environment& env, const OnlineReport& report, double tolerance);

/// The same for a decomposition the caller already has (of the component the report covered).
OnlineComparison compare_with_offline(const BoustrophedonDecomposition& offline, const OnlineReport& report, double tolerance);

/// Default matching tolerance: how far a sensed critical point may sit from the true one.
double online_tolerance(const OnlineReport& report);

}  // namespace preimage::coverage
