// SPDX-License-Identifier: Apache-2.0
// The nondeterministic filter of the beams paper, 4.1: the I-state is the set of
// possible states (regions) and R_{k+1} = phi(R_k, y_{k+1}) marks every successor
// of a marked state under y. The cost of one update is proportional to the marked
// states and their out-transitions, not to the size of the system.
#pragma once
#include <preimage/filter/transition_system.hpp>

#include <vector>

namespace preimage::filter {

class SubsetFilter {
 public:
  /// Starts from `initial` (any order, duplicates ignored) or, if empty, from all states.
  explicit SubsetFilter(const TransitionSystem& system, const std::vector<State>& initial = {});
  SubsetFilter(TransitionSystem&&, const std::vector<State>& = {}) = delete;  // keeps a pointer to the system

  /// One observation. Returns false if the I-state became empty (no state explains it).
  bool step(Symbol y);
  /// Current I-state, in the order states were marked (use sorted() for a canonical form).
  const std::vector<State>& current() const { return cur_; }
  std::vector<State> sorted() const;
  bool empty() const { return cur_.empty(); }
  bool contains(State s) const;
  /// Replaces the I-state (e.g. after a cache flush elsewhere).
  void reset(const std::vector<State>& states);

  const TransitionSystem& system() const { return *sys_; }

 private:
  const TransitionSystem* sys_;
  std::vector<State> cur_, next_;
  std::vector<std::uint32_t> mark_;  // mark_[s] == gen_: s already in next_
  std::uint32_t gen_ = 0;
};

/// phi applied to a sorted set, giving a sorted set (the update as a pure function).
std::vector<State> successors(const TransitionSystem& system, const std::vector<State>& set, Symbol y);

}  // namespace preimage::filter
