// SPDX-License-Identifier: Apache-2.0
// The free group F_n (beams paper, Appendix A): words over generators s_1..s_n and
// their inverses, kept freely reduced. The fundamental group of the plane with n
// obstacles is F_n, so a reduced word names one homotopy class of loops (section 5),
// and its abelianisation is the winding vector (section 6).
#pragma once
#include <compare>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace preimage::beams {

/// A letter of F_n: +(g+1) is generator g, -(g+1) its inverse. 0 is not a letter.
using Letter = std::int32_t;
inline Letter generator(std::uint32_t g) { return static_cast<Letter>(g) + 1; }
inline std::uint32_t generator_of(Letter x) { return static_cast<std::uint32_t>(x < 0 ? -x : x) - 1; }

/// An element of F_n as its freely reduced word. Appending a letter cancels against the
/// last one when they are inverse, so building a word letter by letter is O(1)
/// amortised per letter and the stored word is always the reduced one.
class FreeWord {
 public:
  FreeWord() = default;
  /// The reduced word of any letter sequence, in linear time (one stack pass).
  static FreeWord reduce(std::span<const Letter> letters);

  /// this <- this * x.
  void push(Letter x) {
    if (!letters_.empty() && letters_.back() == -x) letters_.pop_back();
    else letters_.push_back(x);
  }
  /// this <- this * w.
  FreeWord& operator*=(const FreeWord& w);
  friend FreeWord operator*(FreeWord a, const FreeWord& b) { return a *= b; }
  FreeWord inverse() const;

  bool identity() const { return letters_.empty(); }
  std::size_t length() const { return letters_.size(); }
  std::span<const Letter> letters() const { return letters_; }

  /// Exponent sum of each of the first `rank` generators: the image in Z^rank = H_1.
  std::vector<std::int64_t> abelianised(std::size_t rank) const;
  /// "a b a' b'" with generator names, or "1" for the identity.
  std::string format(const std::vector<std::string>& names) const;

  friend bool operator==(const FreeWord&, const FreeWord&) = default;
  /// Shortlex order (shorter first), for stable listings.
  friend std::strong_ordering operator<=>(const FreeWord& a, const FreeWord& b);

 private:
  std::vector<Letter> letters_;
};

/// The Cayley graph of F_n with respect to its free basis is a tree, grown here on
/// demand: a node is a reduced word, its parent the word without its last letter. Two
/// words are equal iff their nodes are, so sets of group elements are sets of integers,
/// and multiplying by a letter is one hash lookup (or a step to the parent).
class CayleyTree {
 public:
  using Node = std::uint32_t;
  static constexpr Node kIdentity = 0;

  CayleyTree() : parent_{kIdentity}, last_{0}, depth_{0} {}
  Node times(Node w, Letter x);
  Node times(Node w, std::span<const Letter> u) {
    for (Letter x : u) w = times(w, x);
    return w;
  }
  Node times(Node w, const FreeWord& u) { return times(w, u.letters()); }
  FreeWord word(Node w) const;
  std::size_t length(Node w) const { return depth_[w]; }
  std::size_t num_nodes() const { return parent_.size(); }

 private:
  std::vector<Node> parent_;
  std::vector<Letter> last_;
  std::vector<std::uint32_t> depth_;
  std::unordered_map<std::uint64_t, Node> child_;
};

}  // namespace preimage::beams
