// SPDX-License-Identifier: Apache-2.0
// The `preimage` Python module: the library's scenes, visibility, decompositions, plans
// and coverage, with coordinates as NumPy arrays and InputError as preimage.InputError
// (a ValueError) carrying the CLI's one-line message.
#include <preimage/beams/arrangement.hpp>
#include <preimage/beams/region_filter.hpp>
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/coverage/coverage.hpp>
#include <preimage/decompose/planner.hpp>
#include <preimage/decompose/trapezoidal.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/landmarks/order_type.hpp>
#include <preimage/pursuit/cells.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/scene/geojson.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/tracking/dynamic_visibility_game.hpp>
#include <preimage/tracking/replay.hpp>
#include <preimage/tracking/visibility_game.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/environment.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>

namespace py = pybind11;
using namespace preimage;
using geometry::Point;

namespace {

py::array_t<double> to_array(const std::vector<Point>& pts) {
  py::array_t<double> a({static_cast<py::ssize_t>(pts.size()), py::ssize_t{2}});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < pts.size(); ++i) m(i, 0) = pts[i].x(), m(i, 1) = pts[i].y();
  return a;
}

// An (n, 2) array or any sequence of (x, y) pairs, as Shapely's coords give them.
std::vector<Point> to_points(const py::handle& obj, const std::string& what) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 2 || a.shape(1) != 2) throw InputError(what + ": expected an (n, 2) array of x, y coordinates");
  std::vector<Point> pts;
  auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i) pts.emplace_back(r(i, 0), r(i, 1));
  return pts;
}

Point to_point(const py::handle& obj, const std::string& what) {
  auto pts = to_points(py::array_t<double>::ensure(obj).reshape({1, 2}), what);
  return pts.at(0);
}

// A ring as Shapely gives it (closed: last point = first) or open.
geometry::Ring to_ring(const py::handle& obj, const std::string& what) {
  std::vector<Point> r = to_points(obj, what);
  if (r.size() > 3 && r.front() == r.back()) r.pop_back();
  return r;
}

geometry::Environment make_environment(const py::handle& boundary, const std::vector<py::handle>& holes) {
  geometry::Ring outer = to_ring(boundary, "boundary");
  std::vector<geometry::Ring> hs;
  for (std::size_t i = 0; i < holes.size(); ++i) hs.push_back(to_ring(holes[i], "holes[" + std::to_string(i) + "]"));
  return geometry::Environment::make(std::move(outer), std::move(hs), "boundary", "holes");
}

py::list rings_list(const geometry::Environment& env) {
  py::list out;
  for (std::size_t r = 0; r < env.num_rings(); ++r) out.append(to_array(env.ring(r)));
  return out;
}

}  // namespace

PYBIND11_MODULE(preimage, m) {
  m.doc() = "Combinatorial planning and filtering in the plane, computed exactly (the preimage library)";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);

  py::class_<geometry::Environment>(m, "Environment", "A polygon with holes, validated with exact predicates")
      .def(py::init(&make_environment), py::arg("boundary"), py::arg("holes") = std::vector<py::handle>{},
           "boundary: (n, 2) array; holes: list of (m, 2) arrays (rings closed or not)")
      .def_property_readonly("num_vertices", &geometry::Environment::num_vertices)
      .def_property_readonly("num_holes", &geometry::Environment::num_holes)
      .def_property_readonly("rings", &rings_list, "Boundary (counter-clockwise) then holes (clockwise), as (n, 2) arrays")
      .def("to_geojson", [](const geometry::Environment& env) {
        return scene::format_json(scene::GeoJsonWriter().environment(env).json(), scene::JsonLayout::Compact);
      });

  py::class_<scene::Scene>(m, "Scene", "A scene file: environment, start, goal, robot and other slots")
      .def_readonly("name", &scene::Scene::name)
      .def_property_readonly("environment", [](const scene::Scene& s) { return s.require_environment(); })
      .def_property_readonly("start", [](const scene::Scene& s) -> py::object {
        return s.start ? py::object(py::make_tuple(s.start->x(), s.start->y())) : py::none();
      })
      .def_property_readonly("goal", [](const scene::Scene& s) -> py::object {
        return s.goal ? py::object(py::make_tuple(s.goal->x(), s.goal->y())) : py::none();
      })
      .def_property_readonly("robot_radius", [](const scene::Scene& s) { return s.robot_radius.value_or(0.0); });

  m.def("load_scene", [](const std::string& path) { return scene::load_scene(path); }, py::arg("path"), "Read a scene JSON file");
  m.def("import_plan", [](const std::string& path, const std::string& fmt) {
    if (fmt == "houseexpo") return scene::import_houseexpo(path);
    if (fmt == "visilibity") return scene::import_visilibity(path);
    if (fmt == "geojson") return scene::import_geojson(path);
    if (fmt == "wkt") return scene::import_wkt(path);
    throw InputError("format: unknown format '" + fmt + "' (expected houseexpo, visilibity, geojson or wkt)");
  }, py::arg("path"), py::arg("format"), "A floor plan file as a Scene (formats of `preimage import`)");

  m.def("visibility", [](const geometry::Environment& env, const py::handle& q) {
    const geometry::VisibilityIndex index(env);
    const auto v = index.compute(to_point(q, "viewpoint"));
    std::vector<Point> pts;
    std::vector<bool> free;
    for (std::size_t i = 0; i < v.vertices.size(); ++i) {
      pts.push_back(v.vertices[i].approx);
      free.push_back(v.edges[i].kind == geometry::VisibilityEdge::Kind::Free);
    }
    py::dict d;
    d["vertices"] = to_array(pts);
    d["free_edges"] = free;
    d["area"] = v.area();
    d["location"] = std::string(geometry::to_string(v.location.kind));
    return d;
  }, py::arg("environment"), py::arg("viewpoint"), "Exact visibility polygon from a point; edge i runs from vertex i to i+1");

  m.def("decompose", [](const geometry::Environment& env, const std::string& method, double angle) {
    py::list cells;
    if (method == "trapezoidal") {
      if (angle != 0) throw InputError("angle: the trapezoidal decomposition sweeps along x (use method='boustrophedon')");
      const decompose::TrapezoidalDecomposition d(env);
      for (std::size_t i = 0; i < d.cells().size(); ++i) {
        std::vector<Point> ring;
        for (auto& p : d.polygon(i)) ring.push_back(geometry::to_double(p));
        cells.append(to_array(ring));
      }
    } else if (method == "boustrophedon") {
      const decompose::BoustrophedonDecomposition b(env, angle);
      for (std::size_t i = 0; i < b.cells().size(); ++i) cells.append(to_array(b.polygon(i)));
    } else {
      throw InputError("method: expected 'trapezoidal' or 'boustrophedon', got '" + method + "'");
    }
    return cells;
  }, py::arg("environment"), py::arg("method") = "trapezoidal", py::arg("angle") = 0.0, "The cells' polygons");

  m.def("plan", [](const geometry::Environment& env, const py::handle& start, const py::handle& goal, double radius, const std::string& method) {
    if (method != "shortest" && method != "trapezoidal") throw InputError("method: expected 'shortest' or 'trapezoidal', got '" + method + "'");
    const auto p = decompose::plan_path(env, to_point(start, "start"), to_point(goal, "goal"), radius,
                                        method == "shortest" ? decompose::PlanMethod::Shortest : decompose::PlanMethod::Trapezoidal);
    py::dict d;
    d["found"] = p.found;
    d["path"] = to_array(p.path);
    d["length"] = p.length;
    if (!p.found) d["reason"] = p.why_not;
    return d;
  }, py::arg("environment"), py::arg("start"), py::arg("goal"), py::arg("radius") = 0.0, py::arg("method") = "shortest",
     "A collision-free path for a disc robot (every segment certified in the configuration space)");

  m.def("beams_filter", [](const scene::Scene& s, const std::string& word) {
    const auto A = beams::BeamArrangement::build(s);
    beams::RegionFilter F(A);
    const auto symbols = A.alphabet().parse_word(word);
    py::dict d;
    d["consistent"] = true;
    for (std::size_t i = 0; i < symbols.size(); ++i)
      if (!F.step(symbols[i])) {
        d["consistent"] = false;
        d["inconsistent_at"] = i + 1;  // 1-based, as the CLI says it
        break;
      }
    d["regions"] = F.regions();
    d["num_regions"] = A.num_regions();
    return d;
  }, py::arg("scene"), py::arg("word"),
     "The region filter (beams paper, section 3) on an observation word such as \"a b' c\": the possible final regions");

  m.def("order_type", [](const py::handle& points) {
    const auto pts = to_points(points, "points");
    const auto T = landmarks::OrderType::of(pts);
    const std::size_t n = T.size();
    py::array_t<int> chi({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(n)});
    auto c = chi.mutable_unchecked<3>();
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t k = 0; k < n; ++k) c(i, j, k) = T.chi(i, j, k);
    py::list around;
    for (std::uint32_t i = 0; i < n; ++i) {
      auto a = T.around(i);
      around.append(std::vector<std::uint32_t>(a.begin(), a.end()));
    }
    py::dict d;
    d["chirotope"] = chi;
    d["hull"] = T.hull();
    d["around"] = around;
    return d;
  }, py::arg("points"), "Order type of landmarks in general position (landmark paper, section 3): chi[i, j, k], hull, cyclic orders");

  m.def("cut_ordering", [](const geometry::Environment& env) {
    wallfollow::require_general_position(env, "boundary");
    const auto T = wallfollow::true_cut_ordering(env);
    py::dict d;
    d["ordering"] = T.ordering.str();  // v1 = the boundary's first vertex
    d["canonical"] = T.ordering.canonical().str();
    return d;
  }, py::arg("environment"), "The cut ordering (wall-following paper, section 4) of a simple polygon in general position and its canonical form, as `preimage wallfollow cut-ordering` prints them");

  m.def("pursuit_plan", [](const geometry::Environment& env, std::size_t max_pursuers, const py::object& start, std::size_t max_states) {
    if (max_pursuers < 1 || max_pursuers > 8) throw InputError("max_pursuers: expected 1 to 8, got " + std::to_string(max_pursuers));
    const auto cells = pursuit::ConservativeCells::build(env);
    pursuit::SearchOptions o;
    if (!start.is_none()) o.start = to_point(start, "start");
    o.max_states = max_states;
    const auto r = pursuit::least_pursuers(cells, max_pursuers, o);
    py::dict d;
    d["outcome"] = std::string(pursuit::to_string(r.outcome));
    d["pursuers"] = r.pursuers;
    d["states"] = r.states;
    if (r.plan) {
      py::list paths;
      for (const auto& p : r.plan->paths) paths.append(to_array(p));
      d["paths"] = paths;
      d["length"] = r.plan->length;
      // The independent checker of module pursuit, as `preimage pursuit plan` runs it.
      d["cleared"] = pursuit::check_paths(env, r.plan->paths).cleared;
    }
    return d;
  }, py::arg("environment"), py::arg("max_pursuers") = 1, py::arg("start") = py::none(), py::arg("max_states") = 4'000'000,
     "Visibility-based pursuit-evasion (conservative cells, information graph): a plan for the fewest pursuers up to "
     "max_pursuers, one (n, 2) path each, certified in free space and re-checked by the contamination checker");

  m.def("pursuit_check", [](const geometry::Environment& env, const std::vector<py::handle>& paths, std::optional<double> range,
                            std::size_t range_sides) {
    pursuit::Paths P;
    for (std::size_t l = 0; l < paths.size(); ++l) P.push_back(to_points(paths[l], "paths[" + std::to_string(l) + "]"));
    pursuit::CheckOptions o;
    if (range) o.range = *range;
    o.range_sides = range_sides;
    const auto r = pursuit::check_paths(env, P, o);
    py::dict d;
    d["cleared"] = r.cleared;
    d["moments"] = r.moments;
    d["contaminated_area"] = r.contaminated_area;
    d["contaminated_at_end"] = to_array(r.contaminated_at_end);
    d["cleared_at_waypoint"] = r.cleared_at ? py::object(py::int_(r.cleared_at->waypoint)) : py::object(py::none());
    d["recontaminated_at_waypoint"] =
        r.first_recontamination ? py::object(py::int_(r.first_recontamination->waypoint)) : py::object(py::none());
    return d;
  }, py::arg("environment"), py::arg("paths"), py::arg("range") = py::none(), py::arg("range_sides") = 32,
     "The independent contamination checker on pursuer paths (a list of (n, 2) arrays, waypoint i passed together), as "
     "`preimage pursuit check` runs it; with `range`, pursuers that see only within it (an inscribed polygon of range_sides "
     "corners: what it clears, the disc clears)");

  m.def("replay_line", [](const std::string& line, double max_range, double radius, double ahead, const std::string& where) -> py::object {
    const auto scan = tracking::parse_log_line(line, max_range, where);
    if (!scan) return py::none();  // a line that carries no scan (ODOM, PARAM, comments)
    tracking::TrackerParams tp;
    tp.detect.radius = radius;
    tp.risk.delta = radius;
    const auto r = tracking::replay_scan(*scan, tp, ahead);
    py::dict d;
    d["timestamp"] = r.timestamp;
    d["vertices"] = r.vertices;
    d["occlusion_edges"] = r.occlusion;
    d["range_edges"] = r.range;
    d["target_rule"] = r.target_rule;
    d["sde"] = r.has_tree && std::isfinite(r.sde) ? py::object(py::float_(r.sde)) : py::object(py::none());
    d["escape_paths"] = r.escape_paths;
    d["micros"] = r.micros;
    d["points"] = to_array(r.points);
    d["V"] = to_array(r.map.vertices);
    return d;
  }, py::arg("line"), py::arg("max_range") = 50.0, py::arg("radius") = 0.2, py::arg("ahead") = 1.0, py::arg("where") = "line",
     "TRACK's steps on one log line (CARMEN FLASER/ROBOTLASER1 or the text format), as `preimage track replay` does; None for other lines");

  m.def("track_game", [](const geometry::Environment& env, double resolution, double speed_ratio, double range, double separation,
                         double target_radius, const py::object& observer, const py::object& target, double accel,
                         const std::string& observer_step) {
    if (observer_step != "semi-implicit" && observer_step != "constant-acceleration")
      throw InputError("observer_step: expected semi-implicit or constant-acceleration, got \"" + observer_step + "\"");
    tracking::GameParams p;
    p.resolution = resolution;
    p.speed_ratio = speed_ratio;
    p.range = range > 0 ? range : std::numeric_limits<double>::infinity();
    p.separation = separation;
    p.target_radius = target_radius;
    const auto shared = std::make_shared<const tracking::VisibilityGame>(env, p);
    const tracking::VisibilityGame& g = *shared;
    std::optional<tracking::DynamicVisibilityGame> dyn;
    if (accel > 0) {
      tracking::DynamicGameParams dp;
      dp.accel = accel;
      if (observer_step == "constant-acceleration") dp.step = tracking::ObserverStep::ConstantAcceleration;
      dyn.emplace(tracking::DynamicVisibilityGame::base_game(env, p, dp, shared), dp);
    }
    const auto& st = g.stats();
    py::dict d;
    d["points"] = st.points;
    d["states"] = st.states;
    d["seen"] = st.seen;
    d["kept"] = st.winning;
    d["step_time"] = g.step_time();
    d["memory_bytes"] = st.memory_bytes;
    d["seconds"] = st.seconds_visibility + st.seconds_solve;
    if (!target.is_none()) {
      const std::uint32_t t = g.nearest_target(to_point(target, "target"));
      if (t == tracking::VisibilityGame::kNoPoint) throw InputError("target: no grid point of the game within two grid steps where the target's disc fits");
      std::vector<geometry::Point> keepers;
      for (std::uint32_t o : g.keeping_observers(t)) keepers.push_back(g.point(o));
      d["target_point"] = py::make_tuple(g.point(t).x(), g.point(t).y());
      d["keeping_observers"] = to_array(keepers);
      if (!observer.is_none()) {
        const std::uint32_t o = g.nearest(to_point(observer, "observer"));
        if (o == tracking::VisibilityGame::kNoPoint) throw InputError("observer: no grid point of the game within two grid steps");
        const std::uint32_t v = g.escape_steps(o, t);
        d["observer_point"] = py::make_tuple(g.point(o).x(), g.point(o).y());
        d["escape_steps"] = v == tracking::VisibilityGame::kForever ? py::object(py::none()) : py::object(py::int_(v));
        if (dyn) {
          const std::uint32_t w = dyn->escape_steps(o, 0, t);
          d["escape_steps_at_rest"] = w == tracking::VisibilityGame::kForever ? py::object(py::none()) : py::object(py::int_(w));
        }
      }
    }
    if (dyn) {
      const auto& ds = dyn->stats();
      py::dict dd;
      dd["accel_steps"] = dyn->accel_steps();
      dd["step_time"] = dyn->game().step_time();
      dd["velocities"] = ds.velocities;
      dd["states"] = ds.states;
      dd["seen"] = ds.seen;
      dd["kept"] = ds.winning;
      dd["kept_at_rest"] = ds.winning_at_rest;
      d["dynamics"] = dd;
    }
    return d;
  }, py::arg("environment"), py::arg("resolution") = 0.25, py::arg("speed_ratio") = 0.5, py::arg("range") = 8.0,
     py::arg("separation") = 0.35, py::arg("target_radius") = 0.2, py::arg("observer") = py::none(), py::arg("target") = py::none(),
     py::arg("accel") = 0.0, py::arg("observer_step") = "semi-implicit",
     "The visibility game of `preimage track game`: can an observer keep the target in view forever? Counts, and for a "
     "target point the keeping observer points ((n, 2) array); with an observer too, escape_steps (None: kept forever). "
     "accel > 0 (m/s^2 per axis, as `--accel`): also the game with the observer's velocity in the state, under "
     "'dynamics', and escape_steps_at_rest for the observer starting still; observer_step as `--observer-step`");

  m.def("cover", [](const geometry::Environment& env, double radius, std::optional<double> width, std::optional<double> angle,
                    const py::object& start, double min_turn_radius) {
    coverage::CoverageOptions o;
    o.robot_radius = radius;
    o.width = width.value_or(0.0);
    if (!width && radius == 0) throw InputError("width: not given, and without a robot radius it has no default of 2r");
    o.angle_deg = angle;
    if (!start.is_none()) o.start = to_point(start, "start");
    o.min_turn_radius = min_turn_radius;
    const auto rep = coverage::plan_coverage(env, o);
    const auto met = coverage::measure_coverage(env, rep);
    py::list moves;
    for (auto mv : rep.moves) moves.append(std::string(coverage::to_string(mv)));
    py::dict d;
    d["path"] = to_array(rep.path);
    d["moves"] = moves;
    d["length"] = rep.length;
    d["angle"] = rep.angle;
    d["laps"] = rep.laps;
    d["turns"] = rep.turns;
    d["turns_over_15_deg"] = rep.sharp_turns;
    d["turned_cells"] = rep.turned_cells;
    d["merged_cells"] = rep.merged_cells;
    d["rotation_deg"] = rep.rotation_deg;
    d["touch_ups"] = rep.touch_ups;
    d["arcs"] = rep.arcs.size();
    d["shortened_laps"] = rep.shortened_laps;
    d["skipped"] = rep.skipped;
    d["covered_fraction"] = met.covered_fraction;
    d["overlap"] = met.overlap;
    return d;
  }, py::arg("environment"), py::arg("radius") = 0.0, py::arg("width") = py::none(), py::arg("angle") = py::none(),
     py::arg("start") = py::none(), py::arg("min_turn_radius") = 0.0,
     "A boustrophedon coverage path (certified); angle None tries candidates and keeps the shortest; min_turn_radius > 0: "
     "drivable by a robot that cannot turn in place (moves 'turn' are chords of certified arcs)");
}
