// SPDX-License-Identifier: Apache-2.0
// Demo section for the landmark paper: the swap cell decomposition of six landmarks, the
// hull the robot learns from readings alone, and a navigation run to a goal reading.
#include "common.hpp"
#include "demo.hpp"

#include <preimage/landmarks/figures.hpp>
#include <preimage/landmarks/strategies.hpp>
#include <preimage/landmarks/swap_cells.hpp>

#include <optional>
#include <set>

namespace preimage::cli {

void demo_landmarks(DemoContext& ctx) {
  auto& R = ctx.report;
  R.section("Landmarks: order types, swap cells and navigation from cyclic permutations (landmark paper)");
  landmarks::LandmarkSet L;
  L.points = {geometry::Point(0, 0), geometry::Point(10, 1), geometry::Point(12, 8),
              geometry::Point(5, 12), geometry::Point(4, 4), geometry::Point(8, 5)};
  for (int k = 1; k <= 6; ++k) L.labels.push_back(std::to_string(k));
  const auto D = landmarks::SwapCellDecomposition::of(L.points);
  std::set<landmarks::Reading> inside;
  std::size_t n_inside = 0;
  for (const auto& c : D.cells())
    if (c.meets_hull) inside.insert(c.permutation), ++n_inside;

  landmarks::Simulator robot(L.points, std::uint32_t{0});
  const auto hull = landmarks::learn_hull(robot);
  const std::size_t hull_prims = robot.primitives();
  R.result("Six landmarks, 30 swap rays: " + std::to_string(D.cells().size()) + " swap cells, " + std::to_string(n_inside) +
           " meeting the convex hull, with " + std::to_string(inside.size()) + " distinct readings (Theorem 7); swap graph of " +
           std::to_string(D.swap_graph().size()) + " edges. The robot learned the hull " + landmarks::format_reading(hull, L.labels) +
           " with " + std::to_string(hull_prims) + " track primitives (Strategies 4-5), from readings alone.");
  landmarks::LandmarkFigureOptions o;
  o.route = hull;
  o.route_label = "hull learned by the robot";
  ctx.figure("landmarks-swap-cells.svg", landmarks::swap_cell_figure(L, D, o).str(),
             "Swap cell decomposition of six landmarks: every cell reads one cyclic permutation; blue cells meet the hull");

  // Navigation: the robot starts at landmark 1, learns the order type on one hull tour,
  // then goes to a cell meeting the hull; shown for the first goal (in reverse
  // lexicographic order) that takes it onto a swap line inside the hull.
  landmarks::Reading goal;
  std::optional<landmarks::Simulator> best;
  std::size_t p0 = 0;
  landmarks::NavigationResult r;
  for (auto it = inside.rbegin(); it != inside.rend() && !best; ++it) {
    landmarks::Simulator nav(L.points, std::uint32_t{0});
    const auto tour = landmarks::learn_by_hull_tour(nav);
    p0 = nav.primitives();
    r = landmarks::navigate(nav, tour.order_type.chirotope(), tour.hull, *it);
    if (r.swap_lines_searched > 0 || std::next(it) == inside.rend()) best.emplace(nav), goal = *it;
  }
  auto& nav = *best;
  std::uint32_t goal_cell = 0;
  while (D.cells()[goal_cell].permutation != goal || !D.cells()[goal_cell].meets_hull) ++goal_cell;
  R.result("Navigation to the reading [" + landmarks::format_reading(goal, L.labels) + "]: " +
           (r.reached ? "reached, reading " + landmarks::format_reading(landmarks::normalized(nav.lcd()), L.labels) : "NOT REACHED") +
           ", after " + std::to_string(p0) + " primitives to learn the order type on one hull tour and " +
           std::to_string(nav.primitives() - p0) + " to navigate along the swap lines of its polar pairs (Strategy 7).");
  landmarks::LandmarkFigureOptions no;
  no.highlight_cells = {goal_cell};
  for (const auto& p : nav.waypoints()) no.path.push_back(geometry::to_double(p));
  no.path_label = "robot path (tracks only)";
  ctx.figure("landmarks-navigation.svg", landmarks::swap_cell_figure(L, D, no).str(),
             "Strategy 7: from landmark 1, around the hull, then onto a swap line and into the goal cell");

  landmarks::Simulator patroller(L.points, std::uint32_t{0});
  const auto tour = landmarks::learn_by_hull_tour(patroller);
  const std::vector<std::uint32_t> W{4, 5};
  const auto plan = landmarks::patrol_route(L.size(), tour.order_type.chirotope(), tour.hull, W, L.labels);
  R.result("Patrolling landmarks 5 and 6 (Strategy 6, planned from the learned order type): the route " +
           landmarks::format_reading(plan.route, L.labels) + " keeps both strictly inside with " + std::to_string(plan.route.size()) +
           " landmarks.");
}

}  // namespace preimage::cli
