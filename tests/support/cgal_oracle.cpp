#include "cgal_oracle.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>

#include <CGAL/Arr_vertical_decomposition_2.h>

#include <cmath>

namespace preimage::testing {

Arrangement make_arrangement(const Environment& env) {
  std::vector<ExactKernel::Segment_2> segs;
  for (std::size_t e = 0; e < env.num_vertices(); ++e) segs.emplace_back(env.exact_vertex(e), env.exact_vertex(env.next(e)));
  Arrangement arr;
  CGAL::insert_non_intersecting_curves(arr, segs.begin(), segs.end());
  return arr;
}

VerticalDecomposition vertical_decomposition(const Arrangement& arr) {
  VerticalDecomposition vd;
  CGAL::decompose(arr, std::back_inserter(vd));
  return vd;
}

Environment snapped_random_environment(std::size_t n, std::size_t holes, std::uint64_t seed, double scale) {
  for (std::uint64_t s = seed, attempt = 0;; s += 7919, ++attempt) {
    if (attempt == 2000) throw std::runtime_error("snapped_random_environment: no valid snapping found");
    Environment raw = geometry::generators::random_environment(n, holes, s);
    const auto box = raw.bbox();
    const double k = scale / std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    std::vector<geometry::Ring> rings;
    for (std::size_t r = 0; r < raw.num_rings(); ++r) {
      geometry::Ring ring;
      for (auto& p : raw.ring(r)) ring.emplace_back(std::round((p.x() - box.xmin()) * k), std::round((p.y() - box.ymin()) * k));
      rings.push_back(std::move(ring));
    }
    try {
      geometry::Ring outer = rings[0];
      rings.erase(rings.begin());
      return Environment::make(std::move(outer), std::move(rings));
    } catch (const InputError&) {
      continue;  // snapping made it invalid: next seed
    }
  }
}

std::vector<Query> random_queries(const Environment& env, std::size_t interior, std::size_t on_edges,
                                  std::size_t at_vertices, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Query> out;
  const auto box = env.bbox();
  std::uniform_real_distribution<double> X(box.xmin(), box.xmax()), Y(box.ymin(), box.ymax());
  std::uniform_int_distribution<std::size_t> V(0, env.num_vertices() - 1);
  std::size_t tries = 0;
  while (out.size() < interior && ++tries < 1000000) {
    Point p = geometry::random_point(rng, X, Y);
    auto loc = geometry::locate(env, p);
    if (loc.kind == geometry::Location::Kind::Interior) out.push_back({p, loc});
  }
  std::size_t edges = 0;
  tries = 0;
  while (edges < on_edges && ++tries < 1000000) {
    const std::size_t e = V(rng);
    const Point &a = env.vertex(e), &b = env.vertex(env.next(e));
    // A lattice point strictly inside the edge (coordinates are integers).
    const long dx = std::lround(b.x() - a.x()), dy = std::lround(b.y() - a.y());
    const long g = std::gcd(std::labs(dx), std::labs(dy));
    if (g < 2) continue;
    std::uniform_int_distribution<long> K(1, g - 1);
    const long k = K(rng);
    Point p(a.x() + static_cast<double>(dx / g * k), a.y() + static_cast<double>(dy / g * k));
    if (!geometry::strictly_inside_segment(a, b, p)) continue;
    out.push_back({p, {geometry::Location::Kind::OnEdge, e}});
    ++edges;
  }
  for (std::size_t i = 0; i < at_vertices; ++i) {
    const std::size_t v = V(rng);
    out.push_back({env.vertex(v), {geometry::Location::Kind::AtVertex, v}});
  }
  return out;
}

std::size_t cgal_swap_cell_count(const std::vector<Point>& landmarks, double box) {
  std::vector<ExactKernel::Segment_2> segs;
  for (const auto& a : landmarks)
    for (const auto& b : landmarks) {
      if (a == b) continue;
      const ExactPoint pa = geometry::to_exact(a), pb = geometry::to_exact(b);
      const auto d = pa - pb;
      const double len = std::sqrt(CGAL::to_double(d.squared_length()));
      segs.emplace_back(pa, pa + d * (4 * box / len));
    }
  const ExactPoint c[4] = {ExactPoint(-box, -box), ExactPoint(box, -box), ExactPoint(box, box), ExactPoint(-box, box)};
  for (int s = 0; s < 4; ++s) segs.emplace_back(c[s], c[(s + 1) % 4]);
  Arrangement arr;
  CGAL::insert(arr, segs.begin(), segs.end());
  std::size_t bounded = 0;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) bounded += !f->is_unbounded();
  return bounded;
}

}  // namespace preimage::testing
