// SPDX-License-Identifier: Apache-2.0
// The wave-front decomposition (section 6.2.3, Fig. 6.18): the Morse decomposition of free
// space by h, the length of a shortest path from a start point. Its slices h = λ are wave
// fronts expanding from the start; a cell is what one front sweeps between two critical
// levels, where fronts are born (the start), touch an obstacle and split, collide and merge,
// close on themselves or vanish. The cells are the edges of h's Reeb graph; the nodes are
// its critical slices.
//
// A front at a level λ is computed, not sampled: in the region of a root v (the start or a
// reflex vertex, geometry::ShortestPathMap), h = D(v) + |vp|, so the front there is a part of
// the circle C_v of radius λ - D(v) about v. h is continuous, so along C_v the set where
// another root is shorter (the complement of the front) can only start or end where C_v
// crosses another root's circle, an obstacle edge, or the extension of v's shortest path
// through one of its children. C_v is cut at all those points (circle-circle and circle-
// segment intersections, in double) and a piece is kept when its midpoint m is seen from v
// (an exact walk from v), the path bends taut at v (m tangent at v, and on the obstacle's
// side of the line from v's predecessor through v: exact orientations) and no root u with
// D(u) + |um| < λ sees m (a walk per such u; distances in double). Roots at one point (the
// start at a reflex vertex) are one root. Pieces are
// glued into fronts by what their ends are (the same circle-circle intersection of the
// same two roots, the same extension), never by distance; an end on an obstacle edge is a
// free end.
//
// Following a front from one level λb down to λa < λb is exact bookkeeping: a point of the
// front at λb moves back along its own shortest path (a ray to its root, then the path's
// edges) to the point at distance λa from the start, which is on the front at λa. Two
// levels with no critical value between them have fronts in one-to-one correspondence this
// way, with equal topology (open chain or closed curve, and an open chain's ends on the
// same obstacles). The levels are placed between
// consecutive candidate critical values:
//  - the start (a minimum: the first front is a closed circle);
//  - the distance of every vertex (a reflex vertex reached head-on is where a front first
//    touches an obstacle; a convex corner is where a front vanishes);
//  - the feet of perpendiculars from each root to the walls it sees, where that root is
//    the point's root (a front tangent to a wall: h has a local minimum along the wall);
//  - between two consecutive such minima along an edge, h (a minimum of convex functions)
//    has one maximum: where fronts from both sides reach the wall, or a front leaves it;
//    found by golden-section search on h, 1e-7 of the edge's length inside free space;
//  - the fronts' first collisions and the ends of the extensions
//    (ShortestPathMap::collisions, extensions).
// Between two consecutive levels the fronts that do not correspond one to one form groups;
// each group is one critical slice (a node) placed at the candidate value between the two
// levels. A group of several fronts on both sides (two events in one interval) is split by
// bisection on the level. A critical point that is not a candidate (three fronts meeting
// in the open, a bisector meeting an extension) is still seen as a change of fronts and
// placed at the interval's candidate (WavefrontNode::lo, hi bound it); what is missed is a
// front born and gone within one interval, which needs a split that is a candidate and a
// death that is not in the same interval (not seen on any map tried: random points all
// find their cell). The independent check in the suite is homology: free space with k
// holes has k independent cycles, each a cycle of the Reeb graph or carried by closed
// fronts around holes. Events closer than 1e-9 of the range of h are one slice.
//
// Holes touching at vertices (contacts; free space is closed, so a front passes through
// the point): the ring vertices there are one root, and a front reaching it from one free
// wedge goes on into the others as that root's circle. Three things such maps (and
// lattice-like plans) bring, each handled exactly by construction rather than by distance:
//  - a root on the segment from another root's predecessor to it (a sight line along two
//    walls through a contact) becomes its predecessor, so straight chains of bends share
//    one extension angle and glue their circles;
//  - ties: a root w reached by two shortest paths (through s and through its predecessor)
//    has the ray from s through w as a cut of both circles, and s owns whatever it sees
//    beyond w; fronts reaching w along both at one level meet there (at a contact they
//    touch only at that point: a kiss, one slice with two fronts in and out);
//  - a front merging into another whose part is then overrun within one interval looks
//    like a death beside a change of the other front, and is bisected until the merge shows.
//
// Degeneracies of real floor plans: bends exactly in line (p -> s -> w all collinear; a
// wall with notches) carry all their labels on one cut of p's circle; bends so nearly in
// line that the order of their rays is below double resolution (staircase walls rasterised
// from images), or three circles nearly through one point, leave ends without a partner,
// joined to the nearest such end (within 1e-6 of the map's size, snapped_ends) or, failing
// that, counted (unmatched_ends) and treated as free.
#pragma once
#include <preimage/geometry/shortest_path_map.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace preimage::decompose {

using geometry::Environment;
using geometry::Point;

/// A piece of a front: part of the circle of `radius` about a root, counterclockwise from
/// angle `from` through `sweep` radians.
struct WavefrontArc {
  std::uint32_t root = 0;  // ShortestPathMap root id (kSource or a reflex vertex)
  double radius = 0;       // λ - D(root)
  double from = 0, sweep = 0;
};

/// One component of the slice h = λ: arcs in order along it.
struct WavefrontFront {
  std::vector<WavefrontArc> arcs;
  bool closed = false;      // a closed curve; else a chain whose two ends lie on obstacles
  std::uint32_t cell = UINT32_MAX;
};

/// A critical slice of h.
struct WavefrontNode {
  double level = 0;           // the candidate critical value it is placed at
  double lo = 0, hi = 0;      // the topology changes in (lo, hi]
  Point point;                // the candidate critical point (the start for node 0)
  std::vector<std::uint32_t> below, above;  // cells ending at it, cells starting at it
};

struct WavefrontCell {
  static constexpr std::uint32_t kNone = UINT32_MAX;
  std::uint32_t lower = kNone, upper = kNone;  // nodes it starts and ends at
  double lo = 0, hi = 0;                       // its range of h
};

class WavefrontDecomposition {
 public:
  /// Keeps a pointer to `spm`.
  explicit WavefrontDecomposition(const geometry::ShortestPathMap& spm);
  WavefrontDecomposition(geometry::ShortestPathMap&&) = delete;

  const geometry::ShortestPathMap& shortest_path_map() const { return *spm_; }
  const std::vector<WavefrontNode>& nodes() const { return nodes_; }
  const std::vector<WavefrontCell>& cells() const { return cells_; }
  /// Cells sharing a node (sorted, no repeats).
  std::vector<std::vector<std::uint32_t>> adjacency() const;

  /// The fronts at level λ > 0, each with the cell it runs through (UINT32_MAX at a level
  /// where the decomposition cannot tell: at a critical level).
  std::vector<WavefrontFront> fronts(double lambda) const;
  /// The cell containing free point p (UINT32_MAX outside free space or on a critical slice).
  std::uint32_t cell_at(const Point& p) const;
  /// Points of an arc, no chord farther than `sag` from the circle.
  std::vector<Point> arc_points(const WavefrontArc& arc, double sag) const;

  /// Candidate critical values (ascending, distinct) and the levels the fronts were
  /// computed at (one between each two candidates, plus bisections).
  const std::vector<double>& candidates() const { return candidates_; }
  const std::vector<double>& levels() const { return levels_; }
  /// Ends of front pieces, over every level followed, that found no partner by label (0 on
  /// every map tried), and those joined by position instead (bends on one ray to within
  /// double resolution, as on staircase walls of rasterised floor plans).
  std::size_t unmatched_ends() const { return unmatched_; }
  std::size_t snapped_ends() const { return snapped_; }
  /// Upper bound on h (every front is empty above it).
  double top() const { return top_; }

  struct Level;  // the fronts at one level, with the bookkeeping to follow them

 private:
  const geometry::ShortestPathMap* spm_;
  std::vector<double> candidates_, levels_;
  std::vector<std::pair<double, Point>> all_candidates_;  // every candidate, ascending
  std::vector<std::vector<std::uint32_t>> level_cells_;  // per level, per front: its cell
  std::vector<WavefrontNode> nodes_;
  std::vector<WavefrontCell> cells_;
  std::size_t unmatched_ = 0, snapped_ = 0;
  double top_ = 0;
  // Per root slot: the root id, its point, D, and its children in the shortest path tree.
  std::vector<std::uint32_t> slot_root_, root_slot_;
  std::vector<Point> slot_point_;
  std::vector<double> slot_dist_;
  std::vector<std::uint32_t> slot_pred_;  // slot of the predecessor (UINT32_MAX for the start)
  std::vector<std::vector<std::uint32_t>> slot_alias_;  // per slot: the reflex vertices at its point
  std::vector<char> slot_live_;                         // 0 for an alias of an earlier slot
  // Per slot: its visibility polygon's edges (double), each on an obstacle edge or a window
  // (where the feet of perpendiculars are looked for).
  struct Sight {
    std::vector<Point> a, b;
    std::vector<std::uint32_t> edge;  // the obstacle edge, or kNone for a window
  };
  std::vector<Sight> sight_;
  std::vector<double> ext_angle_;  // per slot: direction of its extension (from its predecessor)
  // Ties: (s, w) where the path through root s to root w is as short as w's own (lattice
  // maps, paths along walls through contacts). Beyond w, the ray from s through w bounds
  // what s sees, and the two circles are tangent there, so it is a cut of both.
  struct Tie {
    std::uint32_t s, w;
    double angle;
  };
  std::vector<Tie> ties_;
  std::vector<std::vector<std::uint32_t>> tie_sources_;  // per slot w: the s of its ties
  std::vector<std::vector<std::uint32_t>> collinear_chain_;  // per slot: itself and the bends straight beyond it

  Level compute(double lambda) const;
  // Pairs (front at A, front at B) joined by following B's fronts back to A's level.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> relation(const Level& A, const Level& B) const;
  bool continues(const Level& A, std::uint32_t a, const Level& B, std::uint32_t b) const;
  // The front of A holding the point of A's level on the path leaving slot s at `angle`
  // (-1 if none).
  std::int64_t front_on_path(const Level& A, std::uint32_t s, double angle) const;
  // The arc of A holding that point (-1 if none).
  std::int64_t arc_on_path(const Level& A, std::uint32_t s, double angle) const;
  // Whether a path can end at m with its last bend at (reflex) slot s.
  bool taut(std::uint32_t s, const Point& m) const;
  // Follows the fronts from A (the last level recorded) to B, creating nodes and cells.
  void step(const Level& A, const Level& B, int depth);
  // The cell of each front of a level (kNone where it cannot tell).
  std::vector<std::uint32_t> cells_of(const Level& C) const;
};

}  // namespace preimage::decompose
