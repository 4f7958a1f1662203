// SPDX-License-Identifier: Apache-2.0
// preimage decompose | plan
#include "common.hpp"

#include <preimage/scene/geojson.hpp>

#include <preimage/coverage/coverage.hpp>
#include <preimage/coverage/online_coverage.hpp>
#include <preimage/geometry/local_frame.hpp>
#include <preimage/decompose/planner.hpp>
#include <preimage/decompose/wavefront.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/geometry/shortest_path_map.hpp>
#include <preimage/coverage/figures.hpp>
#include <preimage/decompose/figures.hpp>
#include <preimage/error.hpp>
#include <preimage/render/figures.hpp>

#include <cmath>
#include <numbers>
#include <iostream>
#include <limits>
#include <optional>

namespace preimage::cli {

namespace {

using nlohmann::json;

json point_json(const geometry::ExactPoint& p) { return json::array({CGAL::to_double(p.x()), CGAL::to_double(p.y())}); }

void write_cells_geojson(const std::string& file, const geometry::Environment& env, const std::vector<std::vector<geometry::Point>>& cells,
                         const std::string& method) {
  scene::GeoJsonWriter w;
  w.environment(env, {{"kind", "environment"}});
  for (std::size_t i = 0; i < cells.size(); ++i) w.polygon({cells[i]}, {{"kind", "cell"}, {"method", method}, {"id", i}});
  w.save(file);
}

void run_boustrophedon(const scene::Scene& s, double angle, bool as_json, const std::string& svg, const std::string& geojson) {
  const decompose::BoustrophedonDecomposition b(s.require_environment(), angle);
  const auto adj = b.adjacency();
  const auto& slices = b.critical_slices();
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    decompose::draw_boustrophedon(c, b);
    c.save(svg);
  }
  if (!geojson.empty()) {
    std::vector<std::vector<geometry::Point>> cells;
    for (std::size_t i = 0; i < b.cells().size(); ++i) cells.push_back(b.polygon(i));
    write_cells_geojson(geojson, s.require_environment(), cells, "boustrophedon");
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
            << "N_cells = N_critical + N_obstacles - 1";
  // With holes touching at vertices, each merge (k rings at a point: k - 1) is one loop less.
  const auto& env = s.require_environment();
  if (env.has_contacts()) std::cout << " - N_merges";
  std::cout << ": " << b.cells().size() << " = " << slices.size() << " + " << env.num_holes() << " - 1";
  if (env.has_contacts()) std::cout << " - " << env.contact_merges();
  std::cout << "\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
  if (!geojson.empty()) std::cout << "wrote " << geojson << "\n";
}

// The default centre of the variable-slice decompositions: the middle of the bounding box.
geometry::Point default_centre(const geometry::Environment& env) {
  const auto b = env.bbox();
  return {(b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2};
}

void run_morse(const scene::Scene& s, decompose::SliceFamily family, const std::string& centre_s, bool as_json, const std::string& svg,
               const std::string& geojson) {
  const auto& env = s.require_environment();
  const geometry::Point centre = centre_s.empty() ? default_centre(env) : parse_point(centre_s, "--center");
  const decompose::MorseDecomposition m(env, family, centre);
  const std::string name(decompose::to_string(family));
  const auto box = env.bbox();
  const double err = 1e-6 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    decompose::draw_morse(c, m);
    c.save(svg);
  }
  if (!geojson.empty()) {
    scene::GeoJsonWriter w;
    w.environment(env, {{"kind", "environment"}});
    for (std::size_t i = 0; i < m.cells().size(); ++i) w.polygon(m.cell_rings(i, err), {{"kind", "cell"}, {"method", name}, {"id", i}});
    w.save(geojson);
  }
  const auto adj = m.adjacency();
  if (as_json) {
    json cells = json::array(), crit = json::array(), arcs = json::array();
    for (std::size_t i = 0; i < m.cells().size(); ++i) {
      json rings = json::array();
      for (const auto& r : m.cell_rings(i, err)) rings.push_back(points_json(r));
      cells.push_back({{"id", i}, {"area", m.cells()[i].area}, {"rings", rings}, {"nodes", m.cells()[i].nodes}, {"adjacent", adj[i]}});
    }
    for (const auto& k : m.critical_points()) {
      const char* kind = k.kind == decompose::CriticalKind::SplitMerge ? "split_merge" : k.kind == decompose::CriticalKind::BirthDeath ? "birth_death" : "minimum";
      const auto& p = m.points()[k.point].approx;
      crit.push_back({{"point", {p.x(), p.y()}}, {"kind", kind}, {"level", k.level}, {"node", k.node}});
    }
    for (const auto& a : m.arcs()) {
      json arc = {{"from", {a.a.x(), a.a.y()}}, {"to", {a.b.x(), a.b.y()}}, {"node", a.node}};
      if (family == decompose::SliceFamily::Circular) arc["radius"] = std::sqrt(CGAL::to_double(a.level)), arc["angle"] = a.span;
      if (family == decompose::SliceFamily::Squarel) arc["corners"] = points_json(a.corners), arc["level"] = CGAL::to_double(a.level);
      arcs.push_back(arc);
    }
    print_json({{"method", name}, {"center", {centre.x(), centre.y()}}, {"cells", cells}, {"critical_points", crit}, {"critical_slices", arcs},
                {"reeb_graph", {{"nodes", m.num_nodes()}, {"edges", m.cells().size()}}}});
    return;
  }
  std::cout << name << " decomposition around " << geometry::format_point(centre) << ": " << m.cells().size() << " cells, "
            << m.critical_points().size() << " critical points in " << m.num_nodes() << " critical slices (Reeb graph nodes), "
            << m.arcs().size() << " critical slice intervals\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
  if (!geojson.empty()) std::cout << "wrote " << geojson << "\n";
}

// The scene moved into its environment's local frame (geometry::LocalFrame): the brushfire
// and wave-front decompositions compute levels, offsets and fronts in floating point, which
// a georeferenced plan (1e5..1e12 from the origin) would otherwise round away. Points are
// reported in input coordinates (frame.to_input); the SVG is drawn in the frame.
scene::Scene in_local_frame(const scene::Scene& s, const geometry::LocalFrame& frame) {
  scene::Scene local = s;
  if (!frame.identity()) local.environment = frame.to_local(s.require_environment());
  return local;
}

void run_brushfire(const scene::Scene& input, bool as_json, const std::string& svg, const std::string& geojson) {
  const geometry::LocalFrame frame = geometry::LocalFrame::of(input.require_environment());
  const scene::Scene s = in_local_frame(input, frame);
  const auto& env = s.require_environment();
  auto out = [&](const geometry::Point& p) { return frame.to_input(p); };
  const decompose::BrushfireDecomposition b(env);
  const auto box = env.bbox();
  const double sag = 1e-4 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    decompose::draw_brushfire(c, b);
    c.save(svg);
  }
  if (!geojson.empty()) {
    scene::GeoJsonWriter w;
    w.environment(input.require_environment(), {{"kind", "environment"}});
    for (std::uint32_t k = 0; k < b.num_bands(); ++k) {
      auto ring = b.band_polygon(k, sag);
      for (auto& p : ring) p = out(p);
      w.polygon({ring}, {{"kind", "band"}, {"method", "brushfire"}, {"cell", b.band_cell(k)}});
    }
    w.save(geojson);
  }
  const auto adj = b.adjacency();
  std::size_t saddles = 0;
  for (const auto& k : b.critical_points()) saddles += k.kind == decompose::BrushfireCriticalPoint::Kind::Saddle;
  if (as_json) {
    json cells = json::array(), crit = json::array(), nodes = json::array();
    auto node_json = [](std::uint32_t n) { return n == decompose::BrushfireCell::kNone ? json(nullptr) : json(n); };
    for (std::size_t i = 0; i < b.cells().size(); ++i) {
      const auto& c = b.cells()[i];
      json cell{{"id", i}, {"area", c.area}, {"lo", c.lo}, {"hi", c.hi}, {"lower", node_json(c.lower)}, {"upper", node_json(c.upper)}, {"adjacent", adj[i]}};
      if (c.obstacle != decompose::BrushfireCell::kNone) cell["obstacle"] = c.obstacle;
      cells.push_back(cell);
    }
    for (const auto& k : b.critical_points())
      crit.push_back({{"point", {out(k.p).x(), out(k.p).y()}}, {"kind", k.kind == decompose::BrushfireCriticalPoint::Kind::Saddle ? "saddle" : "maximum"},
                      {"level", k.level}, {"rising", k.rising}, {"node", k.node}});
    for (const auto& n : b.nodes()) nodes.push_back({{"level", n.level}, {"critical_points", n.critical_points}});
    print_json({{"method", "brushfire"}, {"resolution", b.gvd().resolution()}, {"free_area", b.free_area()}, {"cells", cells},
                {"critical_points", crit}, {"critical_slices", nodes}, {"medial_axis_edges", b.gvd().medial_edges().size()},
                {"gvd_edges", b.gvd().edges().size()}, {"reeb_graph", {{"nodes", b.num_nodes()}, {"edges", b.cells().size()}}}});
    return;
  }
  std::cout << "brushfire decomposition: " << b.cells().size() << " cells, " << saddles << " saddles and " << b.critical_points().size() - saddles
            << " maxima of D in " << b.num_nodes() << " critical slices (Reeb graph nodes); medial axis of " << b.gvd().medial_edges().size()
            << " edges (" << b.gvd().edges().size() << " of them the GVD between obstacles), grid " << geometry::format_number(b.gvd().resolution())
            << "\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
  if (!geojson.empty()) std::cout << "wrote " << geojson << "\n";
}

// Wave-front decomposition (6.2.3, Fig. 6.18): the shortest path map from --start, its
// critical points (geometry/shortest_path_map.hpp) and the cells and critical slices of h
// (decompose/wavefront.hpp). The SVG's region colours are sampled on a grid (a drawing); the
// fronts drawn are the computed ones.
void run_wavefront(const scene::Scene& input, const std::string& start_s, bool as_json, const std::string& svg) {
  const geometry::LocalFrame frame = geometry::LocalFrame::of(input.require_environment());
  const scene::Scene s = in_local_frame(input, frame);
  const auto& env = s.require_environment();
  auto out = [&](const geometry::Point& p) { return frame.to_input(p); };
  auto xy = [&](const geometry::Point& p) { const auto q = out(p); return json::array({q.x(), q.y()}); };
  if (start_s.empty()) throw InputError("--method wavefront: needs --start X,Y (the source of the wave front)");
  const geometry::Point input_start = parse_point(start_s, "--start");
  if (!geometry::locate(input.require_environment(), input_start).in_free_space())
    throw InputError("shortest path map: the source " + geometry::format_point(input_start) + " is not in free space");
  const geometry::Point start = frame.to_local(input_start);
  const geometry::VisibilityIndex index(env);
  const geometry::VisibilityGraph graph(index);
  const geometry::ShortestPathMap spm(graph, start);
  const decompose::WavefrontDecomposition wave(spm);
  const auto ext = spm.extensions();
  const auto meets = spm.collisions();
  std::size_t collisions = 0;
  for (const auto& e : ext) collisions += e.collides;
  auto root_json = [&](std::uint32_t r) { return r == geometry::ShortestPathMap::kSource ? json("source") : json(r); };
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    const auto grid = spm.sample(160);
    const double half = grid.step / 2;
    for (std::size_t j = 0; j < grid.rows; ++j)
      for (std::size_t i = 0, k; i < grid.columns; i = k) {  // one rectangle per run of samples with one root
        const std::uint32_t r = grid.at(i, j).root;
        for (k = i + 1; k < grid.columns && grid.at(k, j).root == r;) ++k;
        if (r == geometry::kNone) continue;
        const std::uint32_t h = r == geometry::ShortestPathMap::kSource ? 0u : (r * 2654435761u) % 360u;
        const geometry::Point p = grid.point(i, j), q = grid.point(k - 1, j);
        c.polygon({{p.x() - half, p.y() - half}, {q.x() + half, p.y() - half}, {q.x() + half, p.y() + half}, {p.x() - half, p.y() + half}},
                  {std::string("hsl(").append(std::to_string(h)).append(",55%,82%)"), "none", 0, 0.8, ""});
      }
    decompose::draw_wavefront(c, wave);
    const render::Style bound{"none", "#222", 1.4, 1, ""}, clipped{"none", "#888", 0.8, 1, "3 3"};
    for (const auto& e : ext) {
      const auto& V = env.vertex(e.vertex);
      c.segment(V, e.end, bound, std::string("extension of the shortest path through vertex ").append(std::to_string(e.vertex)));
      if (e.collides) {
        c.segment(e.end, geometry::to_double(e.hit), clipped);
        c.point(e.end, 3, {"#c0392b", "none", 0, 1, ""}, "collision on the extension");
      }
      c.point(V, 2.5, {"#e67e22", "none", 0, 1, ""}, "tangency bend");
    }
    for (const auto& m : meets) {
      c.segment(env.vertex(m.a), env.vertex(m.b), clipped);
      c.point(m.point, 3.5, {"#8e44ad", "none", 0, 1, ""}, "two fronts collide (saddle of h)");
    }
    c.legend("tangency bend (critical point)", {"#e67e22", "none", 0, 1, ""});
    c.legend("extension: SPM boundary", bound);
    c.legend("collision on an extension", {"#c0392b", "none", 0, 1, ""});
    c.legend("two fronts collide (saddle of h)", {"#8e44ad", "none", 0, 1, ""});
    c.save(svg);
  }
  double dmin = std::numeric_limits<double>::infinity();
  for (auto v : graph.reflex_vertices())
    if (spm.reached(v)) dmin = std::min(dmin, spm.vertex_distance(v));
  if (spm.num_reached() == 0) dmin = 0;
  if (as_json) {
    json verts = json::array(), crit = json::array();
    for (auto v : graph.reflex_vertices())
      verts.push_back({{"id", v}, {"point", xy(env.vertex(v))}, {"distance", spm.reached(v) ? json(spm.vertex_distance(v)) : json(nullptr)},
                       {"predecessor", spm.reached(v) ? root_json(spm.vertex_predecessor(v)) : json(nullptr)}});
    for (const auto& e : ext) {
      json k{{"kind", "tangency"}, {"vertex", e.vertex}, {"point", xy(env.vertex(e.vertex))}, {"from", root_json(e.from)},
             {"distance", spm.vertex_distance(e.vertex)}, {"extension", {xy(env.vertex(e.vertex)), xy(geometry::to_double(e.hit))}},
             {"boundary_end", xy(e.end)}};
      if (e.collides) k["collision"] = {{"point", xy(e.end)}, {"roots", {e.vertex, root_json(e.from), root_json(e.collider)}}};
      crit.push_back(k);
    }
    for (const auto& m : meets)
      crit.push_back({{"kind", "fronts_collide"}, {"point", xy(m.point)}, {"roots", {m.a, m.b}}, {"distance", m.distance}});
    json nodes = json::array(), cells = json::array();
    auto opt = [](std::uint32_t x) { return x == decompose::WavefrontCell::kNone ? json(nullptr) : json(x); };
    for (const auto& n : wave.nodes())
      nodes.push_back({{"level", n.level}, {"bracket", {n.lo, n.hi}}, {"point", xy(n.point)}, {"below", n.below}, {"above", n.above}});
    for (const auto& cl : wave.cells()) cells.push_back({{"lower", opt(cl.lower)}, {"upper", opt(cl.upper)}, {"h", {cl.lo, cl.hi}}});
    print_json({{"method", "wavefront"}, {"start", {input_start.x(), input_start.y()}}, {"reflex_vertices", spm.num_reflex()}, {"reached", spm.num_reached()},
                {"dijkstra_edges", spm.num_edges()}, {"distance_range", {dmin, spm.max_vertex_distance()}}, {"vertices", verts},
                {"critical_points", crit}, {"collisions_on_extensions", collisions}, {"nodes", nodes}, {"cells", cells},
                {"adjacency", wave.adjacency()}});
    return;
  }
  std::cout << "wavefront: shortest path map from " << geometry::format_point(input_start) << ": " << spm.num_reached() << " of " << spm.num_reflex()
            << " reflex vertices reached, D at reflex vertices from " << dmin << " to " << spm.max_vertex_distance() << "\n";
  std::cout << "critical points: " << ext.size() << " tangency bends (extensions to the boundary), " << collisions
            << " collisions on extensions, " << meets.size() << " first collisions of two fronts (saddles of h)\n";
  std::cout << "wave-front decomposition: " << wave.cells().size() << " cells, " << wave.nodes().size() << " critical slices (levels followed: "
            << wave.levels().size() << ")\n";
  if (wave.unmatched_ends() != 0)
    std::cout << "warning: " << wave.unmatched_ends() << " front piece ends found no partner (treated as ends on a wall: double-precision ties)\n";
  for (std::size_t i = 0; i < wave.nodes().size(); ++i) {
    const auto& n = wave.nodes()[i];
    std::cout << "  slice " << i << " at h " << n.level << " near " << geometry::format_point(out(n.point)) << ": " << n.below.size() << " cell(s) end, "
              << n.above.size() << " begin\n";
  }
  for (const auto& e : ext) {
    std::cout << "  bend at " << geometry::format_point(out(env.vertex(e.vertex))) << " (D " << spm.vertex_distance(e.vertex) << ") from "
              << geometry::format_point(out(spm.root_point(e.from))) << ": extension to " << geometry::format_point(out(geometry::to_double(e.hit)));
    if (e.collides) std::cout << ", collision at " << geometry::format_point(out(e.end));
    std::cout << "\n";
  }
  for (const auto& m : meets)
    std::cout << "  fronts from " << geometry::format_point(out(env.vertex(m.a))) << " and " << geometry::format_point(out(env.vertex(m.b))) << " meet at "
              << geometry::format_point(out(m.point)) << " (h " << m.distance << ")\n";
  if (!svg.empty()) std::cout << "wrote " << svg << " (regions sampled on a grid; wave fronts computed, coloured by cell)\n";
}

void run_decompose(const std::string& path, const std::string& method, double angle, const std::string& centre, const std::string& start,
                   bool as_json, const std::string& svg, const std::string& geojson) {
  const scene::Scene s = scene::load_scene(path);
  if (method == "wavefront") {
    if (angle != 0 || !centre.empty() || !geojson.empty()) throw InputError("--method wavefront: takes --start, --json and --svg only");
    return run_wavefront(s, start, as_json, svg);
  }
  if (!start.empty()) throw InputError("--start: only the wavefront decomposition has a start point");
  if (const auto family = decompose::parse_slice_family(method)) {
    if (angle != 0) throw InputError("--angle: only the boustrophedon decomposition has a sweep direction");
    return run_morse(s, *family, centre, as_json, svg, geojson);
  }
  if (!centre.empty()) throw InputError("--center: only the circular, spike and squarel decompositions have a centre");
  if (method == "brushfire") {
    if (angle != 0) throw InputError("--angle: the brushfire decomposition has no sweep direction");
    return run_brushfire(s, as_json, svg, geojson);
  }
  if (method == "boustrophedon") return run_boustrophedon(s, angle, as_json, svg, geojson);
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
  if (!geojson.empty()) {
    std::vector<std::vector<geometry::Point>> cells;
    for (std::size_t i = 0; i < d.cells().size(); ++i) {
      std::vector<geometry::Point> ring;
      for (auto& p : d.polygon(i)) ring.push_back(geometry::to_double(p));
      cells.push_back(std::move(ring));
    }
    write_cells_geojson(geojson, env, cells, "trapezoidal");
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
  if (!geojson.empty()) std::cout << "wrote " << geojson << "\n";
}

// The robot's radius: --radius, else the scene's robot.radius, else 0 (a point).
double robot_radius(const scene::Scene& s, const std::optional<double>& flag) {
  if (flag) return *flag;
  return s.robot_radius.value_or(0.0);
}

void run_plan(const std::string& path, const std::string& start_s, const std::string& goal_s, const std::optional<double>& radius_flag,
              const std::string& method, bool no_shorten, bool as_json, const std::string& svg, const std::string& geojson) {
  scene::Scene s = scene::load_scene(path);
  const auto& env = s.require_environment();
  if (!start_s.empty()) s.start = parse_point(start_s, "--start");
  if (!goal_s.empty()) s.goal = parse_point(goal_s, "--goal");
  if (!s.start) throw InputError("--start: not given and the scene has no \"start\"");
  if (!s.goal) throw InputError("--goal: not given and the scene has no \"goal\"");
  if (method == "shortest" && no_shorten) throw InputError("--no-shorten: applies to --method trapezoidal only");
  const double r = robot_radius(s, radius_flag);
  const auto plan = decompose::plan_path(env, *s.start, *s.goal, r,
                                         method == "shortest" ? decompose::PlanMethod::Shortest : decompose::PlanMethod::Trapezoidal, !no_shorten);
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    if (r > 0) render::draw_configuration_space(c, geometry::ConfigurationSpace(env, r));
    if (method == "trapezoidal" && r == 0) {
      const decompose::TrapezoidalDecomposition d(env);
      const decompose::TrapezoidalPlanner planner(d);
      decompose::draw_decomposition(c, d, &planner);
    }
    if (plan.found) render::draw_route(c, plan.path, "planned path", "#d93025");
    c.save(svg);
  }
  if (!geojson.empty()) {
    scene::GeoJsonWriter w;
    w.environment(env, {{"kind", "environment"}});
    if (plan.found) w.line(plan.path, {{"kind", "path"}, {"robot_radius", r}, {"length", plan.length}, {"method", method}});
    w.point(*s.start, {{"kind", "start"}}).point(*s.goal, {{"kind", "goal"}}).save(geojson);
  }
  if (as_json) {
    json out{{"found", plan.found}, {"robot_radius", r}, {"method", method}, {"length", plan.length}, {"path", points_json(plan.path)}};
    if (!plan.found) out["reason"] = plan.why_not;
    if (method == "trapezoidal") out["cells_crossed"] = plan.cells_crossed, out["decomposition_cells"] = plan.decomposition_cells;
    print_json(out);
    return;
  }
  const std::string robot = r > 0 ? " for a robot of radius " + geometry::format_number(r) : "";
  if (!plan.found) {
    std::cout << "no path from " << geometry::format_point(*s.start) << " to " << geometry::format_point(*s.goal) << robot << ": " << plan.why_not << "\n";
  } else {
    std::cout << "path from " << geometry::format_point(*s.start) << " to " << geometry::format_point(*s.goal) << robot << ": "
              << plan.path.size() << " points, length " << geometry::format_number(plan.length);
    if (method == "trapezoidal") std::cout << ", through " << plan.cells_crossed << " of " << plan.decomposition_cells << " cells";
    std::cout << " (every segment certified)\n";
  }
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
  if (!geojson.empty()) std::cout << "wrote " << geojson << "\n";
}

struct CoverArgs {
  std::string path, start, angle = "auto", order = "optimised", transit = "shortest", svg, geojson, pattern = "boustrophedon", centre;
  std::optional<double> width, radius;
  bool json = false;
  bool online = false, raster = false;
  std::size_t sensors = 32;
  double range = 0, noise = 0;
  std::uint64_t seed = 1;
  double min_turn_radius = 0;
  double turn_cost = 0.1;
  bool no_merge = false;
};

// cover --online: the robot does not know the map (6.2.4).
void run_cover_online(const CoverArgs& a, const scene::Scene& s, double radius, double angle) {
  if (a.pattern != "boustrophedon" || a.order != "optimised" || a.transit != "shortest" || !a.centre.empty())
    throw InputError("--online: the robot sweeps boustrophedon cells as it finds them; --pattern, --order, --transit and --center do not apply");
  if (a.min_turn_radius > 0) throw InputError("--min-turn-radius: not with --online (the online robot turns in place at critical points)");
  if (!a.geojson.empty()) throw InputError("--online: --geojson is not supported; use --json or --svg");
  const auto& env = s.require_environment();
  coverage::OnlineOptions o;
  o.robot_radius = radius;
  o.width = a.width.value_or(0.0);
  o.angle_deg = angle;
  o.sensors = a.sensors, o.range = a.range, o.noise = a.noise, o.seed = a.seed, o.cycle = !a.raster;
  o.start = s.start;
  const auto rep = coverage::plan_online_coverage(env, o);
  const double tol = coverage::online_tolerance(rep);
  const auto cmp = coverage::compare_with_offline(env, rep, tol);
  coverage::CoverageReport cr;
  cr.path = rep.path, cr.moves = rep.moves, cr.width = rep.width, cr.robot_radius = rep.robot_radius, cr.length = rep.length;
  const auto m = coverage::measure_coverage(env, cr);
  if (!a.svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    render::draw_configuration_space(c, geometry::ConfigurationSpace(env, rep.robot_radius));
    coverage::draw_online_coverage(c, rep, rep.path.size());
    c.save(a.svg);
  }
  if (a.json) {
    json moves = json::array(), nodes = json::array(), edges = json::array();
    for (auto mv : rep.moves) moves.push_back(std::string(coverage::to_string(mv)));
    for (std::size_t i = 0; i < rep.nodes.size(); ++i) {
      const auto& n = rep.nodes[i];
      nodes.push_back({{"id", i}, {"kind", std::string(coverage::to_string(n.kind))}, {"at", {n.at.x(), n.at.y()}},
                       {"sweep_x", n.x}, {"sweep_y", {n.y_low, n.y_high}}, {"sensed_at", n.sensed_at}, {"ports", n.ports}, {"left_ports", n.left}, {"port_spans", n.spans},
                       {"offline_slice", cmp.offline_of.empty() ? -1 : cmp.offline_of[i]}});
    }
    for (const auto& e : rep.edges)
      edges.push_back({{"from", e.from}, {"to", e.to}, {"laps", e.laps}, {"path", {e.path_begin, e.path_end}}});
    print_json({{"online", true}, {"cycle", !a.raster}, {"complete", rep.complete}, {"inconsistency", rep.inconsistency},
                {"width", rep.width}, {"robot_radius", rep.robot_radius}, {"angle", rep.angle},
                {"sensors", rep.sensors}, {"range", rep.range}, {"noise", rep.noise}, {"resolution_rad", rep.resolution},
                {"tolerance", tol}, {"length", rep.length}, {"transit_length", rep.transit_length}, {"laps", rep.laps},
                {"readings", rep.readings}, {"steps", rep.steps}, {"ring_disagreements", rep.ring_disagreements},
                {"reeb_graph", {{"nodes", nodes}, {"edges", edges}, {"sensing_order", rep.sensing_order}}},
                {"offline", {{"isomorphic", cmp.isomorphic}, {"critical_slices", cmp.offline_nodes}, {"cells", cmp.offline_edges},
                             {"max_offset", cmp.max_offset}, {"detail", cmp.detail}}},
                {"metrics", {{"covered_fraction", m.covered_fraction}, {"overlap", m.overlap}, {"efficiency", m.efficiency}, {"samples", m.samples}}},
                {"target_area", rep.target_area}, {"path", points_json(rep.path)}, {"moves", moves}});
    return;
  }
  std::cout << "online coverage (" << (a.raster ? "plain raster scan" : "cycle algorithm") << ") with width " << geometry::format_number(rep.width)
            << ", robot radius " << geometry::format_number(rep.robot_radius) << ", sweep at " << geometry::format_number(rep.angle) << " degrees, "
            << rep.sensors << " sensors (normal resolution " << geometry::format_number(rep.resolution * 180 / 3.141592653589793)
            << " degrees; the ring's minimum missed " << rep.ring_disagreements << " of the reflex critical points the robot's odometry sensed)";
  if (rep.noise > 0) std::cout << ", noise " << geometry::format_number(rep.noise);
  std::cout << "\n";
  std::cout << (rep.complete ? "complete: every critical point has all its edges explored" : "NOT complete: " + rep.inconsistency) << "\n";
  std::cout << "Reeb graph as built: " << rep.nodes.size() << " critical slices, " << rep.edges.size() << " cells; sensed in the order";
  for (auto k : rep.sensing_order) std::cout << " " << k;
  std::cout << "\n";
  for (std::size_t i = 0; i < rep.nodes.size(); ++i) {
    const auto& n = rep.nodes[i];
    std::cout << "  " << i << ": " << coverage::to_string(n.kind) << " at " << geometry::format_point(n.at);
    if (n.kind == coverage::OnlineKind::Slice) std::cout << " (" << n.left << " cells left, " << n.ports.size() - n.left << " right)";
    std::cout << "\n";
  }
  for (const auto& e : rep.edges) std::cout << "  cell " << e.from << " - " << e.to << " (" << e.laps << " laps)\n";
  std::cout << "offline boustrophedon Reeb graph: " << cmp.offline_nodes << " critical slices, " << cmp.offline_edges << " cells: "
            << (cmp.isomorphic ? "isomorphic, critical points within " + geometry::format_number(cmp.max_offset) : "differs: " + cmp.detail) << "\n";
  std::cout << "length " << geometry::format_number(rep.length) << " (transits " << geometry::format_number(rep.transit_length) << "), "
            << rep.laps << " laps; covered " << geometry::format_number(std::round(m.covered_fraction * 10000) / 100) << "% of the configuration space\n";
  if (!a.svg.empty()) std::cout << "wrote " << a.svg << "\n";
}

void run_cover(const CoverArgs& a) {
  scene::Scene s = scene::load_scene(a.path);
  const auto& env = s.require_environment();
  coverage::CoverageOptions o;
  o.robot_radius = robot_radius(s, a.radius);
  o.width = a.width.value_or(0.0);
  if (!a.width && o.robot_radius == 0)
    throw InputError("--width: not given, and without a robot radius (--radius or the scene's robot.radius) it has no default of 2r");
  if (!a.start.empty()) s.start = parse_point(a.start, "--start");
  o.start = s.start;
  if (a.online && a.angle == "auto") return run_cover_online(a, s, o.robot_radius, 0);
  if (a.angle != "auto") {
    std::size_t used = 0;
    double deg = 0;
    try {
      deg = std::stod(a.angle, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != a.angle.size() || !std::isfinite(deg))
      throw InputError("--angle: expected degrees or 'auto', got '" + a.angle + "'");
    o.angle_deg = deg;
  }
  if (a.online) return run_cover_online(a, s, o.robot_radius, *o.angle_deg);
  if (a.raster || a.sensors != 32 || a.range != 0 || a.noise != 0)
    throw InputError("--sensors/--range/--noise/--raster: only with --online");
  o.order = a.order == "dfs" ? coverage::CellOrder::DepthFirst : coverage::CellOrder::Optimised;
  o.transit = a.transit == "decomposition" ? coverage::Transit::Decomposition : coverage::Transit::Shortest;
  o.pattern = *coverage::parse_pattern(a.pattern);
  o.min_turn_radius = a.min_turn_radius;
  o.turn_cost = a.turn_cost;
  o.merge_cells = !a.no_merge;
  if (a.no_merge && o.pattern != coverage::Pattern::Boustrophedon) throw InputError("--no-merge: only the boustrophedon pattern merges cells");
  if (o.pattern != coverage::Pattern::Boustrophedon) {
    if (a.angle != "auto") throw InputError("--angle: only the boustrophedon pattern has a sweep direction");
    if (a.order != "optimised" || a.transit != "shortest")
      throw InputError("--order/--transit: the " + a.pattern + " pattern walks its cells depth-first with shortest transits");
    if (!a.centre.empty()) {
      if (o.pattern == coverage::Pattern::Brushfire) throw InputError("--center: the brushfire pattern grows from the obstacles, it has no centre");
      if (o.pattern == coverage::Pattern::Wavefront) throw InputError("--center: the wavefront pattern grows from --start (the tether's anchor)");
      o.centre = parse_point(a.centre, "--center");
    }
  } else if (!a.centre.empty()) {
    throw InputError("--center: only the spiral, concentric, spike and squarel patterns have a centre");
  }
  const auto rep = coverage::plan_coverage(env, o);
  const auto m = coverage::measure_coverage(env, rep);
  if (!a.svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    if (o.robot_radius > 0) render::draw_configuration_space(c, geometry::ConfigurationSpace(env, o.robot_radius));
    coverage::draw_coverage(c, rep);
    c.save(a.svg);
  }
  if (!a.geojson.empty()) {
    scene::GeoJsonWriter w;
    w.environment(env, {{"kind", "environment"}});
    // One LineString per run of one kind of move, so a GIS can style laps and transits.
    for (std::size_t i = 0; i < rep.moves.size();) {
      std::size_t j = i;
      while (j < rep.moves.size() && rep.moves[j] == rep.moves[i]) ++j;
      const std::string kind(coverage::to_string(rep.moves[i]));
      w.line(std::vector<geometry::Point>(rep.path.begin() + static_cast<long>(i), rep.path.begin() + static_cast<long>(j + 1)),
             {{"kind", "coverage path"}, {"move", kind}, {"first_segment", i}});
      i = j;
    }
    w.save(a.geojson);
  }
  if (a.json) {
    json moves = json::array();
    for (auto mv : rep.moves) moves.push_back(std::string(coverage::to_string(mv)));
    json arcs = json::array();
    for (const auto& arc : rep.arcs)
      arcs.push_back({{"center", {arc.centre.x(), arc.centre.y()}}, {"radius", arc.radius}, {"turn_deg", arc.turn * 180 / std::numbers::pi},
                      {"first", arc.first}, {"last", arc.last}, {"reverse", arc.reverse}});
    json centre = nullptr;
    if (o.pattern != coverage::Pattern::Boustrophedon) {
      const auto b = env.bbox();
      const auto c = o.centre.value_or(geometry::Point((b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2));
      centre = {c.x(), c.y()};
    }
    print_json({{"pattern", a.pattern}, {"center", centre}, {"width", rep.width}, {"robot_radius", rep.robot_radius}, {"angle", rep.angle},
                {"order", o.pattern == coverage::Pattern::Boustrophedon ? a.order : "dfs"}, {"transit", a.transit},
                {"length", rep.length}, {"transit_length", rep.transit_length}, {"laps", rep.laps}, {"turns", rep.turns},
                {"turns_over_15_deg", rep.sharp_turns}, {"rotation_deg", rep.rotation_deg}, {"cells", rep.cells}, {"turned_cells", rep.turned_cells}, {"merged_cells", rep.merged_cells}, {"critical_points", rep.critical_points},
                {"cell_order", rep.cell_order}, {"sweeps", rep.sweeps},
                {"order_optimal", rep.order_optimal}, {"order_lower_bound", rep.order_lower_bound},
                {"metrics", {{"covered_fraction", m.covered_fraction}, {"overlap", m.overlap}, {"efficiency", m.efficiency},
                             {"samples", m.samples}}},
                {"target_area", rep.target_area}, {"unreachable_area", rep.unreachable_area}, {"cspace_error", rep.cspace_error},
                {"rounding_detours", rep.rounding_detours}, {"touch_ups", rep.touch_ups},
                {"min_turn_radius", rep.min_turn_radius}, {"arcs", arcs}, {"shortened_laps", rep.shortened_laps}, {"skipped", rep.skipped}, {"unreached", rep.unreached}, {"cusps", rep.cusps},
                {"bound", {{"value", rep.bound}, {"diameter", rep.diameter}, {"perimeter", rep.perimeter},
                           {"formula", "D^2/w + 4 D (N_cp + N_ob) + 5 P_total - 4 D"}}},
                {"path", points_json(rep.path)}, {"moves", moves}});
    return;
  }
  std::cout << "coverage with width " << geometry::format_number(rep.width);
  if (rep.robot_radius > 0) std::cout << " (robot radius " << geometry::format_number(rep.robot_radius) << ")";
  if (o.pattern == coverage::Pattern::Boustrophedon) std::cout << " at " << geometry::format_number(rep.angle) << " degrees";
  else std::cout << ", " << a.pattern << " pattern";
  std::cout << ": length " << geometry::format_number(rep.length)
            << " (transits " << geometry::format_number(rep.transit_length) << "; bound " << geometry::format_number(rep.bound) << "), "
            << rep.laps << " laps, " << rep.turns << " turns (" << rep.sharp_turns << " over 15 degrees), " << rep.cells << " cells, " << rep.critical_points << " critical points";
  if (rep.touch_ups > 0) std::cout << ", " << rep.touch_ups << " touch-ups";
  if (rep.turned_cells > 0) std::cout << "; " << rep.turned_cells << " of the decomposition's cells swept at " << geometry::format_number(std::fmod(rep.angle + 90, 360)) << " degrees (fewer laps)";
  if (rep.merged_cells > 0) std::cout << "; " << rep.merged_cells << " cells swept on with the cell before them (monotone union, fewer laps)";
  std::cout << "\n";
  if (rep.min_turn_radius > 0)
    std::cout << "drivable with turning radius " << geometry::format_number(rep.min_turn_radius) << ": " << rep.arcs.size()
              << " arcs, every one certified; " << rep.cusps.size() << " changes of direction (reversing); " << rep.shortened_laps << " laps cut back to make room for a turn, " << rep.skipped
              << " laps or wall runs out of reach, " << rep.unreached << " uncovered places out of reach\n";
  std::cout << "covered " << geometry::format_number(std::round(m.covered_fraction * 10000) / 100) << "% of the configuration space ("
            << geometry::format_number(rep.target_area) << " m2), overlap " << geometry::format_number(std::round(m.overlap * 10000) / 100)
            << "%, length / (area / width) = " << geometry::format_number(std::round(m.efficiency * 1000) / 1000);
  if (rep.unreachable_area > 0) std::cout << "; unreachable from the start: " << geometry::format_number(rep.unreachable_area);
  std::cout << "\n";
  if (o.pattern != coverage::Pattern::Boustrophedon)
    std::cout << "cell order: depth-first walk of the adjacency graph (6.2.1)\n";
  else if (a.order == "optimised")
    std::cout << "cell order: " << (rep.order_optimal ? "optimal" : "local search, lower bound " + geometry::format_number(rep.order_lower_bound)) << "\n";
  if (!a.svg.empty()) std::cout << "wrote " << a.svg << "\n";
  if (!a.geojson.empty()) std::cout << "wrote " << a.geojson << "\n";
}

}  // namespace

void add_decompose_commands(CLI::App& app) {
  {
    auto* cmd = app.add_subcommand("decompose", "Exact cell decomposition of the free space, with its adjacency graph");
    set_examples(cmd, {"preimage decompose examples/gallery.json --svg cells.svg", "preimage decompose examples/gallery.json --method boustrophedon --angle 30 --json",
                       "preimage decompose examples/gallery.json --method circular --center 6.1,4.05 --svg circular.svg",
                       "preimage decompose examples/gallery.json --method brushfire --svg brushfire.svg",
                       "preimage decompose examples/gallery.json --method wavefront --start 0.5,7.5 --svg wavefront.svg"});
    auto path = std::make_shared<std::string>();
    auto method = std::make_shared<std::string>("trapezoidal");
    auto angle = std::make_shared<double>(0.0);
    auto json_out = std::make_shared<bool>(false);
    auto svg = std::make_shared<std::string>();
    cmd->add_option("scene", *path, "Scene JSON file")->required();
    auto centre = std::make_shared<std::string>();
    cmd->add_option("--method", *method, "Decomposition method: trapezoidal, boustrophedon, a variable slice of 6.2.3 (circular, spike, squarel), brushfire (distance to the obstacles), or wavefront (shortest path map from --start)")
        ->check(CLI::IsMember({"trapezoidal", "boustrophedon", "circular", "spike", "squarel", "brushfire", "wavefront"}))
        ->capture_default_str();
    cmd->add_option("--angle", *angle, "Sweep direction in degrees, counter-clockwise from +x (boustrophedon)");
    cmd->add_option("--center", *centre, "Centre X,Y of the circles, rays or diamonds (circular, spike, squarel; default: the middle of the bounding box)");
    add_json_flag(cmd, *json_out, "Machine-readable output on stdout");
    auto geojson = std::make_shared<std::string>();
    cmd->add_option("--svg", *svg, "Draw cells, extensions and the adjacency graph to this SVG file");
    cmd->add_option("--geojson", *geojson, "Also write the environment and the cells as GeoJSON polygons");
    auto start = std::make_shared<std::string>();
    cmd->add_option("--start", *start, "Source X,Y of the wave front (wavefront)");
    cmd->callback([=] { run_decompose(*path, *method, *angle, *centre, *start, *json_out, *svg, *geojson); });
  }
  {
    auto* cmd = app.add_subcommand("plan", "Collision-free path for a point or disc robot: shortest, or through the trapezoidal decomposition");
    set_examples(cmd, {"preimage plan examples/gallery.json --start 0.5,7.5 --goal 11.5,0.5 --svg plan.svg", "preimage plan examples/gallery.json --start 0.5,7.5 --goal 11.5,0.5 --radius 0.2 --json"});
    auto path = std::make_shared<std::string>();
    auto start = std::make_shared<std::string>(), goal = std::make_shared<std::string>();
    auto method = std::make_shared<std::string>("shortest");
    auto radius = std::make_shared<std::optional<double>>();
    auto no_shorten = std::make_shared<bool>(false), json_out = std::make_shared<bool>(false);
    auto svg = std::make_shared<std::string>();
    cmd->add_option("scene", *path, "Scene JSON file")->required();
    cmd->add_option("--start", *start, "Start X,Y (default: the scene's \"start\")");
    cmd->add_option("--goal", *goal, "Goal X,Y (default: the scene's \"goal\")");
    cmd->add_option("--radius", *radius, "Robot radius r: the path keeps r from every obstacle (default: the scene's robot.radius, else 0)")
        ->check(number_in(0, geometry::kMaxCoordinate));
    cmd->add_option("--method", *method, "shortest (visibility graph) or trapezoidal (section 6.1)")
        ->check(CLI::IsMember({"shortest", "trapezoidal"}))->capture_default_str();
    cmd->add_flag("--no-shorten", *no_shorten, "Trapezoidal: keep the path through extension midpoints and cell centroids");
    add_json_flag(cmd, *json_out, "Machine-readable output on stdout");
    auto geojson = std::make_shared<std::string>();
    cmd->add_option("--svg", *svg, "Draw the scene, the configuration space and the path to this SVG file");
    cmd->add_option("--geojson", *geojson, "Also write the environment, the path (LineString), start and goal as GeoJSON");
    cmd->callback([=] { run_plan(*path, *start, *goal, *radius, *method, *no_shorten, *json_out, *svg, *geojson); });
  }
  {
    auto* cmd = app.add_subcommand("cover", "Coverage path for a tool of width W (and a robot of radius r) on the boustrophedon decomposition");
    set_examples(cmd, {"preimage cover examples/gallery.json --width 0.5 --svg cover.svg", "preimage cover examples/gallery.json --width 0.5 --radius 0.2 --angle auto --json"});
    auto a = std::make_shared<CoverArgs>();
    cmd->add_option("scene", a->path, "Scene JSON file")->required();
    cmd->add_option("--width", a->width, "Tool width w: laps are w apart (default: 2r)")->check(number_in(0, geometry::kMaxCoordinate, true));
    cmd->add_option("--radius", a->radius, "Robot radius r: the path keeps r from every obstacle (default: the scene's robot.radius, else 0)")
        ->check(number_in(0, geometry::kMaxCoordinate));
    cmd->add_option("--start", a->start, "Start X,Y (default: the scene's \"start\", else where the first sweep begins)");
    cmd->add_option("--angle", a->angle, "Sweep direction in degrees, or 'auto': the best-scored directions, each cell turned to the perpendicular where that needs fewer laps, and the cheaper path (length, --turn-cost per turn, twice over 15 degrees)")->capture_default_str();
    cmd->add_option("--order", a->order, "optimised (sweeps and order by a generalised TSP) or dfs (6.2.1's depth-first walk)")
        ->check(CLI::IsMember({"optimised", "dfs"}))->capture_default_str();
    cmd->add_option("--transit", a->transit, "shortest (visibility graph) or decomposition (trapezoid midpoints and centroids)")
        ->check(CLI::IsMember({"shortest", "decomposition"}))->capture_default_str();
    cmd->add_option("--pattern", a->pattern, "Laps along straight slices (boustrophedon), around --center (6.2.3: spiral, concentric, spike, squarel), at fixed distances from the obstacles (brushfire), or at fixed tether lengths from --start (wavefront)")
        ->check(CLI::IsMember({"boustrophedon", "spiral", "concentric", "spike", "squarel", "brushfire", "wavefront"}))->capture_default_str();
    cmd->add_option("--center", a->centre, "Centre X,Y of the spiral, concentric, spike or squarel pattern (default: the middle of the bounding box)");
    add_json_flag(cmd, a->json, "Machine-readable output on stdout");
    cmd->add_option("--svg", a->svg, "Draw the configuration space and the coverage path to this SVG file");
    cmd->add_option("--geojson", a->geojson, "Also write the environment and the path (a LineString per run of laps, follows or transits) as GeoJSON");
    cmd->add_option("--min-turn-radius", a->min_turn_radius, "A robot that cannot turn in place: every turn an arc of at least this radius, forward only (Dubins curves; laps cut back where a turn needs room)")
        ->check(number_in(0, geometry::kMaxCoordinate));
    cmd->add_option("--turn-cost", a->turn_cost, "Metres of path a turn is worth: runs of small turns round corners become fewer corners where that adds at most this much per turn saved (0: shortest transits)")
        ->check(number_in(0, geometry::kMaxCoordinate))->capture_default_str();
    cmd->add_flag("--no-merge", a->no_merge, "Sweep every boustrophedon cell on its own (by default adjacent cells whose union is monotone in the sweep direction are also tried as one region, and the cheaper path is kept)");
    cmd->add_flag("--online", a->online, "The robot does not know the map: it senses critical points with a range ring and builds the Reeb graph as it covers (6.2.4; --angle auto means 0)");
    cmd->add_option("--sensors", a->sensors, "--online: range sensors on the ring (a multiple of 4)")->capture_default_str();
    cmd->add_option("--range", a->range, "--online: the sensors' maximum range (default 10 r)");
    cmd->add_option("--noise", a->noise, "--online: standard deviation of the Gaussian noise on each reading");
    cmd->add_option("--seed", a->seed, "--online: seed of the noise")->capture_default_str();
    cmd->add_flag("--raster", a->raster, "--online: a plain raster scan instead of the cycle algorithm (misses ceiling critical points, Fig. 6.22)");
    cmd->callback([a] { run_cover(*a); });
  }
}

}  // namespace preimage::cli
