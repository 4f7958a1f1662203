// SPDX-License-Identifier: Apache-2.0
// Exact visibility polygons by triangular expansion (Bungiu, Hemmer, Hershberger,
// Huang, Kröller 2014) over this library's own constrained Delaunay triangulation.
// Every decision is an orientation test on input points (the query and environment
// vertices), so it is exact and fast; only output vertices on edges are constructed,
// lazily exact (ExactPoint).
#pragma once
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/triangulation.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace preimage::geometry {

/// A visibility-polygon vertex, described exactly by where it comes from: an environment
/// vertex, the query itself, or the point where the ray from the query through `vertex`
/// meets environment edge `edge`. Exact coordinates are constructed on demand
/// (VisibilityPolygon::exact); `approx` is a double rounding for drawing and reports, not
/// filled by compute_abstract (NaN there; VisibilityPolygon::approx_point computes it).
struct VisibilityVertex {
  enum class Kind : std::uint8_t { EnvironmentVertex, RayHit, Query };
  Kind kind;
  std::uint32_t vertex = kNone;  // EnvironmentVertex: its id; RayHit: the vertex the ray passes through
  std::uint32_t edge = kNone;    // RayHit: environment edge hit
  Point approx;
};

/// An edge of the visibility polygon, from vertex i to vertex i+1.
struct VisibilityEdge {
  enum class Kind : std::uint8_t { Solid, Free };
  Kind kind;
  std::uint32_t edge = kNone;    // Solid: the environment edge it lies on
  std::uint32_t reflex = kNone;  // Free: the vertex whose occlusion causes the gap
  bool occluder_on_left = false; // Free: the occluding obstacle lies left of the ray query -> reflex
};

/// Visibility polygon V(q), counter-clockwise, regularised (no needles).
struct VisibilityPolygon {
  const Environment* environment = nullptr;
  Point query;        // the query (its double rounding for a constructed query)
  Location location;  // of the query
  std::vector<VisibilityVertex> vertices;
  std::vector<VisibilityEdge> edges;
  /// True when computed by VisibilityIndex::compute_abstract: the vertices' `approx`
  /// coordinates are not filled (ids and kinds only); approx_point(i) computes them.
  bool abstract = false;
  /// The query when it was a constructed point (VisibilityIndex::compute(const ExactPoint&));
  /// empty for a double query, whose exact twin exact_query() builds on demand.
  std::optional<ExactPoint> constructed_query;

  /// The query, exact: built on demand (nothing exact is made by compute for a double query).
  ExactPoint exact_query() const;
  /// Exact coordinates of vertex i (lazy exact construction for ray hits).
  ExactPoint exact(std::size_t i) const;
  /// All vertices, exact.
  std::vector<ExactPoint> points() const;
  /// Double coordinates of vertex i: `approx`, or computed from the ids in abstract mode
  /// (for drawing and reports only; decisions never read it).
  Point approx_point(std::size_t i) const;
  double area() const;
};

/// Exact coordinates of a visibility vertex of V(query) (lazy-exact construction for ray hits).
ExactPoint exact_point(const Environment& env, const ExactPoint& query, const VisibilityVertex& v);

/// Preprocesses one environment (triangulation + point-location grid) for many queries.
/// Every const member is safe to call from several threads at once; the scratch space of a
/// query (work stack, piece list) is kept per thread.
class VisibilityIndex {
 public:
  explicit VisibilityIndex(const Environment& env);
  VisibilityIndex(Environment&&) = delete;  // keeps a pointer to the environment
  const Environment& environment() const { return *env_; }
  const Triangulation& triangulation() const { return tri_; }

  /// Where q is, in O(1) expected (grid of triangles) when q is in free space; naming the
  /// hole or the outside of a point not in free space takes O(n).
  Location locate(const Point& q) const;
  /// Whether q is in free space (open free space, an edge or a vertex): O(1) expected.
  bool in_free_space(const Point& q) const;
  /// Diagnostic for benchmarks: the number of exact orientation tests locate(q) makes to
  /// find q's triangle (the same code as locate, instantiated with a counter).
  std::size_t locate_tests(const Point& q) const;
  /// V(q) for q in the interior, on an edge, or at a vertex; throws InputError if q is
  /// outside free space. At a contact point (rings touching there) V(q) is the union of
  /// what q sees in each free wedge there: a weakly simple polygon through q once per
  /// wedge, wedges in counter-clockwise order.
  VisibilityPolygon compute(const Point& q) const;
  /// V of vertex v's point within one free wedge: the one starting at v's out-edge
  /// (counter-clockwise to the in-edge of Environment::wedge_end(v)). Without contacts the
  /// same as compute(vertex(v)).
  VisibilityPolygon compute_in_wedge(std::uint32_t v) const;
  /// The same into `out`, reusing its vectors' capacity: with a reused `out` and this
  /// thread's scratch grown, a query allocates nothing.
  void compute(const Point& q, VisibilityPolygon& out) const;
  /// Abstract mode: the same polygon (kinds, vertex, edge and reflex ids, edge tags) without
  /// double coordinates — every `approx` is NaN and `out.abstract` is set. Coordinates on
  /// demand: out.approx_point(i) (double) or out.exact(i) (exact). About the work of the
  /// expansion alone; for callers that need the symbolic answer (which vertices and edges
  /// are seen) rather than a drawing.
  void compute_abstract(const Point& q, VisibilityPolygon& out) const;
  /// V(q) for a constructed (lazy-exact) query, e.g. a point inside a region thinner than
  /// double precision resolves. The same decisions on lazy-exact predicates: slower.
  VisibilityPolygon compute(const ExactPoint& q) const;
  /// V(q) of every query, in order, on `threads` threads (0: one per hardware thread), each
  /// with its own scratch; `abstract` as compute_abstract. If a query is outside free space
  /// the InputError of the first such query (lowest index) is rethrown after all threads end.
  std::vector<VisibilityPolygon> compute_many(std::span<const Point> queries, unsigned threads = 0,
                                              bool abstract = false) const;
  /// The same into `out` (resized to the number of queries), each polygon reusing its
  /// vectors' capacity: a batch repeated over reused polygons allocates nothing once they
  /// have grown, and its threads then share no allocator and take no page faults. Errors
  /// as above; a failing query's polygon is left as it was.
  void compute_many(std::span<const Point> queries, std::vector<VisibilityPolygon>& out, unsigned threads = 0,
                    bool abstract = false) const;

  /// Does the closed segment pq lie in closed free space (grazing the boundary allowed)?
  /// The same answer as geometry::visible, by a walk through the triangles the segment
  /// crosses: O(k) orientation tests for k triangles, no V(p) built. False when p or q is
  /// outside free space.
  bool visible(const Point& p, const Point& q) const;
  /// The same from environment vertex v's point, the walk starting in v's fan (no point
  /// location of v, whose degenerate position makes locating it slow).
  bool visible_from_vertex(std::uint32_t v, const Point& q) const;
  /// Environment vertices visible from q (q in closed free space), ascending: every
  /// vertex w with visible(q, w), needles and grazed vertices included (at a contact, every
  /// ring's vertex there).
  std::vector<std::uint32_t> visible_vertices(const Point& q) const;

 private:
  struct Located { Location loc; std::uint32_t tri; int slot; };
  struct NoCount {
    void operator()() const {}
  };
  template <class Q, class Count = NoCount>
  Located locate_triangle(const Q& q, const Point& approx, bool name_outside = true, Count count = {}) const;
  static constexpr std::size_t kSlabMinTriangles = 12;  // a cell listing more gets a slab
  template <class Q>
  void compute_at(const Q& q, const Point& approx, VisibilityPolygon& out, bool coordinates,
                  std::uint32_t only_wedge = kNone) const;
  template <class OnVertex>
  bool walk(const Point& a, const Point& b, std::uint32_t start, bool to_b, OnVertex&& on_vertex) const;
  std::uint32_t cell_x(double x) const {  // monotone in x: the grid's cell bounds are derived from it
    const double f = (x - x0_) / cw_;
    return f >= static_cast<double>(gx_) ? gx_ - 1 : f > 0 ? static_cast<std::uint32_t>(f) : 0;
  }
  std::uint32_t cell_y(double y) const {
    const double f = (y - y0_) / ch_;
    return f >= static_cast<double>(gy_) ? gy_ - 1 : f > 0 ? static_cast<std::uint32_t>(f) : 0;
  }

  const Environment* env_;
  Triangulation tri_;
  // Point-location grid. Cell (i, j) holds every triangle that meets the closed box of all
  // doubles that cell_x, cell_y map to (i, j) — an exact triangle/box test — sorted by the
  // area of the overlap, largest first; a first entry with kInsideCell set is a triangle
  // holding the whole box in its interior.
  static constexpr std::uint32_t kInsideCell = 0x80000000u;
  // A heavy cell (many triangles, e.g. long thin fans crossing it) lists only an entry
  // kSlabCell | s naming slab s. Slab s: the triangle edges crossing the cell from side to
  // side (left to right, or bottom to top), sorted across the cell; they cut it into bands.
  // A query finds its band by binary search (a float guess verified by two exact
  // orientations; exact binary search if that fails); a band between two edges of one
  // triangle is that triangle (proved by the two strict tests), so these triangles are
  // not listed. The slab lists the cell's other triangles (no edge in the slab); a query on
  // an edge tests the edge's two triangles; a miss (rounding in the guess, a band of other
  // triangles) scans the other list, then every triangle of the slab's edges: all of the
  // cell's triangles, so the answer stays exact.
  static constexpr std::uint32_t kSlabCell = 0x40000000u;
  struct SlabEdge {
    std::uint32_t tri;   // the triangle on the edge's left (after-bands side), or on its
    std::uint8_t slot;   // right when `reversed`; slot of the edge in it
    bool reversed;
    float w_mid, slope;  // across-coordinate at the cell's middle and its slope: the guess only
  };
  struct Slab {
    std::uint32_t edges, edge_end;    // slab_edges_[edges, edge_end), sorted
    std::uint32_t others, others_end; // slab_others_[others, others_end)
    bool vertical;                    // edges cross from bottom to top (else left to right)
    double lo, hi;                    // the cell's extent along the edges (x, or y if vertical)
    double mid;                       // where the edges' w_mid are taken: the first cell of the
                                      // block of cells sharing this run of edges (<= 32 cells away)
  };
  double x0_, y0_, cw_, ch_;
  std::uint32_t gx_, gy_;
  std::vector<std::uint32_t> cell_off_, cell_tris_;
  std::vector<Slab> slabs_;
  // The expansion's step across half-edge h = 3t + s (edge s of triangle t) in one record,
  // so following a cone is one load per triangle (not the triangle, its neighbour, the
  // slot there and the apex's point). Across a diagonal: the neighbour's apex c (id and
  // coordinates) and the half-edges (r, c) and (c, l) the cone goes on through. On the
  // boundary (c == kNone): the edge's ends r, l and its environment edge id.
  struct HalfStep {
    std::uint32_t c;
    std::uint32_t right, left;  // diagonal: half-edges of the neighbour; boundary: vertices r, l
    std::uint32_t edge;         // boundary: environment edge
    double cx, cy;
  };
  std::vector<HalfStep> steps_;
  // The expansion's static filter bound (CGAL's Orientation_2 error bound with the largest
  // coordinate differences any query in the bounding box can have): a determinant beyond
  // it has a certain sign; otherwise CGAL decides. +inf when the box's extent is outside
  // the range where that bound holds (every test then goes to CGAL).
  double orient_eps_ = 0;
  std::vector<SlabEdge> slab_edges_;
  std::vector<std::uint32_t> slab_others_;
};

/// Removes repeated and collinear middle vertices and rotates the cycle to start at its
/// lexicographically smallest vertex: two polygons are the same region iff equal after this.
std::vector<ExactPoint> canonical_cycle(std::vector<ExactPoint> pts);

}  // namespace preimage::geometry
