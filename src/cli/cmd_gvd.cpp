// SPDX-License-Identifier: Apache-2.0
// preimage gvd: the generalized Voronoi diagram, its saddles and maxima.
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/gvd.hpp>
#include <preimage/render/figures.hpp>

#include <iostream>

namespace preimage::cli {

namespace {

using nlohmann::json;

struct GvdArgs {
  std::string path, svg;
  bool json = false;
  double max_deviation = 0;
};

json gvd_site_json(const geometry::Environment& env, const geometry::GvdSite& s) {
  const bool edge = s.kind == geometry::GvdSite::Kind::Edge;
  return {{"kind", edge ? "edge" : "vertex"},
          {"ring", env.ring_name(env.ring_of(s.index))},
          {"index", edge ? env.input_edge_index(s.index) : env.input_index(s.index)},
          {"obstacle", s.obstacle}};
}

json gvd_critical_json(const geometry::GvdCriticalPoint& c) {
  static const char* kinds[] = {"interior", "vertex", "plateau"};
  json j{{"kind", kinds[static_cast<int>(c.kind)]},
         {"x", c.p.x()},
         {"y", c.p.y()},
         {"clearance", c.clearance},
         {"nearest", json::array({json::array({c.nearest[0].x(), c.nearest[0].y()}), json::array({c.nearest[1].x(), c.nearest[1].y()})})}};
  if (c.edge != UINT32_MAX) j["edge"] = c.edge;
  if (c.vertex != UINT32_MAX) j["vertex"] = c.vertex;
  return j;
}

void run_gvd(const GvdArgs& a) {
  const scene::Scene s = scene::load_scene(a.path);
  const auto& env = s.require_environment();
  const auto g = geometry::GeneralizedVoronoiDiagram::build(env, {a.max_deviation});
  const auto pairs = g.obstacle_pairs();
  std::size_t curved = 0;
  for (const auto& e : g.edges()) curved += e.curved;

  if (!a.svg.empty()) {
    render::SvgCanvas canvas(render::scene_box(s));
    canvas.environment(env);
    const render::Style line{"none", "#1a73e8", 1.4, 0.9, ""};
    for (std::size_t i = 0; i < g.edges().size(); ++i) {
      const auto& e = g.edges()[i];
      canvas.polyline(e.polyline, line,
                      "edge " + std::to_string(i) + ": obstacles " + std::to_string(e.sites[0].obstacle) + " | " + std::to_string(e.sites[1].obstacle) +
                          ", clearance " + geometry::format_number(e.min_clearance) + " to " +
                          geometry::format_number(std::max(e.clearance_from, e.clearance_to)));
    }
    canvas.legend("GVD: " + count_of(g.edges().size(), "edge") + " between " + count_of(pairs.size(), "obstacle pair"), line);
    const render::Style passage{"none", "#e37400", 1.0, 0.8, "3 2"};
    for (const auto& c : g.saddles()) canvas.segment(c.nearest[0], c.nearest[1], passage);
    if (!g.saddles().empty()) canvas.legend("narrowest passages (through the saddles)", passage);
    const render::Style saddle{"#e37400", "#202124", 1.0, 1.0, ""};
    for (const auto& c : g.saddles())
      canvas.point(c.p, 4, saddle, "saddle " + geometry::format_point(c.p) + ", clearance " + geometry::format_number(c.clearance));
    canvas.legend("saddles of D: " + std::to_string(g.saddles().size()), saddle);
    const render::Style maximum{"#d93025", "#202124", 1.0, 1.0, ""};
    for (const auto& c : g.maxima())
      canvas.point(c.p, 4, maximum, "maximum " + geometry::format_point(c.p) + ", clearance " + geometry::format_number(c.clearance));
    canvas.legend("maxima of D: " + std::to_string(g.maxima().size()), maximum);
    canvas.save(a.svg);
  }
  if (a.json) {
    json obstacles = json::array();
    for (std::size_t o = 0; o < g.num_obstacles(); ++o) {
      json rings = json::array();
      for (auto r : g.obstacle_rings(o)) rings.push_back(env.ring_name(r));
      obstacles.push_back({{"id", o}, {"rings", rings}});
    }
    json vertices = json::array();
    for (const auto& v : g.vertices()) vertices.push_back({{"x", v.p.x()}, {"y", v.p.y()}, {"clearance", v.clearance}, {"degree", v.degree}});
    json edges = json::array();
    for (const auto& e : g.edges())
      edges.push_back({{"from", e.from},
                       {"to", e.to},
                       {"curved", e.curved},
                       {"sites", json::array({gvd_site_json(env, e.sites[0]), gvd_site_json(env, e.sites[1])})},
                       {"clearance_from", e.clearance_from},
                       {"clearance_to", e.clearance_to},
                       {"min_clearance", e.min_clearance},
                       {"polyline", points_json(e.polyline)}});
    json jpairs = json::array();
    for (const auto& [p, count] : pairs) jpairs.push_back({{"obstacles", json::array({p.first, p.second})}, {"edges", count}});
    json saddles = json::array(), maxima = json::array();
    for (const auto& c : g.saddles()) saddles.push_back(gvd_critical_json(c));
    for (const auto& c : g.maxima()) maxima.push_back(gvd_critical_json(c));
    print_json({{"scene", a.path},
                {"resolution", g.resolution()},
                {"resolution_exponent", g.resolution_exponent()},
                {"max_deviation", g.max_deviation()},
                {"obstacles", obstacles},
                {"obstacle_pairs", jpairs},
                {"vertices", vertices},
                {"edges", edges},
                {"saddles", saddles},
                {"maxima", maxima}});
  } else {
    std::cout << "gvd: " << count_of(g.vertices().size(), "vertex", "vertices") << ", " << count_of(g.edges().size(), "edge") << " ("
              << curved << " curved) between " << count_of(pairs.size(), "obstacle pair") << " of " << count_of(g.num_obstacles(), "obstacle") << "\n";
    std::cout << "critical points of D: " << count_of(g.saddles().size(), "saddle") << ", " << count_of(g.maxima().size(), "maximum", "maxima") << "\n";
    double narrowest = -1;
    for (const auto& c : g.saddles())
      if (narrowest < 0 || c.clearance < narrowest) narrowest = c.clearance;
    if (narrowest >= 0) std::cout << "narrowest passage between obstacles: width " << geometry::format_number(2 * narrowest) << "\n";
    std::cout << "resolution: 2^" << g.resolution_exponent() << " = " << geometry::format_number(g.resolution())
              << " (input snapped to this grid); curved edges sampled within " << geometry::format_number(g.max_deviation()) << "\n";
    if (!a.svg.empty()) std::cout << "wrote " << a.svg << "\n";
  }
}

}  // namespace

void add_gvd_commands(CLI::App& app) {
  auto* cmd = app.add_subcommand("gvd", "Generalized Voronoi diagram: points equidistant to two obstacles, with the saddles and maxima of the clearance");
  set_examples(cmd, {"preimage gvd examples/gallery.json", "preimage gvd examples/gallery.json --svg gvd.svg", "preimage gvd examples/gallery.json --json"});
  auto a = std::make_shared<GvdArgs>();
  cmd->add_option("scene", a->path, "Scene JSON file")->required();
  add_json_flag(cmd, a->json, "Machine-readable output on stdout");
  cmd->add_option("--svg", a->svg, "Also draw the scene, the GVD, saddles and maxima to this SVG file");
  cmd->add_option("--max-deviation", a->max_deviation, "Sample curved edges within this distance (0: 1/1000 of the scene's size)")
      ->check(number_in(0, 1e12));
  cmd->callback([a] { run_gvd(*a); });
}

}  // namespace preimage::cli
