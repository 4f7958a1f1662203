// SPDX-License-Identifier: Apache-2.0
// The generalized Voronoi diagram of a ~10^4-vertex environment with 50 holes: preimage's
// GeneralizedVoronoiDiagram::build (snapping, exact check of the snapped segments,
// Boost.Polygon's sweep, filtering, sampling, output checks, critical points) beside CGAL's
// Segment_Delaunay_graph_2 (filtered exact predicates, segments known not to intersect,
// spatially sorted insertion) on the same snapped segments, in the same run.
//
//   gvd/preimage/<map>                 the whole build
//   gvd/reference/<map>                CGAL's SDG alone (no GVD extraction: a lower bound)
//   boost-voronoi-only/<map>           Boost's sweep alone (what the build adds on top)
//   clearance/<map>                    one D(p) query through the uniform grid
// Counters: vertices, gvd_edges, saddles, maxima.
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/gvd.hpp>

#include "ratio_reporter.hpp"
#include "support/gvd_oracle.hpp"

#include <boost/polygon/voronoi_builder.hpp>
#include <boost/polygon/voronoi_diagram.hpp>

#include <cmath>
#include <map>
#include <memory>
#include <random>

using namespace preimage::geometry;

namespace {

struct GvdCase {
  std::unique_ptr<Environment> env;
  std::vector<Point> snapped;
  std::vector<std::pair<std::size_t, std::size_t>> segments;  // point indices (contacts share one)
};

GvdCase& gvd_case(const std::string& name) {
  static std::map<std::string, GvdCase> cases;
  auto it = cases.find(name);
  if (it != cases.end()) return it->second;
  GvdCase c;
  if (name == "random-10000-50") c.env = std::make_unique<Environment>(generators::random_environment(10000, 50, 11));
  else if (name == "random-40000-200") c.env = std::make_unique<Environment>(generators::random_environment(40000, 200, 12));
  else c.env = std::make_unique<Environment>(generators::office(35, 35));
  const auto g = GeneralizedVoronoiDiagram::build(*c.env);
  c.snapped = g.snapped_vertices();
  for (std::size_t e = 0; e < c.env->num_vertices(); ++e) c.segments.emplace_back(e, c.env->next(e));
  return cases.emplace(name, std::move(c)).first->second;
}

void gvd_preimage(benchmark::State& state, const std::string& name, int bits) {
  const GvdCase& c = gvd_case(name);
  std::size_t edges = 0, vertices = 0, saddles = 0, maxima = 0;
  for (auto _ : state) {
    const auto g = GeneralizedVoronoiDiagram::build(*c.env, {0, bits});
    edges = g.edges().size(), vertices = g.vertices().size(), saddles = g.saddles().size(), maxima = g.maxima().size();
    benchmark::DoNotOptimize(edges);
  }
  state.counters["vertices"] = static_cast<double>(c.env->num_vertices());
  state.counters["holes"] = static_cast<double>(c.env->num_holes());
  state.counters["gvd_edges"] = static_cast<double>(edges);
  state.counters["gvd_vertices"] = static_cast<double>(vertices);
  state.counters["saddles"] = static_cast<double>(saddles);
  state.counters["maxima"] = static_cast<double>(maxima);
}

void gvd_reference(benchmark::State& state, const std::string& name) {
  const GvdCase& c = gvd_case(name);
  // CGAL's own input format: the points once each (contacts share one), segments as index pairs
  std::map<std::pair<double, double>, std::size_t> index;
  std::vector<Point> pts;
  std::vector<std::size_t> id(c.snapped.size());
  for (std::size_t v = 0; v < c.snapped.size(); ++v) {
    auto [it, fresh] = index.emplace(std::make_pair(c.snapped[v].x(), c.snapped[v].y()), pts.size());
    if (fresh) pts.push_back(c.snapped[v]);
    id[v] = it->second;
  }
  std::vector<std::pair<std::size_t, std::size_t>> segs;
  for (const auto& [a, b] : c.segments) segs.emplace_back(id[a], id[b]);
  for (auto _ : state) benchmark::DoNotOptimize(preimage::testing::cgal_segment_delaunay_graph_size(pts, segs));
  state.counters["vertices"] = static_cast<double>(c.env->num_vertices());
}

void boost_only(benchmark::State& state, const std::string& name) {
  const GvdCase& c = gvd_case(name);
  const int e = [&] {
    double M = 0;
    for (const Point& p : c.env->vertices()) M = std::max({M, std::fabs(p.x()), std::fabs(p.y())});
    int k = 0;
    std::frexp(M, &k);
    return k - 29;
  }();
  for (auto _ : state) {
    boost::polygon::voronoi_builder<std::int32_t> builder;
    for (const auto& [a, b] : c.segments)
      builder.insert_segment(static_cast<std::int32_t>(std::ldexp(c.snapped[a].x(), -e)), static_cast<std::int32_t>(std::ldexp(c.snapped[a].y(), -e)),
                             static_cast<std::int32_t>(std::ldexp(c.snapped[b].x(), -e)), static_cast<std::int32_t>(std::ldexp(c.snapped[b].y(), -e)));
    boost::polygon::voronoi_diagram<double> vd;
    builder.construct(&vd);
    benchmark::DoNotOptimize(vd.num_edges());
  }
}

void clearance_query(benchmark::State& state, const std::string& name) {
  const GvdCase& c = gvd_case(name);
  const auto g = GeneralizedVoronoiDiagram::build(*c.env);
  std::mt19937_64 rng(3);
  const auto box = c.env->bbox();
  std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax());
  std::vector<Point> qs;
  for (int i = 0; i < 1024; ++i) qs.emplace_back(ux(rng), uy(rng));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(g.clearance(qs[i++ & 1023]));
}

const int registered = [] {
  for (const std::string name : {"random-10000-50", "office-35x35", "random-40000-200"}) {
    benchmark::RegisterBenchmark(("gvd/preimage/" + name).c_str(), gvd_preimage, name, 29)->Unit(benchmark::kMillisecond);
    for (int bits : {20, 24, 26})
      benchmark::RegisterBenchmark(("gvd-grid-bits-" + std::to_string(bits) + "/" + name).c_str(), gvd_preimage, name, bits)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("gvd/reference/" + name).c_str(), gvd_reference, name)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("boost-voronoi-only/" + name).c_str(), boost_only, name)->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("clearance/random-10000-50", clearance_query, std::string("random-10000-50"));
  return 0;
}();

}  // namespace

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
