// SPDX-License-Identifier: Apache-2.0
// A finite labelled transition system: states, observation symbols and transitions
// (s, y, s'). It is the shared form of every combinatorial filter's model: the region
// graph G of a beam network (beams paper, 4.1), the product G^n of several bodies
// (4.2), and later wall-following and pursuit status graphs. The filters in this
// module run over it without knowing what a state means.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace preimage::filter {

using State = std::uint32_t;
using Symbol = std::uint32_t;
inline constexpr State kNoState = UINT32_MAX;

struct Transition {
  State from;
  Symbol symbol;
  State to;
  friend bool operator==(const Transition&, const Transition&) = default;
};

/// Transitions stored flat (CSR), sorted by (from, symbol, to), duplicates removed:
/// the successors of s under y are one contiguous range found by binary search.
class TransitionSystem {
 public:
  TransitionSystem() = default;
  /// Throws std::invalid_argument if a transition names a state or symbol out of range.
  TransitionSystem(std::size_t num_states, std::size_t num_symbols, std::vector<Transition> transitions);

  std::size_t num_states() const { return offset_.empty() ? 0 : offset_.size() - 1; }
  std::size_t num_symbols() const { return num_symbols_; }
  std::size_t num_transitions() const { return tr_.size(); }
  const std::vector<Transition>& transitions() const { return tr_; }

  /// All transitions leaving s.
  std::span<const Transition> out(State s) const {
    return {tr_.data() + offset_[s], tr_.data() + offset_[s + 1]};
  }
  /// Transitions leaving s labelled y.
  std::span<const Transition> out(State s, Symbol y) const;

 private:
  std::size_t num_symbols_ = 0;
  std::vector<std::uint32_t> offset_;
  std::vector<Transition> tr_;
};

}  // namespace preimage::filter
