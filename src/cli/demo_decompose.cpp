// SPDX-License-Identifier: Apache-2.0
// Demo section of the decompose module: trapezoidal decomposition and a planned path.
#include "demo.hpp"

#include <preimage/coverage/coverage.hpp>
#include <preimage/coverage/figures.hpp>
#include <preimage/decompose/figures.hpp>
#include <preimage/coverage/online_coverage.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/render/figures.hpp>

#include <cmath>

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
  c.path(plan.path, route, "shortened path");
  c.legend("path through extension midpoints and cell centroids", rawst);
  c.legend("shortened path", route);
  ctx.figure("decompose-trapezoidal.svg", c.str(), "Trapezoidal decomposition of the office and a planned path");
}

}  // namespace preimage::cli

namespace preimage::cli {

namespace {
// The field with three obstacles that the boustrophedon and variable-slice sections share.
scene::Scene coverage_field() {
  scene::Scene field;
  field.environment = geometry::Environment::make({{0, 0}, {12, 0}, {12, 8}, {0, 8}},
                                                  {{{2, 3}, {3.5, 2}, {4, 4}, {2.5, 5}},
                                                   {{6, 1.5}, {8.5, 1}, {8, 3}},
                                                   {{7, 5}, {9, 4.5}, {10, 6.5}, {8, 7}}});
  return field;
}
}  // namespace

void demo_coverage(DemoContext& ctx) {
  using namespace geometry;
  auto& R = ctx.report;
  R.section("Cell decompositions: boustrophedon decomposition, Reeb graph and coverage (6.2)");
  scene::Scene field = coverage_field();
  field.start = Point(0.5, 0.5);
  const Environment& env = *field.environment;
  const decompose::BoustrophedonDecomposition b(env);
  R.result("Field with three obstacles: " + std::to_string(b.cells().size()) + " boustrophedon cells from " +
           std::to_string(b.trapezoids().cells().size()) + " trapezoids; Reeb graph with " +
           std::to_string(b.critical_slices().size()) + " critical points; Euler's formula N_cells = N_cp + N_ob - 1: " +
           std::to_string(b.cells().size()) + " = " + std::to_string(b.critical_slices().size()) + " + " +
           std::to_string(env.num_holes()) + " - 1.");
  // A robot of radius 0.25 with a tool as wide as itself.
  coverage::CoverageOptions o;
  o.robot_radius = 0.25, o.start = field.start, o.angle_deg = 0.0;
  const auto rep = coverage::plan_coverage(env, o);
  const auto m = coverage::measure_coverage(env, rep);
  o.order = coverage::CellOrder::DepthFirst, o.transit = coverage::Transit::Decomposition;
  const auto dfs = coverage::plan_coverage(env, o);
  R.result("Coverage by a robot of radius 0.25 (tool width 0.5) from " + format_point(*field.start) + ", in its configuration space: length " +
           format_number(rep.length) + " (" + format_number(rep.transit_length) + " of it transits), " + std::to_string(rep.laps) + " laps, " +
           std::to_string(rep.turns) + " turns, " + format_number(std::round(m.covered_fraction * 1000) / 10) + "% of the configuration space covered, overlap " +
           format_number(std::round(m.overlap * 1000) / 10) + "%; every segment certified 0.25 away from the obstacles. The chapter's depth-first walk with transits " +
           "through the trapezoids: length " + format_number(dfs.length) + " (bound " + format_number(dfs.bound) + ").");
  o.order = coverage::CellOrder::Optimised, o.transit = coverage::Transit::Shortest, o.angle_deg.reset();
  const auto best = coverage::plan_coverage(env, o);
  R.result("Automatic sweep direction (axes and the longest edges' directions, ranked by laps and cells): " + format_number(best.angle) +
           " degrees, length " + format_number(best.length) + ".");
  render::SvgCanvas c(render::scene_box(field));
  render::draw_scene(c, field);
  decompose::draw_boustrophedon(c, b);
  ctx.figure("decompose-boustrophedon.svg", c.str(), "Boustrophedon decomposition with its Reeb graph");
  render::SvgCanvas cc(render::scene_box(field));
  render::draw_scene(cc, field);
  render::draw_configuration_space(cc, geometry::ConfigurationSpace(env, 0.25));
  coverage::draw_coverage(cc, rep);
  ctx.figure("decompose-coverage.svg", cc.str(), "Coverage path of a robot of radius 0.25 in its configuration space");
  // The same robot unable to turn in place: every turn an arc of radius >= 0.4.
  o.angle_deg = 0.0, o.min_turn_radius = 0.4;
  const auto car = coverage::plan_coverage(env, o);
  const auto mc = coverage::measure_coverage(env, car);
  R.result("The same robot unable to turn in place (turning radius 0.4, Dubins curves, reversing where no forward curve fits): length " +
           format_number(car.length) + ", " + std::to_string(car.arcs.size()) + " arcs, " + std::to_string(car.cusps.size()) + " changes of direction, " +
           std::to_string(car.shortened_laps) + " laps cut back for a turn, " + format_number(std::round(mc.covered_fraction * 1000) / 10) +
           "% covered; every arc certified 0.25 away from the obstacles (the capsule around each chord that holds it).");
  render::SvgCanvas cd(render::scene_box(field));
  render::draw_scene(cd, field);
  render::draw_configuration_space(cd, geometry::ConfigurationSpace(env, 0.25));
  coverage::draw_coverage(cd, car);
  ctx.figure("coverage-drivable.svg", cd.str(), "Coverage by a robot with turning radius 0.4: arcs, laps cut back at the walls");
}

}  // namespace preimage::cli

namespace preimage::cli {

void demo_morse(DemoContext& ctx) {
  using namespace geometry;
  auto& R = ctx.report;
  R.section("Cell decompositions: variable slices — circular, spike and squarel (6.2.3)");
  scene::Scene field = coverage_field();
  const Environment& env = *field.environment;
  const Point centre(5.3, 4.1);
  R.result("The field of the boustrophedon section, sliced around " + format_point(centre) +
           " by circles (h = |p - c|), rays (h = angle) and diamonds (h = |x - cx| + |y - cy|). Critical points are "
           "decided exactly (circle crossings as a + b sqrt(d)); cells are faces of the boundary cut by the critical slices.");
  struct Case { decompose::SliceFamily f; coverage::Pattern p; const char* file; };
  for (const Case k : {Case{decompose::SliceFamily::Circular, coverage::Pattern::Spiral, "decompose-circular"},
                       Case{decompose::SliceFamily::Spike, coverage::Pattern::Spike, "decompose-spike"},
                       Case{decompose::SliceFamily::Squarel, coverage::Pattern::Squarel, "decompose-squarel"}}) {
    const decompose::MorseDecomposition m(env, k.f, centre);
    coverage::CoverageOptions o;
    o.robot_radius = 0.2, o.pattern = k.p, o.centre = centre;
    const auto rep = coverage::plan_coverage(env, o);
    const auto q = coverage::measure_coverage(env, rep);
    const std::string name(decompose::to_string(k.f));
    R.result(name + ": " + std::to_string(m.cells().size()) + " cells, " + std::to_string(m.critical_points().size()) + " critical points in " +
             std::to_string(m.num_nodes()) + " critical slices; " + std::string(coverage::to_string(k.p)) + " coverage (robot radius 0.2, width 0.4): length " +
             format_number(std::round(rep.length * 10) / 10) + ", " + std::to_string(rep.laps) + " laps, " +
             format_number(std::round(q.covered_fraction * 1000) / 10) + "% of the configuration space covered, every segment certified.");
    render::SvgCanvas c(render::scene_box(field));
    render::draw_scene(c, field);
    decompose::draw_morse(c, m);
    ctx.figure(std::string(k.file) + ".svg", c.str(), name + " decomposition around " + format_point(centre) + " (Fig. 6.1" +
               (k.f == decompose::SliceFamily::Circular ? "2" : k.f == decompose::SliceFamily::Spike ? "3" : "4") + ")");
    render::SvgCanvas cc(render::scene_box(field));
    render::draw_scene(cc, field);
    render::draw_configuration_space(cc, geometry::ConfigurationSpace(env, 0.2));
    coverage::draw_coverage(cc, rep);
    ctx.figure(std::string(k.file) + "-coverage.svg", cc.str(), std::string(coverage::to_string(k.p)) + " coverage pattern");
  }
}

void demo_brushfire(DemoContext& ctx) {
  using namespace geometry;
  auto& R = ctx.report;
  R.section("Cell decompositions: distance functions — brushfire and the tethered wave front (6.2.3, Figs. 6.15–6.18)");
  scene::Scene field = coverage_field();
  const Environment& env = *field.environment;
  const decompose::BrushfireDecomposition b(env);
  std::size_t saddles = 0;
  for (const auto& k : b.critical_points()) saddles += k.kind == decompose::BrushfireCriticalPoint::Kind::Saddle;
  coverage::CoverageOptions o;
  o.robot_radius = 0.2, o.pattern = coverage::Pattern::Brushfire;
  const auto rep = coverage::plan_coverage(env, o);
  const auto q = coverage::measure_coverage(env, rep);
  R.result("Wave fronts grow from the walls and the three obstacles; they collide at " + std::to_string(saddles) + " saddles of D and vanish at " +
           std::to_string(b.critical_points().size() - saddles) + " maxima, giving " + std::to_string(b.cells().size()) + " cells in " +
           std::to_string(b.num_nodes()) + " critical slices. Built on the medial axis (Boost.Polygon's segment Voronoi diagram on a grid of " +
           format_number(b.gvd().resolution()) + "); the GVD between different obstacles is drawn in blue.");
  R.result("Brushfire coverage (robot radius 0.2, width 0.4): offset laps every 0.4 from the obstacles of the configuration space and the "
           "medial axis between them; length " + format_number(std::round(rep.length * 10) / 10) + ", " + std::to_string(rep.laps) + " laps, " +
           format_number(std::round(q.covered_fraction * 1000) / 10) + "% of the configuration space covered, every segment certified.");
  render::SvgCanvas c(render::scene_box(field));
  render::draw_scene(c, field);
  decompose::draw_brushfire(c, b);
  ctx.figure("decompose-brushfire.svg", c.str(), "Brushfire decomposition: cells of the wave fronts, the GVD, saddles and maxima of D (Fig. 6.16)");
  render::SvgCanvas cc(render::scene_box(field));
  render::draw_scene(cc, field);
  render::draw_configuration_space(cc, geometry::ConfigurationSpace(env, 0.2));
  coverage::draw_coverage(cc, rep);
  ctx.figure("decompose-brushfire-coverage.svg", cc.str(), "Brushfire coverage pattern (Fig. 6.17)");

  // The wave-front decomposition (Fig. 6.18): cells of the fronts of the geodesic distance.
  const geometry::VisibilityIndex windex(env);
  const geometry::VisibilityGraph wgraph(windex);
  const geometry::ShortestPathMap wspm(wgraph, Point(0.5, 0.5));
  const decompose::WavefrontDecomposition wave(wspm);
  R.result("Wave-front decomposition from " + format_point(Point(0.5, 0.5)) + ": the fronts h = const of the shortest-path length, computed "
           "as circle arcs about the start and the reflex vertices, give " + std::to_string(wave.cells().size()) + " cells between " +
           std::to_string(wave.nodes().size()) + " critical slices (a front touches a wall and splits, two fronts collide and merge, a front "
           "vanishes in a corner); the Reeb graph has " + std::to_string(wave.cells().size() + 1 - wave.nodes().size()) +
           " independent cycles, one per obstacle.");
  render::SvgCanvas wc(render::scene_box(field));
  render::draw_scene(wc, field);
  decompose::draw_wavefront(wc, wave);
  ctx.figure("decompose-wavefront.svg", wc.str(), "Wave-front decomposition: fronts coloured by cell, critical slices (Fig. 6.18)");

  // The tethered robot (Fig. 6.18): fronts of the geodesic distance from its anchor.
  coverage::CoverageOptions t;
  t.robot_radius = 0.2, t.pattern = coverage::Pattern::Wavefront, t.start = Point(0.5, 0.5);
  const auto tether = coverage::plan_coverage(env, t);
  const auto tq = coverage::measure_coverage(env, tether);
  R.result("Tethered coverage from the anchor " + format_point(*t.start) + ": laps along the wave fronts of the geodesic distance (constant "
           "tether length), 0.4 apart, outwards; the fronts' cusps are where the fronts from either side of an obstacle collided. Length " +
           format_number(std::round(tether.length * 10) / 10) + ", " + std::to_string(tether.laps) + " laps, " +
           format_number(std::round(tq.covered_fraction * 1000) / 10) + "% covered, every segment certified.");
  render::SvgCanvas tc(render::scene_box(field));
  render::draw_scene(tc, field);
  render::draw_configuration_space(tc, geometry::ConfigurationSpace(env, 0.2));
  coverage::draw_coverage(tc, tether);
  ctx.figure("decompose-wavefront-coverage.svg", tc.str(), "Tethered robot: wave fronts of constant tether length (Fig. 6.18)");
}

// Online coverage (6.2.4): the robot that does not know the field builds its Reeb graph as
// it covers (Fig. 6.21: four stages), and the final path beside the offline one.
void demo_online(DemoContext& ctx) {
  using namespace geometry;
  auto& R = ctx.report;
  R.section("Sensor-based coverage of an unknown environment: the incremental Reeb graph (Choset et al., 6.2.4)");
  const scene::Scene field = coverage_field();
  const Environment& env = *field.environment;
  coverage::OnlineOptions o;
  o.robot_radius = 0.25, o.angle_deg = 17;
  const auto rep = coverage::plan_online_coverage(env, o);
  const auto cmp = coverage::compare_with_offline(env, rep, coverage::online_tolerance(rep));
  coverage::CoverageOptions co;
  co.robot_radius = 0.25, co.angle_deg = 17;
  const auto off = coverage::plan_coverage(env, co);
  std::string order;
  for (auto k : rep.sensing_order) order.append(order.empty() ? "" : " ").append(std::to_string(k));
  R.result(std::string("Robot of radius 0.25, sweep at 17 degrees, ").append(std::to_string(rep.sensors)).append(" range sensors: ")
               .append(rep.complete ? "complete" : "stopped: " + rep.inconsistency).append("; ")
               .append(std::to_string(rep.nodes.size())).append(" critical points sensed in the order ").append(order).append(", ")
               .append(std::to_string(rep.edges.size())).append(" cells; offline Reeb graph ")
               .append(std::to_string(cmp.offline_nodes)).append(" critical slices, ").append(std::to_string(cmp.offline_edges))
               .append(" cells: ").append(cmp.isomorphic ? "isomorphic" : "differs (" + cmp.detail + ")").append("."));
  R.result(std::string("Path ").append(format_number(rep.length)).append(" online against ").append(format_number(off.length))
               .append(" for the offline boustrophedon coverage (the price of not knowing the map: ")
               .append(format_number(rep.length / off.length)).append(" times)."));
  const ConfigurationSpace cs(env, 0.25);
  const std::size_t n = rep.path.size();
  const std::size_t stages[] = {n / 8, n / 3, 2 * n / 3, n};
  const char* names[] = {"a", "b", "c", "d"};
  for (std::size_t k = 0; k < 4; ++k) {
    render::SvgCanvas c(render::scene_box(field));
    render::draw_scene(c, field);
    render::draw_configuration_space(c, cs);
    coverage::draw_online_coverage(c, rep, stages[k]);
    ctx.figure(std::string("decompose-online-").append(names[k]).append(".svg"), c.str(),
               k < 3 ? std::string("Online coverage, stage (").append(names[k]).append("): the path so far, the critical points sensed (numbered) and the cells covered; dashed stubs are unexplored ports (Fig. 6.21)")
                     : std::string("Online coverage, final (d): every critical point has all its edges explored, so the robot concludes it has covered the space"));
  }
}

}  // namespace preimage::cli
