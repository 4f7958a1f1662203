// SPDX-License-Identifier: Apache-2.0
// Several bodies in one transition system, observed anonymously (beams paper, 4.2):
// each observation is made by exactly one body, which one is unknown. The I-state is
// the set of possible assignments of bodies to states.
//  - distinguishable bodies: assignments are tuples (s_1, ..., s_n), the filter over
//    the n-fold product G^n;
//  - indistinguishable bodies: assignments are multisets (bodies per state, the
//    "balls and urns" counting representation of Fig. 12), stored as sorted tuples.
#pragma once
#include <preimage/filter/transition_system.hpp>

#include <vector>

namespace preimage::filter {

class ProductFilter {
 public:
  using Assignment = std::vector<State>;

  /// Starts from `initial` assignments (each of size `bodies`), or all of them if
  /// empty (then the number of states must keep that set small).
  ProductFilter(const TransitionSystem& system, std::size_t bodies, bool distinguishable,
                const std::vector<Assignment>& initial = {});
  // Keeps a pointer to the system.
  ProductFilter(TransitionSystem&&, std::size_t, bool, const std::vector<Assignment>& = {}) = delete;

  /// Every tuple of `bodies` states drawn from `states` (the n-fold product).
  static std::vector<Assignment> all_assignments(const std::vector<State>& states, std::size_t bodies);

  bool step(Symbol y);
  std::size_t bodies() const { return n_; }
  bool distinguishable() const { return distinguishable_; }
  std::size_t size() const { return n_ ? flat_.size() / n_ : 0; }
  bool empty() const { return flat_.empty(); }
  /// The I-state as sorted assignments (tuples; sorted tuples when indistinguishable).
  std::vector<Assignment> assignments() const;
  /// Multisets of the current assignments (sorted tuples, duplicates removed): the
  /// counting view, for comparing distinguishable with indistinguishable filters.
  std::vector<Assignment> multisets() const;

 private:
  void normalise(std::vector<State>& flat) const;

  const TransitionSystem* sys_;
  std::size_t n_;
  bool distinguishable_;
  std::vector<State> flat_;  // assignments, n_ states each, sorted and unique
};

}  // namespace preimage::filter
