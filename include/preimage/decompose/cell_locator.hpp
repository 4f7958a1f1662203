// SPDX-License-Identifier: Apache-2.0
// Point location in a trapezoidal decomposition, O(log n) expected per query: the slab
// method of section 6.1 (binary search for the slab between event abscissae, then a
// search among the cells crossing it), with the per-slab orders stored as one
// persistent treap (path copying), so preprocessing is O(n log n) time and space.
#pragma once
#include <preimage/decompose/trapezoidal.hpp>

#include <optional>

namespace preimage::decompose {

class CellLocator {
 public:
  /// Copies what it needs from d: the locator may outlive the decomposition.
  explicit CellLocator(const TrapezoidalDecomposition& d);
  /// The cell whose closure contains q, or none when q is not in closed free space.
  /// A point on an extension belongs to two cells; either may be returned.
  std::optional<std::uint32_t> locate(const Point& q) const;

 private:
  struct Node { std::uint32_t cell, prio, left, right; };
  std::uint32_t insert(std::uint32_t root, std::uint32_t cell);
  std::uint32_t erase(std::uint32_t root, std::uint32_t cell);
  std::uint32_t merge(std::uint32_t a, std::uint32_t b);
  std::uint32_t copy(std::uint32_t n);
  bool cell_below(std::uint32_t a, std::uint32_t b) const;  // a's floor below b's floor in a shared slab
  std::optional<std::uint32_t> search(std::uint32_t root, const Point& q) const;

  // Floor and ceiling of each cell, left end first: the search reads only this array.
  struct Bounds { Point floor_l, floor_r, ceil_l, ceil_r; };
  std::vector<Bounds> bounds_;
  std::vector<double> xs_;             // distinct event abscissae
  // Uniform buckets over [xs_.front(), xs_.back()]: bucket b holds the index of the last
  // abscissa at or before its left end, so finding the slab is a short scan, not a
  // binary search through a large array (which costs a cache miss per step).
  std::vector<std::uint32_t> bucket_;
  double bucket_scale_ = 0;
  std::vector<std::uint32_t> roots_;   // treap root per slab (xs_[j], xs_[j+1])
  std::vector<Node> nodes_;
  std::uint64_t rng_ = 0x9E3779B97F4A7C15ull;
};

}  // namespace preimage::decompose
