// Trapezoidal decomposition: preimage's sweep vs CGAL's arrangement construction +
// CGAL::decompose (the vertical decomposition) on the same environments; point location
// throughput of the cell locator; coverage of a 10^4-vertex field, optimised against the
// text's depth-first order.
#include <preimage/decompose/cell_locator.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/coverage/coverage.hpp>
#include <preimage/decompose/brushfire.hpp>
#include <preimage/decompose/morse.hpp>
#include <preimage/coverage/online_coverage.hpp>
#include <preimage/geometry/generators.hpp>

#include "ratio_reporter.hpp"
#include "support/cgal_oracle.hpp"


#include <chrono>
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
void coverage(benchmark::State& state, coverage::CellOrder order, coverage::Transit transit) {
  coverage::CoverageReport rep;
  for (auto _ : state) {
    coverage::CoverageOptions o;
    o.width = 2.0, o.angle_deg = 0.0, o.order = order, o.transit = transit;
    rep = coverage::plan_coverage(field(), o);
    benchmark::DoNotOptimize(rep);
  }
  state.counters["cells"] = static_cast<double>(rep.cells);
  state.counters["length"] = rep.length;
  state.counters["turns"] = static_cast<double>(rep.turns);
  state.counters["transit_share"] = rep.transit_length / rep.length;
  state.counters["lower_bound"] = rep.order_lower_bound;
}

void coverage_preimage(benchmark::State& state) { coverage(state, coverage::CellOrder::Optimised, coverage::Transit::Shortest); }
void coverage_reference(benchmark::State& state) { coverage(state, coverage::CellOrder::DepthFirst, coverage::Transit::Decomposition); }
void coverage_dfs_shortest(benchmark::State& state) { coverage(state, coverage::CellOrder::DepthFirst, coverage::Transit::Shortest); }

void decomposition_reference(benchmark::State& state) {
  for (auto _ : state) {
    auto vd = testing::vertical_decomposition(testing::make_arrangement(field()));
    benchmark::DoNotOptimize(vd);
  }
}

// Variable-slice Morse decompositions (6.2.3) of the same field around a point near its
// middle, decomposition alone and decomposition + coverage (tool width 2), each beside the
// boustrophedon decomposition / coverage (depth-first order, the same walk the patterns use)
// as the reference of the same run.
const geometry::Point& field_centre() {
  static const geometry::Point c = [] {
    const auto b = field().bbox();
    return geometry::Point((b.xmin() + b.xmax()) / 2 + 0.123, (b.ymin() + b.ymax()) / 2 + 0.0456);
  }();
  return c;
}

void morse_decomposition(benchmark::State& state, decompose::SliceFamily f) {
  std::size_t cells = 0, critical = 0;
  for (auto _ : state) {
    const decompose::MorseDecomposition m(field(), f, field_centre());
    cells = m.cells().size(), critical = m.critical_points().size();
    benchmark::DoNotOptimize(cells);
  }
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["critical_points"] = static_cast<double>(critical);
}

void boustrophedon_decomposition(benchmark::State& state) {
  std::size_t cells = 0;
  for (auto _ : state) {
    const decompose::BoustrophedonDecomposition b(field());
    cells = b.cells().size();
    benchmark::DoNotOptimize(cells);
  }
  state.counters["cells"] = static_cast<double>(cells);
}

void brushfire_decomposition(benchmark::State& state) {
  std::size_t cells = 0, critical = 0, axis = 0;
  for (auto _ : state) {
    const decompose::BrushfireDecomposition b(field());
    cells = b.cells().size(), critical = b.critical_points().size(), axis = b.gvd().medial_edges().size();
    benchmark::DoNotOptimize(cells);
  }
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["critical_points"] = static_cast<double>(critical);
  state.counters["axis_edges"] = static_cast<double>(axis);
}

void pattern_coverage(benchmark::State& state, coverage::Pattern p) {
  coverage::CoverageReport rep;
  for (auto _ : state) {
    coverage::CoverageOptions o;
    o.width = 2.0, o.pattern = p, o.centre = field_centre();
    if (p == coverage::Pattern::Boustrophedon) o.angle_deg = 0.0, o.order = coverage::CellOrder::DepthFirst;
    rep = coverage::plan_coverage(field(), o);
    benchmark::DoNotOptimize(rep);
  }
  state.counters["cells"] = static_cast<double>(rep.cells);
  state.counters["laps"] = static_cast<double>(rep.laps);
  state.counters["length"] = rep.length;
  state.counters["transit_share"] = rep.transit_length / rep.length;
}

}  // namespace

BENCHMARK_CAPTURE(morse_decomposition, circular, decompose::SliceFamily::Circular)->Name("morse/preimage/circular")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(morse_decomposition, spike, decompose::SliceFamily::Spike)->Name("morse/preimage/spike")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(morse_decomposition, squarel, decompose::SliceFamily::Squarel)->Name("morse/preimage/squarel")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(morse_decomposition, linear, decompose::SliceFamily::Linear)->Name("morse/preimage/linear-generic")->Unit(benchmark::kMillisecond);
BENCHMARK(boustrophedon_decomposition)->Name("morse/reference/linear-generic")->Unit(benchmark::kMillisecond);
BENCHMARK(brushfire_decomposition)->Name("morse/preimage/brushfire")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pattern_coverage, brushfire, coverage::Pattern::Brushfire)->Name("pattern-coverage/preimage/brushfire")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pattern_coverage, spiral, coverage::Pattern::Spiral)->Name("pattern-coverage/preimage/spiral")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pattern_coverage, spike, coverage::Pattern::Spike)->Name("pattern-coverage/preimage/spike")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pattern_coverage, squarel, coverage::Pattern::Squarel)->Name("pattern-coverage/preimage/squarel")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(pattern_coverage, boustrophedon, coverage::Pattern::Boustrophedon)->Name("pattern-coverage/boustrophedon-dfs")->Unit(benchmark::kMillisecond);

BENCHMARK(coverage_preimage)->Name("coverage/preimage/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(coverage_reference)->Name("coverage/reference/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(coverage_dfs_shortest)->Name("coverage-dfs-shortest/preimage/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(decomposition_reference)->Name("cgal-vertical-decomposition/reference/n:10000")->Unit(benchmark::kMillisecond);
BENCHMARK(trapezoidal_preimage)->Name("trapezoidal/preimage")->Arg(10000)->Arg(100000)->ArgName("n")->Unit(benchmark::kMillisecond);
BENCHMARK(trapezoidal_reference)->Name("trapezoidal/reference")->Arg(10000)->Arg(100000)->ArgName("n")->Unit(benchmark::kMillisecond);
BENCHMARK(point_location)->Name("cell-location")->Arg(100000)->ArgName("n");

// Online coverage (6.2.4): the robot that does not know the map beside the offline
// boustrophedon coverage of the same configuration space at the same angle, in the same run.
// Counters: the price of not knowing the map (path length ratio online / offline), whether
// the robot finished, and the critical points it sensed against the offline count. Two
// environments: the gallery (robot radius 0.2, 17 degrees) and a 10^3-vertex random
// environment with 20 holes (radius 1/200 of its size).
void online_coverage(benchmark::State& state, int which) {
  static const geometry::Environment random_env = geometry::generators::random_environment(1000, 20, 1);
  static const geometry::Environment gallery = geometry::Environment::make(
      {{0, 0}, {6, 0}, {12, 0}, {12, 4}, {12, 8}, {6, 8}, {0, 8}, {0, 4}},
      {{{2, 2}, {3, 2}, {3, 3}, {2, 3}}, {{8, 5}, {9.5, 5}, {9.5, 6.5}, {8, 6.5}}, {{5.8, 2.5}, {6.2, 2.5}, {6.2, 7}, {5.8, 7}}});
  const geometry::Environment& env = which == 0 ? gallery : random_env;
  const auto b = env.bbox();
  const double r = which == 0 ? 0.2 : std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin()) / 200, angle = which == 0 ? 17.0 : 0.0;
  coverage::OnlineReport rep;
  for (auto _ : state) {
    coverage::OnlineOptions o;
    o.robot_radius = r, o.angle_deg = angle;
    rep = coverage::plan_online_coverage(env, o);
    benchmark::DoNotOptimize(rep);
  }
  coverage::CoverageOptions co;
  co.robot_radius = r, co.angle_deg = angle;
  const auto t0 = std::chrono::steady_clock::now();
  const auto off = coverage::plan_coverage(env, co);
  const double offline_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const auto cmp = coverage::compare_with_offline(env, rep, coverage::online_tolerance(rep));
  state.counters["complete"] = rep.complete ? 1 : 0;
  state.counters["isomorphic"] = cmp.isomorphic ? 1 : 0;
  state.counters["sensed"] = static_cast<double>(rep.nodes.size());
  state.counters["offline_cps"] = static_cast<double>(cmp.offline_nodes);
  state.counters["length"] = rep.length;
  state.counters["offline_length"] = off.length;
  state.counters["length_ratio"] = rep.length / off.length;
  state.counters["offline_ms"] = offline_ms;
}
BENCHMARK_CAPTURE(online_coverage, gallery, 0)->Name("online-coverage/preimage/gallery")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(online_coverage, random1000, 1)->Name("online-coverage/preimage/random-1000-20holes")->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
