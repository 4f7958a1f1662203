// SPDX-License-Identifier: Apache-2.0
// The interval [lower, upper] of pursuers an environment needs (see bounds.hpp).
#include <preimage/pursuit/bounds.hpp>
#include <preimage/pursuit/figures.hpp>
#include <preimage/geometry/coordinates.hpp>

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace preimage::pursuit {

namespace {
std::string count(std::size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }
}  // namespace

PursuerBounds pursuer_bounds(const geometry::Environment& env, const BoundsOptions& o) {
  // A plan that fails the checker is a bug, not an answer.
  auto check = [&](const Plan& plan, const std::string& source) {
    CheckOptions co;
    if (o.check_frames) co.frames = frame_waypoints(plan.paths[0].size(), o.check_frames);
    CheckResult r = check_paths(env, plan.paths, co);
    if (!r.cleared)
      throw std::logic_error("pursuit: the " + source + "'s plan with " + count(plan.paths.size(), "pursuer", "pursuers") +
                             " fails the independent check (" + count(r.contaminated_at_end.size(), "region", "regions") +
                             " contaminated at the end)");
    return r;
  };
  // With a range the plans below are for unlimited sight: checked with the range at the end.
  const bool limited = o.range != 0;
  if (limited) range_sensor(o.range, o.range_sides);  // a bad range is refused before any work
  const bool check_unlimited = o.check && !limited;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  // Every search gets what is left of the time budget (at least a moment, so that a
  // search always starts and reports its budget).
  auto left = [&] { return std::max(1e-3, o.time_limit - std::chrono::duration<double>(Clock::now() - t0).count()); };
  auto say = [&](const std::string& s) {
    if (o.progress) o.progress(s);
  };
  PursuerBounds b;
  b.holes = env.num_holes();
  b.lower_reason = "the evader may be anywhere";
  if (b.holes > 0) {
    b.lower = 2;
    b.lower_reason = "free space has " + count(b.holes, "hole", "holes") + ": one pursuer never clears a hole (Guibas et al. 1999)";
  }
  std::optional<ConservativeCells> cells;
  auto build_cells = [&] {
    if (cells) return;
    say("building the conservative cells");
    cells.emplace(ConservativeCells::build(env));
  };
  if (b.holes == 0) {
    build_cells();
    say("searching with one pursuer (" + count(cells->size(), "cell", "cells") + ")");
    SearchOptions so{o.start, o.max_states, false, left(), o.max_mb};
    const SearchResult any = b.searches.emplace_back(search(*cells, 1, so));  // a copy: more searches follow
    b.roles.push_back("any plan");
    if (any.outcome == SearchResult::Outcome::Plan) {
      b.upper = 1;
      b.plan = any.plan;
      b.plan_source = "search";
      b.upper_reason = "a plan found by the one-pursuer search";
      if (o.shortest) {
        // The shortest plan, within twice the time the first plan took (or a second): the
        // answer stays within three times that of the any-plan search.
        say("searching for the shortest one-pursuer plan");
        so.shortest = true;
        so.time_limit = std::min(left(), std::max(2 * any.seconds, 1.0));
        const SearchResult& shortest = b.searches.emplace_back(search(*cells, 1, so));
        b.roles.push_back("shortest plan");
        if (shortest.outcome == SearchResult::Outcome::Plan) b.plan = shortest.plan, b.shortest = true;
      }
    } else if (any.outcome == SearchResult::Outcome::NoPlan && !env.has_contacts()) {
      // With contact points the search's pursuer never passes through one: its "no
      // plan" covers only such paths, and proves nothing about H(W).
      b.lower = 2;
      b.lower_reason = "the complete one-pursuer search finds no plan (" + std::to_string(any.states) + " information states)";
    }
  }
  if (!b.plan) {
    say("static-guard strategy");
    b.strategy = split_strategy(env, o.start);
    b.upper = b.strategy->pursuers;
    b.plan = b.strategy->plan;
    b.plan_source = "strategy";
    b.upper_reason = "the static-guard strategy: " + count(b.strategy->guards, "guard", "guards") + ", " +
                     count(b.strategy->regions, "region", "regions") + " cleared by one pursuer from " + count(b.strategy->stops, "stop", "stops");
    // The strategy's plan is checked before the searches try for fewer pursuers, so the
    // upper end is certified first and the searches get what is left of the time budget
    // (the check of office 848's plan takes half a minute; after a 45 s search the answer
    // came in 85 s).
    const std::size_t first_k = std::max<std::size_t>(b.lower, 2);
    if (check_unlimited && first_k < b.upper && first_k <= o.max_pursuers) {
      say("checking the static-guard plan");
      b.check = check(*b.plan, b.plan_source);
    }
    for (std::size_t k = first_k; k < b.upper && k <= o.max_pursuers; ++k) {
      build_cells();
      say("searching with " + std::to_string(k) + " pursuers");
      const SearchResult& r = b.searches.emplace_back(search(*cells, k, {o.start, o.max_states, false, left(), o.max_mb}));
      b.roles.push_back(std::to_string(k) + " pursuers");
      if (r.outcome != SearchResult::Outcome::Plan) continue;
      b.upper = k;
      b.plan = r.plan;
      b.check.reset();  // the new plan is checked below
      b.plan_source = "joint search";
      b.upper_reason = "a plan found by the " + std::to_string(k) + "-pursuer search";
      break;
    }
  }
  cells.reset();  // the check needs none of it (house 1451: 41,440 cells)
  if (check_unlimited && !b.check) {
    say("checking the plan");
    b.check = check(*b.plan, b.plan_source);
  }
  if (limited) {
    const std::string R = geometry::format_number(o.range);
    say("checking the plan with range " + R);
    CheckOptions co;
    co.range = o.range, co.range_sides = o.range_sides;
    if (o.check_frames) co.frames = frame_waypoints(b.plan->paths[0].size(), o.check_frames);
    CheckResult r = check_paths(env, b.plan->paths, co);
    if (r.cleared) {
      b.check = std::move(r);
      b.upper_reason += ", which also clears with range " + R;
    } else {
      say("posting a static range cover");
      const std::size_t unlimited = b.upper;
      b.cover = static_range_cover(env, o.range, o.range_sides, o.start);
      b.upper = b.cover->guards.size();
      b.plan = b.cover->plan;
      b.plan_source = "range cover";
      if (o.check_frames) {
        co.frames = frame_waypoints(b.plan->paths[0].size(), o.check_frames);
        b.check = check_paths(env, b.plan->paths, co);
      } else {
        b.check = b.cover->check;
      }
      b.upper_reason = count(b.upper, "guard", "guards") + " standing where together they see all of free space within range " + R +
                       " (a static cover; the plan for unlimited sight with " + count(unlimited, "pursuer", "pursuers") +
                       " leaves " + count(r.contaminated_at_end.size(), "region", "regions") + " with this range)";
    }
  }
  return b;
}

}  // namespace preimage::pursuit
