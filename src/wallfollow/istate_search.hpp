// SPDX-License-Identifier: Apache-2.0
// Breadth-first search over a derived I-space (internal to the section VI strategies):
// every reachable I-state once, the first goal state found gives a plan with the fewest
// actions. Complete when it runs dry (Propositions 8 and 10): no plan exists.
#pragma once
#include <preimage/wallfollow/pursuit.hpp>

#include <deque>
#include <unordered_map>

namespace preimage::wallfollow {

template <class State>
struct IStateSearch {
  PursuitReport::Outcome outcome = PursuitReport::Outcome::NoPlan;
  std::vector<Action> plan;
  std::vector<State> along;  // the I-states after each plan action (start first)
  std::size_t states = 0;
  bool out_of_time = false;  // Budget because the deadline passed
};

/// `next(s, emit)` calls emit(u, s') for each action u applicable in s; `goal(s)`. Gives
/// up (Budget) with `max_states` I-states stored or, checked every 256, at `deadline`.
template <class State, class Hash, class Next, class Goal>
IStateSearch<State> breadth_first(const State& start, Next&& next, Goal&& goal, std::size_t max_states, const Deadline& deadline) {
  IStateSearch<State> r;
  std::vector<State> states{start};
  std::vector<long> parent{-1};
  std::vector<Action> via{Action::RFollow};
  std::unordered_map<State, std::size_t, Hash> index{{start, 0}};
  auto finish = [&](std::size_t k) {
    r.outcome = PursuitReport::Outcome::Plan;
    for (long j = static_cast<long>(k); j >= 0; j = parent[static_cast<std::size_t>(j)]) {
      r.along.push_back(states[static_cast<std::size_t>(j)]);
      if (parent[static_cast<std::size_t>(j)] >= 0) r.plan.push_back(via[static_cast<std::size_t>(j)]);
    }
    std::reverse(r.plan.begin(), r.plan.end());
    std::reverse(r.along.begin(), r.along.end());
  };
  for (std::size_t head = 0; head < states.size(); ++head) {
    if (goal(states[head])) {
      r.states = states.size();
      finish(head);
      return r;
    }
    const bool late = deadline && head % 256 == 0 && std::chrono::steady_clock::now() >= *deadline;
    if (states.size() >= max_states || late) {
      r.states = states.size();
      r.outcome = PursuitReport::Outcome::Budget;
      r.out_of_time = late;
      return r;
    }
    const State s = states[head];
    next(s, [&](Action u, State t) {
      if (index.emplace(t, states.size()).second) {
        states.push_back(std::move(t));
        parent.push_back(static_cast<long>(head));
        via.push_back(u);
      }
    });
  }
  r.states = states.size();
  return r;
}

}  // namespace preimage::wallfollow
