// SPDX-License-Identifier: Apache-2.0
// The visibility game (tracking/visibility_game): backward induction over the losing
// states' attractor, against synchronous value iteration (every state re-evaluated each
// round until nothing changes, the textbook method) on the same grid, same sight and moves.
// One thread each, so the ratio is the algorithm's; the solver's threads are timed apart.
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/tracking/visibility_game.hpp>

#include "ratio_reporter.hpp"

#include <CGAL/Kernel/global_functions.h>
#include <benchmark/benchmark.h>

#include <cmath>

using namespace preimage;
using namespace preimage::tracking;

namespace {

const geometry::Environment& box_environment() {
  static const scene::Scene sc = scene::load_scene(std::string(PREIMAGE_BENCH_EXAMPLES) + "/tracking/box.json");
  return sc.require_environment();
}

GameParams params(unsigned threads) {
  GameParams p;
  p.resolution = 0.5;
  p.threads = threads;
  return p;
}

void solver(benchmark::State& st) {
  const auto& env = box_environment();
  for (auto _ : st) {
    const VisibilityGame g(env, params(static_cast<unsigned>(st.range(0))));
    benchmark::DoNotOptimize(g.stats().winning);
  }
}

// Synchronous value iteration on the solver's grid points, computing its own sight
// (exact, grazing excluded) and moves.
void value_iteration(benchmark::State& st) {
  const auto& env = box_environment();
  const VisibilityGame grid(env, params(1));  // for the point set only
  const std::size_t n = grid.num_points();
  const GameParams p = params(1);
  for (auto _ : st) {
    const geometry::VisibilityIndex index(env);
    auto moves = [&](double reach) {
      std::vector<std::vector<std::uint32_t>> m(n);
      for (std::uint32_t a = 0; a < n; ++a)
        for (std::uint32_t b = 0; b < n; ++b)
          if (std::hypot(grid.point(a).x() - grid.point(b).x(), grid.point(a).y() - grid.point(b).y()) <= reach * (1 + 1e-9) &&
              (a == b || index.visible(grid.point(a), grid.point(b))))
            m[a].push_back(b);
      return m;
    };
    const auto mo = moves(grid.observer_reach()), mt = moves(grid.target_reach());
    std::vector<std::uint32_t> v(n * n, VisibilityGame::kForever);
    for (std::uint32_t o = 0; o < n; ++o)
      for (std::uint32_t t = 0; t < n; ++t) {
        const auto &a = grid.point(o), &b = grid.point(t);
        const double d = std::hypot(a.x() - b.x(), a.y() - b.y());
        bool seen = d >= p.separation && d <= p.range && index.visible(a, b);
        for (const auto& q : env.vertices()) seen = seen && !(CGAL::collinear(a, q, b) && CGAL::collinear_are_strictly_ordered_along_line(a, q, b));
        if (!seen) v[o * n + t] = 0;
      }
    for (bool changed = true; changed;) {
      changed = false;
      std::vector<std::uint32_t> w = v;
      for (std::uint32_t o = 0; o < n; ++o)
        for (std::uint32_t t = 0; t < n; ++t) {
          if (v[o * n + t] == 0) continue;
          std::uint32_t worst = VisibilityGame::kForever;
          for (std::uint32_t tp : mt[t]) {
            std::uint32_t best = 0;
            for (std::uint32_t op : mo[o]) best = std::max(best, v[op * n + tp]);
            worst = std::min(worst, best);
          }
          const std::uint32_t value = worst == VisibilityGame::kForever ? worst : worst + 1;
          if (value != w[o * n + t]) {
            w[o * n + t] = value;
            changed = true;
          }
        }
      v.swap(w);
    }
    benchmark::DoNotOptimize(v.data());
  }
}

}  // namespace

BENCHMARK(solver)->Name("visibility-game/preimage/box-0.5m")->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(value_iteration)->Name("visibility-game/reference/box-0.5m")->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(solver)->Name("visibility-game-threads/box-0.5m")->Arg(2)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
