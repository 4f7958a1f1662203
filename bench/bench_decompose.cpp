// Trapezoidal decomposition: preimage's sweep vs CGAL's arrangement construction +
// CGAL::decompose (the vertical decomposition) on the same environments; and point
// location throughput of the cell locator.
#include <preimage/decompose/cell_locator.hpp>
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
  for (int i = 0; i < 4096; ++i) qs.emplace_back(X(rng), Y(rng));
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

void coverage_preimage(benchmark::State& state) {
  std::size_t laps = 0;
  for (auto _ : state) {
    decompose::CoverageOptions o;
    o.width = 2.0, o.angle_deg = 0.0;
    auto rep = decompose::plan_coverage(field(), o);
    laps = rep.laps;
    benchmark::DoNotOptimize(rep);
  }
  state.counters["laps"] = static_cast<double>(laps);
}

void coverage_reference(benchmark::State& state) {
  for (auto _ : state) {
    auto vd = testing::vertical_decomposition(testing::make_arrangement(field()));
    benchmark::DoNotOptimize(vd);
  }
}

}  // namespace

BENCHMARK(coverage_preimage)->Name("boustrophedon+coverage/preimage/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(coverage_reference)->Name("boustrophedon+coverage/reference/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(trapezoidal_preimage)->Name("trapezoidal/preimage")->Arg(10000)->Arg(100000)->ArgName("n")->Unit(benchmark::kMillisecond);
BENCHMARK(trapezoidal_reference)->Name("trapezoidal/reference")->Arg(10000)->Arg(100000)->ArgName("n")->Unit(benchmark::kMillisecond);
BENCHMARK(point_location)->Name("cell-location")->Arg(100000)->ArgName("n");

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
