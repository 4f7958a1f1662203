// SPDX-License-Identifier: Apache-2.0
// Strategy 2 (wall-following paper, VI.B): the derived I-space I_gap of positions in the
// cut ordering and 0/1 labels of the shadow components. The robot first executes every
// motion once and records what the gap sensor says (the components' correspondence
// composed over the motion's events); the search then needs no more motion. Labels are
// the shared shadow-label filter (filter::ShadowTransition).
#include "istate_search.hpp"
#include "strategies.hpp"

#include <stdexcept>

namespace preimage::wallfollow {
namespace {

struct GapState {
  Position p;
  filter::ShadowLabels labels;
  bool operator==(const GapState&) const = default;
};
struct GapStateHash {
  std::size_t operator()(const GapState& s) const {
    return s.labels.hash() * 1000003u ^ (static_cast<std::size_t>(s.p.at) * 3 + static_cast<std::size_t>(s.p.arrived + 1));
  }
};

// Events of one motion composed into one correspondence (rules 1-4 compose: the labels
// after are the OR over chains of corresponding components).
filter::ShadowEvent compose(std::size_t before, const std::vector<filter::ShadowEvent>& events) {
  std::vector<std::vector<char>> rel(before, std::vector<char>(before, 0));
  for (std::size_t c = 0; c < before; ++c) rel[c][c] = 1;
  std::size_t now = before;
  for (const auto& e : events) {
    if (e.before != now) throw std::runtime_error("gap sensor: an event does not start from the components of the previous one");
    std::vector<std::vector<char>> next(before, std::vector<char>(e.after, 0));
    for (auto [a, b] : e.pairs)
      for (std::size_t c = 0; c < before; ++c)
        if (rel[c][a]) next[c][b] = 1;
    rel = std::move(next);
    now = e.after;
  }
  filter::ShadowEvent out{before, now, {}};
  for (std::uint32_t c = 0; c < before; ++c)
    for (std::uint32_t d = 0; d < now; ++d)
      if (rel[c][d]) out.pairs.push_back({c, d});
  return out;
}

}  // namespace

void gap_strategy(Navigator& nav, const OrderingMap& m, std::size_t max_states, const Deadline& deadline, PursuitReport& rep) {
  std::vector<long> gaps_at(m.size(), -1);
  auto note = [&](std::uint32_t k, std::size_t g) {
    if (gaps_at[k] >= 0 && gaps_at[k] != static_cast<long>(g))
      throw std::runtime_error("gap sensor: " + std::to_string(g) + " components at " + m.name(k) + ", earlier " +
                               std::to_string(gaps_at[k]));
    gaps_at[k] = static_cast<long>(g);
  };
  note(nav.at().at, nav.last().gaps);
  std::map<Motion, std::vector<filter::ShadowEvent>> events;
  nav.explore([&](const Motion& mo, const Position& to, const Observation& y) {
    note(to.at, y.gaps);
    events[mo] = y.gap_events;
  });
  auto table = std::make_shared<GapTable>();
  table->gaps_at = gaps_at;
  for (auto& [mo, ev] : events) {
    if (gaps_at[mo.at] < 0) throw std::logic_error("gap strategy: a motion from a point never reached");
    const auto e = compose(static_cast<std::size_t>(gaps_at[mo.at]), ev);
    const Position to = *m.move(Position{mo.at, static_cast<std::int8_t>(mo.u == Action::Jump ? mo.arrived : 0)}, mo.u);
    if (e.after != static_cast<std::size_t>(gaps_at[to.at])) throw std::runtime_error("gap sensor: a motion ends with a wrong count");
    table->transitions.emplace(mo, filter::ShadowTransition(e));
  }
  search_gap(nav.at(), m, *table, max_states, rep, deadline);
  rep.gap_table = std::move(table);
}

void search_gap(const Position& start_at, const OrderingMap& m, const GapTable& table, std::size_t max_states, PursuitReport& rep,
                const Deadline& deadline) {
  const GapState start{start_at, filter::ShadowLabels(static_cast<std::size_t>(table.gaps_at.at(start_at.at)), true)};
  auto r = breadth_first<GapState, GapStateHash>(
      start,
      [&](const GapState& s, auto&& emit) {
        for (Action u : {Action::RFollow, Action::LFollow, Action::Jump}) {
          const auto q = m.move(s.p, u);
          if (!q) continue;
          emit(u, GapState{*q, table.transitions.at(motion_of(s.p, u)).apply(s.labels)});
        }
      },
      [](const GapState& s) { return s.labels.all_clear(); }, max_states, deadline);
  rep.outcome = r.outcome;
  rep.out_of_time = r.out_of_time;
  rep.plan = r.plan;
  rep.states = r.states;
  rep.labels_along.clear();
  for (auto& s : r.along) rep.labels_along.push_back(m.name(s.p.at) + " " + s.labels.str());
}

}  // namespace preimage::wallfollow
