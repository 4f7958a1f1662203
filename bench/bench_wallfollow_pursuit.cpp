// Wall-following pursuit-evasion (section VI): the search over the derived I-space of
// Strategy 2 (gap sensor: positions and 0/1 labels of shadow components, transitions
// read once per motion) against Strategy 6 (no special sensor: compounds of primitives,
// every bitangent candidate approximated) on random polygons with about 10, 20 and 40
// reflex vertices, in the same run. The paper calls the search exponential but fast in
// practice; counters give the I-states explored and the plan length (-1: no plan).
// The name pairs are "reference" = Strategy 2, "preimage" = Strategy 6 (the ratio is
// Strategy 2's time over Strategy 6's). The end-to-end runs (learning the cut ordering,
// exploring every motion with the simulated gap sensor, searching) are timed too.
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/wallfollow/environment.hpp>
#include <preimage/wallfollow/pursuit.hpp>

#include "ratio_reporter.hpp"

#include <map>
#include <stdexcept>

using namespace preimage;
using namespace preimage::wallfollow;

namespace {

struct Case {
  geometry::Environment env;
  std::size_t reflex = 0;
  PursuitReport gap;  // Strategy 2 run once: its table and start
};

// The first general-position polygon (by seed) with exactly `reflex` reflex vertices.
const Case& get(std::size_t reflex) {
  static std::map<std::size_t, Case> cases;
  auto it = cases.find(reflex);
  if (it != cases.end()) return it->second;
  for (std::uint64_t seed = 1;; ++seed) {
    auto env = geometry::Environment::make(geometry::generators::random_simple_polygon(2 * reflex + 2, 40000 + seed, 100.0), {});
    std::size_t r = 0;
    for (std::size_t v = 0; v < env.num_vertices(); ++v) r += env.is_reflex(v);
    if (r != reflex) continue;
    try {
      require_general_position(env);
      Simulator sim(env, env.vertex(0), geometry::Vector(1, 0));
      Sensors s;
      s.gap = true;
      sim.enable(s);
      PursuitOptions o;
      o.sensor = PursuitSensor::Gap;
      PursuitReport rep = pursue(sim, o);
      return cases.emplace(reflex, Case{std::move(env), r, std::move(rep)}).first->second;
    } catch (const InputError&) {
      continue;
    }
  }
}

void counters(benchmark::State& state, const Case& c, const PursuitReport& rep) {
  state.counters["vertices"] = static_cast<double>(c.env.num_vertices());
  state.counters["reflex"] = static_cast<double>(c.reflex);
  state.counters["istates"] = static_cast<double>(rep.states);
  state.counters["plan"] = rep.outcome == PursuitReport::Outcome::Plan ? static_cast<double>(rep.plan.size()) : -1;
}

void search_strategy2(benchmark::State& state, std::size_t reflex) {
  const Case& c = get(reflex);
  const OrderingMap m(c.gap.learned.ordering);
  PursuitReport rep;
  for (auto _ : state) {
    search_gap(c.gap.start, m, *c.gap.gap_table, 50'000'000, rep);
    benchmark::DoNotOptimize(rep.states);
  }
  counters(state, c, rep);
}

void search_strategy6(benchmark::State& state, std::size_t reflex) {
  const Case& c = get(reflex);
  const OrderingMap m(c.gap.learned.ordering);
  PursuitReport rep;
  for (auto _ : state) {
    search_compounds(c.gap.start, m, approximate_bitangents(m), 50'000'000, rep);
    benchmark::DoNotOptimize(rep.states);
  }
  counters(state, c, rep);
  state.counters["candidates"] = static_cast<double>(rep.bitangents);
}

void end_to_end(benchmark::State& state, std::size_t reflex, PursuitSensor sensor) {
  const Case& c = get(reflex);
  PursuitReport rep;
  for (auto _ : state) {
    Simulator sim(c.env, c.env.vertex(0), geometry::Vector(1, 0));
    sim.enable(sensors_of(sensor));
    PursuitOptions o;
    o.sensor = sensor;
    rep = pursue(sim, o);
    benchmark::DoNotOptimize(rep.states);
  }
  counters(state, c, rep);
  state.counters["actions"] = static_cast<double>(rep.learned.actions + rep.prepare_actions);
}

}  // namespace

int main(int argc, char** argv) {
  for (std::size_t r : {10, 20, 40}) {
    const std::string k = "reflex:" + std::to_string(r);
    benchmark::RegisterBenchmark(("wallfollow-search/reference/" + k).c_str(), search_strategy2, r)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("wallfollow-search/preimage/" + k).c_str(), search_strategy6, r)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("wallfollow-pursue-gap/" + k).c_str(), end_to_end, r, PursuitSensor::Gap)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
    benchmark::RegisterBenchmark(("wallfollow-pursue-none/" + k).c_str(), end_to_end, r, PursuitSensor::None)
        ->Unit(benchmark::kMillisecond);
  }
  return preimage::bench::run_with_ratios(argc, argv);
}
