// SPDX-License-Identifier: Apache-2.0
// The constructive strategy of 6.3 for simply connected free space: if a chord splits
// W into W1 and W2, then H(W) <= max(H(W1), H(W2)) + 1 — keep a "static pursuer" on the
// chord and clear W1, then W2, with the others. Splitting the triangulation's dual tree
// at balanced edges makes the depth O(log n) (each part keeps at least a third of the
// triangles), so O(log n) pursuers always suffice.
//
// Here a region is a connected set of triangles of geometry::Triangulation, bounded by
// walls and by chords whose guards stand inside a triangle next to the chord (a triangle
// is convex, so its interior sees the whole chord: nobody crosses unseen). A region whose
// kernel (exact half-plane intersection) holds a double point is cleared by one pursuer
// standing there (the book's base case is a triangle); a region one pursuer can clear on
// its own (exhaustive search of 6.3 in that region alone) by one pursuer walking that
// plan; otherwise it is split at a balanced dual edge, preferring star-shaped sides.
// Travel between triangles goes through points next to the shared diagonals, every
// segment certified with geometry::visible.
#pragma once
#include <preimage/pursuit/search.hpp>

namespace preimage::pursuit {

struct SplitResult {
  Plan plan;
  std::size_t pursuers = 0;  // used: the deepest nesting of guards, plus the one who clears
  std::size_t guards = 0;    // chords guarded over the whole plan
  std::size_t regions = 0;   // regions cleared by one pursuer (star-shaped, or by its own search)
};

/// Throws InputError if the environment has holes (the O(sqrt(h) + log n) construction
/// with trichromatic triangles is not implemented) or the start is not in free space.
/// `search_regions`: also clear regions one pursuer can clear by search (false: only
/// star-shaped regions, the book's construction as stated).
SplitResult split_strategy(const geometry::Environment& env, const std::optional<Point>& start = std::nullopt,
                           bool search_regions = true);

}  // namespace preimage::pursuit
