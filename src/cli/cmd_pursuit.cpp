// SPDX-License-Identifier: Apache-2.0
// preimage pursuit cells | plan | check
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/pursuit/bounds.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/examples.hpp>
#include <preimage/pursuit/figures.hpp>
#include <preimage/pursuit/paths_input.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/pursuit/split.hpp>
#include <preimage/render/figures.hpp>
#include <preimage/scene/scene.hpp>

#include <cmath>
#include <fstream>
#include <iostream>

#include <unistd.h>

namespace preimage::cli {
namespace {

using nlohmann::json;
using geometry::Point;

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// ---------------------------------------------------------------- cells
void run_cells(const std::string& file, bool as_json, const std::string& svg) {
  const scene::Scene s = scene::load_scene(file);
  const auto C = pursuit::ConservativeCells::build(s.require_environment());
  std::size_t ext = 0, bit = 0, contact = 0, merged = 0, max_gaps = 0;
  using Kind = pursuit::CriticalGenerator::Kind;
  for (auto& seg : C.critical()) {
    if (seg.generators.size() > 1) ++merged;
    for (auto& g : seg.generators) (g.kind == Kind::Extension ? ext : g.kind == Kind::Bitangent ? bit : contact)++;
  }
  for (auto& c : C.cells()) max_gaps = std::max(max_gaps, c.shadows.gaps.size());
  if (!svg.empty()) {
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    pursuit::draw_cells(c, C);
    c.save(svg);
  }
  if (as_json) {
    json segs = json::array(), cells = json::array(), bounds = json::array();
    for (auto& seg : C.critical()) {
      json gens = json::array();
      for (auto& g : seg.generators)
        gens.push_back({{"kind", g.kind == Kind::Extension ? "extension" : g.kind == Kind::Bitangent ? "bitangent" : "contact"},
                        {"vertex", geometry::describe_vertex(C.environment(), g.vertex)},
                        {"other", geometry::describe_vertex(C.environment(), g.other)}});
      segs.push_back({{"from", point_json(seg.from)}, {"to", point_json(seg.to)}, {"generators", gens}});
    }
    for (std::size_t i = 0; i < C.size(); ++i) {
      const auto& c = C.cell(i);
      json comps = json::array();
      for (std::uint32_t k = 0; k < c.shadows.num_components; ++k) {
        json gaps = json::array();
        for (auto v : c.shadows.gap_vertices(k)) gaps.push_back(geometry::describe_vertex(C.environment(), v));
        comps.push_back(gaps);
      }
      cells.push_back({{"id", i}, {"polygon", points_json(c.polygon)}, {"sample", {c.sample.x(), c.sample.y()}},
                       {"thin", c.tiny}, {"shadow_components", comps}});
    }
    for (auto& b : C.boundaries()) {
      json pairs = json::array();
      for (auto [o, n] : b.to_right.pairs) pairs.push_back({o, n});
      bounds.push_back({{"left", b.left}, {"right", b.right}, {"segment", b.segment}, {"left_to_right", pairs}});
    }
    print_json({{"reflex_vertices", C.reflex_vertices()}, {"critical_segments", segs}, {"cells", cells}, {"boundaries", bounds}});
    return;
  }
  std::cout << "conservative cells: " << plural(C.reflex_vertices(), "reflex vertex", "reflex vertices") << ", "
            << plural(C.critical().size(), "critical segment", "critical segments") << " (" << ext << " edge extensions, " << bit
            << " bitangent rays, " << (contact ? std::to_string(contact) + " contact rays, " : "") << merged
            << " segments where rays coincide), " << plural(C.size(), "cell", "cells") << " ("
            << C.tiny_cells() << " thinner than double precision), " << plural(C.boundaries().size(), "boundary", "boundaries")
            << "; at most " << plural(max_gaps, "gap", "gaps") << " in a cell\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

// ---------------------------------------------------------------- check (shared by plan)
json check_json(const pursuit::CheckResult& r) {
  auto moment = [](const std::optional<pursuit::CheckResult::Moment>& m) -> json {
    if (!m) return nullptr;
    return {{"waypoint", m->waypoint}, {"fraction", m->fraction}, {"at", {m->where.x(), m->where.y()}}};
  };
  return {{"cleared", r.cleared}, {"moments", r.moments}, {"cleared_at", moment(r.cleared_at)},
          {"first_recontamination", moment(r.first_recontamination)}, {"contaminated_at_end", points_json(r.contaminated_at_end)},
          {"contaminated_area", r.contaminated_area}};
}

std::string check_text(const pursuit::CheckResult& r) {
  std::string s;
  if (r.cleared) {
    s = "cleared";
    if (r.cleared_at) s += " (from waypoint " + std::to_string(r.cleared_at->waypoint) + " on)";
  } else {
    s = "NOT cleared: " + plural(r.contaminated_at_end.size(), "region", "regions") + " contaminated at the end (area " +
        geometry::format_number(r.contaminated_area) + ")";
    for (std::size_t i = 0; i < r.contaminated_at_end.size() && i < 3; ++i)
      s += (i ? ", " : " near ") + geometry::format_point(r.contaminated_at_end[i]);
  }
  if (r.first_recontamination) {
    const auto& m = *r.first_recontamination;
    s += "; first recontamination on the way from waypoint " + std::to_string(m.waypoint) + " (" +
         geometry::format_number(100 * m.fraction) + "% along) near " + geometry::format_point(m.where);
  }
  return s + "; " + std::to_string(r.moments) + " moments sampled";
}

void write_figure(const std::string& svg, const geometry::Environment& env, const pursuit::Paths& paths,
                  const pursuit::CheckResult& r) {
  std::ofstream f(svg);
  f << pursuit::plan_frames_figure(env, paths, r.frames);
  if (!f) throw InputError(svg + ": cannot write file");
}

void write_frames(const std::string& svg, const geometry::Environment& env, const pursuit::Paths& paths,
                  std::size_t frames, pursuit::CheckResult* checked) {
  pursuit::CheckOptions o;
  o.frames = pursuit::frame_waypoints(paths[0].size(), frames);
  const auto r = pursuit::check_paths(env, paths, o);
  write_figure(svg, env, paths, r);
  if (checked) *checked = r;
}

// ---------------------------------------------------------------- plan
struct PlanFlags {
  std::string file, start, svg;
  std::size_t pursuers = 1, max_states = 4'000'000, frames = 6, max_mb = 2048, range_sides = 32;
  double time_limit = 45, range = 0;
  bool pursuers_given = false, split = false, no_check = false, as_json = false, any = false;
};

double path_length(const std::vector<Point>& path) {
  double l = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) l += std::hypot(path[i].x() - path[i + 1].x(), path[i].y() - path[i + 1].y());
  return l;
}

json plan_json(const pursuit::Plan& p) {
  json paths = json::array(), moves = json::array();
  for (auto& path : p.paths) paths.push_back(points_json(path));
  for (auto& m : p.moves) moves.push_back({{"pursuer", m.pursuer + 1}, {"from_cell", m.from}, {"to_cell", m.to}});
  json lengths = json::array();
  for (auto& path : p.paths) lengths.push_back(path_length(path));
  return {{"paths", paths}, {"length", p.length}, {"lengths", lengths}, {"moves", moves}};
}

// A search's outcome as one line (the wording the search mode has always printed).
std::string search_line(const pursuit::SearchResult& a, const PlanFlags& F, const std::string& avoiding,
                        const std::string& role = "") {
  using O = pursuit::SearchResult::Outcome;
  const std::string who = a.pursuers == 1 ? "one pursuer" : plural(a.pursuers, "pursuer", "pursuers");
  const std::string took = ", " + geometry::format_number(std::round(a.seconds * 100) / 100) + " s";
  if (a.outcome == O::Plan)
    return "plan with " + who + " (" + std::to_string(a.states) + " information states explored" + took + ")";
  if (a.outcome == O::NoPlan)
    return a.pursuers == 1 ? "no plan with one pursuer exists" + avoiding + " (complete search, " + std::to_string(a.states) +
                                 " information states explored" + took + ")"
                           : "no plan with " + who + " waiting at cell samples" + avoiding + " (not a proof: " +
                                 std::to_string(a.states) + " information states explored" + took + ")";
  const std::string flag = role == "shortest plan" ? "twice the time the first plan took, at least 1 s"
                           : a.budget == "time"    ? "--time-limit " + geometry::format_number(F.time_limit) + " s"
                           : a.budget == "memory" ? "--max-mb " + std::to_string(F.max_mb)
                                                  : "--max-states " + std::to_string(F.max_states);
  return plural(a.pursuers, "pursuer", "pursuers") + ": search stopped after " + std::to_string(a.states) +
         " information states (" + flag + ")";
}

// The default: the interval [lower, upper] of pursuers needed, with a checked plan.
void run_bounds(const PlanFlags& F, const geometry::Environment& env, const std::optional<Point>& start) {
  pursuit::BoundsOptions o;
  o.start = start;
  o.time_limit = F.time_limit;
  o.max_states = F.max_states;
  o.max_mb = F.max_mb;
  o.shortest = !F.any;
  o.range = F.range, o.range_sides = F.range_sides;
  // The figure's frames come from the checker, so --svg checks even with --no-check. The
  // bounds check the strategy's plan before searching for fewer pursuers, within the time.
  o.check = !F.no_check || !F.svg.empty();
  if (!F.svg.empty()) o.check_frames = F.frames;
  const bool tty = isatty(STDERR_FILENO);
  if (tty) o.progress = [](const std::string& s) { std::cerr << "\r\033[K" << s << "..." << std::flush; };
  const auto b = pursuit::pursuer_bounds(env, o);
  const std::optional<pursuit::CheckResult>& checked = b.check;
  if (tty) std::cerr << "\r\033[K" << std::flush;
  const std::vector<Point> guards = b.guard_points();
  const std::string interval = "[" + std::to_string(b.lower) + ", " + std::to_string(b.upper) + "]";
  const std::string with_range = F.range > 0 ? " with range " + geometry::format_number(F.range) : "";
  if (!F.svg.empty()) {
    const auto map = pursuit::plan_map_panel(env, b.plan->paths, guards, "pursuers needed" + with_range + ": " + interval + "; the plan");
    std::ofstream f(F.svg);
    f << pursuit::plan_frames_figure(env, b.plan->paths, checked->frames, 3, {}, &map);
    if (!f) throw InputError(F.svg + ": cannot write file");
  }
  const std::string avoiding = env.has_contacts() ? " on paths that avoid contact points" : "";
  json searches = json::array();
  for (std::size_t i = 0; i < b.searches.size(); ++i) {
    const auto& a = b.searches[i];
    searches.push_back({{"for", b.roles[i]}, {"pursuers", a.pursuers}, {"outcome", pursuit::to_string(a.outcome)},
                        {"states", a.states}, {"seconds", a.seconds}, {"megabytes", static_cast<double>(a.bytes) / (1 << 20)},
                        {"budget", a.budget.empty() ? json(nullptr) : json(a.budget)}});
  }
  json lengths = json::array();
  for (auto& p : b.plan->paths) lengths.push_back(path_length(p));
  if (F.as_json) {
    json out = {{"strategy", "bounds"}, {"lower", b.lower}, {"upper", b.upper}, {"exact", b.exact()},
                {"lower_reason", b.lower_reason}, {"upper_reason", b.upper_reason}, {"holes", b.holes},
                {"plan_source", b.plan_source}, {"searches", searches}, {"guards", points_json(guards)},
                {"plan", plan_json(*b.plan)}, {"certified", checked.has_value()}};
    if (b.plan->paths.size() == 1) out["shortest"] = b.shortest;
    if (env.has_contacts()) out["paths_avoid_contacts"] = true;
    if (checked) out["check"] = check_json(*checked);
    out["range"] = F.range > 0 ? json(F.range) : json(nullptr);
    if (F.range > 0) out["range_sides"] = F.range_sides;
    return print_json(out);
  }
  std::cout << "pursuers needed" << with_range << ": " << interval << (b.exact() ? " (exact)" : "") << "\n";
  std::cout << "  lower " << b.lower << ": " << b.lower_reason << "\n";
  std::cout << "  upper " << b.upper << ": " << b.upper_reason << (checked ? ", cleared by the independent check" : " (not checked: --no-check)") << "\n";
  for (std::size_t i = 0; i < b.searches.size(); ++i)
    std::cout << "search (" << b.roles[i] << "): " << search_line(b.searches[i], F, avoiding, b.roles[i]) << "\n";
  if (!guards.empty()) {
    std::cout << "static guards at";
    for (std::size_t i = 0; i < guards.size(); ++i) std::cout << (i ? ", " : " ") << geometry::format_point(guards[i]);
    std::cout << "\n";
  }
  std::cout << "plan: " << plural(b.plan->paths.size(), "pursuer", "pursuers") << ", " << plural(b.plan->paths[0].size(), "waypoint", "waypoints")
            << ", length " << (b.plan->paths.size() == 1 ? "" : "per pursuer ");
  for (std::size_t i = 0; i < b.plan->paths.size(); ++i) std::cout << (i ? ", " : "") << geometry::format_number(path_length(b.plan->paths[i]));
  if (b.plan->paths.size() == 1 && b.plan_source == "search")
    std::cout << (b.shortest ? " (the shortest walk between cell samples)" : " (not the shortest: --any, or the shortest-first search ran out of its budget)");
  std::cout << "\n";
  if (checked) std::cout << "independent check: " << check_text(*checked) << "\n";
  if (!F.svg.empty()) std::cout << "wrote " << F.svg << "\n";
}

void run_plan(const PlanFlags& F) {
  const scene::Scene s = scene::load_scene(F.file);
  const auto& env = s.require_environment();
  std::optional<Point> start = s.start;
  if (!F.start.empty()) start = parse_point(F.start, "--start");
  if (F.range > 0 && (F.split || F.pursuers_given))
    throw InputError("--range: works with the interval (the default); --pursuers and --split plan for unlimited sight");
  if (!F.split && !F.pursuers_given) return run_bounds(F, env, start);
  json out;
  std::optional<pursuit::Plan> plan;
  std::string summary;
  if (F.split) {
    const auto r = pursuit::split_strategy(env, start);
    plan = r.plan;
    // The exact minimum where exhaustive search settles it: one pursuer, or not one (then
    // the split plan with two is optimal).
    const auto C = pursuit::ConservativeCells::build(env);
    pursuit::SearchOptions o{start, F.max_states, false, F.time_limit, F.max_mb};  // existence is the question
    const auto one = pursuit::search(C, 1, o);
    std::string minimum = "unknown";
    json min_json = nullptr;
    if (one.outcome == pursuit::SearchResult::Outcome::Plan) minimum = "1", min_json = 1;
    else if (one.outcome == pursuit::SearchResult::Outcome::NoPlan && r.pursuers == 2) minimum = "2", min_json = 2;
    else if (one.outcome == pursuit::SearchResult::Outcome::NoPlan) minimum = "at least 2", min_json = ">=2";
    summary = "split strategy: " + plural(r.pursuers, "pursuer", "pursuers") + " (" + plural(r.guards, "static guard", "static guards") +
              ", " + plural(r.regions, "region", "regions") + " cleared by one pursuer from " + plural(r.stops, "stop", "stops") + "), " +
              plural(r.plan.paths[0].size(), "waypoint", "waypoints") + ", length " + geometry::format_number(r.plan.length) +
              "; exact minimum " + minimum + " (one-pursuer search: " + pursuit::to_string(one.outcome) + ", " +
              std::to_string(one.states) + " information states)";
    out = {{"strategy", "split"}, {"pursuers", r.pursuers}, {"guards", r.guards}, {"regions", r.regions}, {"stops", r.stops},
           {"exact_minimum", min_json}, {"plan", plan_json(r.plan)}};
  } else {
    const auto C = pursuit::ConservativeCells::build(env);
    std::vector<pursuit::SearchResult> attempts;
    const auto r = pursuit::least_pursuers(C, F.pursuers, {start, F.max_states, !F.any, F.time_limit, F.max_mb}, &attempts);
    json att = json::array();
    // Cells meet at a contact point only there: the search's pursuers never pass through one
    // (the evader does), so with contacts "no plan" is about such paths (docs/pursuit.md).
    const std::string avoiding = env.has_contacts() ? " on paths that avoid contact points" : "";
    for (auto& a : attempts) {
      att.push_back({{"pursuers", a.pursuers}, {"outcome", pursuit::to_string(a.outcome)}, {"states", a.states}});
      if (a.outcome == pursuit::SearchResult::Outcome::NoPlan)
        summary += (a.pursuers == 1 ? "no plan with one pursuer exists" + avoiding + " (complete search, "
                                    : "no plan with " + plural(a.pursuers, "pursuer", "pursuers") + " waiting at cell samples" +
                                          avoiding + " (") +
                   std::to_string(a.states) + " information states explored)\n";
      else if (a.outcome == pursuit::SearchResult::Outcome::Budget)
        summary += plural(a.pursuers, "pursuer", "pursuers") + ": search stopped after " + std::to_string(a.states) +
                   " information states (--max-states " + std::to_string(F.max_states) + ")\n";
    }
    out = {{"strategy", "search"}, {"cells", C.size()}, {"attempts", att}};
    if (env.has_contacts()) out["paths_avoid_contacts"] = true;
    if (r.plan) {
      plan = r.plan;
      summary += "plan with " + plural(r.pursuers, "pursuer", "pursuers") + ": " + plural(r.plan->moves.size(), "crossing", "crossings") +
                 " of cell boundaries, " + plural(r.plan->paths[0].size(), "waypoint", "waypoints") + ", length " +
                 geometry::format_number(r.plan->length) + " (" + std::to_string(r.states) + " information states explored)";
      out["pursuers"] = r.pursuers;
      out["plan"] = plan_json(*r.plan);
    } else {
      if (!summary.empty() && summary.back() == '\n') summary.pop_back();
      out["pursuers"] = nullptr;
    }
  }
  std::optional<pursuit::CheckResult> checked;
  if (plan && !F.svg.empty()) {
    pursuit::CheckResult r;
    write_frames(F.svg, env, plan->paths, F.frames, &r);
    checked = r;
  } else if (plan && !F.no_check) {
    checked = pursuit::check_paths(env, plan->paths);
  }
  if (checked) out["check"] = check_json(*checked);
  if (F.as_json) return print_json(out);
  std::cout << summary << "\n";
  if (checked) std::cout << "independent check: " << check_text(*checked) << "\n";
  if (plan && !F.svg.empty()) std::cout << "wrote " << F.svg << "\n";
}

// ---------------------------------------------------------------- check
void run_check(const std::string& file, const std::string& path_file, bool as_json, const std::string& svg, std::size_t frames,
               std::size_t threads, double range, std::size_t range_sides) {
  const scene::Scene s = scene::load_scene(file);
  const auto& env = s.require_environment();
  const pursuit::PathsInput paths = pursuit::parse_paths(scene::read_file(path_file), path_file);
  pursuit::CheckOptions o;
  o.threads = static_cast<unsigned>(threads);
  o.range = range, o.range_sides = range_sides;
  if (!svg.empty()) o.frames = pursuit::frame_waypoints(paths.exact[0].size(), frames);
  const pursuit::CheckResult r = pursuit::check_paths(env, paths, o);
  if (!svg.empty()) write_figure(svg, env, paths.rounded(), r);
  if (as_json) {
    json out = check_json(r);
    out["range"] = range > 0 ? json(range) : json(nullptr);
    if (range > 0) out["range_sides"] = range_sides;
    return print_json(out);
  }
  std::cout << plural(paths.exact.size(), "pursuer", "pursuers") << ", " << plural(paths.exact[0].size(), "waypoint", "waypoints")
            << (paths.exact_strings ? " (exact)" : "");
  if (range > 0)
    std::cout << ", range " << geometry::format_number(range) << " (seen through an inscribed " << range_sides
              << "-gon: what it clears, the disc clears)";
  std::cout << ": " << check_text(r) << "\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

}  // namespace

void add_pursuit_commands(CLI::App& app) {
  auto* group = app.add_subcommand("pursuit", "Visibility-based pursuit-evasion: conservative cells, plans, independent check");
  group->require_subcommand(1);
  {
    auto* cmd = group->add_subcommand("cells", "Conservative cells of 6.3 (critical rays, gaps, transitions)");
    set_examples(cmd, {"preimage pursuit cells examples/pursuit/pillar.json --svg cells.svg"});
    auto file = std::make_shared<std::string>(), svg = std::make_shared<std::string>();
    auto as_json = std::make_shared<bool>(false);
    cmd->add_option("scene", *file, "Scene JSON file")->required();
    add_json_flag(cmd, *as_json, "Machine-readable output on stdout");
    cmd->add_option("--svg", *svg, "Draw the critical rays and cells to this SVG file");
    cmd->callback([=] { run_cells(*file, *as_json, *svg); });
  }
  {
    auto* cmd = group->add_subcommand(
        "plan", "How many pursuers the scene needs, as an interval [lower, upper] with a checked plan; or a search, or the split strategy");
    set_examples(cmd, {"preimage pursuit plan examples/pursuit/three_arms.json",
                       "preimage pursuit plan examples/floorplans/office_mlstruct_302.json --no-check",
                       "preimage pursuit plan examples/pursuit/pillar.json --pursuers 2 --json > plan.json"});
    auto F = std::make_shared<PlanFlags>();
    cmd->add_option("scene", F->file, "Scene JSON file")->required();
    auto* k = add_count(cmd, "--pursuers", F->pursuers, 1, 8,
                        "Search with 1, 2, ... up to this many pursuers and report the least that succeeds (instead of the interval)");
    cmd->add_option("--time-limit", F->time_limit, "Seconds for the searches together (the interval is printed whatever they reach)")
        ->check(CLI::PositiveNumber);
    add_count(cmd, "--max-mb", F->max_mb, 1, 1'000'000, "Megabytes of search state per search before giving up");
    cmd->add_option("--start", F->start, "Every pursuer starts here (default: the scene's \"start\", else anywhere)");
    add_count(cmd, "--max-states", F->max_states, 1, 1'000'000'000, "Information states to store before giving up");
    cmd->add_flag("--split", F->split, "The static-guard strategy of 6.3 alone (any scene, holes included), beside the exact minimum");
    cmd->add_flag("--any", F->any, "Any plan, not the shortest: states with fewer contaminated components first (still complete)");
    cmd->add_flag("--no-check", F->no_check, "Skip the independent contamination check of the plan");
    cmd->add_option("--range", F->range,
                    "Pursuers see only within this distance: the plan is checked with it (an inscribed polygon), and where the plan "
                    "for unlimited sight does not clear, the upper end is a static cover of guards (default: unlimited)")
        ->check(number_in(0, 1e15, true));
    add_count(cmd, "--range-sides", F->range_sides, 8, 1024, "Corners of the polygon inscribed in the range's disc");
    add_count(cmd, "--frames", F->frames, 1, 24, "Moments drawn in the --svg small multiples");
    add_json_flag(cmd, F->as_json, "Machine-readable output on stdout");
    cmd->add_option("--svg", F->svg, "Draw the plan as small multiples (pursuers, V, contaminated regions) to this SVG file");
    cmd->callback([=] {
      F->pursuers_given = k->count() > 0;
      run_plan(*F);
    });
  }
  {
    auto* cmd = group->add_subcommand("nested-u", "Write the nested-U scene of Fig. 6.40 (level L needs L pursuers)");
    set_examples(cmd, {"preimage pursuit nested-u --level 3 -o nested3.json && preimage pursuit plan nested3.json --svg nested3.svg"});
    auto level = std::make_shared<std::size_t>(2);
    auto out = std::make_shared<std::string>();
    add_count(cmd, "--level", *level, 1, 6, "Nesting depth: 1 a dead end, 2 three bent arms around a hub, ...")->required();
    cmd->add_option("-o,--output", *out, "Scene file to write (default: stdout)");
    cmd->callback([=] {
      scene::Scene s;
      s.name = "nested U, level " + std::to_string(*level);
      s.description = "Fig. 6.40's family: a hub with three arms bending twice, each ending in the level below (1 m corridors)";
      s.environment = pursuit::examples::nested_u(*level);
      if (out->empty()) return print_json(scene::to_json(s));
      scene::save_scene(s, *out);
      std::cout << "wrote " << *out << ": " << s.environment->num_vertices() << " vertices\n";
    });
  }
  {
    auto* cmd = group->add_subcommand("check", "Check pursuer paths with the independent contamination checker");
    set_examples(cmd, {"preimage pursuit plan examples/pursuit/pillar.json --pursuers 2 --json > plan.json && preimage pursuit check examples/pursuit/pillar.json --path plan.json --svg check.svg"});
    auto file = std::make_shared<std::string>(), path = std::make_shared<std::string>(), svg = std::make_shared<std::string>();
    auto as_json = std::make_shared<bool>(false);
    auto frames = std::make_shared<std::size_t>(6);
    auto threads = std::make_shared<std::size_t>(0);
    cmd->add_option("scene", *file, "Scene JSON file")->required();
    cmd->add_option("--path", *path,
                    "JSON: one polyline [[x, y], ...], several [[[x, y], ...], ...] or {\"paths\": ...} (pursuers pass waypoint i "
                    "together); a coordinate is a number or an exact string (\"-7/2\", \"0.1\")")
        ->required();
    add_json_flag(cmd, *as_json, "Machine-readable output on stdout");
    cmd->add_option("--svg", *svg, "Draw the check as small multiples to this SVG file");
    add_count(cmd, "--frames", *frames, 1, 24, "Moments drawn in the --svg small multiples");
    add_count(cmd, "--threads", *threads, 0, 256, "Threads building the moments (0: one per core); the verdict does not depend on it");
    auto range = std::make_shared<double>(0);
    auto range_sides = std::make_shared<std::size_t>(32);
    cmd->add_option("--range", *range,
                    "Each pursuer sees only within this distance (checked with a polygon inscribed in the disc: a plan it clears is "
                    "cleared by the real sensor; default: unlimited)")
        ->check(number_in(0, 1e15, true));
    add_count(cmd, "--range-sides", *range_sides, 8, 1024, "Corners of the polygon inscribed in the range's disc");
    cmd->callback([=] { run_check(*file, *path, *as_json, *svg, *frames, *threads, *range, *range_sides); });
  }
}

}  // namespace preimage::cli
