// Beam networks: building the arrangement and G for 1,000 beams among 100 obstacles
// (reference: CGAL's Arrangement_2 of the same segments, faces only), and region-filter
// throughput on that scene, plain (NFA simulation) vs cached (lazy subset automaton).
#include <preimage/beams/arrangement.hpp>
#include <preimage/beams/region_filter.hpp>

#include "ratio_reporter.hpp"
#include "support/beam_scenes.hpp"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include <random>

using namespace preimage;

namespace {

// 1,000 line beams among 100 obstacles; 500 labels shared by two beams each, half undirected.
const scene::Scene& big_scene() {
  static const scene::Scene s = preimage::testing::random_beam_scene(400, 100, 1000, 17, 500, 0.5);
  return s;
}
const beams::BeamArrangement& big_arrangement() {
  static const beams::BeamArrangement a = beams::BeamArrangement::build(big_scene());
  return a;
}

void build_preimage(benchmark::State& state) {
  std::size_t regions = 0, crossings = 0, edges = 0;
  const scene::Scene& s = big_scene();  // generated outside the timed loop
  for (auto _ : state) {
    const auto A = beams::BeamArrangement::build(s);
    regions = A.num_regions(), crossings = A.num_crossings(), edges = A.edges().size();
    benchmark::DoNotOptimize(regions);
  }
  state.counters["regions"] = static_cast<double>(regions);
  state.counters["beam_crossings"] = static_cast<double>(crossings);
  state.counters["G_edges"] = static_cast<double>(edges);
}

void build_reference(benchmark::State& state) {
  using K = geometry::ExactKernel;
  using Arr = CGAL::Arrangement_2<CGAL::Arr_segment_traits_2<K>>;
  const auto& A = big_arrangement();
  const auto& env = A.environment();
  std::vector<K::Segment_2> segs;
  for (std::size_t e = 0; e < env.num_vertices(); ++e) segs.emplace_back(env.exact_vertex(e), env.exact_vertex(env.next(e)));
  for (auto& b : A.beams()) segs.emplace_back(b.from, b.to);
  std::size_t faces = 0;
  for (auto _ : state) {
    Arr arr;
    CGAL::insert(arr, segs.begin(), segs.end());
    faces = arr.number_of_faces();
    benchmark::DoNotOptimize(faces);
  }
  state.counters["faces"] = static_cast<double>(faces);
}

// A consistent word: a random walk in G.
const std::vector<beams::Symbol>& walk() {
  static const std::vector<beams::Symbol> w = [] {
    const auto& A = big_arrangement();
    std::mt19937_64 rng(5);
    std::vector<beams::Symbol> out;
    std::uint32_t r = 0;
    while (out.size() < (1u << 20)) {
      const auto o = A.graph().out(r);
      if (o.empty()) { r = static_cast<std::uint32_t>(rng() % A.num_regions()); continue; }
      const auto& t = o[rng() % o.size()];
      out.push_back(t.symbol);
      r = t.to;
    }
    return out;
  }();
  return w;
}

void filter_plain(benchmark::State& state) {
  const auto& A = big_arrangement();
  const auto& w = walk();
  filter::SubsetFilter F(A.graph());
  std::size_t i = 0;
  for (auto _ : state) {
    for (std::size_t k = 0; k < 4096; ++k) {
      if (!F.step(w[i])) F.reset({0});
      i = (i + 1) & (w.size() - 1);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 4096);
}

void filter_cached(benchmark::State& state) {
  const auto& A = big_arrangement();
  const auto& w = walk();
  filter::SubsetAutomaton D(A.graph());
  std::vector<filter::State> all(A.num_regions());
  for (std::uint32_t r = 0; r < all.size(); ++r) all[r] = r;
  auto id = D.intern(all);
  std::size_t i = 0;
  for (auto _ : state) {
    id = D.run(id, std::span<const beams::Symbol>(w.data() + i, 4096));
    i = (i + 4096) & (w.size() - 1);
  }
  benchmark::DoNotOptimize(id);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 4096);
  state.counters["cached_istates"] = static_cast<double>(D.cached_states());
  state.counters["flushes"] = static_cast<double>(D.flushes());
}

}  // namespace

BENCHMARK(build_preimage)->Name("build-G/preimage/beams:1000")->Unit(benchmark::kMillisecond);
BENCHMARK(build_reference)->Name("build-G/reference/beams:1000")->Unit(benchmark::kMillisecond);
// The reference for the cached filter is the plain filter on the same word.
BENCHMARK(filter_plain)->Name("region-filter/reference/beams:1000");  // plain mode
BENCHMARK(filter_cached)->Name("region-filter/preimage/beams:1000");   // cached mode

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
