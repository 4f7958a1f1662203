// Trapezoidal decomposition: preimage's sweep vs CGAL's arrangement construction +
// CGAL::decompose (the vertical decomposition) on the same environments; point location
// throughput of the cell locator; coverage of a 10^4-vertex field, optimised against the
// text's depth-first order.
#include <preimage/decompose/cell_locator.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/decompose/coverage.hpp>
#include <preimage/geometry/generators.hpp>

#include "ratio_reporter.hpp"
#include "support/cgal_oracle.hpp"


#include <map>
#include <memory>
#include <random>

using namespace preimage;

namespace {

const geometry::Environment& environment(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<geometry::Environment>> cache;
  auto& e = cache[n];
  if (!e) e = std::make_unique<geometry::Environment>(geometry::generators::random_environment(n, 100, 7 + n));
  return *e;
}

void trapezoidal_preimage(benchmark::State& state) {
  const auto& env = environment(static_cast<std::size_t>(state.range(0)));
  std::size_t cells = 0;
  for (auto _ : state) {
    decompose::TrapezoidalDecomposition d(env);
    cells = d.cells().size();
    benchmark::DoNotOptimize(cells);
  }
  state.counters["cells"] = static_cast<double>(cells);
}

void trapezoidal_reference(benchmark::State& state) {
  const auto& env = environment(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    auto vd = testing::vertical_decomposition(testing::make_arrangement(env));
    benchmark::DoNotOptimize(vd);
  }
}

void point_location(benchmark::State& state) {
  const auto& env = environment(static_cast<std::size_t>(state.range(0)));
  decompose::TrapezoidalDecomposition d(env);
  decompose::CellLocator loc(d);
  std::mt19937_64 rng(3);
  const auto box = env.bbox();
  std::uniform_real_distribution<double> X(box.xmin(), box.xmax()), Y(box.ymin(), box.ymax());
  std::vector<geometry::Point> qs;
  for (int i = 0; i < 4096; ++i) qs.push_back(geometry::random_point(rng, X, Y));
  std::size_t i = 0, found = 0;
  for (auto _ : state) found += loc.locate(qs[i++ & 4095]).has_value();
  benchmark::DoNotOptimize(found);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// A 10^4-vertex field with 50 holes: boustrophedon decomposition + full coverage path
// (tool width 2 in a field 200 across), against CGAL's vertical decomposition alone.
const geometry::Environment& field() {
  static const geometry::Environment env = geometry::generators::random_environment(10000, 50, 11);
  return env;
}

// Coverage of the field: plan (decomposition, four sweeps per cell, order, transits,
// certification of every segment) and its metrics as counters. "preimage" is the optimised
// order with shortest transits; "reference" the order the text gives (6.2.1: depth-first over
// the adjacency graph, every cell swept the same way) with transits through the trapezoids
// of the decomposition (the paper's planner), and DFS with shortest transits beside it.
void coverage(benchmark::State& state, decompose::CellOrder order, decompose::Transit transit) {
  decompose::CoverageReport rep;
  for (auto _ : state) {
    decompose::CoverageOptions o;
    o.width = 2.0, o.angle_deg = 0.0, o.order = order, o.transit = transit;
    rep = decompose::plan_coverage(field(), o);
    benchmark::DoNotOptimize(rep);
  }
  state.counters["cells"] = static_cast<double>(rep.cells);
  state.counters["length"] = rep.length;
  state.counters["turns"] = static_cast<double>(rep.turns);
  state.counters["transit_share"] = rep.transit_length / rep.length;
  state.counters["lower_bound"] = rep.order_lower_bound;
}

void coverage_preimage(benchmark::State& state) { coverage(state, decompose::CellOrder::Optimised, decompose::Transit::Shortest); }
void coverage_reference(benchmark::State& state) { coverage(state, decompose::CellOrder::DepthFirst, decompose::Transit::Decomposition); }
void coverage_dfs_shortest(benchmark::State& state) { coverage(state, decompose::CellOrder::DepthFirst, decompose::Transit::Shortest); }

void decomposition_reference(benchmark::State& state) {
  for (auto _ : state) {
    auto vd = testing::vertical_decomposition(testing::make_arrangement(field()));
    benchmark::DoNotOptimize(vd);
  }
}

}  // namespace

BENCHMARK(coverage_preimage)->Name("coverage/preimage/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(coverage_reference)->Name("coverage/reference/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(coverage_dfs_shortest)->Name("coverage-dfs-shortest/preimage/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(decomposition_reference)->Name("cgal-vertical-decomposition/reference/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(trapezoidal_preimage)->Name("trapezoidal/preimage")->Arg(10000)->Arg(100000)->ArgName("n")->Unit(benchmark::kMillisecond);
BENCHMARK(trapezoidal_reference)->Name("trapezoidal/reference")->Arg(10000)->Arg(100000)->ArgName("n")->Unit(benchmark::kMillisecond);
BENCHMARK(point_location)->Name("cell-location")->Arg(100000)->ArgName("n");

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
