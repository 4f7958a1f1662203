// SPDX-License-Identifier: Apache-2.0
// preimage validate | import | render | visibility
#include "common.hpp"

#include <preimage/scene/geojson.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/render/figures.hpp>
#include <preimage/scene/import.hpp>

#include <iostream>

namespace preimage::cli {

namespace {

using nlohmann::json;

// The search for three collinear vertices anywhere takes n^2 log n time (the problem is
// 3SUM-hard: nothing much faster is known); above this many vertices validate reports it
// as not searched rather than run for minutes. Straight vertices (collinear with their
// neighbours) are found in O(n) at every size.
constexpr std::size_t kCollinearSearchLimit = 5000;

void run_validate(const std::string& path, bool as_json) {
  const scene::Scene s = scene::load_scene(path);
  json out{{"scene", path}, {"valid", true}, {"name", s.name}};
  std::string text = "ok: " + path;
  if (s.environment) {
    const auto& env = *s.environment;
    const auto straight = geometry::straight_vertices(env);
    const bool search_triples = env.num_vertices() <= kCollinearSearchLimit;
    const auto collinear = search_triples ? geometry::find_collinear_triple(env.vertices()) : std::nullopt;
    const auto equal_x = geometry::find_equal_x(env.vertices());
    out["environment"] = {{"vertices", env.num_vertices()},
                          {"boundary_vertices", env.ring_size(0)},
                          {"obstacles", env.num_holes()},
                          {"free_area", env.area()},
                          {"reflex_vertices", [&] { std::size_t r = 0; for (std::size_t v = 0; v < env.num_vertices(); ++v) r += env.is_reflex(v); return r; }()},
                          {"straight_vertices", straight.size()},
                          {"contacts", env.num_contacts()},
                          {"general_position", {{"three_collinear_vertices", search_triples ? json(collinear.has_value()) : json(nullptr)},
                                                {"equal_x_coordinates", equal_x.has_value()}}}};
    text += ": " + std::to_string(env.num_vertices()) + " vertices (" + std::to_string(env.ring_size(0)) +
            " on the boundary), " + count_of(env.num_holes(), "obstacle") + ", free area " + geometry::format_number(env.area());
    if (env.has_contacts()) text += ", " + count_of(env.num_contacts(), "contact") + " (rings touching at a vertex)";
    // Every degeneracy the JSON reports is named in the text too.
    std::vector<std::string> degenerate;
    if (collinear)
      degenerate.push_back(geometry::describe_vertex(env, (*collinear)[0]) + ", " + geometry::describe_vertex(env, (*collinear)[1]) +
                           " and " + geometry::describe_vertex(env, (*collinear)[2]) + " are collinear");
    if (equal_x)
      degenerate.push_back(geometry::describe_vertex(env, (*equal_x)[0]) + " and " + geometry::describe_vertex(env, (*equal_x)[1]) +
                           " have equal x-coordinates");
    if (!straight.empty())
      degenerate.push_back(std::to_string(straight.size()) + (straight.size() == 1 ? " straight vertex" : " straight vertices") +
                           " (collinear with both neighbours)");
    for (std::size_t i = 0; i < degenerate.size(); ++i)
      text += (i ? "; " : "; not in general position: ") + degenerate[i];
    if (!search_triples)
      text += "; three collinear vertices not searched (more than " + std::to_string(kCollinearSearchLimit) +
              " vertices: the search takes n^2 log n time)";
  } else {
    text += ": no environment";
  }
  out["landmarks"] = s.landmarks.size();
  out["beams"] = s.beams.size();
  if (!s.landmarks.empty()) text += ", " + std::to_string(s.landmarks.size()) + " landmarks";
  if (!s.beams.empty()) text += ", " + std::to_string(s.beams.size()) + " beams";
  if (as_json) print_json(out);
  else std::cout << text << "\n";
}

void run_import(const std::string& in, const std::string& from, const std::string& out) {
  scene::Scene s;
  if (from == "houseexpo") s = scene::import_houseexpo(in);
  else if (from == "visilibity") s = scene::import_visilibity(in);
  else if (from == "geojson") s = scene::import_geojson(in);
  else if (from == "wkt") s = scene::import_wkt(in);
  else throw InputError("--from: unknown format '" + from + "' (expected houseexpo, visilibity, geojson or wkt)");
  scene::save_scene(s, out);
  const auto& env = s.require_environment();
  std::cout << "wrote " << out << ": " << count_of(env.num_vertices(), "vertex", "vertices") << ", " << count_of(env.num_holes(), "obstacle") << "\n";
}

void run_render(const std::string& path, const std::string& out, bool triangulation) {
  const scene::Scene s = scene::load_scene(path);
  render::SvgCanvas canvas(render::scene_box(s));
  render::draw_scene(canvas, s);
  if (triangulation) {
    geometry::Triangulation t(s.require_environment());
    render::draw_triangulation(canvas, t);
  }
  canvas.save(out);
  std::cout << "wrote " << out << "\n";
}

json visibility_json(const geometry::VisibilityPolygon& v) {
  const auto& env = *v.environment;
  json verts = json::array(), edges = json::array();
  for (std::size_t i = 0; i < v.vertices.size(); ++i) {
    const auto& vv = v.vertices[i];
    json j{{"x", vv.approx.x()}, {"y", vv.approx.y()}};
    switch (vv.kind) {
      case geometry::VisibilityVertex::Kind::EnvironmentVertex:
        j["kind"] = "vertex";
        j["ring"] = env.ring_name(env.ring_of(vv.vertex));
        j["index"] = env.input_index(vv.vertex);
        break;
      case geometry::VisibilityVertex::Kind::Query: j["kind"] = "query"; break;
      case geometry::VisibilityVertex::Kind::RayHit: {
        const auto p = v.exact(i);
        j["kind"] = "ray-hit";
        j["through"] = {{"ring", env.ring_name(env.ring_of(vv.vertex))}, {"index", env.input_index(vv.vertex)}};
        j["exact"] = {exact_string(p.x()), exact_string(p.y())};
        break;
      }
    }
    verts.push_back(j);
  }
  for (const auto& e : v.edges) {
    if (e.kind == geometry::VisibilityEdge::Kind::Solid) {
      edges.push_back({{"kind", "solid"}, {"on", edge_json(env, e.edge)}});
    } else {
      edges.push_back({{"kind", "free"},
                       {"occluding_vertex", {{"ring", env.ring_name(env.ring_of(e.reflex))}, {"index", env.input_index(e.reflex)}}},
                       {"occluder_side", e.occluder_on_left ? "left" : "right"}});
    }
  }
  return json{{"query", {v.query.x(), v.query.y()}},
              {"location", geometry::to_string(v.location.kind)},
              {"area", v.area()},
              {"vertices", verts},
              {"edges", edges}};
}

void run_visibility(const std::string& path, const std::string& from, bool as_json, const std::string& svg, const std::string& geojson) {
  const scene::Scene s = scene::load_scene(path);
  const geometry::Point q = parse_point(from, "--from");
  geometry::VisibilityIndex index(s.require_environment());
  const auto v = index.compute(q);
  if (!svg.empty()) {
    render::SvgCanvas canvas(render::scene_box(s));
    render::draw_scene(canvas, s);
    render::draw_visibility(canvas, v);
    canvas.save(svg);
  }
  if (!geojson.empty()) {
    std::vector<geometry::Point> ring;
    for (const auto& vv : v.vertices) ring.push_back(vv.approx);
    scene::GeoJsonWriter()
        .environment(s.require_environment(), {{"kind", "environment"}})
        .polygon({ring}, {{"kind", "visibility polygon"}, {"area", v.area()}})
        .point(q, {{"kind", "viewpoint"}})
        .save(geojson);
  }
  if (as_json) {
    print_json(visibility_json(v));
    return;
  }
  std::size_t free = 0;
  for (auto& e : v.edges) free += e.kind == geometry::VisibilityEdge::Kind::Free;
  std::cout << "visibility polygon from " << geometry::format_point(q) << " (" << geometry::to_string(v.location.kind)
            << "): " << v.vertices.size() << " vertices, " << v.edges.size() - free << " solid and " << free
            << " free edges, area " << geometry::format_number(v.area()) << "\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
  if (!geojson.empty()) std::cout << "wrote " << geojson << "\n";
}

}  // namespace

void add_geometry_commands(CLI::App& app) {
  {
    auto* cmd = app.add_subcommand("validate", "Check a scene file: exact validity of the environment and every slot");
    set_examples(cmd, {"preimage validate examples/gallery.json", "preimage validate examples/pursuit/pillar.json --json"});
    auto path = std::make_shared<std::string>();
    auto json_out = std::make_shared<bool>(false);
    cmd->add_option("scene", *path, "Scene JSON file")->required();
    add_json_flag(cmd, *json_out, "Machine-readable output on stdout");
    cmd->callback([=] { run_validate(*path, *json_out); });
  }
  {
    auto* cmd = app.add_subcommand("import", "Convert a floor plan into a preimage scene (validated)");
    set_examples(cmd, {"preimage import examples/floorplans/house_expo_room_0000.json --from houseexpo -o house.json", "preimage import examples/room_with_pillar.visilibity.txt --from visilibity -o pillar.json",
                       "preimage import examples/formats/l_room.wkt --from wkt -o l_room.json"});
    auto in = std::make_shared<std::string>();
    auto from = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    cmd->add_option("file", *in, "Input file")->required();
    cmd->add_option("--from", *from, "Input format: houseexpo | visilibity | geojson | wkt")->required();
    cmd->add_option("-o,--output", *out, "Scene JSON to write")->required();
    cmd->callback([=] { run_import(*in, *from, *out); });
  }
  {
    auto* cmd = app.add_subcommand("render", "Draw a scene to SVG");
    set_examples(cmd, {"preimage render examples/gallery.json -o gallery.svg", "preimage render examples/gallery.json -o triangles.svg --triangulation"});
    auto path = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    auto tri = std::make_shared<bool>(false);
    cmd->add_option("scene", *path, "Scene JSON file")->required();
    cmd->add_option("-o,--output", *out, "SVG file to write")->required();
    cmd->add_flag("--triangulation", *tri, "Overlay the constrained Delaunay triangulation");
    cmd->callback([=] { run_render(*path, *out, *tri); });
  }
  {
    auto* cmd = app.add_subcommand("visibility", "Exact visibility polygon from a point (interior, on an edge, or at a vertex)");
    set_examples(cmd, {"preimage visibility examples/gallery.json --from 1,1", "preimage visibility examples/gallery.json --from 1,1 --svg vis.svg --json"});
    auto path = std::make_shared<std::string>();
    auto from = std::make_shared<std::string>();
    auto json_out = std::make_shared<bool>(false);
    auto svg = std::make_shared<std::string>();
    cmd->add_option("scene", *path, "Scene JSON file")->required();
    cmd->add_option("--from", *from, "Viewpoint X,Y")->required();
    add_json_flag(cmd, *json_out, "Machine-readable output on stdout");
    auto geojson = std::make_shared<std::string>();
    cmd->add_option("--svg", *svg, "Also draw the polygon to this SVG file");
    cmd->add_option("--geojson", *geojson, "Also write the environment, the polygon and the viewpoint as GeoJSON features");
    cmd->callback([=] { run_visibility(*path, *from, *json_out, *svg, *geojson); });
  }
}

}  // namespace preimage::cli
