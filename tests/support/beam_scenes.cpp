#include "beam_scenes.hpp"

#include <preimage/beams/homotopy.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>

#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Polygon_2.h>

#include <map>
#include <random>

namespace preimage::testing {

scene::Scene random_beam_scene(std::size_t n, std::size_t holes, std::size_t nbeams, std::uint64_t seed, std::size_t labels,
                               double undirected_fraction) {
  for (std::uint64_t s = seed;; s += 1000003) {
    scene::Scene sc;
    sc.environment = geometry::generators::random_environment(n, holes, s);
    const auto box = sc.environment->bbox();
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax()), ang(0, 6.283185307179586),
        coin(0, 1);
    while (sc.beams.size() < nbeams) {
      const geometry::Point p = geometry::random_point(rng, ux, uy);
      if (geometry::locate(*sc.environment, p).kind != geometry::Location::Kind::Interior) continue;
      const double a = ang(rng);
      const std::size_t k = sc.beams.size();
      // Appended, not "b" + to_string: GCC 12 flags that with a false -Wrestrict at -O3.
      const std::string label = std::string("b").append(std::to_string(labels ? k % labels : k));
      const bool directed = labels ? (k % labels) >= undirected_fraction * labels : coin(rng) >= undirected_fraction;
      sc.beams.push_back({label, p, geometry::Point(p.x() + std::cos(a), p.y() + std::sin(a)), directed, scene::Beam::Shape::Line});
    }
    try {
      (void)beams::BeamArrangement::build(sc);
      return sc;
    } catch (const InputError&) {
      // A degenerate draw (three beams through a point, a beam through a vertex): redraw.
    }
  }
}

scene::Scene random_sufficient_scene(std::size_t n, std::size_t holes, std::size_t lines, std::uint64_t seed, bool ddd,
                                     std::size_t labels, double undirected_fraction) {
  for (std::uint64_t s = seed;; s += 7919) {
    scene::Scene sc;
    sc.environment = geometry::generators::random_environment(n, holes, s);
    const auto& env = *sc.environment;
    const auto box = env.bbox();
    std::mt19937_64 rng(s);
    std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax()), ang(0, 6.283185307179586),
        coin(0, 1);
    auto label = [&](std::size_t k) {
      return std::string("b").append(std::to_string(ddd ? k : std::size_t(coin(rng) * double(labels))));
    };
    for (std::size_t h = 1; h < env.num_rings(); ++h) {
      // A ray from a random vertex into the free wedge there.
      const std::size_t v = env.ring_begin(h) + std::size_t(coin(rng) * double(env.ring_size(h))) % env.ring_size(h);
      const geometry::Point p = env.vertex(v);
      for (int tries = 0; tries < 100; ++tries) {
        const double a = ang(rng);
        const geometry::Point q(p.x() + std::cos(a), p.y() + std::sin(a));
        if (!geometry::in_free_wedge(env, v, q)) continue;
        const std::string l = label(sc.beams.size());
        sc.beams.push_back({l, p, q, ddd || coin(rng) >= undirected_fraction, scene::Beam::Shape::Ray});
        break;
      }
    }
    while (!ddd && sc.beams.size() < holes + lines) {
      const geometry::Point p = geometry::random_point(rng, ux, uy);
      if (geometry::locate(env, p).kind != geometry::Location::Kind::Interior) continue;
      const double a = ang(rng);
      const std::string l = label(sc.beams.size());
      sc.beams.push_back({l, p, geometry::Point(p.x() + std::cos(a), p.y() + std::sin(a)), coin(rng) >= undirected_fraction,
                          scene::Beam::Shape::Line});
    }
    try {
      const auto A = beams::BeamArrangement::build(sc);
      if (ddd && A.num_crossings() > 0) continue;
      beams::require_sufficient(A);
      return sc;
    } catch (const InputError&) {
      // Degenerate, or a ring of obstacles not joined to the boundary: redraw.
    }
  }
}

OracleRegions cgal_regions(const beams::BeamArrangement& A) {
  using K = geometry::ExactKernel;
  using Arr = CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<K>>;
  const auto& env = A.environment();
  std::vector<K::Segment_2> segs;
  for (std::size_t e = 0; e < env.num_vertices(); ++e) segs.emplace_back(env.exact_vertex(e), env.exact_vertex(env.next(e)));
  for (auto& b : A.beams()) segs.emplace_back(b.from, b.to);
  Arr arr;
  CGAL::insert(arr, segs.begin(), segs.end());
  // A face is free iff a point inside it is inside the outer ring and outside every hole:
  // test with a point of each face found by locating our own samples, and count faces
  // that are neither unbounded nor obstacle interiors by subtraction.
  std::vector<CGAL::Polygon_2<K>> rings;
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    CGAL::Polygon_2<K> p;
    for (auto& q : env.ring(r)) p.push_back(geometry::to_exact(q));
    rings.push_back(p);
  }
  OracleRegions out;
  out.free_faces = arr.number_of_faces() - 1 - env.num_holes();  // minus the unbounded face and obstacle interiors
  CGAL::Arr_naive_point_location<Arr> pl(arr);
  std::map<Arr::Face_const_handle, long> ids;
  for (const auto& R : A.regions()) {
    auto obj = pl.locate(R.sample);
    const Arr::Face_const_handle* f = boost::get<Arr::Face_const_handle>(&obj);
    bool free = f && !(*f)->is_unbounded() && rings[0].bounded_side(R.sample) == CGAL::ON_BOUNDED_SIDE;
    for (std::size_t r = 1; r < rings.size() && free; ++r) free = rings[r].bounded_side(R.sample) == CGAL::ON_UNBOUNDED_SIDE;
    if (!free) {
      out.face_of_sample.push_back(-1);
      continue;
    }
    auto [it, fresh] = ids.try_emplace(*f, static_cast<long>(ids.size()));
    out.face_of_sample.push_back(it->second);
  }
  return out;
}

}  // namespace preimage::testing
