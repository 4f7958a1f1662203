// Visibility polygon per query, per map: preimage's VisibilityIndex beside CGAL's
// Triangular_expansion_visibility_2 (exact-constructions kernel), same environments, same
// queries, outputs checked identical before timing. Maps: both HouseExpo plans, offices
// and combs from about 10^2 to 3 * 10^4 vertices, random environments with holes.
//
// Per map:
//   preprocess/<map>                building the VisibilityIndex (triangulation, grid, slabs)
//   locate/<map>                    point location alone (counter tests_per_locate)
//   abstract/preimage/<map>         compute_abstract into a reused polygon: ids only
//   compute/preimage/<map>          compute(q, out) into a reused polygon, with coordinates
//   compute-by-value/<map>          compute(q), a new polygon per query
//   {abstract,compute}/reference    CGAL TE (its face located outside the loop)
//   compute+exact-points/preimage   ... plus every vertex's lazy-exact coordinates
//   batch-{1,2}-threads/<map>       compute_many over the map's 500 queries (real time)
//   batch-speedup/<map>             both, interleaved: median 1-thread time / median 2-thread time
//   batch-speedup-reused/<map>      the same into polygons reused across batches (no allocation)
// Breakdown per query: locate = locate/, expand = abstract - locate, output = compute -
// abstract. Counters: allocs_per_query (global operator new in this binary, steady state),
// preprocess_ms (building the index, once), vertices, out_vertices.
#if defined(__GNUC__) && !defined(__clang__)
// The counting operator new/delete below pair malloc with free; GCC sees CGAL's inlined
// new/delete through them and warns of a mismatch that is not one.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/import.hpp>

#include "ratio_reporter.hpp"
#include "support/cgal_oracle.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <new>

// ---------------------------------------------------------------- allocation counter
namespace {
std::atomic<std::size_t> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace preimage::geometry;

namespace {

struct Case {
  std::unique_ptr<Environment> env;
  std::unique_ptr<VisibilityIndex> ours;
  std::unique_ptr<preimage::testing::CgalVisibility> cgal;
  std::vector<preimage::testing::Query> queries;
  double preprocess_ms = 0;
  bool identical = true;
};

// The repository's copies (examples/floorplans), so a clean clone runs the bench.
std::string floorplan(const char* name) { return std::string(PREIMAGE_BENCH_EXAMPLES).append("/floorplans/").append(name); }

const std::map<std::string, std::function<Environment()>>& maps() {
  static const std::map<std::string, std::function<Environment()>> m = {
      {"houseexpo-0000", [] { return *preimage::scene::import_houseexpo(floorplan("house_expo_room_0000.json")).environment; }},
      {"houseexpo-1451", [] { return *preimage::scene::import_houseexpo(floorplan("house_expo_room_1451.json")).environment; }},
      {"office-3x3", [] { return generators::office(3, 3); }},
      {"office-5x5", [] { return generators::office(5, 5); }},
      {"office-20x20", [] { return generators::office(20, 20); }},
      {"office-35x35", [] { return generators::office(35, 35); }},
      {"comb-25", [] { return Environment::make(generators::comb(25), {}); }},
      {"comb-120", [] { return Environment::make(generators::comb(120), {}); }},
      {"comb-2500", [] { return Environment::make(generators::comb(2500), {}); }},
      {"comb-7500", [] { return Environment::make(generators::comb(7500), {}); }},
      {"random-1000-h20", [] { return generators::random_environment(1000, 20, 1062); }},
  };
  return m;
}

Case& get_case(const std::string& name) {
  static std::map<std::string, Case> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Case c;
  c.env = std::make_unique<Environment>(maps().at(name)());
  const auto t0 = std::chrono::steady_clock::now();
  c.ours = std::make_unique<VisibilityIndex>(*c.env);
  c.preprocess_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  c.cgal = std::make_unique<preimage::testing::CgalVisibility>(*c.env);
  c.queries = preimage::testing::random_queries(*c.env, 500, 0, 0, 7);
  for (std::size_t k = 0; k < c.queries.size(); k += 5) {  // every fifth query against CGAL
    const auto& q = c.queries[k];
    if (canonical_cycle(c.ours->compute(q.p).points()) != canonical_cycle(c.cgal->compute(q.p, q.loc))) c.identical = false;
  }
  return cache.emplace(name, std::move(c)).first->second;
}

// Building the index alone, repeatedly (the environment built once, outside the loop).
void bm_preprocess(benchmark::State& state, const std::string& name) {
  static std::map<std::string, std::unique_ptr<Environment>> envs;
  auto& env = envs[name];
  if (!env) env = std::make_unique<Environment>(maps().at(name)());
  for (auto _ : state) {
    VisibilityIndex index(*env);
    benchmark::DoNotOptimize(&index);
  }
  state.counters["vertices"] = static_cast<double>(env->vertices().size());
}

void common_counters(benchmark::State& state, const Case& c, std::size_t allocs, std::size_t queries) {
  state.counters["allocs_per_query"] = static_cast<double>(allocs) / static_cast<double>(std::max<std::size_t>(1, queries));
  state.counters["preprocess_ms"] = c.preprocess_ms;
  state.counters["vertices"] = static_cast<double>(c.env->vertices().size());
}

void bm_locate(benchmark::State& state, const std::string& name) {
  Case& c = get_case(name);
  std::size_t i = 0;
  for (auto _ : state) {
    auto loc = c.ours->locate(c.queries[i++ % c.queries.size()].p);
    benchmark::DoNotOptimize(loc);
  }
  std::size_t tests = 0;
  for (const auto& q : c.queries) tests += c.ours->locate_tests(q.p);
  state.counters["tests_per_locate"] = static_cast<double>(tests) / static_cast<double>(c.queries.size());
}

void bm_compute_by_value(benchmark::State& state, const std::string& name) {
  Case& c = get_case(name);
  if (!c.identical) state.SkipWithError("outputs differ from CGAL");
  std::size_t i = 0, verts = 0;
  const std::size_t a0 = g_allocations.load();
  for (auto _ : state) {
    auto v = c.ours->compute(c.queries[i++ % c.queries.size()].p);
    verts += v.vertices.size();
    benchmark::DoNotOptimize(v);
  }
  common_counters(state, c, g_allocations.load() - a0, i);
  state.counters["out_vertices"] = static_cast<double>(verts) / static_cast<double>(std::max<std::size_t>(1, i));
}

// Into one reused polygon; one pass over the queries first, so the output's and this
// thread's scratch capacity are grown and allocs_per_query is the steady state.
void bm_compute_reused(benchmark::State& state, const std::string& name, bool abstract) {
  Case& c = get_case(name);
  if (!c.identical) state.SkipWithError("outputs differ from CGAL");
  VisibilityPolygon out;
  for (const auto& q : c.queries) abstract ? c.ours->compute_abstract(q.p, out) : c.ours->compute(q.p, out);
  std::size_t i = 0;
  const std::size_t a0 = g_allocations.load();
  for (auto _ : state) {
    const Point& q = c.queries[i++ % c.queries.size()].p;
    if (abstract) c.ours->compute_abstract(q, out);
    else c.ours->compute(q, out);
    benchmark::DoNotOptimize(out.vertices.data());
    benchmark::ClobberMemory();
  }
  common_counters(state, c, g_allocations.load() - a0, i);
}

void bm_batch(benchmark::State& state, const std::string& name, unsigned threads) {
  Case& c = get_case(name);
  std::vector<Point> qs;
  for (const auto& q : c.queries) qs.push_back(q.p);
  for (auto _ : state) {
    auto all = c.ours->compute_many(qs, threads);
    benchmark::DoNotOptimize(all.data());
  }
  state.counters["queries"] = static_cast<double>(qs.size());
}

// The two batch runs interleaved in one loop (1 thread, then 2, each timed in real time),
// so a load change on the machine hits both alike: speedup = the median over the pairs of
// 1-thread time / 2-thread time; best_speedup = best over best (the quietest moments).
// By value (compute_many returning new polygons) or, `reused`, into polygons kept across
// iterations (one set per thread count), where the batch allocates nothing once grown:
// allocs_per_batch counts global operator new over the timed iterations after the first.
void bm_batch_speedup(benchmark::State& state, const std::string& name, bool reused) {
  Case& c = get_case(name);
  std::vector<Point> qs;
  for (const auto& q : c.queries) qs.push_back(q.p);
  std::vector<double> one, two;
  std::vector<VisibilityPolygon> kept[2];
  std::size_t allocs = 0, counted = 0;
  for (auto _ : state) {
    for (unsigned threads : {1u, 2u}) {
      const std::size_t a0 = g_allocations.load();
      const auto t0 = std::chrono::steady_clock::now();
      if (reused) {
        c.ours->compute_many(qs, kept[threads - 1], threads);
        benchmark::DoNotOptimize(kept[threads - 1].data());
      } else {
        auto all = c.ours->compute_many(qs, threads);
        benchmark::DoNotOptimize(all.data());
      }
      const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
      (threads == 1 ? one : two).push_back(us);
      if (one.size() > 1) allocs += g_allocations.load() - a0, ++counted;
    }
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  std::vector<double> ratio;  // per pair: the two runs of a pair met about the same load
  for (std::size_t k = 0; k < one.size(); ++k) ratio.push_back(one[k] / two[k]);
  state.counters["us_1_thread"] = median(one);
  state.counters["us_2_threads"] = median(two);
  state.counters["speedup"] = median(ratio);
  state.counters["best_speedup"] = two.empty() ? 0 : *std::min_element(one.begin(), one.end()) / *std::min_element(two.begin(), two.end());
  state.counters["allocs_per_batch"] = counted ? static_cast<double>(allocs) / static_cast<double>(counted) : 0;
}

void bm_compute_exact_points(benchmark::State& state, const std::string& name) {
  Case& c = get_case(name);
  if (!c.identical) state.SkipWithError("outputs differ from CGAL");
  std::size_t i = 0;
  for (auto _ : state) {
    auto v = c.ours->compute(c.queries[i++ % c.queries.size()].p);
    auto pts = v.points();
    benchmark::DoNotOptimize(pts);
  }
}

void bm_reference(benchmark::State& state, const std::string& name) {
  Case& c = get_case(name);
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

void register_all() {
  auto reg = [](const char* what, auto fn, const std::string& name, auto... extra) {
    return benchmark::RegisterBenchmark(std::string(what).append(name).c_str(), fn, name, extra...)
        ->Unit(benchmark::kMicrosecond);
  };
  for (const auto& [name, make] : maps()) {
    reg("preprocess/", bm_preprocess, name)->Unit(benchmark::kMillisecond);
    reg("locate/", bm_locate, name);
    reg("abstract/preimage/", bm_compute_reused, name, true);
    reg("abstract/reference/", bm_reference, name);
    reg("compute/preimage/", bm_compute_reused, name, false);
    reg("compute/reference/", bm_reference, name);
    reg("compute-by-value/", bm_compute_by_value, name);
    reg("compute+exact-points/preimage/", bm_compute_exact_points, name);
    reg("compute+exact-points/reference/", bm_reference, name);
    reg("batch-1-thread/", bm_batch, name, 1u)->UseRealTime();
    reg("batch-2-threads/", bm_batch, name, 2u)->UseRealTime();
    reg("batch-speedup/", bm_batch_speedup, name, false)->UseRealTime();
    reg("batch-speedup-reused/", bm_batch_speedup, name, true)->UseRealTime();
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  return preimage::bench::run_with_ratios(argc, argv);
}
