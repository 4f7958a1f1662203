// SPDX-License-Identifier: Apache-2.0
// Demo section of the pursuit module: conservative cells, the known answers of 6.3 and
// Guibas et al. 1999, plans drawn as small multiples, every plan checked independently.
#include "demo.hpp"

#include <preimage/geometry/generators.hpp>
#include <preimage/pursuit/bounds.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/examples.hpp>
#include <preimage/pursuit/figures.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/pursuit/split.hpp>
#include <preimage/render/figures.hpp>

namespace preimage::cli {

namespace {
using geometry::Environment;
using geometry::Point;

std::string verdict(const pursuit::CheckResult& c) { return c.cleared ? "the independent checker confirms it" : "the checker REJECTS it"; }

// Draws a plan's frames and returns the check.
pursuit::CheckResult frames(DemoContext& ctx, const Environment& env, const pursuit::Plan& plan, const std::string& file,
                            const std::string& caption) {
  pursuit::CheckOptions o;
  o.frames = pursuit::frame_waypoints(plan.paths[0].size(), 6);
  const auto c = pursuit::check_paths(env, plan.paths, o);
  ctx.figure(file, pursuit::plan_frames_figure(env, plan.paths, c.frames), caption);
  return c;
}

// The interval of pursuers needed (searches get 2 s), its plan drawn as a map.
pursuit::PursuerBounds bounds_figure(DemoContext& ctx, const Environment& env, const std::string& file, const std::string& title,
                                     const std::string& caption) {
  pursuit::BoundsOptions o;
  o.time_limit = 2;
  auto b = pursuit::pursuer_bounds(env, o);
  ctx.figure(file, pursuit::plan_map_panel(env, b.plan->paths, b.guard_points(), title).str(),
             caption + ": " + std::to_string(b.upper) + " pursuers; white dots are the static guards' posts");
  return b;
}

}  // namespace

void demo_pursuit(DemoContext& ctx) {
  auto& R = ctx.report;
  R.section("Visibility-based pursuit-evasion: conservative cells and the information graph (Choset et al., 6.3)");
  {
    const auto env = Environment::make(geometry::generators::star(6), {});
    const auto C = pursuit::ConservativeCells::build(env);
    const auto r = pursuit::search(C, 1);
    R.result("Star-shaped polygon: " + std::to_string(C.size()) + " conservative cells; the search starts in a cell of the kernel, which has no gap: a plan with " +
             std::to_string(r.plan->moves.size()) + " moves (no motion).");
  }
  const auto arms = pursuit::examples::three_arms();
  const auto AC = pursuit::ConservativeCells::build(arms);
  {
    scene::Scene s;
    s.environment = arms;
    render::SvgCanvas c(render::scene_box(s));
    render::draw_scene(c, s);
    pursuit::draw_cells(c, AC);
    ctx.figure("pursuit-cells.svg", c.str(),
               "Conservative cells of three bent arms around a hub: extension rays (blue) and bitangent rays (red); labels give each cell's number of gaps");
  }
  {
    const auto env = pursuit::examples::corridor_with_rooms(3);
    const auto C = pursuit::ConservativeCells::build(env);
    const auto r = pursuit::search(C, 1, {Point(0.5, 0.5)});
    const auto c = pursuit::check_paths(env, r.plan->paths);
    R.result("Corridor with three side rooms: " + std::to_string(C.size()) + " cells; one pursuer clears it with " +
             std::to_string(r.plan->moves.size()) + " crossings, length " + geometry::format_number(r.plan->length) + " (" +
             std::to_string(r.states) + " information states); " + verdict(c) + ".");
  }
  {
    const auto env = pursuit::examples::room_with_pillar();
    const auto C = pursuit::ConservativeCells::build(env);
    const auto one = pursuit::search(C, 1);
    const auto two = pursuit::search(C, 2);
    const auto c = frames(ctx, env, *two.plan, "pursuit-pillar.svg",
                          "Two pursuers clear a room with a pillar (one holds still while the other sweeps); red: contaminated");
    R.result("Room with a pillar (a hole): no plan with one pursuer exists (complete search over " + std::to_string(one.states) +
             " information states), as Guibas et al. prove for every environment with a hole; two pursuers: " +
             std::to_string(two.plan->moves.size()) + " moves; " + verdict(c) + ".");
  }
  {
    const auto one = pursuit::search(AC, 1);
    const auto two = pursuit::search(AC, 2, {Point(0, 0)});
    const auto c = frames(ctx, arms, *two.plan, "pursuit-arms.svg", "Three bent arms: the plan for two pursuers found by exhaustive search");
    const auto split = pursuit::split_strategy(arms, Point(0, 0));
    const auto sc = pursuit::check_paths(arms, split.plan.paths);
    R.result("Three bent arms (simply connected): no plan with one pursuer (" + std::to_string(one.states) +
             " information states); two pursuers: a plan with " + std::to_string(two.plan->moves.size()) + " moves; " + verdict(c) +
             ". The static-guard strategy uses " + std::to_string(split.pursuers) + " (" + std::to_string(split.guards) +
             " static guard); " + verdict(sc) + ".");
  }
  {
    // Fig. 6.40's family: level 3 needs three pursuers.
    const auto b = bounds_figure(ctx, pursuit::examples::nested_u(3), "pursuit-nested-u.svg", "nested U, level 3: the static-guard plan",
                                 "Nested U of Fig. 6.40, level 3 (98 vertices)");
    R.result("Nested U, level 3 (Fig. 6.40): pursuers needed [" + std::to_string(b.lower) + ", " + std::to_string(b.upper) + "] (lower: " +
             b.lower_reason + "; upper: " + b.upper_reason + "); " + verdict(*b.check) + ".");
  }
  {
    // An office: rooms off a corridor, walls as holes.
    const auto env = geometry::generators::office(1, 3);
    const std::string holes = std::to_string(env.num_holes()) + " holes";
    const auto b = bounds_figure(ctx, env, "pursuit-office.svg", "office, 1 x 3 rooms: the static-guard plan",
                                 "An office of 1 x 3 rooms (walls are " + holes + ")");
    R.result("Office, 1 x 3 rooms (" + holes + "): pursuers needed [" + std::to_string(b.lower) + ", " + std::to_string(b.upper) + "] (" +
             b.upper_reason + "); " + verdict(*b.check) + ".");
  }
}

}  // namespace preimage::cli
