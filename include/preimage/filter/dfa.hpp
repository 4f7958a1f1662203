// SPDX-License-Identifier: Apache-2.0
// Deterministic combinatorial filters with few I-states (beams paper, 4.2: the
// together/separated filter of Fig. 11(b), per-region parity), and the search over
// I-states that finds every I-state a filter can reach, so its size can be reported
// and two filters compared state by state.
#pragma once
#include <preimage/filter/transition_system.hpp>

#include <deque>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace preimage::filter {

/// A table filter: I-state ids 0..n-1 with names, a transition table (kNoState:
/// the observation is impossible from that I-state), and the initial I-state.
struct Dfa {
  std::vector<std::string> names;
  std::size_t num_symbols = 0;
  std::vector<State> table;  // table[s * num_symbols + y]
  State initial = 0;

  std::size_t size() const { return names.size(); }
  State step(State s, Symbol y) const { return s == kNoState ? kNoState : table[s * num_symbols + y]; }
  State run(State s, std::span<const Symbol> word) const {
    for (Symbol y : word) s = step(s, y);
    return s;
  }
};

/// Breadth-first search over the I-states reachable from `initial` under a
/// deterministic update `step(I, y) -> optional<I>` (nullopt: impossible observation).
/// Returns the reachable part as a Dfa plus the I-states themselves (id order), or
/// nullopt if more than `limit` I-states are reachable.
template <class IState, class Hash = std::hash<IState>>
struct Explored {
  Dfa dfa;
  std::vector<IState> states;
};

template <class IState, class Hash = std::hash<IState>, class Step, class Name>
std::optional<Explored<IState, Hash>> explore(const IState& initial, std::size_t num_symbols, Step step, Name name,
                                              std::size_t limit = 1u << 20) {
  Explored<IState, Hash> out;
  std::unordered_map<IState, State, Hash> id;
  std::deque<State> queue;
  auto intern = [&](const IState& s) -> std::optional<State> {
    auto [it, fresh] = id.try_emplace(s, static_cast<State>(out.states.size()));
    if (fresh) {
      if (out.states.size() >= limit) return std::nullopt;
      out.states.push_back(s);
      out.dfa.names.push_back(name(s));
      out.dfa.table.resize(out.states.size() * num_symbols, kNoState);
      queue.push_back(it->second);
    }
    return it->second;
  };
  out.dfa.num_symbols = num_symbols;
  if (!intern(initial)) return std::nullopt;
  while (!queue.empty()) {
    const State s = queue.front();
    queue.pop_front();
    for (Symbol y = 0; y < num_symbols; ++y) {
      std::optional<IState> t = step(out.states[s], y);
      if (!t) continue;
      auto tid = intern(*t);
      if (!tid) return std::nullopt;
      out.dfa.table[s * num_symbols + y] = *tid;
    }
  }
  return out;
}

}  // namespace preimage::filter
