// SPDX-License-Identifier: Apache-2.0
// Order types of landmark sets (landmark paper, section 3): the chirotope chi, the sets
// Lambda(i, j) of landmarks left of the directed line p_i p_j and their sizes
// lambda(i, j), the chirotope and Knuth axioms as checks on any given Lambda, and a
// canonical form up to relabelling (optionally also reflection) so that point sets can
// be compared and distinct order types counted.
//
// OrderType is built from coordinates by an exact angular sort around each landmark
// (O(n^2 log n)); lambda(i, .) then follows by one rotating sweep, and chi(i, j, k) is
// read off the sorted orders in O(1) (k is left of p_i p_j iff it comes within the
// lambda(i, j) landmarks after j counter-clockwise around i).
#pragma once
#include <preimage/geometry/kernel.hpp>
#include <preimage/scene/scene.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace preimage::landmarks {

/// Labelled landmarks (section 2): label i is landmark p_i; indices are 0-based.
struct LandmarkSet {
  std::vector<std::string> labels;
  std::vector<geometry::Point> points;
  std::size_t size() const { return points.size(); }
};

/// The scene's landmarks, validated: at least three, distinct labels, no two equal and
/// no three collinear (InputError names them: "$.landmarks[1] ('b'), $.landmarks[4]
/// ('e') and $.landmarks[6] ('g') are collinear").
LandmarkSet landmark_set(const scene::Scene& scene);
/// The same check on bare points (names them by index); O(n^2 log n).
void require_general_position(std::span<const geometry::Point> points, const std::vector<std::string>& names = {});

class OrderType {
 public:
  /// From coordinates in general position (checked; InputError otherwise).
  static OrderType of(std::span<const geometry::Point> points);
  /// From an abstract sign function (e.g. learned by a robot) that must be a realizable
  /// order type's chirotope for lambda/around to mean anything; used for checks.
  std::size_t size() const { return n_; }

  /// +1 if p_i p_j p_k is counter-clockwise, -1 if clockwise, 0 unless distinct.
  int chi(std::uint32_t i, std::uint32_t j, std::uint32_t k) const;
  std::uint32_t lambda(std::uint32_t i, std::uint32_t j) const { return lambda_[std::size_t(i) * n_ + j]; }
  /// Lambda(i, j): landmarks to the left of p_i -> p_j, sorted.
  std::vector<std::uint32_t> Lambda(std::uint32_t i, std::uint32_t j) const;
  /// The other landmarks counter-clockwise around p_i, starting from the direction east.
  std::span<const std::uint32_t> around(std::uint32_t i) const { return {order_.data() + std::size_t(i) * (n_ - 1), n_ - 1}; }
  /// The convex hull boundary, counter-clockwise, starting at the landmark of least index.
  std::vector<std::uint32_t> hull() const;

 private:
  std::size_t n_ = 0;
  std::vector<std::uint32_t> order_;   // n x (n-1): angular order around each landmark
  std::vector<std::uint32_t> rank_;    // n x n: position of k in order around i
  std::vector<std::uint32_t> lambda_;  // n x n
};

/// A chirotope given as a sign function on ordered triples of distinct indices.
using Chirotope = std::function<int(std::uint32_t, std::uint32_t, std::uint32_t)>;
/// Chirotope of a given Lambda: chi(i, j, k) = +1 iff k in Lambda(i, j), else -1.
Chirotope chirotope_of(std::size_t n, const std::function<std::vector<std::uint32_t>(std::uint32_t, std::uint32_t)>& Lambda);

/// The first violated axiom, as "axiom 4 (inside a triangle) fails for 1 2 3 4", or
/// nullopt. Knuth's five axioms (section 3.1; O(n^5)) and the chirotope axioms
/// (non-zero, alternating, and the three exchange conditions; O(n^6)): for small n.
std::optional<std::string> knuth_violation(std::size_t n, const Chirotope& chi);
std::optional<std::string> chirotope_violation(std::size_t n, const Chirotope& chi);

/// Canonical form: the lambda matrix under the lexicographically least labelling that
/// starts at a hull landmark and numbers the others counter-clockwise around it. Two
/// order types are equal up to relabelling iff their canonical forms are equal; with
/// `mirror`, also up to reflection.
struct CanonicalForm {
  std::uint32_t n = 0;
  std::vector<std::uint16_t> lambda;  // n x n, row-major, in canonical labels
  std::vector<std::uint32_t> labelling;  // canonical label -> original index
  bool mirrored = false;
  friend bool operator==(const CanonicalForm& a, const CanonicalForm& b) { return a.n == b.n && a.lambda == b.lambda; }
  friend bool operator<(const CanonicalForm& a, const CanonicalForm& b) {
    return a.n != b.n ? a.n < b.n : a.lambda < b.lambda;
  }
};
CanonicalForm canonical_form(const OrderType& order_type, bool mirror = false);

/// n random landmarks with integer coordinates in [-range, range], redrawn until in
/// general position (seeded, reproducible); `redrawn` counts the degenerate draws.
std::vector<geometry::Point> random_landmarks(std::size_t n, std::uint64_t seed, int range = 1 << 20, std::size_t* redrawn = nullptr);

/// Distinct order types among `samples` random sets of n landmarks in general position
/// (integer coordinates, seeded); the tool for checking canonical forms.
struct OrderTypeCount {
  std::size_t distinct = 0, samples = 0, redrawn = 0;
};
/// Time and memory grow as samples * n^2 (one canonical form kept per distinct type);
/// `progress` is told the fraction done now and then.
OrderTypeCount count_order_types(std::size_t n, std::size_t samples, std::uint64_t seed, bool mirror,
                                 const std::function<void(double)>& progress = {});

}  // namespace preimage::landmarks
