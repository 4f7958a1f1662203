// Landmark order types from coordinates (landmark paper, section 3).
//
// order-type: all lambda(i, j) of n landmarks by an exact angular sort around each and
// a rotating sweep (O(n^2 log n)), against brute force in the same run (one orientation
// predicate per triple, O(n^3)) at n = 200; at n = 2,000 (target: under 1 s) alone.
// canonical-form: canonical forms of random 10-landmark order types (target: 10^4/s),
// with and without reflection identified (no reference: the target is absolute).
// swap-graph: the swap cell decomposition and swap graph of n = 30 landmarks (870 swap
// rays; target: under 1 s) against CGAL's Arrangement_2 of the same rays as segments
// (the oracle of the tests) in the same run; both count the same cells.
// strategy-1: the simulated robot learns the whole order type by Strategy 1 for every
// pair (n = 200, 2 tracks per pair), against the same readings taken by one exact
// angular sort per pair (what each reading cost before the simulator read the
// precomputed orders) in the same run.
#include <preimage/geometry/kernel.hpp>
#include <preimage/landmarks/order_type.hpp>
#include <preimage/landmarks/robot.hpp>
#include <preimage/landmarks/swap_cells.hpp>
#include <support/cgal_oracle.hpp>

#include "ratio_reporter.hpp"

#include <random>
#include <stdexcept>

using namespace preimage;
using geometry::Point;

namespace {

std::vector<Point> points(std::size_t n, std::uint64_t seed) { return landmarks::random_landmarks(n, seed, 1 << 24); }

void order_type(benchmark::State& state) {
  const auto P = points(static_cast<std::size_t>(state.range(0)), 1);
  std::size_t hull = 0;
  for (auto _ : state) {
    const auto T = landmarks::OrderType::of(P);
    hull = T.hull().size();
    benchmark::DoNotOptimize(hull);
  }
  state.counters["hull"] = static_cast<double>(hull);
}

void order_type_brute(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const auto P = points(n, 1);
  const auto T = landmarks::OrderType::of(P);
  std::vector<std::uint32_t> lambda(n * n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        std::uint32_t c = 0;
        for (std::size_t k = 0; k < n; ++k) c += k != i && k != j && geometry::orientation(P[i], P[j], P[k]) > 0;
        lambda[i * n + j] = c;
      }
    benchmark::DoNotOptimize(lambda.data());
  }
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j)
      if (i != j && lambda[i * n + j] != T.lambda(i, j)) throw std::logic_error("bench: lambda differs from brute force");
}

std::vector<landmarks::OrderType> small_types() {
  std::vector<landmarks::OrderType> out;
  for (std::uint64_t s = 0; s < 1000; ++s) out.push_back(landmarks::OrderType::of(points(10, 100 + s)));
  return out;
}

void canonical(benchmark::State& state) {
  static const auto types = small_types();
  std::size_t k = 0;
  for (auto _ : state) {
    auto c = landmarks::canonical_form(types[k++ % types.size()], true);
    benchmark::DoNotOptimize(c.lambda.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

}  // namespace

void swap_graph(benchmark::State& state) {
  const auto P = landmarks::random_landmarks(static_cast<std::size_t>(state.range(0)), 3, 1000);
  std::size_t cells = 0;
  for (auto _ : state) {
    const auto D = landmarks::SwapCellDecomposition::of(P);
    cells = D.cells().size();
    benchmark::DoNotOptimize(D.swap_graph().size());
  }
  state.counters["cells"] = static_cast<double>(cells);
}

void swap_graph_cgal(benchmark::State& state) {
  const auto P = landmarks::random_landmarks(static_cast<std::size_t>(state.range(0)), 3, 1000);
  std::size_t cells = 0;
  for (auto _ : state) benchmark::DoNotOptimize(cells = preimage::testing::cgal_swap_cell_count(P, 1e12));
  state.counters["cells"] = static_cast<double>(cells);
}

void strategy1(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const auto P = points(n, 5);
  const auto T = landmarks::OrderType::of(P);
  for (auto _ : state) {
    landmarks::Simulator robot(P, std::uint32_t{0});
    const auto lambda = landmarks::learn_order_type(robot);
    if (lambda[1] != T.lambda(0, 1)) throw std::logic_error("bench: Strategy 1 differs from the order type");
    benchmark::DoNotOptimize(lambda.data());
  }
}

void strategy1_sorting(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const auto P = points(n, 5);
  const auto T = landmarks::OrderType::of(P);
  std::vector<geometry::ExactPoint> E;
  for (const auto& p : P) E.push_back(geometry::to_exact(p));
  std::vector<std::uint32_t> lambda(n * n);
  for (auto _ : state) {
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j) {
        const auto r = landmarks::angular_reading(E, E[i], i, &E[j], {});  // just after leaving p_i towards p_j
        const auto [ij, ji] = landmarks::lemma1(r, i, j);
        lambda[i * n + j] = static_cast<std::uint32_t>(ij.size()), lambda[j * n + i] = static_cast<std::uint32_t>(ji.size());
      }
    benchmark::DoNotOptimize(lambda.data());
  }
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j)
      if (i != j && lambda[i * n + j] != T.lambda(i, j)) throw std::logic_error("bench: sorted readings differ from the order type");
}

BENCHMARK(order_type)->Name("order-type/preimage")->ArgName("n")->Arg(200)->Unit(benchmark::kMillisecond);
BENCHMARK(order_type_brute)->Name("order-type/reference")->ArgName("n")->Arg(200)->Unit(benchmark::kMillisecond);
BENCHMARK(order_type)->Name("order-type-large/preimage")->ArgName("n")->Arg(2000)->Unit(benchmark::kMillisecond);
BENCHMARK(canonical)->Name("canonical-form/n:10")->Unit(benchmark::kMicrosecond);
BENCHMARK(swap_graph)->Name("swap-graph/preimage")->ArgName("n")->Arg(30)->Unit(benchmark::kMillisecond);
BENCHMARK(swap_graph_cgal)->Name("swap-graph/reference")->ArgName("n")->Arg(30)->Unit(benchmark::kMillisecond);

BENCHMARK(strategy1)->Name("strategy-1/preimage")->ArgName("n")->Arg(200)->Unit(benchmark::kMillisecond);
BENCHMARK(strategy1_sorting)->Name("strategy-1/reference")->ArgName("n")->Arg(200)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
