// SPDX-License-Identifier: Apache-2.0
// preimage decompose | plan
#include "common.hpp"

#include <preimage/decompose/coverage.hpp>
#include <preimage/decompose/figures.hpp>
#include <preimage/error.hpp>
#include <preimage/render/figures.hpp>

#include <cmath>
#include <iostream>

namespace preimage::cli {

namespace {

using nlohmann::json;

json point_json(const geometry::ExactPoint& p) { return json::array({CGAL::to_double(p.x()), CGAL::to_double(p.y())}); }

void run_boustrophedon(const scene::Scene& s, double angle, bool as_json, const std::string& svg) {
  const decompose::BoustrophedonDecomposition b(s.require_environment(), angle);
  const auto adj = b.adjacency();
  const auto& slices = b.critical_slices();
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    decompose::draw_boustrophedon(c, b);
    c.save(svg);
  }
  if (as_json) {
    json cells = json::array(), crit = json::array(), reeb = json::array();
    for (std::size_t i = 0; i < b.cells().size(); ++i) {
      cells.push_back({{"id", i}, {"polygon", points_json(b.polygon(i))}, {"area", CGAL::to_double(b.area(i))}, {"adjacent", adj[i]},
                       {"trapezoids", b.cells()[i].trapezoids.size()}});
      reeb.push_back({{"cell", i}, {"from", b.cells()[i].left_slice}, {"to", b.cells()[i].right_slice}});
    }
    for (std::size_t k = 0; k < slices.size(); ++k) {
      const auto& sl = slices[k];
      const double ylo = CGAL::to_double(sl.y_low), yhi = CGAL::to_double(sl.y_high);
      const auto a = b.to_input(geometry::Point(sl.x, ylo)), z = b.to_input(geometry::Point(sl.x, yhi));
      crit.push_back({{"id", k}, {"slice", {{a.x(), a.y()}, {z.x(), z.y()}}}, {"cells_before", sl.cells_left},
                      {"cells_after", sl.cells_right}});
    }
    print_json({{"method", "boustrophedon"}, {"angle", angle}, {"cells", cells}, {"critical_points", crit},
                {"reeb_graph", {{"nodes", slices.size()}, {"edges", reeb}}}});
    return;
  }
  std::cout << "boustrophedon decomposition at " << geometry::format_number(angle) << " degrees: " << b.cells().size()
            << " cells (" << b.trapezoids().cells().size() << " trapezoids), " << slices.size()
            << " critical points; Reeb graph " << slices.size() << " nodes, " << b.cells().size() << " edges; "
            << "N_cells = N_critical + N_obstacles - 1: " << b.cells().size() << " = " << slices.size() << " + "
            << s.require_environment().num_holes() << " - 1\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

void run_decompose(const std::string& path, const std::string& method, double angle, bool as_json, const std::string& svg) {
  const scene::Scene s = scene::load_scene(path);
  if (method == "boustrophedon") return run_boustrophedon(s, angle, as_json, svg);
  if (angle != 0) throw InputError("--angle: the trapezoidal decomposition sweeps along x (use --method boustrophedon)");
  const auto& env = s.require_environment();
  const decompose::TrapezoidalDecomposition d(env);
  const decompose::TrapezoidalPlanner planner(d);
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    decompose::draw_decomposition(c, d, &planner);
    c.save(svg);
  }
  if (as_json) {
    json cells = json::array(), adj = json::array();
    for (std::size_t i = 0; i < d.cells().size(); ++i) {
      json poly = json::array();
      for (auto& p : d.polygon(i)) poly.push_back(point_json(p));
      cells.push_back({{"id", i}, {"polygon", poly}, {"floor", edge_json(env, d.cells()[i].floor)},
                       {"ceiling", edge_json(env, d.cells()[i].ceiling)}, {"area", CGAL::to_double(d.area(i))}});
    }
    for (std::size_t x = 0; x < d.extensions().size(); ++x) {
      auto [a, b] = d.segment(x);
      adj.push_back({{"cells", {d.extensions()[x].left_cell, d.extensions()[x].right_cell}},
                     {"extension", {point_json(a), point_json(b)}}});
    }
    print_json({{"method", "trapezoidal"}, {"cells", cells}, {"adjacency", adj}});
    return;
  }
  std::cout << "trapezoidal decomposition: " << d.cells().size() << " cells, " << d.extensions().size()
            << " adjacencies (vertical extensions between cells)\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

void run_plan(const std::string& path, const std::string& start_s, const std::string& goal_s, bool no_shorten,
              bool as_json, const std::string& svg) {
  scene::Scene s = scene::load_scene(path);
  const auto& env = s.require_environment();
  if (!start_s.empty()) s.start = parse_point(start_s, "--start");
  if (!goal_s.empty()) s.goal = parse_point(goal_s, "--goal");
  if (!s.start) throw InputError("--start: not given and the scene has no \"start\"");
  if (!s.goal) throw InputError("--goal: not given and the scene has no \"goal\"");
  const decompose::TrapezoidalDecomposition d(env);
  const decompose::TrapezoidalPlanner planner(d);
  const decompose::Plan plan = planner.plan(*s.start, *s.goal, !no_shorten);
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    decompose::draw_decomposition(c, d, &planner);
    if (plan.found) {
      render::Style route{"none", "#d93025", 3, 1.0, ""};
      c.polyline(plan.path, route, "planned path");
      c.legend("planned path", route);
    }
    c.save(svg);
  }
  if (as_json) {
    print_json({{"found", plan.found}, {"length", plan.length}, {"cells", plan.cells}, {"path", points_json(plan.path)}});
    return;
  }
  if (!plan.found) {
    std::cout << "no path from " << geometry::format_point(*s.start) << " to " << geometry::format_point(*s.goal) << "\n";
  } else {
    std::cout << "path from " << geometry::format_point(*s.start) << " to " << geometry::format_point(*s.goal) << ": "
              << plan.path.size() << " points, length " << geometry::format_number(plan.length) << ", through "
              << plan.cells.size() << " of " << d.cells().size() << " cells\n";
  }
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

void run_cover(const std::string& path, double width, const std::string& start_s, const std::string& angle_s,
               bool as_json, const std::string& svg) {
  scene::Scene s = scene::load_scene(path);
  const auto& env = s.require_environment();
  decompose::CoverageOptions o{width / 2, std::nullopt, std::nullopt};
  if (!start_s.empty()) s.start = parse_point(start_s, "--start");
  o.start = s.start;
  if (angle_s != "auto") {
    std::size_t used = 0;
    double a = 0;
    try {
      a = std::stod(angle_s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != angle_s.size() || !std::isfinite(a))
      throw InputError("--angle: expected degrees or 'auto', got '" + angle_s + "'");
    o.angle_deg = a;
  }
  const auto rep = decompose::plan_coverage(env, o);
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    const decompose::BoustrophedonDecomposition b(env, rep.angle);
    decompose::draw_boustrophedon(c, b);
    render::Style route{"none", "#d93025", 1.2, 0.9, ""};
    c.polyline(rep.path, route, "coverage path");
    c.legend("coverage path", route);
    c.save(svg);
  }
  if (as_json) {
    print_json({{"width", width}, {"angle", rep.angle}, {"length", rep.length}, {"laps", rep.laps}, {"turns", rep.turns},
                {"cells", rep.cells}, {"critical_points", rep.critical_points}, {"cell_order", rep.cell_order},
                {"bound", {{"value", rep.bound}, {"diameter", rep.diameter}, {"perimeter", rep.perimeter},
                           {"formula", "D^2/(2r) + 4 D (N_cp + N_ob) + 5 P_total - 4 D"}}},
                {"path", points_json(rep.path)}});
    return;
  }
  std::cout << "coverage with width " << geometry::format_number(width) << " at " << geometry::format_number(rep.angle)
            << " degrees: length " << geometry::format_number(rep.length) << " (bound "
            << geometry::format_number(rep.bound) << "), " << rep.laps << " laps, " << rep.turns << " turns, "
            << rep.cells << " cells, " << rep.critical_points << " critical points\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

}  // namespace

void add_decompose_commands(CLI::App& app) {
  {
    auto* cmd = app.add_subcommand("decompose", "Exact cell decomposition of the free space, with its adjacency graph");
    auto path = std::make_shared<std::string>();
    auto method = std::make_shared<std::string>("trapezoidal");
    auto angle = std::make_shared<double>(0.0);
    auto json_out = std::make_shared<bool>(false);
    auto svg = std::make_shared<std::string>();
    cmd->add_option("scene", *path, "Scene JSON file")->required();
    cmd->add_option("--method", *method, "Decomposition method")->check(CLI::IsMember({"trapezoidal", "boustrophedon"}))->capture_default_str();
    cmd->add_option("--angle", *angle, "Sweep direction in degrees, counter-clockwise from +x (boustrophedon)");
    cmd->add_flag("--json", *json_out, "Machine-readable output on stdout");
    cmd->add_option("--svg", *svg, "Draw cells, extensions and the adjacency graph to this SVG file");
    cmd->callback([=] { run_decompose(*path, *method, *angle, *json_out, *svg); });
  }
  {
    auto* cmd = app.add_subcommand("plan", "Collision-free path through the trapezoidal decomposition");
    auto path = std::make_shared<std::string>();
    auto start = std::make_shared<std::string>(), goal = std::make_shared<std::string>();
    auto no_shorten = std::make_shared<bool>(false), json_out = std::make_shared<bool>(false);
    auto svg = std::make_shared<std::string>();
    cmd->add_option("scene", *path, "Scene JSON file")->required();
    cmd->add_option("--start", *start, "Start X,Y (default: the scene's \"start\")");
    cmd->add_option("--goal", *goal, "Goal X,Y (default: the scene's \"goal\")");
    cmd->add_flag("--no-shorten", *no_shorten, "Keep the path through extension midpoints and cell centroids");
    cmd->add_flag("--json", *json_out, "Machine-readable output on stdout");
    cmd->add_option("--svg", *svg, "Draw the decomposition and the path to this SVG file");
    cmd->callback([=] { run_plan(*path, *start, *goal, *no_shorten, *json_out, *svg); });
  }
  {
    auto* cmd = app.add_subcommand("cover", "Coverage path for a tool of width W on the boustrophedon decomposition");
    auto path = std::make_shared<std::string>();
    auto width = std::make_shared<double>(0.0);
    auto start = std::make_shared<std::string>();
    auto angle = std::make_shared<std::string>("0");
    auto json_out = std::make_shared<bool>(false);
    auto svg = std::make_shared<std::string>();
    cmd->add_option("scene", *path, "Scene JSON file")->required();
    cmd->add_option("--width", *width, "Tool width w = 2r (laps are w apart)")->required();
    cmd->add_option("--start", *start, "Start X,Y (default: the scene's \"start\", else the first cell)");
    cmd->add_option("--angle", *angle, "Sweep direction in degrees, or 'auto' to pick the shortest path")->capture_default_str();
    cmd->add_flag("--json", *json_out, "Machine-readable output on stdout");
    cmd->add_option("--svg", *svg, "Draw cells, Reeb graph and the coverage path to this SVG file");
    cmd->callback([=] { run_cover(*path, *width, *start, *angle, *json_out, *svg); });
  }
}

}  // namespace preimage::cli
