// SPDX-License-Identifier: Apache-2.0
// The constructive strategy of 6.3: if a static guard's view separates W into parts,
// H(W) <= max H(part) + 1 — keep the guard still and clear the parts one at a time with
// the others. Free space is triangulated (holes included); a region is a set of
// triangles bounded by walls and by edges some standing guard sees whole. A region whose
// kernel (exact half-plane intersection) holds a double point is cleared by one pursuer
// standing there; a simply connected region one pursuer can clear on its own (exhaustive
// search of 6.3 in that region alone) by one pursuer walking that plan; otherwise a guard
// goes to the centre of one of its triangles, chosen to leave the fewest holes in any
// part, then the smallest largest part (balanced cuts keep the nesting logarithmic).
// The book places its static pursuers in trichromatic triangles (corners on three
// rings); that does not cut a lone hole (docs/pursuit.md), so every triangle is a
// candidate. Travel goes through points next to shared edges, every segment certified
// with geometry::visible.
#pragma once
#include <preimage/pursuit/search.hpp>

namespace preimage::pursuit {

struct SplitResult {
  Plan plan;
  std::size_t pursuers = 0;  // used: the deepest nesting of guards, plus the one who clears
  std::size_t guards = 0;    // static guards posted over the whole plan
  std::size_t regions = 0;   // regions cleared by one pursuer (star-shaped, or by its own search)
  std::size_t stops = 0;     // where a pursuer went to clear them: a point seeing several, or a walk
  std::size_t trichromatic = 0;  // triangles with corners on three different rings (6.3)
  std::vector<Point> guard_points;  // where each static guard stood, in plan order
};

/// Works on every environment. Throws InputError if the start is not in free space.
/// `search_regions`: also clear regions one pursuer can clear by search (false: only
/// star-shaped regions, the book's construction as stated).
SplitResult split_strategy(const geometry::Environment& env, const std::optional<Point>& start = std::nullopt,
                           bool search_regions = true);

}  // namespace preimage::pursuit
