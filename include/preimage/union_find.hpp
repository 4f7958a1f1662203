// SPDX-License-Identifier: Apache-2.0
// Disjoint sets over indices 0..n-1 with path halving: merges cells, vertices and
// records in decompose and landmarks.
#pragma once
#include <cstdint>
#include <numeric>
#include <vector>

namespace preimage {

struct UnionFind {
  std::vector<std::uint32_t> p;
  explicit UnionFind(std::size_t n = 0) { grow(n); }
  /// Adds singletons until there are n elements.
  void grow(std::size_t n) {
    const std::size_t old = p.size();
    if (n <= old) return;
    p.resize(n);
    std::iota(p.begin() + static_cast<std::ptrdiff_t>(old), p.end(), static_cast<std::uint32_t>(old));
  }
  std::uint32_t find(std::uint32_t x) {
    while (p[x] != x) x = p[x] = p[p[x]];
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) { p[find(a)] = find(b); }
};

}  // namespace preimage
