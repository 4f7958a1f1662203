// SPDX-License-Identifier: Apache-2.0
// preimage wallfollow simulate | count | cut-ordering
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/environment.hpp>
#include <preimage/wallfollow/imaps.hpp>
#include <preimage/wallfollow/learn.hpp>
#include <preimage/wallfollow/robot.hpp>

#include <cmath>
#include <iostream>

namespace preimage::cli {
namespace {

using nlohmann::json;
using namespace wallfollow;

struct Setup {
  scene::Scene scene;
  geometry::Point start;
  geometry::Vector heading;
};

// The scene's environment in general position; the robot at --start, else the scene's
// start, else the first vertex; heading --heading degrees (0 = east).
Setup load(const std::string& file, const std::string& start, double heading_deg) {
  Setup s{scene::load_scene(file), {}, {}};
  require_general_position(s.scene.require_environment());
  s.start = !start.empty() ? parse_point(start, "--start") : s.scene.start ? *s.scene.start : s.scene.environment->vertex(0);
  if (!std::isfinite(heading_deg)) throw InputError("--heading: expected degrees");
  const double rad = geometry::radians_from_degrees(heading_deg);
  s.heading = geometry::Vector(std::cos(rad), std::sin(rad));
  return s;
}

std::string describe(const geometry::Environment& env, const Place& p) {
  const std::string at = geometry::format_point(geometry::to_double(p.point));
  switch (p.kind) {
    case Place::Kind::Vertex: return std::string("v").append(std::to_string(p.index + 1)).append(" ").append(at);
    case Place::Kind::Edge:
      return std::string("edge v").append(std::to_string(p.index + 1)).append("-v").append(std::to_string(env.next(p.index) + 1))
          .append(" at ").append(at);
    case Place::Kind::Interior: break;
  }
  return "interior " + at;
}

json imaps_json(const CountingIMaps& k) {
  auto opt = [](const std::optional<long>& v) { return v ? json(*v) : json(nullptr); };
  return {{"k1_edges_traversed", k.k1}, {"k2_combinatorial_distance", k.k2}, {"k3_pebble_contacts", k.k3},
          {"k4_first_contact", opt(k.k4)}, {"k5_winding", k.k5}, {"k6_distance_since_contact", k.k6},
          {"k7_stage", opt(k.k7)}, {"k8_vertex_count", k.k8}};
}

void print_imaps(const CountingIMaps& k) {
  std::cout << "I-maps at stage " << k.stage << ": k1 = " << k.k1 << " edges traversed, k2 = " << k.k2
            << " combinatorial distance, k3 = " << k.k3 << " pebble contacts, k5 = " << k.k5 << " winding, k6 = " << k.k6
            << " since the first contact, k8 = " << k.k8 << (k.k8 ? " vertices" : " (no vertex count yet)") << "\n";
}

// ---------------------------------------------------------------- simulate
void run_simulate(const std::string& file, const std::string& actions, const std::string& start, double heading,
                  const std::string& pebble, bool as_json) {
  const Setup S = load(file, start, heading);
  const auto& env = *S.scene.environment;
  const auto us = parse_actions(actions);
  Simulator sim(env, S.start, S.heading, pebble.empty() ? std::nullopt : std::optional<Place>(Place::of(env, parse_point(pebble, "--pebble"), "--pebble")));
  CountingIMaps k;
  k.start(sim.sense());
  json stages = json::array();
  auto stage_json = [&](const char* u, const Observation& y) {
    stages.push_back({{"action", u ? json(u) : json(nullptr)}, {"touch", to_string(y.touch)}, {"pebble", y.pebble}, {"robot", describe(env, sim.robot())}});
  };
  if (as_json) stage_json(nullptr, sim.sense());
  else std::cout << "stage 1: " << to_string(sim.sense()) << ", robot at " << describe(env, sim.robot()) << std::endl;
  for (std::size_t i = 0; i < us.size(); ++i) {
    Observation y;
    try {
      y = sim.apply(us[i]);
    } catch (const ActionError& e) {
      // Every stage before it was printed (and flushed) already.
      throw InputError(std::string("--actions: action ").append(std::to_string(i + 1)).append(" (").append(to_string(us[i]))
                           .append(") is not applicable: ").append(e.what()));
    }
    k.step(us[i], y);
    if (as_json) stage_json(to_string(us[i]), y);
    else
      std::cout << to_string(us[i]) << " -> stage " << i + 2 << ": " << to_string(y) << ", robot at " << describe(env, sim.robot())
                << std::endl;
  }
  if (as_json) return print_json({{"stages", stages}, {"imaps", imaps_json(k)}});
  print_imaps(k);
}

// ---------------------------------------------------------------- count
void run_count(const std::string& file, const std::string& start, double heading, bool cw, bool as_json) {
  const Setup S = load(file, start, heading);
  Simulator sim(S.scene.environment.value(), S.start, S.heading);
  const CountingIMaps k = count_by_following(sim, cw, 4 * S.scene.environment->num_vertices() + 8);
  if (as_json) return print_json({{"vertices", k.k8}, {"winding", k.k5}, {"actions", sim.actions()}, {"imaps", imaps_json(k)}});
  std::cout << "vertex count " << k.k8 << " (k8, Prop. 2) after " << sim.actions() << " actions; winding number " << k.k5
            << " about the pebble (k5, Prop. 1; " << (cw ? "clockwise" : "counter-clockwise") << " is "
            << (cw ? "negative" : "positive") << ")\n";
  print_imaps(k);
}

// ---------------------------------------------------------------- cut-ordering
void run_cut_ordering(const std::string& file, bool learn, const std::string& sort, const std::string& start, double heading,
                      bool as_json, const std::string& svg) {
  const Setup S = load(file, start, heading);
  const auto& env = *S.scene.environment;
  const TrueCuts T = true_cut_ordering(env);
  std::size_t m = 0;
  for (bool r : T.ordering.reflex) m += r;
  json j = {{"vertices", env.num_vertices()}, {"reflex", m}, {"true", T.ordering.str()}, {"canonical", T.ordering.canonical().str()}};
  const CutOrdering* shown = &T.ordering;
  LearnReport L;
  if (learn) {
    LearnOptions o;
    if (sort == "all-pairs") o.sort = LearnOptions::Sort::AllPairs;
    else if (sort != "quick") throw InputError("--sort: expected quick or all-pairs, got '" + sort + "'");
    Simulator sim(env, S.start, S.heading);
    L = learn_cut_ordering(sim, o);
    shown = &L.ordering;
    const bool same = L.ordering.canonical() == T.ordering.canonical();
    j["learned"] = {{"ordering", L.ordering.str()},
                    {"equals_true_up_to_relabelling", same},
                    {"actions", L.actions},
                    {"actions_by_phase", {L.phase_actions[0], L.phase_actions[1], L.phase_actions[2]}},
                    {"comparisons", L.comparisons},
                    {"action_bound", L.action_bound},
                    {"sort", sort}};
  }
  const auto violations = reflex_chain_violations(*shown);
  j["reflex_chain_violations"] = violations;
  if (!svg.empty()) cut_diagram(*shown, learn ? "cut ordering learned by the robot" : "cut ordering").save(svg);
  if (as_json) return print_json(j);
  std::cout << env.num_vertices() << " vertices, " << m << " reflex; cut ordering " << T.ordering.str() << "\n";
  if (learn) {
    std::cout << "learned (v1 = the pebble's vertex): " << L.ordering.str() << "\n"
              << "equal to the true ordering up to relabelling: " << (j["learned"]["equals_true_up_to_relabelling"] ? "yes" : "NO")
              << "\n"
              << "primitives: " << L.actions << " (" << L.phase_actions[0] << " counting vertices, " << L.phase_actions[1]
              << " locating cut endpoints, " << L.phase_actions[2] << " ordering them with " << L.comparisons
              << " pebble comparisons; bound " << L.action_bound << ")\n";
  }
  std::cout << "reflex-chain rule: " << (violations.empty() ? "satisfied" : violations.front()) << "\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

}  // namespace

void add_wallfollow_commands(CLI::App& app) {
  auto* w = app.add_subcommand("wallfollow", "wall-following robot: simulator, I-maps, cut ordering (wall-following paper)");
  w->require_subcommand(1);
  static std::string file, start, actions, sort = "quick", svg, pebble;
  static double heading = 0;
  static bool as_json = false, cw = false, learn = false;
  auto common = [&](CLI::App* c) {
    c->add_option("scene", file, "scene file (JSON): a simple polygon, no three vertices collinear")->required();
    c->add_option("--start", start, "robot start X,Y (default: the scene's start, else the first vertex)");
    c->add_option("--heading", heading, "robot heading in degrees for INIT from the interior (default 0 = east)");
    c->add_flag("--json", as_json, "JSON output");
  };
  auto* s = w->add_subcommand("simulate", "apply actions; print each observation and the I-maps");
  common(s);
  s->add_option("--actions", actions, "e.g. \"INIT,DROP,LFOLLOW,LFOLLOW,JUMP\"")->required();
  s->add_option("--pebble", pebble, "the pebble lies at X,Y instead of being held");
  s->callback([] { run_simulate(file, actions, start, heading, pebble, as_json); });
  auto* c = w->add_subcommand("count", "vertex count and winding number from the I-maps (section IV)");
  common(c);
  c->add_flag("--clockwise", cw, "follow with LFOLLOW (default RFOLLOW)");
  c->callback([] { run_count(file, start, heading, cw, as_json); });
  auto* o = w->add_subcommand("cut-ordering", "the cut ordering from geometry, or learned by the robot (Strategy 1)");
  common(o);
  o->add_flag("--learn", learn, "learn it through the robot's actions and sensors only");
  o->add_option("--sort", sort, "with --learn: order endpoints on an edge by quick (default) or all-pairs comparisons");
  o->add_option("--svg", svg, "draw the cut diagram (Fig. 4a)");
  o->callback([] { run_cut_ordering(file, learn, sort, start, heading, as_json, svg); });
}

}  // namespace preimage::cli
