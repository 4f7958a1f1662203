// Visibility-based pursuit: conservative cells + information graph + one-pursuer plan on
// random simple polygons (20, 50, 100, 200 reflex vertices) and the office, comb and
// spiral generators; the search beside one that does not merge equal information states
// (depth-first over cell walks, pruning only cycles on the walk itself), in the same run;
// the checker's sampling, threads and keys; and "how many pursuers?" on polygons one
// pursuer cannot clear, by the interval against the two-pursuer search.
#include <preimage/geometry/generators.hpp>
#include <preimage/pursuit/bounds.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/examples.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/pursuit/split.hpp>

#include "ratio_reporter.hpp"

#include <map>
#include <memory>

using namespace preimage;
namespace g = geometry::generators;

namespace {

// Random simple polygons have about half their vertices reflex: n = 2 r.
geometry::Environment make(const std::string& name) {
  if (name == "office") return g::office(2, 2);
  if (name == "comb") return geometry::Environment::make(g::comb(12), {});
  if (name == "spiral") return geometry::Environment::make(g::spiral(3, 1.0, 24), {});
  const std::size_t reflex = std::stoul(name.substr(7));  // "reflex:N"
  for (std::uint64_t seed = 1;; ++seed) {
    auto env = geometry::Environment::make(g::random_simple_polygon(2 * reflex + 2, 900 + seed, 100.0), {});
    std::size_t r = 0;
    for (std::size_t v = 0; v < env.num_vertices(); ++v) r += env.is_reflex(v);
    if (r >= reflex) return env;
  }
}

struct Case {
  geometry::Environment env;
  std::unique_ptr<pursuit::ConservativeCells> cells;
  pursuit::SearchResult plan;
};

Case& get(const std::string& name) {
  static std::map<std::string, std::unique_ptr<Case>> cache;
  auto& c = cache[name];
  if (!c) {
    c = std::make_unique<Case>(Case{make(name), nullptr, {}});
    c->cells = std::make_unique<pursuit::ConservativeCells>(pursuit::ConservativeCells::build(c->env));
    c->plan = pursuit::search(*c->cells, 1);
  }
  return *c;
}

const char* kCases[] = {"reflex:20", "reflex:50", "reflex:100", "reflex:200", "office", "comb", "spiral"};

void counters(benchmark::State& state, const Case& c) {
  state.counters["reflex"] = static_cast<double>(c.cells->reflex_vertices());
  state.counters["cells"] = static_cast<double>(c.cells->size());
  state.counters["states"] = static_cast<double>(c.plan.states);
  state.counters["plan"] = c.plan.outcome == pursuit::SearchResult::Outcome::Plan;
}

// The whole pipeline: critical rays, cells, shadows, transitions, search, drawn plan.
void pipeline(benchmark::State& state, std::string name) {
  const Case& c = get(name);
  for (auto _ : state) {
    const auto cells = pursuit::ConservativeCells::build(c.env);
    auto r = pursuit::search(cells, 1);
    benchmark::DoNotOptimize(r);
  }
  counters(state, c);
}

void cells_only(benchmark::State& state, std::string name) {
  const Case& c = get(name);
  for (auto _ : state) {
    auto cells = pursuit::ConservativeCells::build(c.env);
    benchmark::DoNotOptimize(cells);
  }
  counters(state, c);
}

// Search only, on the same cells: breadth-first over the information graph, equal states
// merged (preimage), against depth-first walks that do not merge them (reference), both
// asked for the fewest crossings from the same start cell. The reference goes as deep as
// the answer (or, with no plan, as there are information states) within 5e6 walks.
void search_merged(benchmark::State& state, std::string name) {
  const Case& c = get(name);
  const std::uint32_t start = c.plan.plan ? c.plan.plan->start_cell : 0;
  std::optional<std::size_t> depth;
  std::size_t reached = 0;
  for (auto _ : state) {
    depth = pursuit::fewest_crossings(*c.cells, start, &reached);
    benchmark::DoNotOptimize(depth);
  }
  state.counters["crossings"] = depth ? static_cast<double>(*depth) : -1;
  state.counters["states"] = static_cast<double>(reached);
}

void search_unmerged(benchmark::State& state, std::string name) {
  const Case& c = get(name);
  const std::uint32_t start = c.plan.plan ? c.plan.plan->start_cell : 0;
  std::size_t reached = 0;
  const auto depth = pursuit::fewest_crossings(*c.cells, start, &reached);
  std::size_t nodes = 0;
  bool complete = false;
  std::optional<std::size_t> found;
  for (auto _ : state) {
    found = pursuit::search_without_merging(*c.cells, start, depth ? *depth : reached, 5'000'000, nodes, complete);
    benchmark::DoNotOptimize(found);
  }
  state.counters["walks"] = static_cast<double>(nodes);
  state.counters["complete"] = complete;
  state.counters["crossings"] = found ? static_cast<double>(*found) : -1;
}

// The contamination checker on a static-guard plan (guards wait while one pursuer moves):
// samples at the critical rays (preimage) against samples at every crossing of the whole
// lines through a reflex vertex and a vertex, or a vertex of a waiting V (reference: the
// sampling before 28 November; both share the rest of the checker).
// checker-threads: the steps built on every core against one thread (real time: the
// threads' CPU is not the caller's). checker-keys: regions carried into the next overlay by
// their stretch keys against locating a point of each (one thread each).
struct CheckerRun {
  bool every_line = false;
  unsigned threads = 1;
  bool locate_regions = false;
};

void checker(benchmark::State& state, std::string name, CheckerRun run) {
  static std::map<std::string, std::unique_ptr<std::pair<geometry::Environment, pursuit::Plan>>> plans;
  auto& p = plans[name];
  if (!p) {
    geometry::Environment env = name == "office-2x3" ? g::office(2, 3) : g::random_rectilinear(6, 5, true, 2024);
    auto plan = pursuit::split_strategy(env).plan;
    p = std::make_unique<std::pair<geometry::Environment, pursuit::Plan>>(std::move(env), std::move(plan));
  }
  pursuit::CheckOptions o;
  o.every_critical_line = run.every_line;
  o.threads = run.threads;
  o.locate_regions = run.locate_regions;
  pursuit::CheckResult r;
  for (auto _ : state) {
    r = pursuit::check_paths(p->first, p->second.paths, o);
    benchmark::DoNotOptimize(r);
  }
  state.counters["pursuers"] = static_cast<double>(p->second.paths.size());
  state.counters["waypoints"] = static_cast<double>(p->second.paths[0].size());
  state.counters["moments"] = static_cast<double>(r.moments);
  state.counters["cleared"] = r.cleared;
}

// Issue 48's question on polygons that one pursuer cannot clear: "how many pursuers?"
// answered by pursuer_bounds (the complete one-pursuer search for the lower end, the
// static-guard strategy's plan, checked, for the upper end; preimage) against the
// two-pursuer search asked directly (reference: any plan, 60 s, 2 GB). Random simple
// polygons of about 54, 100 and 150 vertices (the first seed whose one-pursuer search
// finds no plan) and the nested U of level 3 (which needs 3).
geometry::Environment needs_two(std::size_t n) {
  for (std::uint64_t seed = 1;; ++seed) {
    auto env = geometry::Environment::make(g::random_simple_polygon(n, 4800 + seed, 100.0), {});
    const auto cells = pursuit::ConservativeCells::build(env);
    if (pursuit::search(cells, 1, {std::nullopt, 4'000'000, false}).outcome == pursuit::SearchResult::Outcome::NoPlan) return env;
  }
}

const geometry::Environment& two_case(const std::string& name) {
  static std::map<std::string, std::unique_ptr<geometry::Environment>> cache;
  auto& e = cache[name];
  if (!e) e = std::make_unique<geometry::Environment>(name == "nested-u-3" ? pursuit::examples::nested_u(3) : needs_two(std::stoul(name.substr(8))));
  return *e;
}

void two_bounds(benchmark::State& state, std::string name) {
  const auto& env = two_case(name);
  pursuit::BoundsOptions o;
  o.time_limit = 60;
  pursuit::PursuerBounds b;
  for (auto _ : state) {
    b = pursuit::pursuer_bounds(env, o);
    benchmark::DoNotOptimize(b);
  }
  std::size_t states = 0;
  double mb = 0;
  for (const auto& s : b.searches) states = std::max(states, s.states), mb = std::max(mb, s.bytes / 1048576.0);
  state.counters["vertices"] = static_cast<double>(env.num_vertices());
  state.counters["lower"] = static_cast<double>(b.lower);
  state.counters["upper"] = static_cast<double>(b.upper);
  state.counters["states"] = static_cast<double>(states);
  state.counters["MB"] = mb;
  state.counters["certified"] = b.check && b.check->cleared;
}

void two_search(benchmark::State& state, std::string name) {
  const auto& env = two_case(name);
  pursuit::SearchResult r;
  for (auto _ : state) {
    const auto cells = pursuit::ConservativeCells::build(env);
    pursuit::SearchOptions o;
    o.shortest = false;
    o.time_limit = 60;
    o.max_mb = 2048;
    r = pursuit::search(cells, 2, o);
    benchmark::DoNotOptimize(r);
  }
  state.counters["vertices"] = static_cast<double>(env.num_vertices());
  state.counters["answer"] = r.outcome == pursuit::SearchResult::Outcome::Plan ? 2 : r.outcome == pursuit::SearchResult::Outcome::NoPlan ? -1 : 0;
  state.counters["states"] = static_cast<double>(r.states);
  state.counters["MB"] = r.bytes / 1048576.0;
}

}  // namespace

int main(int argc, char** argv) {
  for (const char* n : {"polygon-54", "polygon-100", "polygon-150", "nested-u-3"}) {
    benchmark::RegisterBenchmark(("two-pursuers/preimage/" + std::string(n)).c_str(), two_bounds, std::string(n))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
    benchmark::RegisterBenchmark(("two-pursuers/reference/" + std::string(n)).c_str(), two_search, std::string(n))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
  }
  for (const char* n : {"office-2x3", "rectilinear-6x5"}) {
    const std::pair<const char*, std::pair<CheckerRun, CheckerRun>> families[] = {
        {"checker", {{false, 1, false}, {true, 1, false}}},
        {"checker-threads", {{false, 0, false}, {false, 1, false}}},
        {"checker-keys", {{false, 1, false}, {false, 1, true}}},
    };
    for (const auto& [family, runs] : families) {
      benchmark::RegisterBenchmark((std::string(family) + "/preimage/" + n).c_str(), checker, std::string(n), runs.first)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
      benchmark::RegisterBenchmark((std::string(family) + "/reference/" + n).c_str(), checker, std::string(n), runs.second)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
    }
  }
  for (const char* n : kCases) {
    benchmark::RegisterBenchmark(("pursuit-pipeline/" + std::string(n)).c_str(), pipeline, std::string(n))->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("pursuit-cells/" + std::string(n)).c_str(), cells_only, std::string(n))->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("fewest-crossings/preimage/" + std::string(n)).c_str(), search_merged, std::string(n))
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
    benchmark::RegisterBenchmark(("fewest-crossings/reference/" + std::string(n)).c_str(), search_unmerged, std::string(n))
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  return preimage::bench::run_with_ratios(argc, argv);
}
