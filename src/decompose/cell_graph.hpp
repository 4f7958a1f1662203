// SPDX-License-Identifier: Apache-2.0
// Private to decompose: cell adjacency from groups of cells that meet (at one critical
// slice, one slice interval...), shared by the Morse and brushfire decompositions.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

namespace preimage::decompose::detail {

/// Cells a and b are adjacent when some group holds both; lists sorted, without repeats.
inline std::vector<std::vector<std::uint32_t>> adjacency_from_groups(const std::vector<std::vector<std::uint32_t>>& groups, std::size_t cells) {
  std::vector<std::vector<std::uint32_t>> adj(cells);
  for (const auto& list : groups)
    for (const std::uint32_t a : list)
      for (const std::uint32_t b : list)
        if (a != b) adj[a].push_back(b);
  for (auto& l : adj) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
  }
  return adj;
}

}  // namespace preimage::decompose::detail
