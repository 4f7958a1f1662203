// SPDX-License-Identifier: Apache-2.0
#include "cell_merging.hpp"

#include "cell_sweep.hpp"

#include <algorithm>
#include <tuple>

namespace preimage::coverage::detail {

std::vector<SweepRegion> single_cells(const decompose::BoustrophedonDecomposition& b, const std::vector<std::size_t>& cells) {
  std::vector<SweepRegion> out;
  for (std::size_t c : cells) out.push_back({{static_cast<std::uint32_t>(c)}, b.cells()[c].trapezoids});
  return out;
}

std::vector<SweepRegion> merge_monotone_cells(const decompose::BoustrophedonDecomposition& b, const std::vector<std::size_t>& cells,
                                              double w) {
  constexpr std::uint32_t kNone = UINT32_MAX;
  const auto& C = b.cells();
  std::vector<std::uint32_t> cell_of(b.trapezoids().cells().size(), kNone);
  for (std::size_t c : cells)
    for (std::uint32_t t : C[c].trapezoids) cell_of[t] = static_cast<std::uint32_t>(c);
  // Pairs a -> b across a critical slice: a's last trapezoid and b's first meet on an
  // extension (a segment of the slice line), so the run a.trapezoids, b.trapezoids is
  // x-monotone and connected through a piece of the slice of positive length.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& e : b.trapezoids().extensions()) {
    const std::uint32_t l = cell_of[e.left_cell], r = cell_of[e.right_cell];
    if (l == kNone || r == kNone || l == r) continue;
    if (C[l].trapezoids.back() != e.left_cell || C[r].trapezoids.front() != e.right_cell) continue;
    pairs.emplace_back(l, r);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  if (pairs.empty()) return single_cells(b, cells);

  const std::size_t n = C.size();
  std::vector<std::size_t> laps(n, 0), left(n, 0);
  for (std::size_t c : cells) laps[c] = lap_positions(b, C[c].trapezoids, w, &left[c]).size();
  auto run = [&](const std::vector<std::uint32_t>& chain) {
    std::vector<std::uint32_t> ts;
    for (std::uint32_t c : chain) ts.insert(ts.end(), C[c].trapezoids.begin(), C[c].trapezoids.end());
    return ts;
  };
  // Pairwise savings first, then each merge re-counted on the regions merged so far (a
  // region's laps are not the sum of its pairs').
  // A union whose laps leave boundary samples no lap reaches (a step of the boundary next
  // to the union's end, where laps keep w/2 inside) is not merged.
  std::vector<std::tuple<long, std::uint32_t, std::uint32_t, std::size_t, std::size_t>> ranked;  // -saved, l, r, laps, left out
  for (const auto& [l, r] : pairs) {
    std::size_t out = 0;
    const std::size_t both = lap_positions(b, run({l, r}), w, &out).size();
    const long saved = static_cast<long>(laps[l] + laps[r]) - static_cast<long>(both);
    if (saved >= 1 && out <= left[l] + left[r]) ranked.emplace_back(-saved, l, r, both, out);
  }
  std::sort(ranked.begin(), ranked.end());
  std::vector<std::uint32_t> next(n, kNone), prev(n, kNone);
  auto head = [&](std::uint32_t c) {
    while (prev[c] != kNone) c = prev[c];
    return c;
  };
  auto chain_through = [&](std::uint32_t c) {
    std::vector<std::uint32_t> chain;
    for (c = head(c); c != kNone; c = next[c]) chain.push_back(c);
    return chain;
  };
  std::vector<std::size_t> region_laps = laps, region_left = left;  // of the region a cell heads
  for (const auto& [neg, l, r, pair_laps, pair_out] : ranked) {
    if (next[l] != kNone || prev[r] != kNone) continue;
    std::vector<std::uint32_t> both = chain_through(l);
    const std::vector<std::uint32_t> after = chain_through(r);
    both.insert(both.end(), after.begin(), after.end());
    std::size_t out = pair_out, merged = pair_laps;  // two cells: counted above
    if (both.size() > 2) merged = lap_positions(b, run(both), w, &out).size();
    if (merged + 1 > region_laps[head(l)] + region_laps[head(r)] || out > region_left[head(l)] + region_left[head(r)]) continue;
    region_laps[head(l)] = merged, region_left[head(l)] = out;
    next[l] = r, prev[r] = l;
  }
  std::vector<SweepRegion> out;
  for (std::size_t c : cells) {
    if (prev[c] != kNone) continue;
    SweepRegion reg;
    reg.cells = chain_through(static_cast<std::uint32_t>(c));
    reg.trapezoids = run(reg.cells);
    out.push_back(std::move(reg));
  }
  return out;
}

}  // namespace preimage::coverage::detail
