// SPDX-License-Identifier: Apache-2.0
// Exact visibility polygons by triangular expansion (Bungiu, Hemmer, Hershberger,
// Huang, Kröller 2014) over this library's own constrained Delaunay triangulation.
// Every decision is an orientation test on input points (the query and environment
// vertices), so it is exact and fast; only output vertices on edges are constructed,
// lazily exact (ExactPoint).
#pragma once
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/triangulation.hpp>

#include <cstdint>
#include <vector>

namespace preimage::geometry {

/// A visibility-polygon vertex, described exactly by where it comes from: an environment
/// vertex, the query itself, or the point where the ray from the query through `vertex`
/// meets environment edge `edge`. Exact coordinates are constructed on demand
/// (VisibilityPolygon::exact); `approx` is a double rounding for drawing and reports.
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
  Point query;
  ExactPoint exact_query;
  Location location;  // of the query
  std::vector<VisibilityVertex> vertices;
  std::vector<VisibilityEdge> edges;

  /// Exact coordinates of vertex i (lazy exact construction for ray hits).
  ExactPoint exact(std::size_t i) const;
  /// All vertices, exact.
  std::vector<ExactPoint> points() const;
  double area() const;
};

/// Exact coordinates of a visibility vertex of V(query) (lazy-exact construction for ray hits).
ExactPoint exact_point(const Environment& env, const ExactPoint& query, const VisibilityVertex& v);

/// Preprocesses one environment (triangulation + point-location grid) for many queries.
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
  /// outside free space.
  VisibilityPolygon compute(const Point& q) const;
  /// V(q) for a constructed (lazy-exact) query, e.g. a point inside a region thinner than
  /// double precision resolves. The same decisions on lazy-exact predicates: slower.
  VisibilityPolygon compute(const ExactPoint& q) const;

  /// Does the closed segment pq lie in closed free space (grazing the boundary allowed)?
  /// The same answer as geometry::visible, by a walk through the triangles the segment
  /// crosses: O(k) orientation tests for k triangles, no V(p) built. False when p or q is
  /// outside free space.
  bool visible(const Point& p, const Point& q) const;
  /// Environment vertices visible from q (q in closed free space), ascending: every
  /// vertex w with visible(q, w), needles and grazed vertices included.
  std::vector<std::uint32_t> visible_vertices(const Point& q) const;

 private:
  struct Located { Location loc; std::uint32_t tri; int slot; };
  struct NoCount {
    void operator()() const {}
  };
  template <class Q, class Count = NoCount>
  Located locate_triangle(const Q& q, const Point& approx, bool name_outside = true, Count count = {}) const;
  template <class Q>
  VisibilityPolygon compute_at(const Q& q, const Point& approx) const;
  template <class OnVertex>
  bool walk(const Point& a, const Point& b, std::uint32_t start, bool to_b, OnVertex&& on_vertex) const;

  const Environment* env_;
  Triangulation tri_;
  // Point-location grid over triangle bounding boxes.
  double x0_, y0_, cw_, ch_;
  std::uint32_t gx_, gy_;
  std::vector<std::uint32_t> cell_off_, cell_tris_;
};

/// Removes repeated and collinear middle vertices and rotates the cycle to start at its
/// lexicographically smallest vertex: two polygons are the same region iff equal after this.
std::vector<ExactPoint> canonical_cycle(std::vector<ExactPoint> pts);

}  // namespace preimage::geometry
