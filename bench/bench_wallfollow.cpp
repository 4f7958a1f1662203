// Wall-following robot: learning the cut ordering of a 1,000-vertex random polygon
// (about half its vertices reflex) in simulation, through the robot interface only.
// preimage's Strategy 1 orders the endpoints on each edge by pebble quicksort; the
// reference is the paper's comparison of every pair of endpoints on an edge (V.C).
// Counters give the primitives executed and their ratio to n^2 (Proposition 5).
#include <preimage/geometry/generators.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/environment.hpp>
#include <preimage/wallfollow/learn.hpp>

#include "ratio_reporter.hpp"

#include <stdexcept>

using namespace preimage;

namespace {

constexpr std::size_t kN = 1000;

const geometry::Environment& polygon() {
  static const geometry::Environment env = [] {
    auto e = geometry::Environment::make(geometry::generators::random_simple_polygon(kN, 7, 1000.0), {});
    wallfollow::require_general_position(e);
    return e;
  }();
  return env;
}

void learn(benchmark::State& state, wallfollow::LearnOptions::Sort sort) {
  const auto& env = polygon();
  const auto truth = wallfollow::true_cut_ordering(env).ordering.canonical();  // outside the timed loop
  wallfollow::LearnReport L;
  std::size_t reflex = 0;
  for (bool r : truth.reflex) reflex += r;
  for (auto _ : state) {
    wallfollow::Simulator sim(env, env.vertex(0), geometry::Vector(1, 0));
    wallfollow::LearnOptions o;
    o.sort = sort;
    L = wallfollow::learn_cut_ordering(sim, o);
    benchmark::DoNotOptimize(L.actions);
  }
  if (!(L.ordering.canonical() == truth)) throw std::logic_error("learned cut ordering differs from the true one");
  state.counters["n"] = static_cast<double>(kN);
  state.counters["reflex"] = static_cast<double>(reflex);
  state.counters["actions"] = static_cast<double>(L.actions);
  state.counters["actions_per_n2"] = static_cast<double>(L.actions) / (kN * kN);
  state.counters["comparisons"] = static_cast<double>(L.comparisons);
  state.counters["max_edge_load"] = static_cast<double>(L.max_edge_load);
}

void learn_quick(benchmark::State& state) { learn(state, wallfollow::LearnOptions::Sort::Quick); }
void learn_all_pairs(benchmark::State& state) { learn(state, wallfollow::LearnOptions::Sort::AllPairs); }

void true_ordering(benchmark::State& state) {
  const auto& env = polygon();
  std::size_t points = 0;
  for (auto _ : state) {
    const auto T = wallfollow::true_cut_ordering(env);
    points = T.ordering.points.size();
    benchmark::DoNotOptimize(points);
  }
  state.counters["points"] = static_cast<double>(points);
}

}  // namespace

BENCHMARK(learn_quick)->Name("learn-cut-ordering/preimage/n:1000")->Unit(benchmark::kMillisecond);
BENCHMARK(learn_all_pairs)->Name("learn-cut-ordering/reference/n:1000")->Unit(benchmark::kMillisecond);
// Geometry's answer, for scale (no reference: it reads coordinates).
BENCHMARK(true_ordering)->Name("true-cut-ordering/n:1000")->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
