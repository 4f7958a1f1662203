// SPDX-License-Identifier: Apache-2.0
// Strategy 3 (wall-following paper, VI.C) and the search it shares with Strategies 5
// and 6: I_bit = (position in the cut ordering, partition of the active primitives into
// compounds, a label per compound), searched breadth-first. The start assumes no
// compounds and every label 1 (harmless, Proposition 10's proof).
//
// With the bitangent sensor the robot executes every motion once and keeps the rays it
// crossed: the pair (named relative to where it stands, turned into its own labels), the
// place of the other ray's end, and whether it entered the merged side — decided from
// the cut ordering: the ray beyond v_i runs into the sector of v_i away from v_j, so of
// the motion's two ends the one met first going from v_i that way is on the merged side.
#include "istate_search.hpp"
#include "strategies.hpp"

#include <set>
#include <sstream>

namespace preimage::wallfollow {
namespace {

struct BitState {
  Position p;
  CompoundState s;
  bool operator==(const BitState&) const = default;
};
struct BitStateHash {
  std::size_t operator()(const BitState& b) const {
    std::size_t h = b.s.labels.hash() ^ (static_cast<std::size_t>(b.p.at) * 3 + static_cast<std::size_t>(b.p.arrived + 1));
    for (auto c : b.s.compound) h = h * 31 + c;
    return h;
  }
};

std::string describe(const OrderingMap& m, const BitState& b) {
  const auto A = m.active(b.p.at);
  std::ostringstream o;
  o << m.name(b.p.at);
  for (std::size_t c = 0; c < b.s.labels.size(); ++c) {
    o << " {";
    bool first = true;
    for (std::size_t k = 0; k < A.size(); ++k)
      if (b.s.compound[k] == c) o << (first ? "" : " ") << (A[k] % 2 ? "R" : "L") << A[k] / 2 + 1, first = false;
    o << "}:" << b.s.labels[c];
  }
  return o.str();
}

template <class Crossings>
void search(const Position& start, const OrderingMap& m, Crossings&& crossings, std::size_t max_states, const Deadline& deadline,
            PursuitReport& rep) {
  const std::size_t a0 = m.active(start.at).size();
  CompoundState s0{std::vector<std::uint16_t>(a0), filter::ShadowLabels(a0, true)};
  for (std::size_t k = 0; k < a0; ++k) s0.compound[k] = static_cast<std::uint16_t>(k);
  auto r = breadth_first<BitState, BitStateHash>(
      BitState{start, s0},
      [&](const BitState& b, auto&& emit) {
        for (Action u : {Action::RFollow, Action::LFollow, Action::Jump}) {
          const auto q = m.move(b.p, u);
          if (!q) continue;
          emit(u, BitState{*q, compound_transition(m, b.p.at, b.s, q->at, crossings(b.p, u, *q))});
        }
      },
      [](const BitState& b) { return b.s.labels.all_clear(); }, max_states, deadline);
  rep.outcome = r.outcome;
  rep.out_of_time = r.out_of_time;
  rep.plan = r.plan;
  rep.states = r.states;
  rep.labels_along.clear();
  for (auto& b : r.along) rep.labels_along.push_back(describe(m, b));
}

}  // namespace

void search_compounds(const Position& start, const OrderingMap& m, const std::vector<KnownBitangent>& bitangents,
                      std::size_t max_states, PursuitReport& rep, const Deadline& deadline) {
  rep.bitangents = bitangents.size();
  rep.known = bitangents;
  // The crossings of each move depend on its ends only: decided once.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<RayCrossing>> memo;
  search(start, m, [&](const Position& from, Action, const Position& to) -> const std::vector<RayCrossing>& {
    auto [it, fresh] = memo.try_emplace({from.at, to.at});
    if (fresh) it->second = crossings_of(m, bitangents, from.at, to.at);
    return it->second;
  }, max_states, deadline, rep);
}

void bitangent_sensor_strategy(Navigator& nav, const OrderingMap& m, std::size_t max_states, const Deadline& deadline,
                               PursuitReport& rep) {
  const std::size_t n = m.n();
  std::map<Motion, std::vector<RayCrossing>> table;
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  nav.explore([&](const Motion& mo, const Position& to, const Observation& y) {
    const std::uint32_t ref = m.edge_of(to.at);
    auto& out = table[mo];
    for (const BitangentCrossing& c : y.bitangents) {
      RayCrossing x;
      x.i = static_cast<std::uint32_t>((ref + c.closer) % n);
      x.j = static_cast<std::uint32_t>((ref + c.farther) % n);
      const std::uint32_t edge = static_cast<std::uint32_t>((ref + c.other_edge) % n);
      x.b_ji = m.key(m.vertex(edge) + c.other_after, 2);
      // The merged side lies next to v_i on the side away from v_j.
      const std::uint64_t vi = m.key(m.vertex(x.i)), a = m.key(mo.at), b = m.key(to.at);
      if (a == vi) x.merge = true;
      else if (b == vi) x.merge = false;
      else if (m.on_right_side(x.i, x.j)) x.merge = m.ccw(b, vi) < m.ccw(a, vi);  // clockwise from v_i
      else x.merge = m.ccw(vi, b) < m.ccw(vi, a);
      out.push_back(x);
      pairs.insert({std::min(x.i, x.j), std::max(x.i, x.j)});
    }
  });
  rep.bitangents = pairs.size();
  search(nav.at(), m, [&](const Position& from, Action u, const Position&) -> const std::vector<RayCrossing>& {
    return table.at(motion_of(from, u));
  }, max_states, deadline, rep);
}

}  // namespace preimage::wallfollow
