// SPDX-License-Identifier: Apache-2.0
// The geodesic distance from a source point and its shortest path map (SPM): the base of
// the wave-front decomposition (section 6.2.3, Fig. 6.18). h(p) is the length of a shortest
// path in closed free space from the source to p; its level sets are the wave fronts.
//
// A shortest path bends only at reflex vertices. Dijkstra runs from the source over the
// reflex vertices: the source reaches every reflex vertex it sees, and a reflex vertex u
// reaches every reflex vertex w it sees with the segment uw tangent at u (both neighbours of
// u on one side of the line: only such a segment can leave a bend). Every "sees" is exact
// (VisibilityIndex: triangular expansion and triangle walks, orientation tests on input
// points); the lengths are doubles, and Dijkstra compares sums of square roots in double:
// where two routes have the same length to within rounding the one kept is the first found
// (for a point query: the source, then the lowest vertex id). So D and h are correct to
// rounding (relative ~1e-15 per edge), the choice of predecessor is exact except at such
// ties, and every path reported is a path in closed free space (exactly).
//
// h(p) = min over { the source if it sees p } ∪ { reflex v seen from p, segment vp tangent
// at v } of D(v) + |vp|; the minimiser is p's root: the last bend of its shortest path (or
// the source). The region of a root is the set of points with that root: a subset of the
// root's visibility polygon. region_of(p) answers membership; the regions' boundaries are
// segments (extensions of a shortest-path edge beyond a bend) and hyperbolic arcs (points of
// equal h through two roots), not constructed here.
//
// Critical points of the wave-front decomposition detected:
//  (a) tangency: every reflex vertex v whose shortest path bends there with the wave front
//      tangent to the obstacle: the ray from v's predecessor through v enters free space
//      beyond v (exact orientation tests). Its extension, from v to the first boundary point
//      hit (exact, shoot_ray), separates the region of v from the region on the other side.
//  (b) collisions on extensions: along an extension, h through v grows at unit rate and the
//      true h at rate at most 1, so the points where another root is strictly shorter form
//      one final interval of the extension; its start (found by bisection in double, a
//      sampled value within `tolerance`) is where a third wave front meets the two fronts
//      separated there — a vertex of the SPM. The extension is an SPM boundary only before it.
//  (c) first collisions of two fronts: for mutually visible reflex vertices a, b with
//      |D(a) - D(b)| < |ab|, the point x of segment ab with D(a) + |ax| = D(b) + |bx| (the
//      vertex of their hyperbolic bisector: h has a maximum there along ab and a minimum
//      along the bisector, a saddle), kept when x is in free space, both segments are
//      tangent at their roots and no root gives a shorter h at x — that last comparison in
//      double, to a relative 1e-9. E.g. behind an obstacle where the fronts from its two
//      sides meet. x is a double point (a sum of square roots solved in double).
// Not detected: collisions elsewhere along bisectors (where a bisector meets a third
// region or an obstacle away from a segment between its roots).
#pragma once
#include <preimage/geometry/visibility_graph.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace preimage::geometry {

class ShortestPathMap {
 public:
  /// Root id of the source (vertex ids are environment vertex ids).
  static constexpr std::uint32_t kSource = kNone - 1;

  /// Dijkstra from `source` (in closed free space, else InputError) over the reflex vertices
  /// of graph's environment. Visibility lists of the reflex vertices are computed on
  /// `threads` threads (0: one per hardware thread, at most 8).
  ShortestPathMap(const VisibilityGraph& graph, const Point& source, unsigned threads = 0);

  const VisibilityGraph& graph() const { return *graph_; }
  const VisibilityIndex& index() const { return graph_->index(); }
  const Environment& environment() const { return graph_->environment(); }
  const Point& source() const { return source_; }

  /// Geodesic distance from the source to environment vertex v if v is reflex and reached;
  /// +infinity for unreached or non-reflex vertices (their distance: distance(vertex(v))).
  double vertex_distance(std::uint32_t v) const { return dist_[v]; }
  /// The previous bend on v's shortest path (kSource for a straight one); kNone if unreached
  /// or not reflex.
  std::uint32_t vertex_predecessor(std::uint32_t v) const { return pred_[v]; }
  bool reached(std::uint32_t v) const { return pred_[v] != kNone; }
  /// Reflex vertices reached (all of them in a valid, connected environment).
  std::size_t num_reached() const { return reached_; }
  std::size_t num_reflex() const { return graph_->reflex_vertices().size(); }
  /// Number of (directed) relaxation edges Dijkstra used.
  std::size_t num_edges() const { return edges_; }
  /// Largest finite vertex distance.
  double max_vertex_distance() const { return max_dist_; }

  struct Query {
    double distance = std::numeric_limits<double>::infinity();
    std::uint32_t root = kNone;  // kSource, a reflex vertex id, or kNone (p outside free space)
  };
  /// h(p) and p's root, from V(p)'s vertices (no scan of the environment). p outside free
  /// space: {+infinity, kNone}.
  Query query(const Point& p) const;
  double distance(const Point& p) const { return query(p).distance; }
  /// The last bend of p's shortest path (or kSource): the SPM region p lies in.
  std::uint32_t predecessor(const Point& p) const { return query(p).root; }
  std::uint32_t region_of(const Point& p) const { return query(p).root; }
  /// A shortest path: source, bends, p (empty if p is outside free space).
  std::vector<Point> path_to(const Point& p) const;
  /// The point of a root (the source or the vertex).
  Point root_point(std::uint32_t root) const;

  /// A tangency critical point and the extension it spawns.
  struct Extension {
    std::uint32_t vertex;  // the bend (reflex vertex)
    std::uint32_t from;    // its predecessor (kSource or a reflex vertex)
    ExactPoint hit;        // first boundary point of the ray from -> vertex beyond vertex (exact)
    std::size_t hit_edge;  // edge containing it (shoot_ray's)
    /// Where the extension stops being an SPM boundary: a collision with a third front (b),
    /// a double point found by bisection; equal to the rounded hit if it never does.
    Point end;
    bool collides = false;  // whether `end` is a collision point (before the hit)
    std::uint32_t collider = kNone;  // root whose front is shorter just beyond `end`
  };
  /// (a) and (b): every bend whose extension enters free space, in ascending vertex order;
  /// collisions located to `tolerance` (relative to the extension's length). Costs O(log
  /// 1/tolerance) point queries per extension that collides, one for the others; on
  /// `threads` threads (0: hardware).
  std::vector<Extension> extensions(double tolerance = 1e-9, unsigned threads = 0) const;
  /// extensions().size(), from the exact turn tests alone (no ray shot, no query).
  std::size_t num_extensions() const;

  /// h and roots on a grid of samples (a drawing, decided by nothing): `columns` across the
  /// bounding box, square cells; row-major from (xmin, ymin), points outside free space
  /// {+inf, kNone}. Each root's visibility polygon is scan-converted onto the grid (O(n)
  /// polygons, not a query per sample); free space is decided by the exact in_free_space
  /// test, and a sample in it that no polygon covered gets a query. On `threads` threads
  /// (0: hardware).
  struct Samples {
    double x0 = 0, y0 = 0, step = 0;
    std::size_t columns = 0, rows = 0;
    std::vector<Query> values;
    Point point(std::size_t i, std::size_t j) const { return {x0 + step * static_cast<double>(i), y0 + step * static_cast<double>(j)}; }
    const Query& at(std::size_t i, std::size_t j) const { return values[j * columns + i]; }
  };
  Samples sample(std::size_t columns, unsigned threads = 0) const;

  /// (c): where two fronts first collide, one per pair of roots, ascending by (a, b). Pairs
  /// whose paths are not taut at the candidate point (exact turn tests) are dropped before
  /// the one point query each other pair costs.
  struct Collision {
    Point point;
    std::uint32_t a, b;  // the two roots (reflex vertices), a < b
    double distance;     // h there
  };
  std::vector<Collision> collisions() const;

 private:
  bool extends(std::uint32_t v) const;  // v is a bend whose extension enters free space
  const VisibilityGraph* graph_;
  Point source_;
  std::vector<double> dist_;
  std::vector<std::uint32_t> pred_;
  std::size_t reached_ = 0, edges_ = 0;
  double max_dist_ = 0;
  // Dijkstra's out-lists (reflex u -> reflex w seen with uw tangent at u), CSR by u's slot.
  std::vector<std::uint32_t> slot_, out_off_, out_;
};

}  // namespace preimage::geometry
