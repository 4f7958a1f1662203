// SPDX-License-Identifier: Apache-2.0
// The shortest path map (base of the wave-front decomposition) from one source on a
// 10^4-vertex environment with 50 holes (issue 20: target under 0.5 s), beside a brute force
// in the same run: Dijkstra over ALL environment vertices with the full vertex visibility
// graph (geometry::vertex_visibility_graph, every visible pair, on all cores) and the source
// joined to the vertices it sees. Both start from the same VisibilityIndex (its build is
// timed on its own: it is shared by every source and every visibility query).
//
//   spm/preimage/<map>            ShortestPathMap(graph, source), all cores
//   spm/reference/<map>           full visibility graph + Dijkstra over all vertices
//   spm-one-thread/{preimage,reference}/<map>   both on one thread
//   spm-with-index/<map>          VisibilityIndex + ShortestPathMap (nothing prepared)
//   visibility-index/<map>        the index alone
//   geodesic-query/<map>          one h(p) query (V(p)'s vertices + one triangle walk)
//   extensions/<map>              tangency extensions and collisions on them (one pass)
//   fronts-collide/<map>          first collisions of two fronts (one pass)
//   wavefront-decomposition/<map> the cells and critical slices (decompose::WavefrontDecomposition)
//                                 on smaller maps, beside spm/<map> of the same source: what the
//                                 decomposition costs over the map it is built on (no other
//                                 method computes these cells to compare with)
#include <preimage/decompose/wavefront.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/shortest_path_map.hpp>
#include <preimage/geometry/visibility_graphs.hpp>

#include "ratio_reporter.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <queue>
#include <random>

using namespace preimage::geometry;

namespace {

struct WaveCase {
  std::unique_ptr<Environment> env;
  std::unique_ptr<VisibilityIndex> index;
  Point source;
  std::vector<Point> queries;
};

WaveCase& wave_case(const std::string& name) {
  static std::map<std::string, WaveCase> cases;
  auto it = cases.find(name);
  if (it != cases.end()) return it->second;
  WaveCase c;
  if (name == "random-10000-50") c.env = std::make_unique<Environment>(generators::random_environment(10000, 50, 11));
  else if (name == "random-300-6") c.env = std::make_unique<Environment>(generators::random_environment(300, 6, 11));
  else if (name == "office-3x3") c.env = std::make_unique<Environment>(generators::office(3, 3));
  else c.env = std::make_unique<Environment>(generators::office(20, 20));
  c.index = std::make_unique<VisibilityIndex>(*c.env);
  std::mt19937_64 rng(5);
  const auto b = c.env->bbox();
  std::uniform_real_distribution<double> ux(b.xmin(), b.xmax()), uy(b.ymin(), b.ymax());
  while (c.queries.size() < 257) {
    const Point p(ux(rng), uy(rng));
    if (c.index->in_free_space(p)) c.queries.push_back(p);
  }
  c.source = c.queries.back();
  c.queries.pop_back();
  return cases.emplace(name, std::move(c)).first->second;
}

void spm_preimage(benchmark::State& state, const std::string& name, unsigned threads) {
  WaveCase& c = wave_case(name);
  std::size_t reached = 0, edges = 0;
  for (auto _ : state) {
    VisibilityGraph graph(*c.index);
    const ShortestPathMap spm(graph, c.source, threads);
    reached = spm.num_reached(), edges = spm.num_edges();
    benchmark::DoNotOptimize(reached);
  }
  state.counters["vertices"] = static_cast<double>(c.env->num_vertices());
  state.counters["holes"] = static_cast<double>(c.env->num_holes());
  state.counters["reflex_reached"] = static_cast<double>(reached);
  state.counters["edges"] = static_cast<double>(edges);
}

void spm_with_index(benchmark::State& state, const std::string& name) {
  WaveCase& c = wave_case(name);
  for (auto _ : state) {
    VisibilityIndex index(*c.env);
    VisibilityGraph graph(index);
    const ShortestPathMap spm(graph, c.source);
    benchmark::DoNotOptimize(spm.num_reached());
  }
}

void spm_reference(benchmark::State& state, const std::string& name, unsigned threads) {
  WaveCase& c = wave_case(name);
  const std::size_t n = c.env->num_vertices();
  std::size_t edges = 0;
  for (auto _ : state) {
    const GraphEdges e = vertex_visibility_graph(*c.index, threads);
    std::vector<std::vector<std::uint32_t>> adj(n);
    for (const auto& [a, b] : e) adj[a].push_back(b), adj[b].push_back(a);
    std::vector<double> d(n, std::numeric_limits<double>::infinity());
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    for (std::uint32_t v : c.index->visible_vertices(c.source)) {
      d[v] = std::hypot(c.env->vertex(v).x() - c.source.x(), c.env->vertex(v).y() - c.source.y());
      open.push({d[v], v});
    }
    while (!open.empty()) {
      const auto [dv, v] = open.top();
      open.pop();
      if (dv > d[v]) continue;
      const Point& V = c.env->vertex(v);
      for (auto w : adj[v]) {
        const double nd = dv + std::hypot(c.env->vertex(w).x() - V.x(), c.env->vertex(w).y() - V.y());
        if (nd < d[w]) d[w] = nd, open.push({nd, w});
      }
    }
    edges = e.size();
    benchmark::DoNotOptimize(d.data());
  }
  state.counters["edges"] = static_cast<double>(edges);
}

void index_only(benchmark::State& state, const std::string& name) {
  WaveCase& c = wave_case(name);
  for (auto _ : state) {
    VisibilityIndex index(*c.env);
    benchmark::DoNotOptimize(&index);
  }
}

void geodesic_query(benchmark::State& state, const std::string& name) {
  WaveCase& c = wave_case(name);
  VisibilityGraph graph(*c.index);
  const ShortestPathMap spm(graph, c.source);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(spm.distance(c.queries[i++ & 255]));
}

// The critical points on demand, after the map: tangency extensions (with the bisection of
// collisions on them) and the first collisions of two fronts.
void critical_points(benchmark::State& state, const std::string& name, bool fronts) {
  WaveCase& c = wave_case(name);
  VisibilityGraph graph(*c.index);
  const ShortestPathMap spm(graph, c.source);
  std::size_t found = 0;
  for (auto _ : state) found = fronts ? spm.collisions().size() : spm.extensions().size();
  state.counters["found"] = static_cast<double>(found);
}

void decomposition(benchmark::State& state, const std::string& name) {
  WaveCase& c = wave_case(name);
  VisibilityGraph graph(*c.index);
  const ShortestPathMap spm(graph, c.source);
  std::size_t cells = 0, levels = 0;
  for (auto _ : state) {
    const preimage::decompose::WavefrontDecomposition d(spm);
    cells = d.cells().size(), levels = d.levels().size();
  }
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["levels"] = static_cast<double>(levels);
}

const int registered = [] {
  for (const std::string name : {"random-300-6", "office-3x3"}) {
    benchmark::RegisterBenchmark(("wavefront-decomposition/" + name).c_str(), decomposition, name)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("spm/preimage/" + name).c_str(), spm_preimage, name, 0u)->Unit(benchmark::kMillisecond);
  }
  for (const std::string name : {"random-10000-50", "office-20x20"}) {
    benchmark::RegisterBenchmark(("spm/preimage/" + name).c_str(), spm_preimage, name, 0u)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("spm/reference/" + name).c_str(), spm_reference, name, 0u)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("spm-one-thread/preimage/" + name).c_str(), spm_preimage, name, 1u)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("spm-one-thread/reference/" + name).c_str(), spm_reference, name, 1u)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("spm-with-index/" + name).c_str(), spm_with_index, name)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("visibility-index/" + name).c_str(), index_only, name)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("geodesic-query/" + name).c_str(), geodesic_query, name)->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("extensions/" + name).c_str(), critical_points, name, false)->Unit(benchmark::kMillisecond)->Iterations(1);
    benchmark::RegisterBenchmark(("fronts-collide/" + name).c_str(), critical_points, name, true)->Unit(benchmark::kMillisecond)->Iterations(1);
  }
  return 0;
}();

}  // namespace

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
