// SPDX-License-Identifier: Apache-2.0
// preimage validate | import | export | render (visibility: cmd_visibility.cpp)
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/render/figures.hpp>
#include <preimage/scene/geojson.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/wkt.hpp>

#include <fstream>
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

void run_import(const std::string& in, const std::string& from, const std::string& out, bool merge_holes) {
  scene::Scene s;
  const scene::ImportOptions options{merge_holes};
  if (from == "houseexpo") s = scene::import_houseexpo(in);
  else if (from == "visilibity") s = scene::import_visilibity(in, options);
  else if (from == "geojson") s = scene::import_geojson(in, options);
  else if (from == "wkt") s = scene::import_wkt(in, options);
  else throw InputError("--from: unknown format '" + from + "' (expected houseexpo, visilibity, geojson or wkt)");
  scene::save_scene(s, out);
  const auto& env = s.require_environment();
  std::cout << "wrote " << out << ": " << count_of(env.num_vertices(), "vertex", "vertices") << ", " << count_of(env.num_holes(), "obstacle");
  if (env.has_contacts()) std::cout << ", " << count_of(env.num_contacts(), "contact");
  std::cout << "\n";
}

// The environment as GIS tools read it: GeoJSON (one Feature named after the scene) or WKT.
// Both read back through `import` to the same environment (coordinates round-trip exactly).
void run_export(const std::string& in, const std::string& to, const std::string& out) {
  const scene::Scene s = scene::load_scene(in);
  const auto& env = s.require_environment();
  std::string text;
  if (to == "geojson") text = scene::GeoJsonWriter().environment(env, {{"name", s.name}}).json().dump() + "\n";
  else if (to == "wkt") text = scene::to_wkt(env) + "\n";
  else throw InputError("--to: unknown format '" + to + "' (expected geojson or wkt)");
  if (out.empty() || out == "-") {
    std::cout << text;
    return;
  }
  std::ofstream f(out, std::ios::binary);
  if (!(f << text) || !f.flush()) throw InputError(out + ": cannot write file");
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
    auto merge = std::make_shared<bool>(false);
    cmd->add_flag("--merge-holes", *merge,
                  "Replace holes that overlap (share an edge, cross, nest) by their union, snapped to a power-of-two grid "
                  "2^-49 of the largest coordinate (without it they are an error naming both; holes touching at a vertex are accepted either way)");
    cmd->callback([=] { run_import(*in, *from, *out, *merge); });
  }
  {
    auto* cmd = app.add_subcommand("export", "Write a scene's environment as GeoJSON or WKT (reads back through import)");
    set_examples(cmd, {"preimage export examples/gallery.json --to geojson -o gallery.geojson", "preimage export examples/pursuit/pillar.json --to wkt"});
    auto in = std::make_shared<std::string>();
    auto to = std::make_shared<std::string>();
    auto out = std::make_shared<std::string>();
    cmd->add_option("scene", *in, "Scene JSON file")->required();
    cmd->add_option("--to", *to, "Output format: geojson | wkt")->required();
    cmd->add_option("-o,--output", *out, "File to write (default: standard output)");
    cmd->callback([=] { run_export(*in, *to, *out); });
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
}

}  // namespace preimage::cli
