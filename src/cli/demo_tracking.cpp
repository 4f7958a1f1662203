// SPDX-License-Identifier: Apache-2.0
// Demo section for the tracking paper: the escape-path tree of the chair scene with both
// averages of -grad phi, a closed-loop run round the corridor's corners, and escape-time
// distributions of the three strategies against the planning targets in the box scene.
#include "common.hpp"
#include "demo.hpp"

#include <preimage/tracking/evaluation.hpp>
#include <preimage/render/svg.hpp>
#include <preimage/tracking/visibility_game.hpp>
#include <preimage/tracking/figures.hpp>
#include <preimage/tracking/replay.hpp>

#include <cstdio>
#include <thread>

namespace preimage::cli {

void demo_tracking(DemoContext& ctx) {
  using namespace preimage::tracking;
  auto& R = ctx.report;
  R.section("Tracking: escape-path trees and escape risk (tracking paper)");
  // The chair scene of Figs. 4-5, built in code so the demo needs no files.
  const auto env = geometry::Environment::make(
      {{-6, -1}, {6, -1}, {6, 10}, {-6, 10}},
      {{{-1.2, 5}, {-1, 5}, {-1, 9}, {-1.2, 9}},
       {{-3.46, 6.54}, {-3.34, 6.54}, {-3.34, 6.66}, {-3.46, 6.66}},
       {{-2.66, 6.54}, {-2.54, 6.54}, {-2.54, 6.66}, {-2.66, 6.66}},
       {{-3.46, 7.34}, {-3.34, 7.34}, {-3.34, 7.46}, {-3.46, 7.46}},
       {{-2.66, 7.34}, {-2.54, 7.34}, {-2.54, 7.46}, {-2.66, 7.46}},
       {{2.5, 5.5}, {3.1, 5.5}, {3.1, 6.1}, {2.5, 6.1}}});
  const geometry::VisibilityIndex index(env);
  const LocalMap map = exact_local_map(index, geometry::Point(0, 0));
  const EscapePathTree tree = escape_path_tree(map, geometry::Point(0.3, 7));
  const auto risks = escape_risks(map, tree, RiskParams{});
  const Vec2 rec = recursive_average(tree, risks).gradient * -1.0, plain = plain_average(risks).gradient * -1.0;
  ctx.figure("tracking-escape-path-tree.svg", escape_path_tree_figure(&env, map, tree, &rec, &plain),
             "Escape-path tree (blue) of the target (green) in V of the observer (purple); free edges red. The chair's "
             "legs give " + std::to_string(tree.paths.size()) + " escape paths, many on one branch round the partition. "
             "-grad phi by the recursive average (solid) and by the plain average (dashed), Figs. 4-5.");
  char line[200];
  std::snprintf(line, sizeof line, "SDE = %.3f m through %zu free edges; -grad phi: recursive (%.2f, %.2f), plain (%.2f, %.2f)",
                tree.sde(), tree.paths.size(), rec.x, rec.y, plain.x, plain.y);
  R.result(line);

  const auto corridor = geometry::Environment::make({{0, 0}, {20, 0}, {20, 14}, {0, 14}, {0, 12}, {18, 12}, {18, 2}, {0, 2}}, {});
  TrackingScenario s;
  s.name = "U-shaped corridor";
  s.environment = &corridor;
  s.observer = Pose{geometry::Point(1.5, 1), 0};
  s.target = Disc{geometry::Point(4, 1), 0.2};
  s.target_speed = 0.6;
  s.target_path = {{19, 1}, {19, 13}, {1, 13}};
  SimulationParams p;
  p.steps = 500;
  const SimulationResult r = simulate(s, p);
  ctx.figure("tracking-run.svg", tracking_run_figure(corridor, r, "risk, recursive average"),
             "TRACK at 10 Hz on simulated 360-beam scans following a target round two corners (observer red, target blue).");
  std::snprintf(line, sizeof line, "corridor run: target visible %.1f%% of %zu steps, escape time %s; paths: observer %.1f m, target %.1f m",
                100 * r.visible_fraction, r.observer.size() - 1, r.escape_time < 0 ? "never" : "reached", r.observer_length,
                r.target_length);
  R.result(line);

  // What `track replay` draws: scans the simulated laser took on that run, replayed as if
  // they were read from a log (sensor frame).
  std::vector<std::string> panels;
  for (std::size_t step : {std::size_t{0}, r.observer.size() / 3, 2 * r.observer.size() / 3}) {
    const Scan scan = simulate_scan(corridor, r.observer[step], LaserSpec{}, Disc{r.target[step], 0.2});
    ReplayScan rs = replay_scan(scan, TrackerParams{});
    rs.index = step;
    std::snprintf(line, sizeof line, "step %zu: target %s", step, rs.target_rule.c_str());
    panels.push_back(replay_scan_figure(rs, line, 360, panels.empty()));
  }
  ctx.figure("tracking-replay.svg", render::panel_grid(panels, 3, "sensor frame (x ahead, y left), metres"),
             "What track replay --svg draws for each scan: the returns (dots), V with solid and free edges, the fitted "
             "target circle, the escape-path tree from the target with arrows, and -grad phi-bar. Here three scans of the "
             "corridor run above, replayed as if read from a log.");

  // The cardboard box of Fig. 6(b) (examples/tracking/box.json): the adversarial and
  // look-ahead targets against each strategy, without and with dynamics.
  const auto box = geometry::Environment::make({{0, 0}, {12, 0}, {12, 8}, {0, 8}},
                                               {{{2.9, 3.25}, {3.5, 3.25}, {3.5, 3.9}, {2.9, 3.9}},
                                                {{6.5, 4.5}, {10.5, 4.5}, {10.5, 4.8}, {6.5, 4.8}}});
  TrackingScenario b;
  b.name = "box";
  b.environment = &box;
  b.observer = Pose{geometry::Point(1, 3), 0};
  b.target = Disc{geometry::Point(5.2, 3), 0.2};
  EvaluationParams ep;
  ep.seeds = 40;
  ep.fovs = {360};
  ep.policies = {TargetPolicy::Adversarial, TargetPolicy::Lookahead};
  ep.jobs = std::max(1u, std::thread::hardware_concurrency());
  ep.game_resolution = 0;  // the CDFs do not use the game; its figure follows
  const auto cells = evaluate({b}, ep);
  ctx.figure("tracking-escape-time-cdf.svg", escape_time_cdf_figure(cells, "Box scene, 360-deg laser: escape-time CDFs, 40 seeds per curve"),
             "Fraction of runs that lost the target by time t, per strategy (risk: TRACK's escape risk; sde: eq. (2) "
             "given the map; naive: steer at the target), against the shortest-escape-path adversary and the look-ahead "
             "target, without and with bounded accelerations (0.5 m/s^2, 1.5 rad/s^2).");
  for (const auto& c : cells) {
    if (c.strategy != Strategy::Risk) continue;
    const CellResult* sde = nullptr;
    for (const auto& d : cells)
      if (d.strategy == Strategy::Sde && d.policy == c.policy && d.dynamics == c.dynamics) sde = &d;
    const Interval diff = paired_difference(c, *sde);
    std::snprintf(line, sizeof line, "box, %s target%s: mean escape time risk %.1f s, sde %.1f s (risk - sde %.1f s, 95%% CI [%.1f, %.1f])",
                  to_string(c.policy), c.dynamics ? ", with dynamics" : "", c.mean_escape.value, sde->mean_escape.value,
                  diff.value, diff.low, diff.high);
    R.result(line);
  }

  // Ground truth for the box: the visibility game at speed ratio 0.5 (tracking/visibility_game).
  GameParams gp = game_params(b, SimulationParams{}, 0.25);
  gp.target_radius = b.target.radius;  // the physical target, as track game draws it
  const VisibilityGame game(box, gp);
  const std::uint32_t go = game.nearest(b.observer.position), gt = game.nearest(b.target.center);
  ctx.figure("tracking-game-box.svg", game_region_figure(box, game, gt, &b.observer.position, "box, target at its start"),
             "The visibility game on a 0.25 m grid, speed ratio 0.5, 8 m range, the target a disc of radius 0.2 m: "
             "for the target at the box scene's start (blue), the observer positions from which it keeps the target in view forever against every target "
             "motion (green), and elsewhere how long the target needs to escape (orange, darker: later). The "
             "observer's start (red) is inside the region.");
  std::snprintf(line, sizeof line,
                "box, visibility game at 0.25 m: %zu grid points, %zu states, kept forever from %.1f%% of the states where "
                "the observer sees the target; the scene's start is %s",
                game.stats().points, game.stats().states,
                100.0 * static_cast<double>(game.stats().winning) / static_cast<double>(game.stats().seen),
                game.keeps(go, gt) ? "kept" : "lost");
  R.result(line);
}

}  // namespace preimage::cli
