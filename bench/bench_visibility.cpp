// Visibility polygon per query: preimage's VisibilityIndex vs CGAL's
// Triangular_expansion_visibility_2 (exact-constructions kernel), same environments,
// same queries, outputs checked identical before timing.
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/visibility.hpp>

#include "ratio_reporter.hpp"
#include "support/cgal_oracle.hpp"

#include <map>
#include <memory>

using namespace preimage::geometry;

namespace {

struct Case {
  std::unique_ptr<Environment> env;
  std::unique_ptr<VisibilityIndex> ours;
  std::unique_ptr<preimage::testing::CgalVisibility> cgal;
  std::vector<preimage::testing::Query> queries;
  bool identical = true;
};

Case& get_case(std::size_t n, std::size_t holes) {
  static std::map<std::pair<std::size_t, std::size_t>, Case> cache;
  auto key = std::make_pair(n, holes);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  Case c;
  c.env = std::make_unique<Environment>(generators::random_environment(n, holes, 42 + n + holes));
  c.ours = std::make_unique<VisibilityIndex>(*c.env);
  c.cgal = std::make_unique<preimage::testing::CgalVisibility>(*c.env);
  c.queries = preimage::testing::random_queries(*c.env, 200, 0, 0, 7);
  for (auto& q : c.queries)
    if (canonical_cycle(c.ours->compute(q.p).points()) != canonical_cycle(c.cgal->compute(q.p, q.loc))) c.identical = false;
  return cache.emplace(key, std::move(c)).first->second;
}

void visibility_preimage(benchmark::State& state) {
  Case& c = get_case(static_cast<std::size_t>(state.range(0)), static_cast<std::size_t>(state.range(1)));
  if (!c.identical) state.SkipWithError("outputs differ from CGAL");
  std::size_t i = 0, verts = 0;
  for (auto _ : state) {
    auto v = c.ours->compute(c.queries[i++ % c.queries.size()].p);
    verts += v.vertices.size();
    benchmark::DoNotOptimize(v);
  }
  state.counters["out_vertices"] = benchmark::Counter(static_cast<double>(verts), benchmark::Counter::kAvgIterations);
}

// The same, also constructing every vertex's exact coordinates (lazy exact), as CGAL does.
void visibility_preimage_exact_points(benchmark::State& state) {
  Case& c = get_case(static_cast<std::size_t>(state.range(0)), static_cast<std::size_t>(state.range(1)));
  if (!c.identical) state.SkipWithError("outputs differ from CGAL");
  std::size_t i = 0;
  for (auto _ : state) {
    auto v = c.ours->compute(c.queries[i++ % c.queries.size()].p);
    auto pts = v.points();
    benchmark::DoNotOptimize(pts);
  }
}

void visibility_reference(benchmark::State& state) {
  Case& c = get_case(static_cast<std::size_t>(state.range(0)), static_cast<std::size_t>(state.range(1)));
  if (!c.identical) state.SkipWithError("outputs differ from CGAL");
  // The face is located outside the timed loop, as a caller with many queries would.
  std::vector<preimage::testing::CgalVisibility::Arrangement::Face_const_handle> faces;
  for (auto& q : c.queries) faces.push_back(c.cgal->face_at(to_exact(q.p)));
  std::size_t i = 0;
  for (auto _ : state) {
    std::size_t k = i++ % c.queries.size();
    preimage::testing::CgalVisibility::Arrangement out;
    c.cgal->tev().compute_visibility(to_exact(c.queries[k].p), faces[k], out);
    benchmark::DoNotOptimize(out);
  }
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {1000, 10000})
    for (int holes : {0, 20}) b->Args({n, holes});
  b->ArgNames({"n", "holes"});
}

}  // namespace

BENCHMARK(visibility_preimage)->Name("visibility/preimage")->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(visibility_preimage_exact_points)->Name("visibility+exact-points/preimage")->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(visibility_reference)->Name("visibility+exact-points/reference")->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(visibility_reference)->Name("visibility/reference")->Apply(sizes)->Unit(benchmark::kMicrosecond);

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
