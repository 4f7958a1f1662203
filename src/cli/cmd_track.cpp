// SPDX-License-Identifier: Apache-2.0
// preimage track ept | simulate | evaluate | replay  (escape-path tree tracking paper)
#include "common.hpp"
#include "progress.hpp"

#include <preimage/error.hpp>
#include <preimage/tracking/dynamic_visibility_game.hpp>
#include <preimage/tracking/evaluation.hpp>
#include <preimage/tracking/figures.hpp>
#include <preimage/tracking/replay.hpp>
#include <preimage/tracking/simulation.hpp>

#include <preimage/render/svg.hpp>
#include <zlib.h>

#include <algorithm>
#include <filesystem>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

namespace preimage::cli {
namespace {

using nlohmann::json;
using namespace preimage::tracking;

json vec_json(const Vec2& v) { return json::array({v.x, v.y}); }
json point_xy(const geometry::Point& p) { return json::array({p.x(), p.y()}); }


json risk_json(const EdgeRisk& r, const RiskParams& rp, const Point& corner, const Vec2& gradient) {
  return {{"corner", point_xy(corner)}, {"r_o", r.r_o}, {"h", r.h}, {"d", r.d}, {"s", r.s}, {"c", rp.c}, {"m", rp.m},
          {"exit", r.exit == EdgeRisk::Exit::Corner ? "corner" : "perpendicular"}, {"phi", r.phi},
          {"gradient", vec_json(gradient)}};
}

void run_ept(const std::string& file, const std::string& observer, const std::string& target, bool as_json,
             const std::string& svg, double radius, int m) {
  const scene::Scene sc = scene::load_scene(file);
  const auto& env = sc.require_environment();
  geometry::Point o, t;
  if (!observer.empty()) o = parse_point(observer, "--observer");
  else if (sc.tracking && sc.tracking->observer) o = *sc.tracking->observer;
  else throw InputError("--observer is required (the scene has no $.tracking.observer)");
  if (!target.empty()) t = parse_point(target, "--target");
  else if (sc.tracking && sc.tracking->target) t = *sc.tracking->target;
  else throw InputError("--target is required (the scene has no $.tracking.target)");
  const geometry::VisibilityIndex index(env);
  if (geometry::locate(env, o).kind != geometry::Location::Kind::Interior)
    throw InputError("--observer " + observer + ": not in the open free space of " + file);
  const LocalMap map = exact_local_map(index, o);
  const auto inside = try_escape_path_tree(map, t);
  if (!inside) throw InputError("--target " + target + ": not strictly inside the observer's visibility polygon");
  const EscapePathTree& tree = *inside;
  RiskParams rp;
  rp.delta = radius > 0 ? radius : (sc.tracking ? sc.tracking->target_radius : rp.delta);
  rp.m = m;
  const auto risks = escape_risks(map, tree, rp);
  const RiskAverage rec = recursive_average(tree, risks), plain = plain_average(risks);
  if (!svg.empty()) {
    const Vec2 d1 = rec.gradient * -1.0, d2 = plain.gradient * -1.0;
    std::ofstream(svg) << escape_path_tree_figure(&env, map, tree, &d1, &d2);
  }
  if (as_json) {
    json j;
    j["observer"] = point_xy(o);
    j["target"] = point_xy(t);
    json V = json::array();
    for (std::size_t e = 0; e < map.size(); ++e) V.push_back({{"from", point_xy(map.vertices[e])}, {"kind", to_string(map.edges[e])}});
    j["visibility_polygon"] = V;
    json nodes = json::array();
    for (auto& nd : tree.nodes)
      nodes.push_back({{"at", point_xy(nd.at)}, {"parent", nd.parent == kNone ? json(nullptr) : json(nd.parent)}, {"distance", nd.distance}});
    j["nodes"] = nodes;
    json paths = json::array();
    for (std::size_t i = 0; i < tree.paths.size(); ++i) {
      const auto& p = tree.paths[i];
      json pj = {{"edge", p.edge}, {"kind", to_string(p.kind)}, {"node", p.node}, {"sde", p.length},
                 {"escape_point", point_xy(p.escape_point)}, {"polyline", points_json(tree.polyline(i))}};
      for (auto& r : risks)
        if (r.path == i) pj["risk"] = risk_json(r, rp, map.vertices[map.corner[p.edge]], r.gradient);
      paths.push_back(pj);
    }
    j["escape_paths"] = paths;
    j["sde"] = tree.shortest == kNone ? json(nullptr) : json(tree.sde());
    j["phi_recursive"] = rec.phi;
    j["gradient_recursive"] = vec_json(rec.gradient);
    j["phi_plain"] = plain.phi;
    j["gradient_plain"] = vec_json(plain.gradient);
    print_json(j);
    return;
  }
  std::cout << "visibility polygon: " << map.size() << " vertices, " << map.count(EdgeKind::Solid) << " solid edges, "
            << map.count(EdgeKind::Occlusion) << " free (occlusion) edges\n";
  std::cout << "escape-path tree: " << tree.nodes.size() << " nodes (target + " << tree.nodes.size() - 1 << " pivots), "
            << tree.paths.size() << " escape paths\n";
  for (std::size_t i = 0; i < tree.paths.size(); ++i) {
    const auto& p = tree.paths[i];
    std::cout << "  edge " << p.edge << ": SDE " << std::setprecision(6) << p.length << " via";
    for (auto& q : tree.polyline(i)) std::cout << " (" << q.x() << ", " << q.y() << ")";
    std::cout << "\n";
  }
  if (tree.shortest != kNone) std::cout << "SDE(q^t, q^o) = " << tree.sde() << " through edge " << tree.paths[tree.shortest].edge << "\n";
  std::cout << "-grad phi: recursive average (" << -rec.gradient.x << ", " << -rec.gradient.y << "), plain average ("
            << -plain.gradient.x << ", " << -plain.gradient.y << ")\n";
}

struct SimOptions {
  std::string policy = "scripted", strategy = "risk", aggregation = "recursive";
  std::size_t steps = 300;
  std::uint64_t seed = 1;
  double fov = 360, accel = 0, alpha = 0, speed_ratio = 0.5, start_spread = 0, heading_spread = 0;
  std::size_t lookahead_steps = 5, headings = 8;
  double game_resolution = 0.125;
};

SimulationParams sim_params(const SimOptions& o) {
  SimulationParams p;
  p.policy = parse_target_policy(o.policy);
  p.strategy = parse_strategy(o.strategy);
  p.steps = o.steps;
  p.seed = o.seed;
  set_sensor(p, o.fov);
  p.accel = o.accel;
  p.alpha = o.alpha;
  p.speed_ratio = o.speed_ratio;
  p.lookahead_steps = o.lookahead_steps;
  p.lookahead_headings = o.headings;
  p.start_spread = o.start_spread;
  p.heading_spread = o.heading_spread * M_PI / 180;
  if (o.aggregation == "plain") p.tracker.aggregation = Aggregation::Plain;
  else if (o.aggregation != "recursive") throw InputError("--aggregation: expected recursive or plain, got \"" + o.aggregation + "\"");
  return p;
}

// One line of `simulate --log`: the step's state, TRACK's tree and risk terms (world
// frame), the command, and the gradient checked on the exact map at the true positions.
json step_json(const StepRecord& r, const SimulationParams& p, const geometry::VisibilityIndex& index, double radius) {
  const Pose& o = r.observer;
  json j = {{"step", r.step}, {"time", static_cast<double>(r.step) * p.dt},
            {"observer", {o.position.x(), o.position.y(), o.heading}}, {"target", point_xy(r.target)},
            {"visible", r.visible}, {"estimate", point_xy(r.estimate)}, {"tracked", r.track->tracked},
            {"command", {r.command.v, r.command.omega}}, {"velocity", {r.velocity.v, r.velocity.omega}}};
  if (r.track->tracked) {
    const TrackStep& ts = *r.track;
    json nodes = json::array(), paths = json::array(), risks = json::array();
    for (const auto& nd : ts.tree.nodes)
      nodes.push_back({{"at", point_xy(to_world(o, nd.at))}, {"parent", nd.parent == kNone ? json(nullptr) : json(nd.parent)}});
    for (const auto& pa : ts.tree.paths)
      paths.push_back({{"edge", pa.edge}, {"kind", to_string(pa.kind)}, {"node", pa.node}, {"sde", pa.length},
                       {"escape_point", point_xy(to_world(o, pa.escape_point))}});
    RiskParams rp = p.tracker.risk;
    rp.delta = radius;
    for (const auto& rk : ts.risks) {
      json rj = risk_json(rk, rp, to_world(o, ts.map.vertices[ts.map.corner[ts.tree.paths[rk.path].edge]]), to_world(o, rk.gradient));
      rj["path"] = rk.path;
      risks.push_back(rj);
    }
    j["tree"] = {{"nodes", nodes}, {"paths", paths}};
    j["risks"] = risks;
    j["phi_bar"] = ts.risk.phi;
    j["gradient"] = vec_json(to_world(o, ts.risk.gradient));
    j["descent"] = vec_json(to_world(o, ts.control.descent));
    j["pull"] = vec_json(to_world(o, ts.control.pull));
  }
  json exact = nullptr;
  try {
    RiskParams rp = p.tracker.risk;
    rp.delta = radius;
    const RiskCheck c = check_risk_gradient(index, o.position, r.target, rp, p.tracker.aggregation, 1e-6);
    exact = {{"phi_bar", c.risk.phi}, {"gradient", vec_json(c.risk.gradient)}, {"difference", vec_json(c.difference)},
             {"stable", c.stable}};
  } catch (const InputError&) {
    // the target is not inside the exact V (lost), or V is degenerate at the observer
  }
  j["exact"] = exact;
  return j;
}

void run_simulate(const std::string& file, const SimulationParams& params, double game_resolution, const std::string& svg,
                  const std::string& log, bool as_json) {
  const scene::Scene sc = scene::load_scene(file);
  const TrackingScenario s = TrackingScenario::from_scene(sc);
  SimulationParams p = params;
  if (p.strategy == Strategy::Game || p.strategy == Strategy::RiskGame || p.policy == TargetPolicy::Game) {
    Progress solving("simulate: the visibility game");
    GameParams gp = game_params(s, p, game_resolution);
    gp.progress = [&](double f) { solving(f); };
    p.game = std::make_shared<const VisibilityGame>(*s.environment, gp);
  }
  std::ofstream log_out;
  std::optional<geometry::VisibilityIndex> index;
  if (!log.empty()) {
    log_out.open(log);
    if (!log_out) throw InputError("--log " + log + ": cannot open for writing");
    index.emplace(*s.environment);
  }
  Progress progress("simulate");
  p.on_step = [&](const StepRecord& r) {
    if (log_out.is_open()) log_out << step_json(r, p, *index, s.target.radius).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    progress(r.step + 1, p.steps);
  };
  const SimulationResult r = simulate(s, p);
  if (!svg.empty()) std::ofstream(svg) << tracking_run_figure(*s.environment, r, to_string(p.strategy));
  if (as_json) {
    json j = {{"scene", s.name}, {"strategy", to_string(p.strategy)}, {"target_policy", to_string(p.policy)},
              {"steps", r.observer.size() - 1}, {"dt", r.dt},
              {"escape_time", r.escape_time < 0 ? json(nullptr) : json(r.escape_time)},
              {"visible_fraction", r.visible_fraction}, {"observer_path_length", r.observer_length},
              {"target_path_length", r.target_length},
              {"command_variation", {{"v", r.variation_v()}, {"omega", r.variation_omega()}}}};
    json O = json::array(), T = json::array(), C = json::array();
    for (std::size_t i = 0; i < r.observer.size(); ++i) {
      O.push_back({r.observer[i].position.x(), r.observer[i].position.y(), r.observer[i].heading});
      T.push_back({r.target[i].x(), r.target[i].y(), static_cast<bool>(r.visible[i])});
    }
    for (const auto& c : r.commands) C.push_back({c.v, c.omega});
    j["observer"] = O;
    j["target"] = T;
    j["commands"] = C;
    print_json(j);
    return;
  }
  std::cout << s.name << ": strategy " << to_string(p.strategy) << ", target " << to_string(p.policy) << ", "
            << r.observer.size() - 1 << " steps of " << r.dt << " s\n";
  std::cout << "escape time: " << (r.escape_time < 0 ? std::string("never (kept in sight)") : geometry::format_number(r.escape_time) + " s")
            << "\nvisible: " << std::fixed << std::setprecision(1) << 100 * r.visible_fraction << "% of the time\n"
            << "path length: observer " << std::setprecision(2) << r.observer_length << " m, target " << r.target_length << " m\n"
            << "command variation: " << std::setprecision(3) << r.variation_v() << " m/s and " << r.variation_omega()
            << " rad/s per second\n";
}

std::string interval(const Interval& i, const char* f = "%.1f") {
  char b[96];
  const std::string fm = std::string(f) + " [" + f + ", " + f + "]";
  std::snprintf(b, sizeof b, fm.c_str(), i.value, i.low, i.high);
  return b;
}

void run_evaluate(const std::vector<std::string>& files, const EvaluationParams& ep, bool as_json, const std::string& cdf_svg) {
  std::vector<scene::Scene> scenes;
  std::vector<TrackingScenario> scenarios;
  scenes.reserve(files.size());
  for (const auto& f : files) scenes.push_back(scene::load_scene(f));
  for (const auto& sc : scenes) scenarios.push_back(TrackingScenario::from_scene(sc));
  std::vector<CellResult> cells;
  {
    EvaluationParams params = ep;
    std::optional<Progress> solving;  // one status line per scene's game, then the runs'
    std::string solving_for;
    params.game_progress = [&](const std::string& scene, double f) {
      if (!solving || scene != solving_for) {
        solving.reset();
        solving.emplace("evaluate: the visibility game of " + scene);
        solving_for = scene;
      }
      (*solving)(f);
    };
    Progress progress("evaluate");
    cells = evaluate(scenarios, params, [&](std::size_t done, std::size_t total) {
      solving.reset();
      progress(done, total);
    });
  }
  if (!cdf_svg.empty()) {
    std::ofstream out(cdf_svg);
    if (!out) throw InputError("--cdf-svg " + cdf_svg + ": cannot open for writing");
    out << escape_time_cdf_figure(cells, "Escape-time CDF, " + std::to_string(ep.seeds) + " seeds per curve");
  }
  // The cells of one scene x sensor x dynamics x policy, one per strategy.
  auto find = [&](std::size_t from, Strategy s) -> const CellResult* {
    for (std::size_t i = from; i < cells.size() && cells[i].scene == cells[from].scene && cells[i].fov == cells[from].fov &&
                               cells[i].dynamics == cells[from].dynamics && cells[i].policy == cells[from].policy;
         ++i)
      if (cells[i].strategy == s) return &cells[i];
    return nullptr;
  };
  if (as_json) {
    json rows = json::array();
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const CellResult& c = cells[i];
      auto iv = [](const Interval& v) { return json{{"value", v.value}, {"low", v.low}, {"high", v.high}}; };
      json row = {{"scene", c.scene}, {"fov", c.fov}, {"dynamics", c.dynamics}, {"target_policy", to_string(c.policy)},
                  {"strategy", to_string(c.strategy)}, {"runs", c.escape_times.size()}, {"horizon", c.horizon},
                  {"escaped", c.escaped}, {"escaped_fraction", iv(c.escaped_fraction)}, {"mean_escape_time", iv(c.mean_escape)},
                  {"median_escape_time", iv(c.median_escape)},
                  {"command_variation", {{"v", c.variation_v}, {"omega", c.variation_omega}}},
                  {"escape_times", c.escape_times}};
      if (c.game_resolution > 0) {
        std::vector<int> w(c.winnable.begin(), c.winnable.end());
        row["game"] = {{"resolution", c.game_resolution}, {"observer_dynamics", c.observer_dynamics},
                       {"winnable_runs", c.winnable_runs}, {"kept_winnable", c.kept_winnable},
                       {"kept_winnable_fraction", iv(c.kept_winnable_fraction)}, {"game_policy_kept_on_grid", c.grid_kept},
                       {"winnable", w}};
      }
      if (c.strategy == Strategy::Risk) {
        std::size_t first = i;
        while (first > 0 && find(first - 1, c.strategy) == &c) --first;
        if (const CellResult* sde = find(first, Strategy::Sde)) row["minus_sde"] = iv(paired_difference(c, *sde));
      }
      rows.push_back(row);
    }
    json out = {{"seeds", ep.seeds}, {"steps", ep.steps}, {"accel", ep.accel}, {"alpha", ep.alpha},
                {"start_spread", ep.start_spread}, {"heading_spread_degrees", ep.heading_spread * 180 / M_PI},
                {"speed_ratio", ep.speed_ratio}, {"lookahead_steps", ep.lookahead_steps},
                {"lookahead_headings", ep.lookahead_headings}, {"game_resolution", ep.game_resolution},
                {"dynamic_game_resolution", ep.dynamic_game_resolution}, {"cells", rows}};
    print_json(out);
    return;
  }
  const bool game = ep.game_resolution > 0;
  std::cout << "| scene | sensor | dynamics | target |";
  if (game) std::cout << " winnable starts | game policy on its grid: kept |";
  for (Strategy s : ep.strategies)
    std::cout << " " << to_string(s) << ": lost, mean escape (s) [95% CI]" << (game ? "; winnable kept [95% CI]" : "") << " |";
  const bool both = std::find(ep.strategies.begin(), ep.strategies.end(), Strategy::Risk) != ep.strategies.end() &&
                    std::find(ep.strategies.begin(), ep.strategies.end(), Strategy::Sde) != ep.strategies.end();
  if (both) std::cout << " risk - sde (s) [95% CI] |";
  std::cout << " command variation, omega (rad/s per s) |\n|---|---|---|---|";
  for (std::size_t k = 0; k < ep.strategies.size() + (both ? 2 : 1) + (game ? 2 : 0); ++k) std::cout << "---|";
  std::cout << "\n";
  for (std::size_t i = 0; i < cells.size(); i += ep.strategies.size()) {
    const CellResult& c = cells[i];
    std::cout << "| " << c.scene << " | " << c.fov << "° | " << (c.dynamics ? "yes" : "no") << " | " << to_string(c.policy) << " |";
    if (game)
      std::cout << " " << c.winnable_runs << "/" << c.escape_times.size() << (c.observer_dynamics ? " (with dynamics)" : "") << " | "
                << c.grid_kept << "/" << c.winnable_runs << " |";
    std::string tv;
    for (Strategy s : ep.strategies) {
      const CellResult* x = find(i, s);
      std::cout << " " << x->escaped << "/" << x->escape_times.size() << ", " << interval(x->mean_escape);
      if (game) {
        std::cout << "; " << x->kept_winnable << "/" << x->winnable_runs;
        if (x->winnable_runs) std::cout << " " << interval(Interval{100 * x->kept_winnable_fraction.value, 100 * x->kept_winnable_fraction.low, 100 * x->kept_winnable_fraction.high}, "%.0f%%");
      }
      std::cout << " |";
      char b[32];
      std::snprintf(b, sizeof b, "%s%.2f", tv.empty() ? "" : " / ", x->variation_omega);
      tv += b;
    }
    if (both) std::cout << " " << interval(paired_difference(*find(i, Strategy::Risk), *find(i, Strategy::Sde))) << " |";
    std::cout << " " << tv << " |\n";
  }
  std::cout << "(" << ep.seeds << " seeds per cell, " << ep.steps / 10.0 << " s each; a run never lost counts "
            << ep.steps / 10.0 << " s; starts spread " << ep.start_spread << " m and " << ep.heading_spread * 180 / M_PI
            << " deg; dynamics: accel " << ep.accel << " m/s^2, alpha " << ep.alpha << " rad/s^2";
  if (game) {
    std::cout << "; winnable: the start, snapped to the visibility game's " << ep.game_resolution
              << " m grid, is kept forever in the game at speed ratio " << ep.speed_ratio;
    const auto dyn = std::find_if(cells.begin(), cells.end(), [](const CellResult& c) { return c.observer_dynamics; });
    if (dyn != cells.end())
      std::cout << "; with dynamics, in the game with the observer's velocity in the state (constant acceleration "
                << ep.accel << " m/s^2 per axis, at rest at the start) on a " << dyn->game_resolution << " m grid";
  }
  std::cout << ")\n";
}

struct GameOptions {
  double resolution = 0.25, speed_ratio = 0.5, range = 8, separation = -1, target_radius = -1;
  double accel = 0;  // > 0: also the game with the observer's velocity in the state
  std::string observer_step = "semi-implicit";
  std::string observer, target, svg;
  std::size_t jobs = 0;
  bool json = false;
};

std::string two_decimals(double x) {
  char b[64];
  std::snprintf(b, sizeof b, "%.2f", x);
  return b;
}

void run_game(const std::string& file, const GameOptions& o) {
  const scene::Scene sc = scene::load_scene(file);
  const auto& env = sc.require_environment();
  std::optional<Point> obs, tgt;
  if (!o.observer.empty()) obs = parse_point(o.observer, "--observer");
  else if (sc.tracking && sc.tracking->observer) obs = *sc.tracking->observer;
  if (!o.target.empty()) tgt = parse_point(o.target, "--target");
  else if (sc.tracking && sc.tracking->target) tgt = *sc.tracking->target;
  GameParams gp;
  gp.resolution = o.resolution;
  gp.speed_ratio = o.speed_ratio;
  gp.range = o.range > 0 ? o.range : std::numeric_limits<double>::infinity();
  const double radius = sc.tracking ? sc.tracking->target_radius : 0.2;
  gp.target_radius = o.target_radius >= 0 ? o.target_radius : radius;
  gp.separation = o.separation >= 0 ? o.separation : radius + 0.15;  // as the simulator keeps the observer off
  gp.threads = static_cast<unsigned>(o.jobs);
  if (!o.svg.empty() && !tgt) throw InputError("--svg draws the region for one target: give --target (the scene has no $.tracking.target)");
  std::optional<Progress> progress(std::in_place, "game");
  gp.progress = [&](double f) { (*progress)(f); };
  const auto shared = std::make_shared<const VisibilityGame>(env, gp);
  const VisibilityGame& g = *shared;
  std::optional<DynamicVisibilityGame> dyn;
  if (o.accel > 0) {
    DynamicGameParams dp;
    dp.accel = o.accel;
    dp.threads = gp.threads;
    if (o.observer_step == "constant-acceleration") dp.step = ObserverStep::ConstantAcceleration;
    GameParams quiet = gp;  // a second solve (its own step) does not redraw the progress line
    quiet.progress = {};
    dyn.emplace(DynamicVisibilityGame::base_game(env, quiet, dp, shared), dp);
  }
  progress.reset();  // erase the status line before the answer
  auto snap = [&](const Point& p, const char* flag) {
    const bool target = std::string(flag) == "--target";
    const std::uint32_t k = target ? g.nearest_target(p) : g.nearest(p);
    if (k == VisibilityGame::kNoPoint)
      throw InputError(std::string(flag) + " (" + geometry::format_number(p.x()) + ", " + geometry::format_number(p.y()) +
                       "): no grid point of the game within two grid steps" +
                       (target ? " where the target's disc fits" : ""));
    return k;
  };
  std::optional<std::uint32_t> go, gt;
  if (tgt) gt = snap(*tgt, "--target");
  if (obs && tgt) go = snap(*obs, "--observer");
  if (!o.svg.empty()) {
    std::ofstream f(o.svg);
    f << game_region_figure(env, g, *gt, obs ? &*obs : nullptr,
                            "where the observer keeps the target (speed ratio " + geometry::format_number(gp.speed_ratio) + ", " +
                                geometry::format_number(gp.resolution) + " m grid)");
    if (!f) throw InputError("--svg " + o.svg + ": cannot write file");
  }
  const GameStats& st = g.stats();
  const double share = st.seen ? static_cast<double>(st.winning) / static_cast<double>(st.seen) : 0;
  std::string start_text;
  json start = nullptr;
  if (go && gt) {
    const std::uint32_t v = g.escape_steps(*go, *gt);
    start = {{"observer", point_xy(g.point(*go))}, {"target", point_xy(g.point(*gt))}, {"kept", v == VisibilityGame::kForever},
             {"escape_steps", v == VisibilityGame::kForever ? json(nullptr) : json(v)},
             {"escape_time", v == VisibilityGame::kForever ? json(nullptr) : json(v * g.step_time())}};
    start_text = "start, on the grid: observer (" + geometry::format_number(g.point(*go).x()) + ", " +
                 geometry::format_number(g.point(*go).y()) + "), target (" + geometry::format_number(g.point(*gt).x()) + ", " +
                 geometry::format_number(g.point(*gt).y()) + "): " +
                 (v == VisibilityGame::kForever ? std::string("the observer keeps the target forever")
                  : v == 0                      ? std::string("the observer does not see the target")
                                                : "the target escapes within " + std::to_string(v) + " steps (" +
                                                      two_decimals(v * g.step_time()) + " s) against every observer");
  }
  // With dynamics: the start with the observer standing still.
  json dyn_json = nullptr;
  std::string dyn_text;
  if (dyn) {
    const DynamicGameStats& ds = dyn->stats();
    json dstart = nullptr;
    std::string verdict;
    if (go && gt) {
      const std::uint32_t v = dyn->escape_steps(*go, 0, *gt);
      dstart = {{"kept", v == VisibilityGame::kForever}, {"escape_steps", v == VisibilityGame::kForever ? json(nullptr) : json(v)}};
      verdict = v == VisibilityGame::kForever ? "the observer, starting at rest, keeps the target forever"
                : v == 0                      ? "the observer does not see the target"
                                              : "the target escapes within " + std::to_string(v) + " steps (" +
                                                    two_decimals(v * dyn->game().step_time()) + " s) against every observer starting at rest";
    }
    dyn_json = {{"accel", o.accel}, {"observer_step", o.observer_step}, {"step_time", dyn->game().step_time()},
                {"velocity_unit", dyn->velocity_unit()}, {"accel_steps", dyn->accel_steps()}, {"velocities", ds.velocities}, {"states", ds.states},
                {"seen", ds.seen}, {"kept", ds.winning}, {"kept_at_rest", ds.winning_at_rest}, {"longest_escape_steps", ds.levels},
                {"memory_bytes", ds.memory_bytes}, {"seconds", ds.seconds}, {"start", dstart}};
    std::ostringstream t;
    t << std::fixed << std::setprecision(2) << "with dynamics (acceleration " << o.accel << " m/s^2 per axis, " << o.observer_step
      << " steps of " << dyn->game().step_time() << " s, " << ds.velocities << " velocities): " << ds.states << " states solved in "
      << ds.seconds << " s, " << std::setprecision(0) << ds.memory_bytes / 1e6
      << " MB; the observer keeps the target forever from " << ds.winning << " of the " << ds.seen << " states where it sees it ("
      << std::setprecision(1) << (ds.seen ? 100.0 * static_cast<double>(ds.winning) / static_cast<double>(ds.seen) : 0.0) << " %)";
    if (!verdict.empty()) t << "\nstart with dynamics: " << verdict;
    dyn_text = t.str();
  }
  if (o.json) {
    json j = {{"scene", sc.name.empty() ? file : sc.name}, {"dynamics", dyn_json},
              {"resolution", gp.resolution}, {"speed_ratio", gp.speed_ratio},
              {"range", std::isfinite(gp.range) ? json(gp.range) : json(nullptr)}, {"separation", gp.separation},
              {"target_radius", gp.target_radius},
              {"step_time", g.step_time()}, {"target_reach", g.target_reach()}, {"observer_reach", g.observer_reach()},
              {"points", st.points}, {"states", st.states}, {"seen", st.seen}, {"kept", st.winning},
              {"longest_escape_steps", st.levels}, {"memory_bytes", st.memory_bytes},
              {"seconds", {{"sight", st.seconds_visibility}, {"induction", st.seconds_solve}}}, {"start", start}};
    if (gt) {
      json keepers = json::array();
      for (std::uint32_t k : g.keeping_observers(*gt)) keepers.push_back(point_xy(g.point(k)));
      j["keeping_observers"] = keepers;
    }
    print_json(j);
    return;
  }
  std::cout << std::fixed << std::setprecision(2);
  std::cout << (sc.name.empty() ? file : sc.name) << ": visibility game on a " << gp.resolution << " m grid, " << st.points
            << " points, " << st.states << " states (speed ratio " << gp.speed_ratio << ", range "
            << (std::isfinite(gp.range) ? geometry::format_number(gp.range) + " m" : std::string("unlimited")) << ", separation "
            << gp.separation << " m, target radius " << gp.target_radius << " m; one step " << g.step_time() << " s: target " << g.target_reach() << " m, observer "
            << g.observer_reach() << " m)\n";
  std::cout << "solved in " << st.seconds_visibility + st.seconds_solve << " s (sight " << st.seconds_visibility
            << " s, induction " << st.seconds_solve << " s), " << std::setprecision(0) << st.memory_bytes / 1e6
            << " MB; escape times up to " << st.levels << " steps\n";
  std::cout << "the observer keeps the target forever from " << st.winning << " of the " << st.seen
            << " states where it sees it (" << std::setprecision(1) << 100 * share << " %)\n";
  if (!start_text.empty()) std::cout << start_text << "\n";
  if (gt) std::cout << "observer points that keep the target at its point: " << g.keeping_observers(*gt).size() << " of " << st.points << "\n";
  if (!dyn_text.empty()) std::cout << dyn_text << "\n";
}

// zlib says Z_BUF_ERROR ("unexpected end of file") when a gzip stream stops before its end.
void throw_if_truncated(gzFile in, const std::string& file, const std::string& where) {
  int err = 0;
  gzerror(in, &err);
  if (err == Z_BUF_ERROR) throw InputError(file + ": the file is truncated (its compressed stream ends early, " + where + ")");
}

// --scans "0,4,10-20": the scan indices to report, as sorted closed ranges.
std::vector<std::pair<std::size_t, std::size_t>> parse_scan_ranges(const std::string& text) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    const std::string item = text.substr(pos, comma - pos);
    const auto bad = [&] {
      return InputError("--scans: item '" + item + "' (character " + std::to_string(pos + 1) + "): expected a scan index N or a range A-B");
    };
    const std::size_t dash = item.find('-');
    std::size_t a = 0, b = 0, used = 0;
    try {
      if (item.empty() || item.find_first_not_of("0123456789-") != std::string::npos) throw bad();
      a = std::stoull(item.substr(0, dash), &used);
      if (used != (dash == std::string::npos ? item.size() : dash)) throw bad();
      b = a;
      if (dash != std::string::npos) {
        b = std::stoull(item.substr(dash + 1), &used);
        if (used != item.size() - dash - 1 || b < a) throw bad();
      }
    } catch (const std::logic_error&) {  // stoull: no digits, or out of range
      throw bad();
    }
    out.emplace_back(a, b);
    pos = comma + 1;
  }
  std::sort(out.begin(), out.end());
  std::vector<std::pair<std::size_t, std::size_t>> merged;  // overlapping or adjacent ranges as one
  for (auto& r : out)
    if (!merged.empty() && r.first <= merged.back().second + 1) merged.back().second = std::max(merged.back().second, r.second);
    else merged.push_back(r);
  return merged;
}

struct ReplayOptions {
  double max_range = 50, radius = 0.2, ahead = 1.0;
  std::string scans, svg;
};
constexpr std::size_t kMaxReplayPanels = 24;

json replay_json(const ReplayScan& r, std::size_t line_no) {
  json j = {{"scan", r.index}, {"line", line_no}, {"timestamp", r.timestamp}, {"vertices", r.vertices},
            {"solid", r.solid}, {"occlusion", r.occlusion}, {"range", r.range}, {"target_rule", r.target_rule},
            {"micros", r.micros}};
  if (r.has_tree) {
    j["target"] = point_xy(r.target);
    j["sde"] = std::isfinite(r.sde) ? json(r.sde) : json(nullptr);
    j["tree_nodes"] = r.tree_nodes;
    j["escape_paths"] = r.escape_paths;
    j["gradient"] = vec_json(r.gradient);
  }
  // What the counts above are about, in the sensor frame (metres).
  json V = json::array();
  for (std::size_t e = 0; e < r.map.size(); ++e)
    V.push_back({{"from", point_xy(r.map.vertices[e])}, {"kind", tracking::to_string(r.map.edges[e])}});
  json g = {{"points", points_json(r.points)}, {"V", V}};
  if (r.detected) g["detected"] = {{"center", point_xy(*r.detected)}, {"radius", r.detected_radius}};
  if (r.tree) {
    json paths = json::array();
    for (std::size_t i = 0; i < r.tree->paths.size(); ++i)
      paths.push_back({{"edge", r.tree->paths[i].edge}, {"length", r.tree->paths[i].length}, {"polyline", points_json(r.tree->polyline(i))}});
    g["escape_path_tree"] = paths;
  }
  j["geometry"] = std::move(g);
  return j;
}

void run_replay(const std::string& file, bool as_json, const ReplayOptions& o) {
  gzFile in = file == "-" ? gzdopen(0, "rb") : gzopen(file.c_str(), "rb");  // reads plain text too
  if (!in) throw InputError(file + ": cannot open");
  struct Closer { gzFile f; ~Closer() { gzclose(f); } } closer{in};
  TrackerParams tp;
  tp.detect.radius = o.radius;
  tp.risk.delta = o.radius;
  std::vector<std::pair<std::size_t, std::size_t>> chosen;
  if (!o.scans.empty()) chosen = parse_scan_ranges(o.scans);
  else if (!o.svg.empty()) chosen = {{0, 11}};  // a figure of every scan of a log would be unreadable
  if (!o.svg.empty()) {
    std::size_t panels = 0;
    for (auto& [a, b] : chosen) panels += std::min<std::size_t>(b - a, kMaxReplayPanels) + 1;
    if (panels > kMaxReplayPanels)
      throw InputError("--svg draws at most " + std::to_string(kMaxReplayPanels) + " scans; choose them with --scans (e.g. --scans 0-11)");
  }
  const auto selected = [&](std::size_t k) {
    if (chosen.empty()) return true;
    for (auto& [a, b] : chosen)
      if (a <= k && k <= b) return true;
    return false;
  };
  const std::size_t last_wanted = chosen.empty() ? SIZE_MAX : chosen.back().second;
  std::error_code ec;
  const std::size_t file_bytes = file == "-" ? 0 : static_cast<std::size_t>(std::filesystem::file_size(file, ec));
  Progress progress("replay " + file, "KiB read");
  std::vector<std::string> panels;
  std::string line;
  char buf[65536];
  std::size_t line_no = 0, scans = 0, reported = 0;
  bool stopped_early = false;
  double total = 0, worst = 0;
  for (;;) {
    line.clear();
    bool got = false;
    while (char* s = gzgets(in, buf, sizeof buf)) {
      got = true;
      line += s;
      if (!line.empty() && line.back() == '\n') break;
    }
    if (!got) break;
    ++line_no;
    if (file_bytes && !ec) progress(static_cast<std::size_t>(gzoffset(in)) / 1024, file_bytes / 1024);
    // A last line without its newline is where a truncated .gz file stops: zlib then
    // reports that the stream ended early, and the line is a fragment, not a bad line.
    if (line.back() != '\n') throw_if_truncated(in, file, "in line " + std::to_string(line_no));
    const std::string where = file + ":" + std::to_string(line_no);
    const auto scan = parse_log_line(line, o.max_range, where);
    if (!scan) continue;
    const std::size_t index = scans++;
    if (!selected(index)) {
      if (index > last_wanted) {  // past the last chosen scan: the rest is not read
        stopped_early = true;
        break;
      }
      continue;
    }
    ReplayScan r = replay_scan(*scan, tp, o.ahead);
    r.index = index;
    ++reported;
    total += r.micros;
    worst = std::max(worst, r.micros);
    if (!o.svg.empty()) {
      char title[96];
      std::snprintf(title, sizeof title, "scan %zu, t=%.3f s, target %s", r.index, r.timestamp, r.target_rule.c_str());
      panels.push_back(tracking::replay_scan_figure(r, title, 420, panels.empty()));
    }
    if (as_json) {
      std::cout << replay_json(r, line_no).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
    } else {
      std::cout << "scan " << r.index << " t=" << std::fixed << std::setprecision(3) << r.timestamp << ": " << r.vertices
                << " vertices, free edges " << r.occlusion + r.range << " (occlusion " << r.occlusion << ", range "
                << r.range << "), target " << r.target_rule;
      if (r.has_tree)
        std::cout << " at (" << std::setprecision(2) << r.target.x() << ", " << r.target.y() << "), SDE "
                  << (std::isfinite(r.sde) ? std::to_string(r.sde) : std::string("none")) << ", tree " << r.tree_nodes
                  << " nodes / " << r.escape_paths << " escape paths";
      std::cout << ", " << std::setprecision(1) << r.micros << " us\n";
    }
  }
  if (!stopped_early) {  // read to the end: check how the stream ended
    throw_if_truncated(in, file, "after line " + std::to_string(line_no));
    int err = 0;
    const char* msg = gzerror(in, &err);
    if (err != Z_OK && err != Z_STREAM_END) throw InputError(file + ": read error after line " + std::to_string(line_no) + " (" + msg + ")");
  }
  if (!o.scans.empty() && reported == 0)
    throw InputError("--scans " + o.scans + ": the log has " + count_of(scans, "scan") + " (numbered from 0)");
  if (!o.svg.empty()) {
    std::ofstream f(o.svg);
    f << render::panel_grid(panels, 3, "sensor frame (x ahead, y left), metres; scans " + (o.scans.empty() ? std::string("0-11") : o.scans));
    if (!f) throw InputError(o.svg + ": cannot write file");
  }
  if (!as_json)
    std::cout << count_of(reported, "scan") << " replayed; time per scan: mean " << std::setprecision(1)
              << (reported ? total / static_cast<double>(reported) : 0) << " us, max " << worst << " us\n";
}

}  // namespace

void add_track_commands(CLI::App& app) {
  auto* cmd = app.add_subcommand("track", "Real-time target tracking with the escape-path tree (tracking paper)");
  cmd->require_subcommand(1);

  auto* e = cmd->add_subcommand("ept", "The observer's visibility polygon, the escape-path tree and the risk gradient");
  set_examples(e, {"preimage track ept examples/tracking/box.json --svg ept.svg"});
  static std::string e_file, e_obs, e_tgt, e_svg;
  static bool e_json = false;
  static double e_radius = 0;
  static int e_m = 0;
  e->add_option("scene", e_file, "Scene (JSON)")->required();
  e->add_option("--observer", e_obs, "Observer X,Y (default: $.tracking.observer)");
  e->add_option("--target", e_tgt, "Target X,Y (default: $.tracking.target)");
  e->add_option("--radius", e_radius, "Target radius delta (default: $.tracking.target_radius, else 0.2)")
      ->check(number_in(0, 100, true));
  add_count(e, "--m", e_m, 0, 16, "Exponent m of equation (3)");
  add_json_flag(e, e_json, "JSON output");
  e->add_option("--svg", e_svg, "Draw V, the tree and -grad phi to this SVG file");
  e->callback([] { run_ept(e_file, e_obs, e_tgt, e_json, e_svg, e_radius, e_m); });

  const CLI::Validator fov_check(
      [](std::string& text) -> std::string {
        return text == "360" || text == "180" ? std::string() : "expected 180 or 360, got '" + text + "'";
      },
      "180|360");

  auto* s = cmd->add_subcommand("simulate", "A closed-loop run: TRACK (or a baseline) against a moving target");
  set_examples(s, {"preimage track simulate examples/tracking/corridor.json --strategy risk --steps 300 --svg run.svg"});
  static std::string s_file, s_svg, s_log;
  static SimOptions so;
  static bool s_json = false;
  s->add_option("scene", s_file, "Scene with a $.tracking slot (JSON)")->required();
  s->add_option("--target-policy", so.policy, "scripted | random | adversarial | lookahead | game (the visibility game's optimal escape)");
  s->add_option("--strategy", so.strategy,
                "risk (escape risk, eq. 6) | sde (eq. 2) | naive (steer at the target) | game (the visibility game's policy) | "
                "risk-game (risk, overruled where the game's value is higher)");
  add_count(s, "--steps", so.steps, 1, 1000000, "TRACK iterations at 10 Hz");
  add_count(s, "--seed", so.seed, 0, INT64_MAX, "Seed of the range noise and of the random target");
  s->add_option("--fov", so.fov, "Sensor field of view: 360 or 180 degrees")->check(fov_check);
  s->add_option("--aggregation", so.aggregation, "recursive (escape-path tree) | plain average of grad phi");
  s->add_option("--accel", so.accel, "Bound on the observer's linear acceleration, m/s^2 (default: none)")->check(number_in(0, 100, true));
  s->add_option("--alpha", so.alpha, "Bound on the observer's angular acceleration, rad/s^2 (default: none)")->check(number_in(0, 1000, true));
  s->add_option("--speed-ratio", so.speed_ratio, "Adversarial and lookahead target speed / observer top speed")
      ->check(number_in(0, 10, true))->capture_default_str();
  add_count(s, "--lookahead-steps", so.lookahead_steps, 1, 50, "Steps the lookahead target simulates ahead");
  add_count(s, "--headings", so.headings, 1, 360, "Headings the lookahead target tries");
  s->add_option("--start-spread", so.start_spread, "Start observer and target up to this far off the scene's start, m (as evaluate does per seed)")
      ->check(number_in(0, 100));
  s->add_option("--heading-spread", so.heading_spread, "Start heading up to this far off the scene's, degrees")->check(number_in(0, 180));
  add_json_flag(s, s_json, "JSON output with both trajectories and the commands");
  s->add_option("--svg", s_svg, "Draw both paths to this SVG file");
  s->add_option("--log", s_log, "Per step, one JSON line: tree, risk terms, gradient (and its check on the exact map), command");
  s->add_option("--game-resolution", so.game_resolution, "Grid of the visibility game the game strategies and target consult, m")
      ->check(number_in(0, 100, true))->capture_default_str();
  s->callback([] { run_simulate(s_file, sim_params(so), so.game_resolution, s_svg, s_log, s_json); });

  auto* v = cmd->add_subcommand("evaluate", "Strategies x target policies x sensors x dynamics over many seeds");
  set_examples(v, {"preimage track evaluate examples/tracking/box.json --seeds 5 --steps 100 --fov 360 --dynamics off"});
  static std::vector<std::string> v_files, v_policies, v_strategies, v_dynamics{"off", "on"};
  static std::vector<double> v_fovs{360, 180};
  static EvaluationParams ep;
  static bool v_json = false;
  static std::string v_cdf;
  ep.jobs = std::max(1u, std::thread::hardware_concurrency());
  v->add_option("scenes", v_files, "Scenes with a $.tracking slot")->required();
  add_count(v, "--seeds", ep.seeds, 1, 10000, "Runs per cell");
  add_count(v, "--steps", ep.steps, 1, 1000000, "TRACK iterations per run (10 Hz)");
  v->add_option("--fov", v_fovs, "Sensors: 360, 180 or both")->check(fov_check)->delimiter(',')->capture_default_str();
  v->add_option("--dynamics", v_dynamics, "off (kinematic), on (bounded accelerations) or both")
      ->check(CLI::IsMember({"off", "on"}))->delimiter(',')->capture_default_str();
  v->add_option("--accel", ep.accel, "Linear acceleration bound with dynamics, m/s^2")->check(number_in(0, 100, true))->capture_default_str();
  v->add_option("--alpha", ep.alpha, "Angular acceleration bound with dynamics, rad/s^2")->check(number_in(0, 1000, true))->capture_default_str();
  v->add_option("--target-policy", v_policies, "Policies (default: scripted,random,adversarial,lookahead; also game)")->delimiter(',');
  v->add_option("--strategy", v_strategies, "Strategies (default: risk,sde,naive; also game, risk-game)")->delimiter(',');
  v->add_option("--game-resolution", ep.game_resolution,
                "Grid of the visibility game that says which starts are winnable, m (0: no game)")
      ->check(number_in(0, 100))->capture_default_str();
  v->add_option("--dynamic-game-resolution", ep.dynamic_game_resolution,
                "With dynamics, the starts are judged in the game with the observer's velocity in the state, on a grid this coarse "
                "at least, m (0: in the game without dynamics)")
      ->check(number_in(0, 100))->capture_default_str();
  v->add_option("--speed-ratio", ep.speed_ratio, "Adversarial and lookahead target speed / observer top speed")
      ->check(number_in(0, 10, true))->capture_default_str();
  add_count(v, "--lookahead-steps", ep.lookahead_steps, 1, 50, "Steps the lookahead target simulates ahead");
  add_count(v, "--headings", ep.lookahead_headings, 1, 360, "Headings the lookahead target tries");
  static double v_heading_spread = 15;
  v->add_option("--start-spread", ep.start_spread, "Each seed starts observer and target up to this far off the scene's start, m")
      ->check(number_in(0, 100))->capture_default_str();
  v->add_option("--heading-spread", v_heading_spread, "And the heading up to this far off, degrees")
      ->check(number_in(0, 180))->capture_default_str();
  add_count(v, "--jobs", ep.jobs, 1, 256, "Worker threads (default: the cores)");
  add_json_flag(v, v_json, "JSON output: every cell with its escape times");
  v->add_option("--cdf-svg", v_cdf, "Draw the escape-time CDFs to this SVG file");
  v->callback([] {
    ep.heading_spread = v_heading_spread * M_PI / 180;
    ep.fovs = v_fovs;
    ep.dynamics.clear();
    for (const auto& d : v_dynamics) ep.dynamics.push_back(d == "on");
    if (!v_policies.empty()) {
      ep.policies.clear();
      for (const auto& p : v_policies) ep.policies.push_back(parse_target_policy(p));
    }
    if (!v_strategies.empty()) {
      ep.strategies.clear();
      for (const auto& p : v_strategies) ep.strategies.push_back(parse_strategy(p));
    }
    run_evaluate(v_files, ep, v_json, v_cdf);
  });

  auto* gm = cmd->add_subcommand("game", "Ground truth: where an observer can keep the target in view forever (a grid game)");
  set_examples(gm, {"preimage track game examples/tracking/box.json --svg region.svg",
                    "preimage track game examples/tracking/lab.json --resolution 0.5 --speed-ratio 0.8 --json"});
  static std::string g_file;
  static GameOptions go;
  gm->add_option("scene", g_file, "Scene (JSON)")->required();
  gm->add_option("--resolution", go.resolution, "Grid spacing, m")->check(number_in(0, 100, true))->capture_default_str();
  gm->add_option("--speed-ratio", go.speed_ratio, "Target speed / observer top speed (1 m/s)")->check(number_in(0, 10, true))->capture_default_str();
  gm->add_option("--range", go.range, "Sensor range, m (0: unlimited)")->check(number_in(0, 1e6))->capture_default_str();
  gm->add_option("--separation", go.separation, "The target this close to the observer is a loss, m (default: its radius + 0.15)")
      ->check(number_in(0, 100));
  gm->add_option("--target-radius", go.target_radius, "The target's disc keeps this far from obstacles, m (default: $.tracking.target_radius, else 0.2)")
      ->check(number_in(0, 100));
  gm->add_option("--accel", go.accel,
                 "Also solve the game with the observer's velocity in the state: its acceleration per axis, m/s^2 (semi-implicit "
                 "steps: the resolution must make it a whole number of grid steps per step squared, 0.25 m at 0.5 m/s^2 and half speed)")
      ->check(number_in(0, 100));
  gm->add_option("--observer-step", go.observer_step,
                 "With --accel: semi-implicit (the new velocity moves the observer for the whole step: it favours the observer) or "
                 "constant-acceleration (what a robot does; the game's step becomes sqrt(2 resolution / accel))")
      ->check(CLI::IsMember({"semi-implicit", "constant-acceleration"}))->capture_default_str();
  gm->add_option("--observer", go.observer, "Observer X,Y for the start's verdict (default: $.tracking.observer)");
  gm->add_option("--target", go.target, "Target X,Y (default: $.tracking.target)");
  gm->add_option("--svg", go.svg, "Draw, for the target's point, where the observer keeps it");
  add_count(gm, "--jobs", go.jobs, 0, 256, "Threads (0: the cores)");
  add_json_flag(gm, go.json, "JSON output, with the keeping observer points");
  gm->callback([] { run_game(g_file, go); });

  auto* r = cmd->add_subcommand("replay", "TRACK's local map and escape-path tree on a recorded laser log (CARMEN or text)");
  set_examples(r, {"preimage track replay examples/tracking/corridor_scans.txt",
                   "preimage track replay examples/tracking/corridor_scans.txt --scans 0-5 --svg scans.svg",
                   "preimage track replay examples/tracking/corridor_scans.txt --scans 3 --json"});
  static std::string r_file;
  static bool r_json = false;
  static ReplayOptions r_opt;
  r->add_option("log", r_file, "Log file (.gz or plain; - for stdin)")->required();
  r->add_option("--max-range", r_opt.max_range, "Saturation range for FLASER and text logs, m")->check(number_in(0, 1e4, true))->capture_default_str();
  r->add_option("--radius", r_opt.radius, "Target radius for detection, m")->check(number_in(0, 100, true))->capture_default_str();
  r->add_option("--ahead", r_opt.ahead, "Distance of the placed target when none is detected, m")->check(number_in(0, 1e4, true))->capture_default_str();
  r->add_option("--scans", r_opt.scans, "Scans to report, numbered from 0: N, A-B, comma-separated (default: all; 0-11 with --svg)");
  r->add_option("--svg", r_opt.svg, "Draw each reported scan (returns, V, escape-path tree, detected target), at most 24");
  add_json_flag(r, r_json, "One JSON object per scan (JSON Lines) with its geometry in the sensor frame");
  r->callback([] { run_replay(r_file, r_json, r_opt); });
}

}  // namespace preimage::cli
