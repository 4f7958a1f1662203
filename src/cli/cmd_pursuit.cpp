// SPDX-License-Identifier: Apache-2.0
// preimage pursuit cells | plan | check
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/figures.hpp>
#include <preimage/pursuit/paths_input.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/pursuit/split.hpp>
#include <preimage/render/figures.hpp>
#include <preimage/scene/scene.hpp>

#include <fstream>
#include <iostream>

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
  std::size_t pursuers = 1, max_states = 4'000'000, frames = 6;
  bool split = false, no_check = false, as_json = false, any = false;
};

json plan_json(const pursuit::Plan& p) {
  json paths = json::array(), moves = json::array();
  for (auto& path : p.paths) paths.push_back(points_json(path));
  for (auto& m : p.moves) moves.push_back({{"pursuer", m.pursuer + 1}, {"from_cell", m.from}, {"to_cell", m.to}});
  return {{"paths", paths}, {"length", p.length}, {"moves", moves}};
}

void run_plan(const PlanFlags& F) {
  const scene::Scene s = scene::load_scene(F.file);
  const auto& env = s.require_environment();
  std::optional<Point> start = s.start;
  if (!F.start.empty()) start = parse_point(F.start, "--start");
  json out;
  std::optional<pursuit::Plan> plan;
  std::string summary;
  if (F.split) {
    const auto r = pursuit::split_strategy(env, start);
    plan = r.plan;
    // The exact minimum where exhaustive search settles it: one pursuer, or not one (then
    // the split plan with two is optimal).
    const auto C = pursuit::ConservativeCells::build(env);
    pursuit::SearchOptions o{start, F.max_states, false};  // existence is the question
    const auto one = pursuit::search(C, 1, o);
    std::string minimum = "unknown";
    json min_json = nullptr;
    if (one.outcome == pursuit::SearchResult::Outcome::Plan) minimum = "1", min_json = 1;
    else if (one.outcome == pursuit::SearchResult::Outcome::NoPlan && r.pursuers == 2) minimum = "2", min_json = 2;
    else if (one.outcome == pursuit::SearchResult::Outcome::NoPlan) minimum = "at least 2", min_json = ">=2";
    summary = "split strategy: " + plural(r.pursuers, "pursuer", "pursuers") + " (" + plural(r.guards, "chord", "chords") +
              " guarded, " + plural(r.regions, "region", "regions") + " cleared by one pursuer), " +
              plural(r.plan.paths[0].size(), "waypoint", "waypoints") + ", length " + geometry::format_number(r.plan.length) +
              "; exact minimum " + minimum + " (one-pursuer search: " + pursuit::to_string(one.outcome) + ", " +
              std::to_string(one.states) + " information states)";
    out = {{"strategy", "split"}, {"pursuers", r.pursuers}, {"guards", r.guards}, {"regions", r.regions},
           {"exact_minimum", min_json}, {"plan", plan_json(r.plan)}};
  } else {
    const auto C = pursuit::ConservativeCells::build(env);
    std::vector<pursuit::SearchResult> attempts;
    const auto r = pursuit::least_pursuers(C, F.pursuers, {start, F.max_states, !F.any}, &attempts);
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
void run_check(const std::string& file, const std::string& path_file, bool as_json, const std::string& svg, std::size_t frames) {
  const scene::Scene s = scene::load_scene(file);
  const auto& env = s.require_environment();
  const pursuit::PathsInput paths = pursuit::parse_paths(scene::read_file(path_file), path_file);
  pursuit::CheckOptions o;
  if (!svg.empty()) o.frames = pursuit::frame_waypoints(paths.exact[0].size(), frames);
  const pursuit::CheckResult r = pursuit::check_paths(env, paths, o);
  if (!svg.empty()) write_figure(svg, env, paths.rounded(), r);
  if (as_json) return print_json(check_json(r));
  std::cout << plural(paths.exact.size(), "pursuer", "pursuers") << ", " << plural(paths.exact[0].size(), "waypoint", "waypoints")
            << (paths.exact_strings ? " (exact)" : "") << ": " << check_text(r) << "\n";
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
    auto* cmd = group->add_subcommand("plan", "Search plan for pursuers (complete for one), or the split strategy");
    set_examples(cmd, {"preimage pursuit plan examples/pursuit/three_arms.json", "preimage pursuit plan examples/pursuit/pillar.json --pursuers 2 --json > plan.json"});
    auto F = std::make_shared<PlanFlags>();
    cmd->add_option("scene", F->file, "Scene JSON file")->required();
    add_count(cmd, "--pursuers", F->pursuers, 1, 8, "Search with 1, 2, ... up to this many pursuers; report the least that succeeds");
    cmd->add_option("--start", F->start, "Every pursuer starts here (default: the scene's \"start\", else anywhere)");
    add_count(cmd, "--max-states", F->max_states, 1, 1'000'000'000, "Information states to store before giving up");
    cmd->add_flag("--split", F->split, "The constructive O(log n) strategy (simply connected scenes), beside the exact minimum");
    cmd->add_flag("--any", F->any, "Any plan, not the shortest: states with fewer contaminated components first (still complete)");
    cmd->add_flag("--no-check", F->no_check, "Skip the independent contamination check of the plan");
    add_count(cmd, "--frames", F->frames, 1, 24, "Moments drawn in the --svg small multiples");
    add_json_flag(cmd, F->as_json, "Machine-readable output on stdout");
    cmd->add_option("--svg", F->svg, "Draw the plan as small multiples (pursuers, V, contaminated regions) to this SVG file");
    cmd->callback([=] { run_plan(*F); });
  }
  {
    auto* cmd = group->add_subcommand("check", "Check pursuer paths with the independent contamination checker");
    set_examples(cmd, {"preimage pursuit plan examples/pursuit/pillar.json --pursuers 2 --json > plan.json && preimage pursuit check examples/pursuit/pillar.json --path plan.json --svg check.svg"});
    auto file = std::make_shared<std::string>(), path = std::make_shared<std::string>(), svg = std::make_shared<std::string>();
    auto as_json = std::make_shared<bool>(false);
    auto frames = std::make_shared<std::size_t>(6);
    cmd->add_option("scene", *file, "Scene JSON file")->required();
    cmd->add_option("--path", *path,
                    "JSON: one polyline [[x, y], ...], several [[[x, y], ...], ...] or {\"paths\": ...} (pursuers pass waypoint i "
                    "together); a coordinate is a number or an exact string (\"-7/2\", \"0.1\")")
        ->required();
    add_json_flag(cmd, *as_json, "Machine-readable output on stdout");
    cmd->add_option("--svg", *svg, "Draw the check as small multiples to this SVG file");
    add_count(cmd, "--frames", *frames, 1, 24, "Moments drawn in the --svg small multiples");
    cmd->callback([=] { run_check(*file, *path, *as_json, *svg, *frames); });
  }
}

}  // namespace preimage::cli
