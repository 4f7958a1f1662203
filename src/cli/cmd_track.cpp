// SPDX-License-Identifier: Apache-2.0
// preimage track ept | simulate | evaluate | replay  (escape-path tree tracking paper)
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/tracking/figures.hpp>
#include <preimage/tracking/replay.hpp>
#include <preimage/tracking/simulation.hpp>

#include <zlib.h>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace preimage::cli {
namespace {

using nlohmann::json;
using namespace preimage::tracking;

json vec_json(const Vec2& v) { return json::array({v.x, v.y}); }

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
  const Vec2 rec = recursive_average(tree, risks), plain = plain_average(risks);
  if (!svg.empty()) {
    const Vec2 d1 = rec * -1.0, d2 = plain * -1.0;
    std::ofstream(svg) << escape_path_tree_figure(&env, map, tree, &d1, &d2);
  }
  if (as_json) {
    json j;
    j["observer"] = points_json({o})[0];
    j["target"] = points_json({t})[0];
    json V = json::array();
    for (std::size_t e = 0; e < map.size(); ++e)
      V.push_back({{"from", points_json({map.vertices[e]})[0]}, {"kind", to_string(map.edges[e])}});
    j["visibility_polygon"] = V;
    json nodes = json::array();
    for (auto& nd : tree.nodes)
      nodes.push_back({{"at", points_json({nd.at})[0]}, {"parent", nd.parent == kNone ? json(nullptr) : json(nd.parent)},
                       {"distance", nd.distance}});
    j["nodes"] = nodes;
    json paths = json::array();
    for (std::size_t i = 0; i < tree.paths.size(); ++i) {
      const auto& p = tree.paths[i];
      json pj = {{"edge", p.edge}, {"kind", to_string(p.kind)}, {"node", p.node}, {"sde", p.length},
                 {"escape_point", points_json({p.escape_point})[0]}, {"polyline", points_json(tree.polyline(i))}};
      for (auto& r : risks)
        if (r.path == i)
          pj["risk"] = {{"phi", r.phi}, {"r_o", r.r_o}, {"h", r.h}, {"gradient", vec_json(r.gradient)},
                        {"exit", r.exit == EdgeRisk::Exit::Corner ? "corner" : "perpendicular"}};
      paths.push_back(pj);
    }
    j["escape_paths"] = paths;
    j["sde"] = tree.shortest == kNone ? json(nullptr) : json(tree.sde());
    j["gradient_recursive"] = vec_json(rec);
    j["gradient_plain"] = vec_json(plain);
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
  std::cout << "-grad phi: recursive average (" << -rec.x << ", " << -rec.y << "), plain average (" << -plain.x << ", "
            << -plain.y << ")\n";
}

SimulationParams sim_params(const std::string& policy, const std::string& strategy, std::size_t steps, std::uint64_t seed,
                            double fov, const std::string& aggregation) {
  SimulationParams p;
  p.policy = parse_target_policy(policy);
  p.strategy = parse_strategy(strategy);
  p.steps = steps;
  p.seed = seed;
  if (fov != 360 && fov != 180) throw InputError("--fov: expected 180 or 360, got " + std::to_string(fov));
  p.laser.fov = fov * M_PI / 180;
  p.laser.beams = fov == 360 ? 360 : 361;
  p.tracker.control.reverse = fov == 360;
  if (aggregation == "plain") p.tracker.aggregation = Aggregation::Plain;
  else if (aggregation != "recursive") throw InputError("--aggregation: expected recursive or plain, got \"" + aggregation + "\"");
  return p;
}

void run_simulate(const std::string& file, const SimulationParams& p, const std::string& svg, bool as_json) {
  const scene::Scene sc = scene::load_scene(file);
  const TrackingScenario s = TrackingScenario::from_scene(sc);
  const SimulationResult r = simulate(s, p);
  if (!svg.empty()) std::ofstream(svg) << tracking_run_figure(*s.environment, r, to_string(p.strategy));
  if (as_json) {
    json j = {{"scene", s.name}, {"strategy", to_string(p.strategy)}, {"target_policy", to_string(p.policy)},
              {"steps", r.observer.size() - 1}, {"dt", r.dt},
              {"escape_time", r.escape_time < 0 ? json(nullptr) : json(r.escape_time)},
              {"visible_fraction", r.visible_fraction}, {"observer_path_length", r.observer_length},
              {"target_path_length", r.target_length}};
    json O = json::array(), T = json::array();
    for (std::size_t i = 0; i < r.observer.size(); ++i) {
      O.push_back({r.observer[i].position.x(), r.observer[i].position.y(), r.observer[i].heading});
      T.push_back({r.target[i].x(), r.target[i].y(), static_cast<bool>(r.visible[i])});
    }
    j["observer"] = O;
    j["target"] = T;
    print_json(j);
    return;
  }
  std::cout << s.name << ": strategy " << to_string(p.strategy) << ", target " << to_string(p.policy) << ", "
            << r.observer.size() - 1 << " steps of " << r.dt << " s\n";
  std::cout << "escape time: " << (r.escape_time < 0 ? std::string("never (kept in sight)") : std::to_string(r.escape_time) + " s")
            << "\nvisible: " << std::fixed << std::setprecision(1) << 100 * r.visible_fraction << "% of the time\n"
            << "path length: observer " << std::setprecision(2) << r.observer_length << " m, target " << r.target_length << " m\n";
}

void run_evaluate(const std::vector<std::string>& files, std::size_t seeds, std::size_t steps, double fov, bool as_json) {
  json rows = json::array();
  if (!as_json)
    std::cout << "| scene | target | strategy | runs | escaped | mean escape time (s) | visible | observer path (m) |\n"
                 "|---|---|---|---|---|---|---|---|\n";
  for (const auto& file : files) {
    const scene::Scene sc = scene::load_scene(file);
    const TrackingScenario s = TrackingScenario::from_scene(sc);
    for (const char* policy : {"scripted", "random", "adversarial"}) {
      for (const char* strategy : {"risk", "sde", "naive"}) {
        double esc_sum = 0, vis_sum = 0, len_sum = 0;
        std::size_t escaped = 0;
        for (std::size_t seed = 1; seed <= seeds; ++seed) {
          const SimulationResult r = simulate(s, sim_params(policy, strategy, steps, seed, fov, "recursive"));
          const double horizon = static_cast<double>(r.observer.size() - 1) * r.dt;
          escaped += r.escape_time >= 0;
          esc_sum += r.escape_time >= 0 ? r.escape_time : horizon;
          vis_sum += r.visible_fraction;
          len_sum += r.observer_length;
        }
        const double k = static_cast<double>(seeds);
        if (as_json) {
          rows.push_back({{"scene", s.name}, {"target_policy", policy}, {"strategy", strategy}, {"runs", seeds},
                          {"escaped", escaped}, {"mean_escape_time", esc_sum / k}, {"visible_fraction", vis_sum / k},
                          {"observer_path_length", len_sum / k}});
        } else {
          std::cout << "| " << s.name << " | " << policy << " | " << strategy << " | " << seeds << " | " << escaped << " | "
                    << std::fixed << std::setprecision(1) << esc_sum / k << " | " << std::setprecision(1)
                    << 100 * vis_sum / k << "% | " << len_sum / k << " |\n" << std::flush;
        }
      }
    }
  }
  if (as_json) print_json(rows);
  else std::cout << "(escape time counts the whole run, " << steps / 10.0 << " s, when the target was never lost)\n";
}

void run_replay(const std::string& file, bool as_json, double max_range, double radius, double ahead) {
  gzFile in = file == "-" ? gzdopen(0, "rb") : gzopen(file.c_str(), "rb");  // reads plain text too
  if (!in) throw InputError(file + ": cannot open");
  struct Closer { gzFile f; ~Closer() { gzclose(f); } } closer{in};
  TrackerParams tp;
  tp.detect.radius = radius;
  tp.risk.delta = radius;
  std::string line;
  char buf[65536];
  std::size_t line_no = 0, scans = 0;
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
    const std::string where = file + ":" + std::to_string(line_no);
    const auto scan = parse_log_line(line, max_range, where);
    if (!scan) continue;
    ReplayScan r = replay_scan(*scan, tp, ahead);
    r.index = scans++;
    total += r.micros;
    worst = std::max(worst, r.micros);
    if (as_json) {
      json j = {{"scan", r.index}, {"line", line_no}, {"timestamp", r.timestamp}, {"vertices", r.vertices},
                {"solid", r.solid}, {"occlusion", r.occlusion}, {"range", r.range}, {"target_rule", r.target_rule},
                {"micros", r.micros}};
      if (r.has_tree) {
        j["target"] = {r.target.x(), r.target.y()};
        j["sde"] = std::isfinite(r.sde) ? json(r.sde) : json(nullptr);
        j["tree_nodes"] = r.tree_nodes;
        j["escape_paths"] = r.escape_paths;
        j["gradient"] = vec_json(r.gradient);
      }
      std::cout << j.dump() << "\n";
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
  int err = 0;
  gzerror(in, &err);
  if (err != Z_OK && err != Z_STREAM_END) throw InputError(file + ": read error after line " + std::to_string(line_no));
  if (!as_json)
    std::cout << scans << " scans replayed; time per scan: mean " << std::setprecision(1) << (scans ? total / scans : 0)
              << " us, max " << worst << " us\n";
}

}  // namespace

void add_track_commands(CLI::App& app) {
  auto* cmd = app.add_subcommand("track", "real-time target tracking with the escape-path tree (tracking paper)");
  cmd->require_subcommand(1);

  auto* e = cmd->add_subcommand("ept", "the observer's visibility polygon, the escape-path tree and the risk gradient");
  static std::string e_file, e_obs, e_tgt, e_svg;
  static bool e_json = false;
  static double e_radius = 0;
  static int e_m = 0;
  e->add_option("scene", e_file, "scene (JSON)")->required();
  e->add_option("--observer", e_obs, "observer X,Y (default: $.tracking.observer)");
  e->add_option("--target", e_tgt, "target X,Y (default: $.tracking.target)");
  e->add_option("--radius", e_radius, "target radius delta (default: $.tracking.target_radius, else 0.2)");
  e->add_option("--m", e_m, "exponent m of equation (3)")->check(CLI::NonNegativeNumber);
  e->add_flag("--json", e_json, "JSON output");
  e->add_option("--svg", e_svg, "draw V, the tree and -grad phi to this SVG file");
  e->callback([] { run_ept(e_file, e_obs, e_tgt, e_json, e_svg, e_radius, e_m); });

  auto* s = cmd->add_subcommand("simulate", "a closed-loop run: TRACK (or a baseline) against a moving target");
  static std::string s_file, s_policy = "scripted", s_strategy = "risk", s_svg, s_agg = "recursive";
  static std::size_t s_steps = 300;
  static std::uint64_t s_seed = 1;
  static double s_fov = 360;
  static bool s_json = false;
  s->add_option("scene", s_file, "scene with a $.tracking slot (JSON)")->required();
  s->add_option("--target-policy", s_policy, "scripted | random | adversarial");
  s->add_option("--strategy", s_strategy, "risk (escape risk, eq. 6) | sde (eq. 2) | naive (steer at the target)");
  s->add_option("--steps", s_steps, "TRACK iterations at 10 Hz");
  s->add_option("--seed", s_seed, "seed of the range noise and of the random target");
  s->add_option("--fov", s_fov, "sensor field of view: 360 or 180 degrees");
  s->add_option("--aggregation", s_agg, "recursive (escape-path tree) | plain average of grad phi");
  s->add_flag("--json", s_json, "JSON output with both trajectories");
  s->add_option("--svg", s_svg, "draw both paths to this SVG file");
  s->callback([] { run_simulate(s_file, sim_params(s_policy, s_strategy, s_steps, s_seed, s_fov, s_agg), s_svg, s_json); });

  auto* v = cmd->add_subcommand("evaluate", "three strategies x three target policies over many seeds, as a table");
  static std::vector<std::string> v_files;
  static std::size_t v_seeds = 10, v_steps = 300;
  static double v_fov = 360;
  static bool v_json = false;
  v->add_option("scenes", v_files, "scenes with a $.tracking slot")->required();
  v->add_option("--seeds", v_seeds, "runs per cell");
  v->add_option("--steps", v_steps, "TRACK iterations per run");
  v->add_option("--fov", v_fov, "360 or 180");
  v->add_flag("--json", v_json, "JSON output");
  v->callback([] { run_evaluate(v_files, v_seeds, v_steps, v_fov, v_json); });

  auto* r = cmd->add_subcommand("replay", "TRACK's local map and escape-path tree on a recorded laser log (CARMEN or text)");
  static std::string r_file;
  static bool r_json = false;
  static double r_max = 50, r_radius = 0.2, r_ahead = 1.0;
  r->add_option("log", r_file, "log file (.gz or plain; - for stdin)")->required();
  r->add_option("--max-range", r_max, "saturation range for FLASER and text logs (default 50 m)");
  r->add_option("--radius", r_radius, "target radius for detection");
  r->add_option("--ahead", r_ahead, "distance of the placed target when none is detected");
  r->add_flag("--json", r_json, "one JSON object per scan (JSON Lines)");
  r->callback([] { run_replay(r_file, r_json, r_max, r_radius, r_ahead); });
}

}  // namespace preimage::cli
