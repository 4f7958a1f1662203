// SPDX-License-Identifier: Apache-2.0
// preimage visibility (one viewpoint or a batch, optionally range-limited) | visibility-graph
#include "common.hpp"

#include <preimage/scene/geojson.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/range_visibility.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/geometry/visibility_graphs.hpp>
#include <preimage/render/figures.hpp>

#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>

namespace preimage::cli {

namespace {

using nlohmann::json;

json vis_vertex_ref(const geometry::Environment& env, std::uint32_t v) {
  return {{"ring", env.ring_name(env.ring_of(v))}, {"index", env.input_index(v)}};
}

json vis_point_json(const geometry::VisibilityPolygon& v, std::size_t i) {
  const auto& env = *v.environment;
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
      j["through"] = vis_vertex_ref(env, vv.vertex);
      j["exact"] = {geometry::exact_string(p.x()), geometry::exact_string(p.y())};
      break;
    }
  }
  return j;
}

json vis_edge_json(const geometry::VisibilityPolygon& v, std::size_t i) {
  const auto& e = v.edges[i];
  if (e.kind == geometry::VisibilityEdge::Kind::Solid) return {{"kind", "solid"}, {"on", edge_json(*v.environment, e.edge)}};
  return {{"kind", "free"}, {"occluding_vertex", vis_vertex_ref(*v.environment, e.reflex)}, {"occluder_side", e.occluder_on_left ? "left" : "right"}};
}

json visibility_json(const geometry::VisibilityPolygon& v) {
  json verts = json::array(), edges = json::array();
  for (std::size_t i = 0; i < v.vertices.size(); ++i) verts.push_back(vis_point_json(v, i));
  for (std::size_t i = 0; i < v.edges.size(); ++i) edges.push_back(vis_edge_json(v, i));
  return json{{"query", {v.query.x(), v.query.y()}},
              {"location", geometry::to_string(v.location.kind)},
              {"area", v.area()},
              {"vertices", verts},
              {"edges", edges}};
}

json range_point_json(const geometry::RangeVisibility& r, const geometry::RangePoint& p) {
  if (p.kind == geometry::RangePoint::Kind::PolygonVertex) return vis_point_json(r.polygon, p.vertex);
  return {{"x", p.approx.x()},
          {"y", p.approx.y()},
          {"kind", "circle-crossing"},
          {"polygon_edge", p.edge},
          {"t", geometry::crossing_parameter(r, p)},
          {"entering", p.entering}};
}

// Pieces of V(q) within the range, counter-clockwise: segments on V's edges (solid: on a
// wall; free: an occlusion gap) and arcs of the range circle.
json range_json(const geometry::RangeVisibility& r) {
  json pieces = json::array();
  std::size_t arcs = 0;
  for (const auto& p : r.pieces) {
    if (p.kind == geometry::RangePiece::Kind::Arc) {
      ++arcs;
      json a{{"kind", "arc"}, {"from_angle", p.from_angle}, {"span", p.span}};
      if (!r.full_disc) a["from"] = range_point_json(r, p.from), a["to"] = range_point_json(r, p.to);
      pieces.push_back(a);
      continue;
    }
    json s = vis_edge_json(r.polygon, p.edge);  // kind solid | free, and what it lies on
    s["polygon_edge"] = p.edge;
    s["from"] = range_point_json(r, p.from);
    s["to"] = range_point_json(r, p.to);
    pieces.push_back(s);
  }
  return json{{"query", {r.query().x(), r.query().y()}},
              {"location", geometry::to_string(r.polygon.location.kind)},
              {"range", r.range},
              {"full_disc", r.full_disc},
              {"area", r.area()},
              {"visibility_polygon_area", r.polygon.area()},
              {"arcs", arcs},
              {"segments", r.pieces.size() - arcs},
              {"pieces", pieces}};
}

// "x y" per line; '#' starts a comment; blank lines skipped. Calls `each(point, line)` as
// it reads, so what was computed before a bad line is already out.
void read_points(const std::string& path, const std::function<void(const geometry::Point&, std::size_t)>& each) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open file");
  std::string line;
  for (std::size_t no = 1; std::getline(in, line); ++no) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream ss(line);
    std::vector<std::string> tokens;
    for (std::string t; ss >> t;) tokens.push_back(t);
    if (tokens.empty()) continue;
    const std::string where = path + ":" + std::to_string(no) + ": ";
    double xy[2] = {0, 0};
    for (std::size_t k = 0; k < std::min<std::size_t>(tokens.size(), 2); ++k) {
      std::size_t used = 0;
      bool ok = true;
      try {
        xy[k] = std::stod(tokens[k], &used);
      } catch (const std::exception&) {
        ok = false;
      }
      if (!ok || used != tokens[k].size() || !std::isfinite(xy[k]))
        throw InputError(where + "expected 'x y' (two numbers), got '" + tokens[k] + "'");
    }
    if (tokens.size() != 2)
      throw InputError(where + "expected 'x y' (two numbers), got " + std::to_string(tokens.size()) + (tokens.size() == 1 ? " token" : " tokens") +
                       (tokens.size() > 2 ? " (extra '" + tokens[2] + "')" : ""));
    each(geometry::Point(xy[0], xy[1]), no);
  }
}

// The library names a point outside free space; in a batch, the line too.
template <class F>
auto at_line(const std::string& path, std::size_t no, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(path + ":" + std::to_string(no) + ": " + e.what());
  }
}

void draw_range_svg(const scene::Scene& s, const geometry::RangeVisibility& r, const std::string& svg) {
  render::SvgCanvas canvas(render::scene_box(s));
  render::draw_scene(canvas, s);
  render::draw_range_visibility(canvas, r);
  canvas.save(svg);
}

struct VisibilityArgs {
  std::string path, from, points, svg, geojson;
  std::optional<double> range;  // set when --range was given
  bool json = false;
};

void run_visibility(const VisibilityArgs& a) {
  const scene::Scene s = scene::load_scene(a.path);
  const auto& env = s.require_environment();
  if (a.from.empty() == a.points.empty()) throw InputError("--from or --points: give one viewpoint X,Y or a file of them");
  if (!a.points.empty() && (!a.svg.empty() || !a.geojson.empty()))
    throw InputError(std::string(a.svg.empty() ? "--geojson" : "--svg") + ": draws one viewpoint (--from), not a batch (--points)");
  geometry::VisibilityIndex index(env);

  if (!a.points.empty()) {  // a batch: JSON lines, one per point, each written as soon as it is known
    read_points(a.points, [&](const geometry::Point& p, std::size_t no) {
      json j = at_line(a.points, no, [&] { return a.range ? range_json(geometry::range_visibility(index, p, *a.range)) : visibility_json(index.compute(p)); });
      j["line"] = no;
      std::cout << j.dump() << std::endl;
    });
    return;
  }

  const geometry::Point q = parse_point(a.from, "--from");
  if (a.range) {
    const auto r = geometry::range_visibility(index, q, *a.range);
    if (!a.svg.empty()) draw_range_svg(s, r, a.svg);
    if (!a.geojson.empty())
      scene::GeoJsonWriter()
          .environment(env, {{"kind", "environment"}})
          .polygon({r.outline(0.02)}, {{"kind", "range-limited visibility"}, {"range", r.range}, {"area", r.area()}})
          .point(q, {{"kind", "viewpoint"}})
          .save(a.geojson);
    if (a.json) {
      print_json(range_json(r));
      return;
    }
    std::size_t arcs = 0;
    for (const auto& p : r.pieces) arcs += p.kind == geometry::RangePiece::Kind::Arc;
    std::cout << "visibility from " << geometry::format_point(q) << " (" << geometry::to_string(r.polygon.location.kind) << ") within range "
              << geometry::format_number(r.range) << ": ";
    if (r.full_disc) std::cout << "the whole disc";
    else std::cout << count_of(r.pieces.size() - arcs, "segment") << " and " << count_of(arcs, "arc");
    std::cout << ", area " << geometry::format_number(r.area()) << " (unlimited: " << geometry::format_number(r.polygon.area()) << ")\n";
  } else {
    const auto v = index.compute(q);
    if (!a.svg.empty()) {
      render::SvgCanvas canvas(render::scene_box(s));
      render::draw_scene(canvas, s);
      render::draw_visibility(canvas, v);
      canvas.save(a.svg);
    }
    if (!a.geojson.empty()) {
      std::vector<geometry::Point> ring;
      for (const auto& vv : v.vertices) ring.push_back(vv.approx);
      scene::GeoJsonWriter()
          .environment(env, {{"kind", "environment"}})
          .polygon({ring}, {{"kind", "visibility polygon"}, {"area", v.area()}})
          .point(q, {{"kind", "viewpoint"}})
          .save(a.geojson);
    }
    if (a.json) {
      print_json(visibility_json(v));
      return;
    }
    std::size_t free = 0;
    for (auto& e : v.edges) free += e.kind == geometry::VisibilityEdge::Kind::Free;
    std::cout << "visibility polygon from " << geometry::format_point(q) << " (" << geometry::to_string(v.location.kind)
              << "): " << v.vertices.size() << " vertices, " << v.edges.size() - free << " solid and " << free
              << " free edges, area " << geometry::format_number(v.area()) << "\n";
  }
  if (!a.svg.empty()) std::cout << "wrote " << a.svg << "\n";
  if (!a.geojson.empty()) std::cout << "wrote " << a.geojson << "\n";
}

struct GraphArgs {
  std::string path, points, kind, svg;
  bool json = false;
};

void run_visibility_graph(const GraphArgs& a) {
  const scene::Scene s = scene::load_scene(a.path);
  const auto& env = s.require_environment();
  std::string kind = a.kind.empty() ? (a.points.empty() ? "vertex" : "point") : a.kind;
  if (kind != "vertex" && kind != "point" && kind != "point-vertex")
    throw InputError("--kind: unknown graph '" + kind + "' (expected vertex, point or point-vertex)");
  if (kind == "vertex" && !a.points.empty()) throw InputError("--points: the vertex graph joins environment vertices only (use --kind point or point-vertex)");
  if (kind != "vertex" && a.points.empty()) throw InputError("--kind " + kind + ": needs --points FILE");
  geometry::VisibilityIndex index(env);
  std::vector<geometry::Point> pts;
  if (!a.points.empty())
    read_points(a.points, [&](const geometry::Point& p, std::size_t no) {
      if (!index.in_free_space(p)) {
        const auto loc = index.locate(p);
        throw InputError(a.points + ":" + std::to_string(no) + ": point " + geometry::format_point(p) + " is not in free space: it lies " +
                         (loc.kind == geometry::Location::Kind::InHole ? "inside " + env.ring_name(loc.index + 1) : "outside " + env.ring_name(0)));
      }
      pts.push_back(p);
    });
  const geometry::GraphEdges edges = kind == "vertex"  ? geometry::vertex_visibility_graph(index)
                                     : kind == "point" ? geometry::point_visibility_graph(index, pts)
                                                       : geometry::point_vertex_visibility_graph(index, pts);
  const std::string name = kind == "vertex" ? "vertex-vertex" : kind == "point" ? "point-point" : "point-vertex";
  auto end_a = [&](std::uint32_t i) { return kind == "vertex" ? env.vertex(i) : pts[i]; };
  auto end_b = [&](std::uint32_t i) { return kind == "point" ? pts[i] : env.vertex(i); };

  if (!a.svg.empty()) {
    render::SvgCanvas canvas(render::scene_box(s));
    canvas.environment(env);
    const render::Style line{"none", "#1a73e8", 0.8, 0.6, ""};
    for (const auto& [u, v] : edges) canvas.segment(end_a(u), end_b(v), line);
    canvas.legend(name + " visibility graph: " + count_of(edges.size(), "edge"), line);
    const render::Style dot{"#d93025", "#202124", 1.0, 1.0, ""};
    for (std::size_t i = 0; i < pts.size(); ++i) canvas.point(pts[i], 3.5, dot, "point " + std::to_string(i) + " " + geometry::format_point(pts[i]));
    if (!pts.empty()) canvas.legend("points", dot);
    canvas.save(a.svg);
  }
  if (a.json) {
    json out{{"kind", name}};
    if (kind != "point") {
      json vs = json::array();
      for (std::uint32_t v = 0; v < env.num_vertices(); ++v)
        vs.push_back({{"ring", env.ring_name(env.ring_of(v))}, {"index", env.input_index(v)}, {"x", env.vertex(v).x()}, {"y", env.vertex(v).y()}});
      out["vertices"] = vs;
    }
    if (kind != "vertex") out["points"] = points_json(pts);
    json es = json::array();
    for (const auto& [u, v] : edges) es.push_back({u, v});
    out["edges"] = es;
    out["note"] = kind == "vertex" ? "edges join positions in 'vertices'" : kind == "point" ? "edges join positions in 'points'" : "edges are [point, vertex] positions";
    print_json(out);
  } else {
    std::cout << name << " visibility graph: ";
    if (kind != "point") std::cout << count_of(env.num_vertices(), "vertex", "vertices") << (kind == "vertex" ? ", " : " and ");
    if (kind != "vertex") std::cout << count_of(pts.size(), "point") << ", ";
    std::cout << count_of(edges.size(), "edge") << "\n";
  }
  if (!a.svg.empty() && !a.json) std::cout << "wrote " << a.svg << "\n";
}

}  // namespace

void add_visibility_commands(CLI::App& app) {
  {
    auto* cmd = app.add_subcommand("visibility", "Exact visibility polygon from a point (interior, on an edge, or at a vertex), optionally range-limited; or a batch of points");
    set_examples(cmd, {"preimage visibility examples/gallery.json --from 1,1", "preimage visibility examples/gallery.json --from 1,1 --svg vis.svg --json",
                       "preimage visibility examples/gallery.json --from 4,4 --range 3 --svg range.svg",
                       "preimage visibility examples/gallery.json --points examples/gallery_points.txt --range 2.5"});
    auto a = std::make_shared<VisibilityArgs>();
    cmd->add_option("scene", a->path, "Scene JSON file")->required();
    auto* from = cmd->add_option("--from", a->from, "Viewpoint X,Y");
    auto* points = cmd->add_option("--points", a->points, "Batch: a file of viewpoints, one 'x y' a line ('#' comments); JSON lines out, one per point");
    from->excludes(points);
    auto range = std::make_shared<double>(0);
    auto* range_opt = cmd->add_option("--range", *range, "Sensor range R: V(q) within distance R (segments and circle arcs)")->check(number_in(0, 1e12, true));
    add_json_flag(cmd, a->json, "Machine-readable output on stdout");
    cmd->add_option("--svg", a->svg, "Also draw the result to this SVG file");
    cmd->add_option("--geojson", a->geojson, "Also write the environment, the polygon and the viewpoint as GeoJSON features");
    cmd->callback([a, range, range_opt] {
      if (range_opt->count()) a->range = *range;
      run_visibility(*a);
    });
  }
  {
    auto* cmd = app.add_subcommand("visibility-graph", "Full visibility graph: environment vertices, a set of points, or points to vertices");
    set_examples(cmd, {"preimage visibility-graph examples/gallery.json", "preimage visibility-graph examples/gallery.json --points examples/gallery_points.txt --json",
                       "preimage visibility-graph examples/gallery.json --points examples/gallery_points.txt --kind point-vertex --svg graph.svg"});
    auto a = std::make_shared<GraphArgs>();
    cmd->add_option("scene", a->path, "Scene JSON file")->required();
    cmd->add_option("--points", a->points, "Points, one 'x y' a line ('#' comments)");
    cmd->add_option("--kind", a->kind, "vertex (vertex-vertex; the default without --points), point (point-point; the default with --points) or point-vertex");
    add_json_flag(cmd, a->json, "Machine-readable output on stdout");
    cmd->add_option("--svg", a->svg, "Also draw the graph to this SVG file");
    cmd->callback([a] { run_visibility_graph(*a); });
  }
}

}  // namespace preimage::cli
