// SPDX-License-Identifier: Apache-2.0
// How many pursuers does this environment need? H(W) as an interval [lower, upper], each
// end with its reason, answered within a time budget whatever the environment:
//   - lower: 1; 2 if free space has a hole (one pursuer never clears a hole, Guibas et
//     al. 1999) or the complete one-pursuer search of 6.3 finds no plan;
//   - upper: a plan the independent checker clears — the one-pursuer search's, the
//     static-guard strategy's (split.hpp: works on every environment), or the k-pursuer
//     search's for k below that (not complete for k >= 2: it can lower the upper end,
//     never raise the lower one).
#pragma once
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/pursuit/split.hpp>
#include <preimage/pursuit/static_cover.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace preimage::pursuit {

struct BoundsOptions {
  std::optional<Point> start;     // every pursuer starts here (unset: anywhere)
  /// Seconds from the start for all searches together (the strategy always runs). The
  /// strategy's plan is checked before the searches for fewer pursuers, within this time.
  double time_limit = 45;
  std::size_t max_states = 4'000'000;
  std::size_t max_mb = 2048;      // per search
  std::size_t max_pursuers = 3;   // the k-pursuer search is tried for k below the upper end, up to this
  /// One pursuer: after a plan is found, look for the shortest, for twice the time the
  /// first search took (at least a second).
  bool shortest = true;
  bool check = true;              // run the independent checker on the plan (false: the plan is not certified)
  std::size_t check_frames = 0;   // moments the check records for a figure (frame_waypoints)
  /// > 0: pursuers see only within this distance (CheckOptions::range). The lower end
  /// stands (a weaker sensor never needs fewer pursuers); the upper end is the plan above
  /// if the range check clears it, else a static range cover (static_cover.hpp). The plan
  /// is always checked with the range then.
  double range = 0;
  std::size_t range_sides = 32;
  /// Called with a line about each step (a terminal shows progress).
  std::function<void(const std::string&)> progress;
};

struct PursuerBounds {
  std::size_t lower = 1, upper = 0;  // upper 0: no plan found
  std::string lower_reason, upper_reason;
  std::size_t holes = 0;
  std::vector<SearchResult> searches;  // every search run, in order
  std::vector<std::string> roles;      // what each search was for: "any plan", "shortest plan", "k pursuers"
  std::optional<SplitResult> strategy; // the static-guard strategy, when it ran
  std::optional<Plan> plan;            // achieves `upper`
  std::string plan_source;             // "search", "strategy" or "joint search"
  /// One pursuer: whether the plan is the shortest by walk length between cell samples
  /// (false: the shortest-first search ran out of its budget, the plan is the first found).
  bool shortest = false;
  std::optional<CheckResult> check;
  std::optional<StaticCover> cover;    // with a range, when the plan above did not clear
  bool exact() const { return upper == lower; }
  /// Where the plan's static guards stand (none unless the plan is the strategy's or a cover).
  std::vector<Point> guard_points() const {
    if (cover && plan_source == "range cover") return cover->guards;
    return strategy && plan_source == "strategy" ? strategy->guard_points : std::vector<Point>{};
  }
};

/// Throws InputError if the start is not in free space; std::logic_error if a plan fails
/// the independent checker (a bug, never an answer).
PursuerBounds pursuer_bounds(const geometry::Environment& env, const BoundsOptions& options = {});

}  // namespace preimage::pursuit
