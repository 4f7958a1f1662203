// Test-only oracles built on CGAL's GPL packages (never linked into the library).
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/geometry/visibility.hpp>

#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Triangular_expansion_visibility_2.h>

#include <memory>
#include <random>
#include <vector>

namespace preimage::testing {

using geometry::Environment;
using geometry::ExactKernel;
using geometry::ExactPoint;
using geometry::Point;

using Arrangement = CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<ExactKernel>>;

/// Swap cells of landmarks by CGAL's Arrangement_2 (an independent oracle): the n(n-1)
/// swap rays as segments reaching past a square box of half-width `box`, which must
/// contain every crossing, plus the box; the count of bounded faces.
std::size_t cgal_swap_cell_count(const std::vector<Point>& landmarks, double box);

/// The environment's edges as a CGAL arrangement (exact constructions), in one sweep.
Arrangement make_arrangement(const Environment& env);

/// CGAL's Triangular_expansion_visibility_2 on the exact-constructions kernel.
class CgalVisibility {
 public:
  using Arrangement = testing::Arrangement;
  using TEV = CGAL::Triangular_expansion_visibility_2<Arrangement, CGAL::Tag_true>;

  explicit CgalVisibility(const Environment& env) : env_(env) {
    arr_.assign(make_arrangement(env));
    locator_ = std::make_unique<CGAL::Arr_naive_point_location<Arrangement>>(arr_);
    tev_ = std::make_unique<TEV>(arr_);
  }

  /// Face handle of free space at an interior point (cached per environment by callers).
  Arrangement::Face_const_handle face_at(const ExactPoint& q) const {
    auto obj = locator_->locate(q);
    auto f = boost::get<Arrangement::Face_const_handle>(&obj);
    if (!f) throw std::logic_error("oracle: query is not in a face");
    return *f;
  }
  /// Halfedge a -> b of the arrangement (free space on its left).
  Arrangement::Halfedge_const_handle halfedge(const Point& a, const Point& b) const {
    for (auto he = arr_.halfedges_begin(); he != arr_.halfedges_end(); ++he)
      if (he->source()->point() == geometry::to_exact(a) && he->target()->point() == geometry::to_exact(b)) return he;
    throw std::logic_error("oracle: halfedge not found");
  }

  /// Visibility polygon as a vertex cycle; `loc` says how q lies (interior, edge e, vertex v).
  std::vector<ExactPoint> compute(const Point& q, const geometry::Location& loc) const {
    Arrangement out;
    const ExactPoint eq = geometry::to_exact(q);
    using K = geometry::Location::Kind;
    if (loc.kind == K::Interior) {
      tev_->compute_visibility(eq, face_at(eq), out);
    } else if (loc.kind == K::OnEdge) {
      tev_->compute_visibility(eq, halfedge(env_.vertex(loc.index), env_.vertex(env_.next(loc.index))), out);
    } else {
      tev_->compute_visibility(eq, halfedge(env_.vertex(env_.prev(loc.index)), env_.vertex(loc.index)), out);
    }
    return cycle_of(out);
  }
  /// Visibility from vertex v's point in the free wedge starting at v's out-edge (holes
  /// touching at a contact): the face left of the wedge's in-edge, prev(u) -> u.
  std::vector<ExactPoint> compute_in_wedge(std::size_t v) const {
    Arrangement out;
    const std::size_t u = env_.wedge_end(v);
    tev_->compute_visibility(geometry::to_exact(env_.vertex(v)), halfedge(env_.vertex(env_.prev(u)), env_.vertex(u)), out);
    return cycle_of(out);
  }

  const Arrangement& arrangement() const { return arr_; }

  static std::vector<ExactPoint> cycle_of(const Arrangement& out) {
    std::vector<ExactPoint> pts;
    for (auto f = out.faces_begin(); f != out.faces_end(); ++f) {
      if (f->is_unbounded()) continue;
      auto c = f->outer_ccb();
      do pts.push_back(c->source()->point());
      while (++c != f->outer_ccb());
    }
    return pts;
  }
  const TEV& tev() const { return *tev_; }

 private:
  const Environment& env_;
  Arrangement arr_;
  std::unique_ptr<CGAL::Arr_naive_point_location<Arrangement>> locator_;
  std::unique_ptr<TEV> tev_;
};

/// CGAL::decompose on an arrangement: per vertex, the features right below and above it.
using VerticalFeature = boost::optional<boost::variant<Arrangement::Vertex_const_handle,
                                                       Arrangement::Halfedge_const_handle,
                                                       Arrangement::Face_const_handle>>;
using VerticalDecomposition =
    std::vector<std::pair<Arrangement::Vertex_const_handle, std::pair<VerticalFeature, VerticalFeature>>>;
VerticalDecomposition vertical_decomposition(const Arrangement& arr);

/// A random environment snapped to an integer grid (so exact points on edges are easy
/// to make), re-validated; retries with the next seed when snapping broke it.
Environment snapped_random_environment(std::size_t n, std::size_t holes, std::uint64_t seed, double scale = 1000.0);

/// Query points of all kinds: random interior points, exact points inside edges,
/// and vertices. Each comes with its exact location.
struct Query {
  Point p;
  geometry::Location loc;
};
std::vector<Query> random_queries(const Environment& env, std::size_t interior, std::size_t on_edges,
                                  std::size_t at_vertices, std::uint64_t seed);

}  // namespace preimage::testing
