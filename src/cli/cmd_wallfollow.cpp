// SPDX-License-Identifier: Apache-2.0
// preimage wallfollow simulate | count | cut-ordering | pursue | completeness
#include "common.hpp"
#include "progress.hpp"
#include "wallfollow_pursuit_run.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/environment.hpp>
#include <preimage/wallfollow/imaps.hpp>
#include <preimage/wallfollow/learn.hpp>
#include <preimage/wallfollow/pursuit.hpp>
#include <preimage/wallfollow/robot.hpp>
#include <preimage/wallfollow/sensors.hpp>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

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

// ---------------------------------------------------------------- pursue
struct PursueFlags {
  std::string file, start, sensor = "gap", svg;
  double heading = 0;
  std::size_t max_states = 20'000'000, frames = 5;
  bool no_check = false, as_json = false;
};

void run_pursue(const PursueFlags& F) {
  const PursuitSensor sensor = parse_sensor(F.sensor);
  const Setup S = load(F.file, F.start, F.heading);
  const auto& env = *S.scene.environment;
  const PursuitRun run = run_pursuit(env, S.start, S.heading, sensor, F.max_states, !F.no_check, F.svg.empty() ? 0 : F.frames);
  const PursuitReport& rep = run.rep;
  const std::size_t v1 = run.v1;
  const auto& check = run.check;
  const OrderingMap m(rep.learned.ordering);
  std::vector<std::string> actions;
  for (Action u : rep.plan) actions.push_back(to_string(u));
  const bool complete = sensor != PursuitSensor::None;
  const char* outcome = rep.outcome == PursuitReport::Outcome::Plan ? "plan" : rep.outcome == PursuitReport::Outcome::NoPlan ? "no plan" : "budget";
  if (!F.svg.empty()) {
    std::ofstream out(F.svg);
    if (!out) throw InputError("--svg: cannot write " + F.svg);
    out << pursuit_figure(env, run);
  }
  if (F.as_json) {
    json j = {{"strategy", strategy_name(sensor)}, {"sensor", to_string(sensor)}, {"outcome", outcome},
              {"plan", actions}, {"primitives", rep.plan.size()}, {"istates", rep.states},
              {"learn_actions", rep.learned.actions}, {"prepare_actions", rep.prepare_actions},
              {"bitangents", rep.bitangents}, {"start", m.name(rep.start.at)}, {"labels", rep.labels_along},
              {"complete", complete}, {"robot_v1_is_vertex", env.input_index(v1)}};
    if (!run.path.empty()) {
      // The executed path as `pursuit check --path` reads it: exact rational strings (cut
      // endpoints are constructed points), and the same rounded to doubles.
      json exact = json::array(), rounded = json::array();
      for (const auto& p : run.path) {
        exact.push_back({geometry::exact_string(p.x()), geometry::exact_string(p.y())});
        rounded.push_back(point_json(p));
      }
      j["paths"] = json::array({exact});
      j["paths_rounded"] = json::array({rounded});
    }
    if (check) j["check"] = {{"cleared", check->cleared}, {"moments", check->moments}};
    return print_json(j);
  }
  std::cout << strategy_name(sensor) << ": cut ordering learned in " << rep.learned.actions << " actions, then "
            << rep.prepare_actions << " more ("
            << (sensor == PursuitSensor::Gap || sensor == PursuitSensor::Bitangent ? "fetching the pebble, executing every motion once"
                : sensor == PursuitSensor::Pebble ? "fetching the pebble, Strategy 4 with it" : "fetching the pebble")
            << ")";
  if (sensor != PursuitSensor::Gap)
    std::cout << "; " << rep.bitangents
              << (sensor == PursuitSensor::Bitangent ? " bitangents sensed" : sensor == PursuitSensor::Pebble ? " bitangents learned" : " candidates taken as bitangents");
  std::cout << "\n";
  if (rep.outcome == PursuitReport::Outcome::Plan) {
    std::cout << "plan of " << rep.plan.size() << " primitives from " << m.name(rep.start.at) << ":";
    for (auto& a : actions) std::cout << " " << a;
    std::cout << " (" << rep.states << " I-states explored)\n";
    std::cout << "labels (robot's names: its v1 is scene vertex " << env.input_index(v1) << "):";
    for (std::size_t k = 0; k < rep.labels_along.size(); ++k) std::cout << (k ? " -> " : " ") << rep.labels_along[k];
    std::cout << "\n";
    if (check)
      std::cout << "independent check of the executed path: " << (check->cleared ? "cleared" : "NOT cleared") << " (" << check->moments
                << " moments sampled)\n";
  } else if (rep.outcome == PursuitReport::Outcome::NoPlan) {
    if (complete)
      std::cout << "no plan exists for this robot (complete search, " << rep.states << " I-states explored)\n";
    else
      std::cout << "Strategy 6 finds no plan (" << rep.states << " I-states explored, it is sound, not known to be complete)\n";
  } else {
    std::cout << "search stopped after " << rep.states << " I-states (--max-states " << F.max_states << ")\n";
  }
  if (!F.svg.empty()) std::cout << "wrote " << F.svg << "\n";
}

// ---------------------------------------------------------------- completeness
struct CompletenessFlags {
  std::size_t polygons = 1000, min_vertices = 6, max_vertices = 40, max_states = 5'000'000;
  double time_limit = 0;  // seconds per polygon; 0: none
  std::uint64_t seed = 1;
  std::string save;
  bool as_json = false, check_all = false;
};

// --save DIR exists (created if missing) and takes a file, before any polygon is tried.
void prepare_save_dir(const std::string& dir) {
  try {
    make_dirs(dir);
  } catch (const InputError& e) {
    throw InputError(std::string("--save: ") + e.what());
  }
  if (!std::filesystem::is_directory(dir)) throw InputError("--save: " + dir + ": not a directory");
  const std::string probe = dir + "/.preimage-save-probe";
  if (!std::ofstream(probe)) throw InputError("--save: " + dir + ": cannot write a file there (" + std::strerror(errno) + ")");
  std::error_code ec;
  std::filesystem::remove(probe, ec);
}

void run_completeness(const CompletenessFlags& F) {
  if (F.min_vertices > F.max_vertices) throw InputError("--min-vertices: more than --max-vertices");
  if (!F.save.empty()) prepare_save_dir(F.save);
  struct Tally {
    std::size_t tried = 0, rejected = 0, gap = 0, none = 0, both = 0, budget = 0, none_checked = 0, none_wrong = 0,
                gap_checked = 0, gap_wrong = 0, free_missing = 0, free_budget = 0;
  } t;
  json counter = json::array(), over = json::array();
  auto plan_clears = [](const geometry::Environment& env, Simulator& sim, const PursuitReport& rep) {
    const std::size_t from = sim.path().size() - 1;
    execute(sim, rep.plan);
    std::vector<geometry::ExactPoint> path(sim.path().begin() + static_cast<long>(from), sim.path().end());
    return pursuit::check_exact_paths(env, pursuit::ExactPaths{path}).cleared;
  };
  // A status line while a terminal watches (redrawn between the robot's actions too, so a
  // large polygon shows it is alive), and a running tally on stderr every 100 polygons, so
  // that a long run can be read (or stopped) part way.
  std::optional<Progress> progress(std::in_place, "wallfollow completeness", "polygons");
  auto report_progress = [&] {
    if (t.tried % 100 != 0) return;
    std::ostringstream o;
    o << "completeness: " << t.tried << "/" << F.polygons << " tried, " << t.rejected << " rejected, " << t.budget
      << " over budget; Strategy 2 solves " << t.gap << ", Strategy 6 " << t.none << "; Strategy 6 plans not clearing "
      << t.none_wrong << "/" << t.none_checked << "; free pursuer missing " << t.free_missing << "; solved by 2 only:";
    for (auto& c : counter) o << " " << c["seed"].get<std::uint64_t>();
    progress->note(o.str());
  };
  for (std::size_t k = 0; k < F.polygons; ++k, report_progress()) {
    (*progress)(k, F.polygons);
    const std::uint64_t seed = F.seed + k;
    const std::size_t n = F.min_vertices + static_cast<std::size_t>(seed % (F.max_vertices - F.min_vertices + 1));
    ++t.tried;
    // The time limit counts from here: the general-position checks below are not
    // interrupted (n^2 log n), everything the robot does after them is.
    Deadline deadline;
    if (F.time_limit > 0)
      deadline = std::chrono::steady_clock::now() +
                 std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(F.time_limit));
    auto env = geometry::Environment::make(geometry::generators::random_simple_polygon(n, seed, 100.0), {});
    Simulator s2(env, env.vertex(0), geometry::Vector(1, 0));
    try {
      require_general_position(env);
      true_cut_ordering(env);
      s2.enable(sensors_of(PursuitSensor::Gap));  // rejects bitangents ending at cut endpoints
    } catch (const InputError&) {
      ++t.rejected;
      continue;
    }
    PursuitOptions o;
    o.max_states = F.max_states;
    o.deadline = deadline;
    o.on_action = [&] { (*progress)(k, F.polygons); };
    auto over_budget = [&](const char* strategy, const PursuitReport& r) {
      ++t.budget;
      over.push_back({{"seed", seed}, {"vertices", n}, {"strategy", strategy}, {"limit", r.out_of_time ? "time" : "states"}});
    };
    o.sensor = PursuitSensor::Gap;
    const auto r2 = pursue(s2, o);
    if (r2.outcome == PursuitReport::Outcome::Budget) {
      over_budget("2", r2);
      continue;
    }
    Simulator s6(env, env.vertex(0), geometry::Vector(1, 0));
    o.sensor = PursuitSensor::None;
    const auto r6 = pursue(s6, o);
    if (r6.outcome == PursuitReport::Outcome::Budget) {
      over_budget("6", r6);
      continue;
    }
    const bool p2 = r2.outcome == PursuitReport::Outcome::Plan, p6 = r6.outcome == PursuitReport::Outcome::Plan;
    t.gap += p2, t.none += p6, t.both += p2 && p6;
    if (p6) {
      ++t.none_checked;
      if (!plan_clears(env, s6, r6)) ++t.none_wrong;
    }
    if (p2 && F.check_all) {
      ++t.gap_checked;
      if (!plan_clears(env, s2, r2)) ++t.gap_wrong;
    }
    if (p2) {
      const auto free = pursuit::search(pursuit::ConservativeCells::build(env), 1).outcome;
      t.free_missing += free == pursuit::SearchResult::Outcome::NoPlan;
      t.free_budget += free == pursuit::SearchResult::Outcome::Budget;
    }
    if (p2 && !p6) {
      counter.push_back({{"seed", seed}, {"vertices", n}, {"gap_istates", r2.states}, {"none_istates", r6.states}});
      if (!F.save.empty()) {
        std::ofstream f(F.save + "/wallfollow_s6_counterexample_" + std::to_string(seed) + ".json");
        if (!f) throw InputError("--save: cannot write into " + F.save);
        f << std::setprecision(17) << "{\"name\": \"Strategy 6 counter-example, seed " << seed << "\", \"environment\": {\"boundary\": [";
        for (std::size_t v = 0; v < env.num_vertices(); ++v)
          f << (v ? ", " : "") << "[" << env.vertex(v).x() << ", " << env.vertex(v).y() << "]";
        f << "]}}\n";
      }
    }
  }
  progress.reset();  // erases the status line before the tally
  const std::size_t used = t.tried - t.rejected - t.budget;
  if (F.as_json)
    return print_json({{"polygons", t.tried}, {"rejected_general_position", t.rejected}, {"budget", t.budget}, {"over_budget", over},
                       {"compared", used}, {"strategy2_solves", t.gap}, {"strategy6_solves", t.none}, {"both", t.both},
                       {"strategy6_plans_checked", t.none_checked}, {"strategy6_plans_not_clearing", t.none_wrong},
                       {"strategy2_plans_checked", t.gap_checked}, {"strategy2_plans_not_clearing", t.gap_wrong},
                       {"free_pursuer_missing", t.free_missing}, {"free_pursuer_budget", t.free_budget},
                       {"counterexamples", counter}});
  std::cout << t.tried << " random polygons (" << F.min_vertices << "-" << F.max_vertices << " vertices, seeds " << F.seed << "-"
            << F.seed + F.polygons - 1 << "): " << t.rejected << " not in general position, " << t.budget
            << " over budget; " << used << " compared\n";
  for (auto& b : over)
    std::cout << "budget exceeded: seed " << b["seed"].get<std::uint64_t>() << " (" << b["vertices"].get<std::size_t>()
              << " vertices), Strategy " << b["strategy"].get<std::string>() << " over "
              << (b["limit"] == "time" ? "--time-limit" : "--max-states") << "\n";
  std::cout << "Strategy 2 (gap sensor, complete) solves " << t.gap << "; Strategy 6 (no special sensor) solves " << t.none << "\n"
            << "Strategy 6 plans checked: " << t.none_checked << ", not clearing: " << t.none_wrong << "\n";
  if (F.check_all) std::cout << "Strategy 2 plans checked: " << t.gap_checked << ", not clearing: " << t.gap_wrong << "\n";
  std::cout << "solved by the wall-follower but not by the free pursuer of module pursuit: " << t.free_missing;
  if (t.free_budget) std::cout << " (" << t.free_budget << " more where it ran out of I-states)";
  std::cout << "\n" << counter.size() << " solved by Strategy 2 and not by Strategy 6";
  for (auto& c : counter) std::cout << (&c == &counter[0] ? ": seed " : ", ") << c["seed"].get<std::uint64_t>() << " (" << c["vertices"].get<std::size_t>() << " vertices)";
  std::cout << "\n";
}

}  // namespace

void add_wallfollow_commands(CLI::App& app) {
  auto* w = app.add_subcommand("wallfollow", "Wall-following robot: simulator, I-maps, cut ordering, pursuit-evasion (wall-following paper)");
  w->require_subcommand(1);
  static std::string file, start, actions, sort = "quick", svg, pebble;
  static double heading = 0;
  static bool as_json = false, cw = false, learn = false;
  auto common = [&](CLI::App* c) {
    c->add_option("scene", file, "Scene file (JSON): a simple polygon, no three vertices collinear")->required();
    c->add_option("--start", start, "Robot start X,Y (default: the scene's start, else the first vertex)");
    c->add_option("--heading", heading, "Robot heading in degrees for INIT from the interior (default 0 = east)");
    add_json_flag(c, as_json, "JSON output");
  };
  auto* s = w->add_subcommand("simulate", "Apply actions; print each observation and the I-maps");
  set_examples(s, {"preimage wallfollow simulate examples/wallfollow/fig05_rooms.json --actions INIT,LFOLLOW,LFOLLOW,RFOLLOW"});
  common(s);
  s->add_option("--actions", actions, "E.g. \"INIT,DROP,LFOLLOW,LFOLLOW,JUMP\"")->required();
  s->add_option("--pebble", pebble, "The pebble lies at X,Y instead of being held");
  s->callback([] { run_simulate(file, actions, start, heading, pebble, as_json); });
  auto* c = w->add_subcommand("count", "Vertex count and winding number from the I-maps (section IV)");
  set_examples(c, {"preimage wallfollow count examples/wallfollow/fig05_rooms.json"});
  common(c);
  c->add_flag("--clockwise", cw, "Follow with LFOLLOW (default RFOLLOW)");
  c->callback([] { run_count(file, start, heading, cw, as_json); });
  auto* o = w->add_subcommand("cut-ordering", "The cut ordering from geometry, or learned by the robot (Strategy 1)");
  set_examples(o, {"preimage wallfollow cut-ordering examples/wallfollow/fig05_rooms.json", "preimage wallfollow cut-ordering examples/wallfollow/fig05_rooms.json --learn --svg cuts.svg"});
  common(o);
  o->add_flag("--learn", learn, "Learn it through the robot's actions and sensors only");
  o->add_option("--sort", sort, "With --learn: order endpoints on an edge by quick (default) or all-pairs comparisons");
  o->add_option("--svg", svg, "Draw the cut diagram (Fig. 4a)");
  o->callback([] { run_cut_ordering(file, learn, sort, start, heading, as_json, svg); });
  {
    auto F = std::make_shared<PursueFlags>();
    auto* p = w->add_subcommand("pursue", "Pursuit-evasion (section VI): learn the cut ordering, plan, execute, check");
    set_examples(p, {"preimage wallfollow pursue examples/wallfollow/fig09_three_teeth.json --sensor bitangent --svg pursue.svg", "preimage wallfollow pursue examples/wallfollow/fig05_rooms.json --sensor none"});
    p->add_option("scene", F->file, "Scene file (JSON): a simple polygon, no three vertices collinear")->required();
    p->add_option("--sensor", F->sensor, "gap (Strategy 2), bitangent (3), pebble (4 + 5) or none (6)")->capture_default_str();
    p->add_option("--start", F->start, "Robot start X,Y (default: the scene's start, else the first vertex)");
    p->add_option("--heading", F->heading, "Robot heading in degrees for INIT from the interior (default 0 = east)");
    add_count(p, "--max-states", F->max_states, 1, 1'000'000'000, "I-states to store before giving up");
    p->add_flag("--no-check", F->no_check, "Skip the independent contamination check of the executed plan");
    add_count(p, "--frames", F->frames, 1, 24, "Moments drawn in the --svg small multiples");
    add_json_flag(p, F->as_json, "JSON output");
    p->add_option("--svg", F->svg, "Draw the cuts, bitangent rays and the plan, and the labels at a few moments");
    p->callback([F] { run_pursue(*F); });
  }
  {
    auto F = std::make_shared<CompletenessFlags>();
    auto* c2 = w->add_subcommand("completeness", "Strategies 2 and 6 on random polygons: is Strategy 6 complete? (VI.E)");
    set_examples(c2, {"preimage wallfollow completeness --polygons 20 --max-vertices 12"});
    add_count(c2, "--polygons", F->polygons, 1, 10'000'000, "Random polygons to try");
    c2->add_option("--seed", F->seed, "First seed (one polygon per seed)")->capture_default_str();
    add_count(c2, "--min-vertices", F->min_vertices, 4, 10'000, "Fewest vertices");
    add_count(c2, "--max-vertices", F->max_vertices, 4, 10'000, "Most vertices");
    add_count(c2, "--max-states", F->max_states, 1, 1'000'000'000, "I-states per search before giving up (the polygon is counted over budget)");
    c2->add_option("--time-limit", F->time_limit,
                   "Seconds per polygon for Strategies 2 and 6 (learning, exploring, searching) before giving up (the polygon is "
                   "counted over budget); 0: none")
        ->check(number_in(0, 1e9))
        ->capture_default_str();
    c2->add_flag("--check-all", F->check_all, "Also check Strategy 2's plans (Strategy 6's always are)");
    c2->add_option("--save", F->save, "Write every counter-example scene into this directory (created if missing; checked before any polygon)");
    add_json_flag(c2, F->as_json, "JSON output");
    c2->callback([F] { run_completeness(*F); });
  }
}

}  // namespace preimage::cli
