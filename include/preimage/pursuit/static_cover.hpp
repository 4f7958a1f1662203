// SPDX-License-Identifier: Apache-2.0
// An upper bound for pursuers who see only within a range (CheckOptions::range): guards
// standing still who together see all of free space within range — no evader survives the
// moment they are all posted. Chosen greedily on a grid of sample points (the candidate
// that sees the most samples not yet seen, through the checker's inscribed sensor polygon),
// then completed where the exact check finds a region left (a guard posted inside it), and
// certified by that check. A cover, not a search: the range-limited static-guard strategy,
// which moves pursuers, would need fewer.
#pragma once
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/search.hpp>

#include <optional>

namespace preimage::pursuit {

struct StaticCover {
  std::vector<Point> guards;
  Plan plan;            // each guard's walk from the start to its post, one after another (or the post alone)
  CheckResult check;    // with the range: cleared
  std::size_t samples = 0, completions = 0;  // grid samples; guards added for regions the samples missed
};

/// Throws InputError for a bad range or a start outside free space; std::logic_error if
/// the check still finds a region after 200 completions (never seen).
StaticCover static_range_cover(const geometry::Environment& env, double range, std::size_t range_sides = 32,
                               const std::optional<Point>& start = std::nullopt);

}  // namespace preimage::pursuit
