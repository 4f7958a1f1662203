// SPDX-License-Identifier: Apache-2.0
// Demo section for the tracking paper: the escape-path tree of the chair scene with both
// averages of -grad phi, and a closed-loop run round the corridor's corners.
#include "common.hpp"
#include "demo.hpp"

#include <preimage/tracking/figures.hpp>

#include <cstdio>

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
}

}  // namespace preimage::cli
