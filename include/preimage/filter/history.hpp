// SPDX-License-Identifier: Apache-2.0
// History I-states and derived I-maps (wall-following paper, III.B).
//  - The history I-state eta_k = (u_1, ..., u_{k-1}, y_1, ..., y_k) (eq. 3) is every
//    action and observation so far.
//  - A derived I-map kappa is useful when it has an information transition function
//    kappa(eta_{k+1}) = f_der(kappa(eta_k), u_k, y_{k+1}) (eq. 4): then it runs as a filter
//    and the history need not be stored.
// `DerivedIMap` is that contract (start from y_1, then step(u_k, y_{k+1})); `replay`
// evaluates an I-map on a stored history, which tests compare with the live filter and
// with ground truth. Wall-following counters and pursuit status plug into this.
#pragma once
#include <cstddef>
#include <vector>

namespace preimage::filter {

template <class U, class Y>
struct History {
  std::vector<U> actions;       // u_1 .. u_{k-1}
  std::vector<Y> observations;  // y_1 .. y_k

  /// Stage k (1-based): the number of observations.
  std::size_t stage() const { return observations.size(); }
  void start(const Y& y1) {
    actions.clear();
    observations.assign(1, y1);
  }
  void push(const U& u, const Y& y) {
    actions.push_back(u);
    observations.push_back(y);
  }
};

template <class M, class U, class Y>
concept DerivedIMap = requires(M m, const U& u, const Y& y) {
  m.start(y);
  m.step(u, y);
};

/// kappa(eta_k) by running the I-map's transition function over the whole history.
template <class M, class U, class Y>
  requires DerivedIMap<M, U, Y>
M replay(const History<U, Y>& eta, M m = {}) {
  if (eta.observations.empty()) return m;
  m.start(eta.observations[0]);
  for (std::size_t i = 0; i < eta.actions.size(); ++i) m.step(eta.actions[i], eta.observations[i + 1]);
  return m;
}

}  // namespace preimage::filter
