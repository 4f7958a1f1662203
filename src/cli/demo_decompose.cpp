// SPDX-License-Identifier: Apache-2.0
// Demo section of the decompose module: trapezoidal decomposition and a planned path.
#include "demo.hpp"

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
