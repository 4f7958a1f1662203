// SPDX-License-Identifier: Apache-2.0
// Demo section: wall-following pursuit-evasion (wall-following paper, VI). Examples in the
// spirit of the paper's figures (which give no coordinates): three teeth whose primitives
// split and merge (Fig. 9) searched with the bitangent sensor, and computed plans of
// Strategy 6 with no special sensor (Figs. 14, 15); then a polygon the gap-sensor robot
// clears while Strategy 6 finds no plan, and a small run of the completeness experiment.
#include "demo.hpp"
#include "wallfollow_pursuit_run.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/wallfollow/environment.hpp>

#include <sstream>

namespace preimage::cli {

namespace {

using namespace wallfollow;

std::string describe(const PursuitRun& r) {
  const auto& rep = r.rep;
  std::ostringstream s;
  s << strategy_name(r.sensor) << ": ";
  if (rep.outcome != PursuitReport::Outcome::Plan) {
    s << "no plan (" << rep.states << " I-states explored)";
    return s.str();
  }
  s << "plan of " << rep.plan.size() << " primitives (";
  for (std::size_t k = 0; k < rep.plan.size(); ++k) s << (k ? " " : "") << to_string(rep.plan[k]);
  s << "), " << rep.states << " I-states explored";
  if (r.check) s << "; the executed path is " << (r.check->cleared ? "cleared" : "NOT cleared") << " by the independent checker";
  return s.str();
}

// examples/wallfollow/fig09_three_teeth.json and fig05_rooms.json.
geometry::Environment three_teeth() {
  return geometry::Environment::make({{0, 0.1}, {2, 0.0}, {3, 3}, {4, 0.05}, {6, 0.12}, {7, 4.2}, {8, 0.02}, {10, 0.08}, {11, 5.1},
                                      {12, 0.15}, {14, 0.03}, {14.1, 8.0}, {7.3, 8.23}, {0.05, 8.1}},
                                     {});
}
geometry::Environment rooms() {
  return geometry::Environment::make({{0, 0}, {6, 0.5}, {5.2, 2}, {8, 1.6}, {9, 5}, {6.5, 4.2}, {7.2, 7}, {3.8, 6.1}, {4.4, 8.3},
                                      {0.6, 7.6}, {1.8, 4.9}, {-0.5, 3.8}, {2.2, 2.4}},
                                     {});
}

}  // namespace

void demo_wallfollow_pursuit(DemoContext& ctx) {
  auto& R = ctx.report;
  R.section("Wall-following pursuit-evasion (wall-following paper, VI)");
  const geometry::Vector east(1, 0);
  {
    const auto env = three_teeth();
    const auto run = run_pursuit(env, env.vertex(0), east, PursuitSensor::Bitangent, 1'000'000, true, 4);
    ctx.figure("wallfollow-pursuit-teeth.svg", pursuit_figure(env, run),
               "Fig. 9 in spirit: three teeth, their primitives in compounds (labels after each move), Strategy 3");
    R.result(describe(run));
  }
  {
    const auto env = rooms();
    const auto run = run_pursuit(env, env.vertex(0), east, PursuitSensor::None, 1'000'000, true, 4);
    ctx.figure("wallfollow-pursuit-rooms.svg", pursuit_figure(env, run),
               "Fig. 14 in spirit: a plan of Strategy 6 (touch and pebble sensors only), every candidate taken as a bitangent");
    R.result(describe(run));
  }
  {
    // Fig. 15 in spirit: the first random 20-gon whose Strategy 6 plan has six primitives or more.
    for (std::uint64_t seed = 1; seed < 200; ++seed) {
      auto env = geometry::Environment::make(geometry::generators::random_simple_polygon(20, seed, 100.0), {});
      try {
        require_general_position(env);
      } catch (const InputError&) {
        continue;
      }
      const auto run = run_pursuit(env, env.vertex(0), east, PursuitSensor::None, 1'000'000, true, 5);
      if (run.rep.outcome != PursuitReport::Outcome::Plan || run.rep.plan.size() < 6) continue;
      ctx.figure("wallfollow-pursuit-random.svg", pursuit_figure(env, run),
                 "Fig. 15 in spirit: Strategy 6 on a random 20-gon (seed " + std::to_string(seed) + ")");
      R.result(describe(run));
      break;
    }
  }
  {
    // tests/fixtures/wallfollow/s6_counterexample_28.json, found by `wallfollow completeness`.
    const auto env = geometry::Environment::make(geometry::generators::random_simple_polygon(34, 28, 100.0), {});
    const auto gap = run_pursuit(env, env.vertex(0), east, PursuitSensor::Gap, 5'000'000, true, 5);
    const auto none = run_pursuit(env, env.vertex(0), east, PursuitSensor::None, 5'000'000, false, 0);
    ctx.figure("wallfollow-pursuit-counterexample.svg", pursuit_figure(env, gap),
               "Random polygon (seed 28, 34 vertices) that the gap-sensor robot clears and Strategy 6 does not");
    R.result(describe(gap) + ". " + describe(none) + ".");
  }
}

}  // namespace preimage::cli
