// SPDX-License-Identifier: Apache-2.0
// Demo section of the decompose module: trapezoidal decomposition and a planned path.
#include "demo.hpp"

#include <preimage/decompose/coverage.hpp>
#include <preimage/decompose/figures.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/render/figures.hpp>

namespace preimage::cli {

void demo_decompose(DemoContext& ctx) {
  using namespace geometry;
  auto& R = ctx.report;
  R.section("Cell decompositions: trapezoidal decomposition and planning (Choset et al., 6.1)");
  scene::Scene office;
  office.environment = generators::office(2, 3);
  office.start = Point(1, 1);
  office.goal = Point(11, 7);
  const Environment& env = *office.environment;
  const decompose::TrapezoidalDecomposition d(env);
  const decompose::TrapezoidalPlanner planner(d);
  ExactFT total = 0;
  for (std::size_t c = 0; c < d.cells().size(); ++c) total += d.area(c);
  R.result("Office floor plan (vertical walls, equal x-coordinates, collinear vertices, no perturbation): " +
           std::to_string(d.cells().size()) + " trapezoids, " + std::to_string(d.extensions().size()) +
           " adjacencies; cell areas sum to the free area exactly: " + (total == env.exact_area() ? "yes" : "NO") + ".");
  const auto raw = planner.plan(*office.start, *office.goal, false);
  const auto plan = planner.plan(*office.start, *office.goal, true);
  R.result("Path from " + format_point(*office.start) + " to " + format_point(*office.goal) + " through " +
           std::to_string(plan.cells.size()) + " cells: " + format_number(raw.length) +
           " through extension midpoints and centroids, " + format_number(plan.length) + " after exact shortening.");

  render::SvgCanvas c(render::scene_box(office));
  render::draw_scene(c, office);
  decompose::draw_decomposition(c, d);
  render::Style rawst{"none", "#1a73e8", 1.5, 1.0, "4 3"}, route{"none", "#d93025", 3, 1.0, ""};
  c.polyline(raw.path, rawst);
  c.polyline(plan.path, route);
  c.legend("path through extension midpoints and cell centroids", rawst);
  c.legend("shortened path", route);
  ctx.figure("decompose-trapezoidal.svg", c.str(), "Trapezoidal decomposition of the office and a planned path");
}

}  // namespace preimage::cli

namespace preimage::cli {

void demo_coverage(DemoContext& ctx) {
  using namespace geometry;
  auto& R = ctx.report;
  R.section("Cell decompositions: boustrophedon decomposition, Reeb graph and coverage (6.2)");
  scene::Scene field;
  field.environment = Environment::make({{0, 0}, {12, 0}, {12, 8}, {0, 8}},
                                        {{{2, 3}, {3.5, 2}, {4, 4}, {2.5, 5}},
                                         {{6, 1.5}, {8.5, 1}, {8, 3}},
                                         {{7, 5}, {9, 4.5}, {10, 6.5}, {8, 7}}});
  field.start = Point(0.5, 0.5);
  const Environment& env = *field.environment;
  const decompose::BoustrophedonDecomposition b(env);
  R.result("Field with three obstacles: " + std::to_string(b.cells().size()) + " boustrophedon cells from " +
           std::to_string(b.trapezoids().cells().size()) + " trapezoids; Reeb graph with " +
           std::to_string(b.critical_slices().size()) + " critical points; Euler's formula N_cells = N_cp + N_ob - 1: " +
           std::to_string(b.cells().size()) + " = " + std::to_string(b.critical_slices().size()) + " + " +
           std::to_string(env.num_holes()) + " - 1.");
  const double width = 0.5;
  const auto rep = decompose::plan_coverage(env, {width / 2, field.start, 0.0});
  R.result("Coverage with a tool of width " + format_number(width) + " from " + format_point(*field.start) + ": length " +
           format_number(rep.length) + " within the chapter's bound " + format_number(rep.bound) + ", " +
           std::to_string(rep.laps) + " laps, " + std::to_string(rep.turns) + " turns.");
  const auto best = decompose::plan_coverage(env, {width / 2, field.start, std::nullopt});
  R.result("Automatic sweep direction (axes and the longest edges' directions): " + format_number(best.angle) +
           " degrees, length " + format_number(best.length) + ".");
  render::SvgCanvas c(render::scene_box(field));
  render::draw_scene(c, field);
  decompose::draw_boustrophedon(c, b);
  ctx.figure("decompose-boustrophedon.svg", c.str(), "Boustrophedon decomposition with its Reeb graph");
  render::SvgCanvas cc(render::scene_box(field));
  render::draw_scene(cc, field);
  const render::Style route{"none", "#d93025", 1.2, 0.9, ""};
  cc.polyline(rep.path, route);
  cc.legend("coverage path (laps along the slice, boundary following, transits)", route);
  ctx.figure("decompose-coverage.svg", cc.str(), "Coverage path for a tool of width 0.5");
}

}  // namespace preimage::cli
