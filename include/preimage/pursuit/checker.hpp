// SPDX-License-Identifier: Apache-2.0
// An independent contamination checker for pursuer paths. It uses neither the cells nor
// the information graph: it moves the pursuers along their paths, computes every V
// exactly at each sampled moment, and carries the contaminated set as a union of faces
// of the arrangement of the current visibility polygons' free edges. A face hidden from
// every pursuer belongs to a shadow region; a shadow region is contaminated iff it meets
// the previously contaminated set (at the first moment every shadow region is).
//
// Moments are chosen so that no step skips a change of the shadows' structure: for a
// single moving pursuer, the visibility polygons change combinatorially only where it
// crosses a line through two mutually visible environment vertices, or through an
// environment vertex and a vertex of a still pursuer's visibility polygon; the checker
// samples once between every two such crossings. Between two samples the
// shadow regions only deform, and a region keeps a part near its fixed anchors, so the
// "meets" rule follows the evader exactly. When several pursuers move at once the
// crossings of each with the vertex lines are sampled and the steps are refined
// uniformly (`substeps`); the result is then as fine as the sampling.
//
// With a limited range (CheckOptions::range) each pursuer sees V ∩ (p + Q), Q a polygon
// inscribed in the range's disc. Q's edges where they run in free space join the free edges
// in the overlay; a segment with nobody's view on either side separates nothing and its
// faces are joined. A moving pursuer's events then also include Q's corners crossing walls,
// free edges and a waiting pursuer's segments, vertices and segment ends crossing Q's edges
// (rational times), and a free edge's end on a wall, or its crossing with Q, crossing a wall
// or a waiting pursuer's segment (quadratic: roots bracketed by exact signs and kept apart
// from every other event by exact bisection).
#pragma once
#include <preimage/geometry/environment.hpp>

#include <optional>
#include <vector>

namespace preimage::pursuit {

using Paths = std::vector<std::vector<geometry::Point>>;
/// Paths through constructed points (a wall-follower's cut endpoints on edges).
using ExactPaths = std::vector<std::vector<geometry::ExactPoint>>;

struct CheckOptions {
  std::size_t substeps = 8;  // samples per segment when several pursuers move together
  std::vector<std::size_t> frames;  // waypoints at which to record a Frame (for figures)
  /// A moving pursuer's events are where it crosses a critical ray: past a tangent reflex
  /// vertex u, away from a vertex w that u sees (V gains or loses w behind u), or, while the
  /// others wait, away from a wall point of a waiting pursuer's V. With this set, every
  /// crossing of the whole lines through u and w, and through u and every vertex of a waiting
  /// V, is an event instead (as before 28 November): more samples, the same verdict (the
  /// tests' reference).
  bool every_critical_line = false;
  /// Threads building the steps (0: one per hardware thread). The contamination is carried
  /// through them in order on the calling thread, so the result does not depend on it.
  unsigned threads = 0;
  /// A step's regions are found in the next step's overlay by the stretch of a free edge
  /// on their boundary (no point location). With this set, a point of each is located
  /// instead: the tests' reference for the keys.
  bool locate_regions = false;
  /// > 0: each pursuer sees only within this distance (a sensor of limited range, the
  /// book's exercise 9 of 6.3). The sensor is a convex polygon of `range_sides` corners
  /// inscribed in the disc of radius `range` (corners checked exactly to lie in it), so what
  /// it sees is a subset of what the range-limited robot sees: a plan it clears is cleared by
  /// the robot (seeing more never contaminates more), and "not cleared" means not shown.
  double range = 0;
  std::size_t range_sides = 32;
};

/// The corners, counter-clockwise around the origin, of the polygon `CheckOptions::range`
/// uses: `sides` corners on or inside the circle of radius `range` (exactly), turned by an
/// irrational-looking fraction of a side so that they do not line up with axis-parallel
/// walls. Throws InputError unless range is finite and > 0 and 8 <= sides <= 1024.
std::vector<geometry::Point> range_sensor(double range, std::size_t sides);

/// The state at a waypoint, rounded for drawing.
struct CheckFrame {
  std::size_t waypoint = 0;
  std::vector<geometry::Point> pursuers;
  std::vector<std::vector<geometry::Point>> visible;       // V of each pursuer
  std::vector<std::vector<std::vector<geometry::Point>>> contaminated;  // faces, each as rings (even-odd)
  std::size_t regions = 0;  // contaminated shadow regions (a region may span several faces)
};

struct CheckResult {
  bool cleared = false;
  std::size_t moments = 0;  // sampled moments
  /// A moment: on the way from waypoint `waypoint` to the next, at `fraction` of it.
  struct Moment {
    std::size_t waypoint = 0;
    double fraction = 0;
    geometry::Point where;  // a point of the region concerned
  };
  /// The first moment a cleared shadow region was contaminated again (merged with a
  /// contaminated one), if any.
  std::optional<Moment> first_recontamination;
  /// The moment the contaminated set became empty (when cleared).
  std::optional<Moment> cleared_at;
  /// A point in each region still contaminated at the end, and their total area.
  std::vector<geometry::Point> contaminated_at_end;
  std::vector<geometry::ExactPoint> contaminated_exact;  // the same points, exact (strictly inside the regions)
  double contaminated_area = 0;
  std::vector<CheckFrame> frames;
};

/// The same paths with exact waypoints (the doubles as they are).
ExactPaths to_exact(const Paths& paths);
/// The same paths rounded to the nearest doubles (for drawing, or the double checker).
Paths to_double(const ExactPaths& paths);

/// Throws InputError naming the pursuer and point or segment when the paths are not
/// polylines in free space with equally many points.
void validate_paths(const geometry::Environment& env, const Paths& paths);
void validate_paths(const geometry::Environment& env, const ExactPaths& paths);

/// Runs the check (validate_paths first).
CheckResult check_paths(const geometry::Environment& env, const Paths& paths, const CheckOptions& options = {});
/// The same for exact waypoints: every moment's V is computed at the exact position (on an
/// edge, where a path follows the boundary), slower than at double points.
CheckResult check_exact_paths(const geometry::Environment& env, const ExactPaths& paths, const CheckOptions& options = {});

}  // namespace preimage::pursuit
