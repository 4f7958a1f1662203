// SPDX-License-Identifier: Apache-2.0
// The landmark robot's tasks (landmark paper, sections 5-8): the hull tour that yields
// the whole order type (5), patrolling (Strategy 6), navigation to a cyclic permutation
// (Strategy 7) and the swap graph inside (Strategy 8) and outside (Strategy 9) the hull.
// Every strategy drives a RobotInterface and sees readings only; the planning parts
// (patrol_route, polar_pairs) take an order type as a chirotope, learned or true.
#pragma once
#include <preimage/landmarks/order_type.hpp>
#include <preimage/landmarks/robot.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace preimage::landmarks {

/// An order type as the robot holds it: left(i, j, k) iff p_k is left of p_i -> p_j.
class LearnedOrderType {
 public:
  explicit LearnedOrderType(std::size_t n) : n_(n), left_(n * n * n, 0), known_(n * n, 0) {}
  std::size_t size() const { return n_; }
  int chi(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    return i == j || j == k || i == k ? 0 : (left_[(std::size_t(i) * n_ + j) * n_ + k] ? 1 : -1);
  }
  std::vector<std::uint32_t> Lambda(std::uint32_t i, std::uint32_t j) const;
  /// Records Lambda(i, j) = left (and Lambda(j, i) = the rest).
  void set(std::uint32_t i, std::uint32_t j, std::span<const std::uint32_t> left);
  bool complete() const;
  Chirotope chirotope() const {
    return [this](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return chi(i, j, k); };
  }

 private:
  std::size_t n_;
  std::vector<std::uint8_t> left_, known_;
};

/// Section 5 / 6.1: learn the hull (Strategies 4-5), then track the hull landmarks once
/// around. Every swap on the way is a line through two landmarks: the landmarks ahead of
/// the pair (from the tracked landmark on) are on one side, the rest on the other; at
/// each hull landmark the reading gives Lambda of every pair with it. O(n) primitives.
struct HullTour {
  std::vector<std::uint32_t> hull;
  LearnedOrderType order_type;
  /// The readings on the tour, each rotated to start at the tracked landmark (the
  /// permutations of the dual arrangement, section 5).
  std::vector<Reading> permutations;
};
HullTour learn_by_hull_tour(RobotInterface& robot);

/// Strategy 6 (patrolling): the smallest M containing W with no landmark of W on the
/// boundary of hull(M); `route` is that boundary counter-clockwise (M = W and route).
/// Found as a shortest directed cycle over edges a -> b with all of W strictly left
/// (every such cycle winds around W), which is exact where peeling the hull one landmark
/// at a time (Corollary 5) only gives an inclusion-minimal M. InputError when W meets
/// the boundary of hull(L).
struct PatrolPlan {
  std::vector<std::uint32_t> route;
  std::vector<std::uint32_t> M;  // sorted
};
PatrolPlan patrol_route(std::size_t n, const Chirotope& chi, std::span<const std::uint32_t> hull,
                        std::span<const std::uint32_t> W, const std::vector<std::string>& labels = {});

/// Polar pairs of g (6.2): consecutive (i, j) in g such that the labels right after them
/// start with Lambda(i, j) or Lambda(j, i).
std::vector<std::pair<std::uint32_t, std::uint32_t>> polar_pairs(std::size_t n, const Chirotope& chi, const Reading& g);
/// The polar lines of g that meet another polar line on the swap lines of both, as far as
/// the order type tells (they share a landmark, or by Lemmas 11-12 each pair lies on one
/// side of the other's line; parallel lines pass too, so no line that meets another is
/// left out). The swap lines on a cell's boundary are among them (Lemma 9; see docs).
std::vector<std::pair<std::uint32_t, std::uint32_t>> meeting_polar_lines(std::size_t n, const Chirotope& chi, const Reading& g);
/// Why g cannot be read in a cell meeting the hull, from the order type alone, or nullopt:
/// Lemma 3 (hull order), and Lemma 10 in the form that holds: some two polar lines meet
/// on their swap lines (the paper's "every polar line meets another" is false, see
/// docs/landmarks.md). Necessary conditions only; landmarks are named by `labels`.
std::optional<std::string> unrealizable_reason(std::size_t n, const Chirotope& chi, std::span<const std::uint32_t> hull,
                                               const Reading& g, const std::vector<std::string>& labels = {});

/// Strategy 7: navigate until the detector reads g in a cell meeting the hull, or report
/// that g is not realizable there. After the fast rejections of unrealizable_reason the
/// robot reads every cell meeting the hull that g could be: along the hull boundary, and
/// along the part inside the hull of every swap line of an interior landmark on a polar
/// line that meets another (Lemma 9), stepping into g's cell when one side reads g. "Not
/// realizable" is thus concluded from readings, not from a lemma about the geometry.
struct NavigationResult {
  bool reached = false;
  std::string reason;  // why not, when not reached
  std::vector<std::pair<std::uint32_t, std::uint32_t>> polar;
  std::size_t swap_lines_searched = 0;
};
NavigationResult navigate(RobotInterface& robot, const Chirotope& chi, std::span<const std::uint32_t> hull, const Reading& goal,
                          const std::vector<std::string>& labels = {});

/// A swap graph as the robot learns it: cells with their permutations, and for
/// Strategy 9 the arrangement vertices each cell was seen to touch (keys as in
/// SwapCellDecomposition::vertex_keys).
struct LearnedSwapGraph {
  struct Cell {
    Reading permutation;
    std::vector<std::vector<std::uint32_t>> vertex_keys;
  };
  struct Edge {
    std::uint32_t a, b, i, j;
  };
  std::vector<Cell> cells;
  std::vector<Edge> edges;  // a < b, sorted, one per pair of cells
};
/// Strategy 8: the swap graph of the cells meeting the hull, with track only (Theorem 7:
/// a reading names its cell). Enters each swap line of an interior landmark where it
/// crosses the hull boundary (Lemma 11) and tracks along it to its landmark.
LearnedSwapGraph learn_inside_swap_graph(RobotInterface& robot, const Chirotope& chi, std::span<const std::uint32_t> hull);
/// Strategy 9: the whole swap graph with repel: every swap line from its landmark outwards.
/// Cells seen on different lines merge when they read the same and share an arrangement
/// vertex (Lemma 6), or read a permutation of a cell meeting the hull (Theorem 14).
/// n(n - 1) repels with O(n^2) events each: Theta(n^4) time and memory; `progress` is
/// told the fraction done now and then.
LearnedSwapGraph learn_swap_graph(RobotInterface& robot, const LearnedSwapGraph& inside, const std::function<void(double)>& progress = {});

}  // namespace preimage::landmarks
