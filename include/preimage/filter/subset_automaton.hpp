// SPDX-License-Identifier: Apache-2.0
// The subset filter compiled lazily into a deterministic automaton over I-states,
// like a lazy DFA in a regular-expression engine: each I-state met is interned once,
// each (I-state, symbol) transition is computed once by the subset construction and
// then costs one table look-up. Memory is bounded: when the cache would exceed its
// budget it is flushed and refilled from the current I-state.
#pragma once
#include <preimage/filter/transition_system.hpp>

#include <span>
#include <unordered_map>
#include <string>
#include <vector>

namespace preimage::filter {

class SubsetAutomaton {
 public:
  using Id = std::uint32_t;

  /// `max_bytes` bounds the table rows plus the stored I-states (at least one row).
  explicit SubsetAutomaton(const TransitionSystem& system, std::size_t max_bytes = std::size_t(64) << 20);
  SubsetAutomaton(TransitionSystem&&, std::size_t = 0) = delete;  // keeps a pointer to the system

  /// Id of the I-state `sorted_states` (sorted, no duplicates), interning it if new.
  Id intern(const std::vector<State>& sorted_states);
  /// Successor I-state: a table look-up when cached.
  Id step(Id id, Symbol y) {
    const Id n = table_[static_cast<std::size_t>(id) * nsym_ + y];
    return n != kUnknown ? n : miss(id, y);
  }
  /// Runs a whole word; returns the final I-state id.
  Id run(Id id, std::span<const Symbol> word) {
    for (const Symbol y : word) id = step(id, y);
    return id;
  }
  std::span<const State> states(Id id) const {
    return {pool_.data() + begin_[id], pool_.data() + begin_[id + 1]};
  }
  bool empty(Id id) const { return begin_[id] == begin_[id + 1]; }

  std::size_t cached_states() const { return begin_.size() - 1; }
  std::size_t max_states() const { return max_states_; }
  std::size_t misses() const { return misses_; }
  std::size_t flushes() const { return flushes_; }

 private:
  static constexpr Id kUnknown = UINT32_MAX;
  Id miss(Id id, Symbol y);
  void flush();
  static std::string key(std::span<const State> s);

  const TransitionSystem* sys_;
  std::size_t nsym_;
  std::size_t max_bytes_, max_states_;
  std::vector<Id> table_;           // row per I-state, nsym_ entries
  std::vector<State> pool_;         // I-states' members, concatenated
  std::vector<std::size_t> begin_;  // I-state i = pool_[begin_[i], begin_[i+1])
  std::unordered_map<std::string, Id> index_;
  std::size_t misses_ = 0, flushes_ = 0;
};

}  // namespace preimage::filter
