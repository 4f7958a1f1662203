// SPDX-License-Identifier: Apache-2.0
// Strategy 3's information transition on I_bit (wall-following paper, VI.C): the
// partition pi(A) of the active primitives into compounds and their labels, updated from
// the cut ordering (inflections crossed) and the bitangent rays crossed.
//
// Proposition 9 names the two compounds of a split or merge at the ray beyond v_i of the
// bitangent (v_i, v_j): the active primitives on the arc between v_j and b_ji without
// v_i, and those "in an interval between v_i and v_j that does not contain the bitangent
// endpoints". That second interval exists only when both obstacles lie on one side of
// the line (cyclic order b_ij, v_i, v_j, b_ji). For a separating bitangent (order b_ij,
// v_i, b_ji, v_j) both arcs between v_i and v_j hold an endpoint; there the shadow behind
// v_i holds the arc from v_i to b_ji instead (docs/wallfollow.md records this). In both
// cases it is the arc from v_i, away from b_ij, to the nearer of v_j and b_ji.
#include <preimage/wallfollow/pursuit.hpp>

#include <algorithm>
#include <stdexcept>

namespace preimage::wallfollow {

namespace {

// The open arc between x and y that does not hold z, as (from, to) counter-clockwise.
std::pair<std::uint64_t, std::uint64_t> arc_without(const OrderingMap& m, std::uint64_t x, std::uint64_t y, std::uint64_t z) {
  return m.in_arc(z, x, y) ? std::make_pair(y, x) : std::make_pair(x, y);
}

bool separating(const OrderingMap& m, std::uint32_t i, std::uint32_t j) {
  // Obstacles on opposite sides: each vertex lies on the same-named side of the other.
  return m.on_right_side(i, j) == m.on_right_side(j, i);
}

}  // namespace

std::pair<std::vector<PrimitiveId>, std::vector<PrimitiveId>> proposition9_sets(const OrderingMap& m, const RayCrossing& c,
                                                                                const std::vector<PrimitiveId>& active) {
  const std::uint64_t vi = m.key(m.vertex(c.i)), vj = m.key(m.vertex(c.j));
  const auto first = arc_without(m, vj, c.b_ji, vi);
  const auto second = separating(m, c.i, c.j) ? arc_without(m, vi, c.b_ji, vj) : arc_without(m, vi, vj, c.b_ji);
  std::pair<std::vector<PrimitiveId>, std::vector<PrimitiveId>> out;
  for (PrimitiveId p : active) {
    const std::uint64_t g = m.germ(p);
    if (m.in_arc(g, first.first, first.second)) out.first.push_back(p);
    else if (m.in_arc(g, second.first, second.second)) out.second.push_back(p);
  }
  return out;
}

CompoundState compound_transition(const OrderingMap& m, std::uint32_t from, const CompoundState& s, std::uint32_t to,
                                  const std::vector<RayCrossing>& crossings) {
  const std::vector<PrimitiveId>& A = m.active(from);
  if (s.compound.size() != A.size()) throw std::invalid_argument("compound_transition: state does not match the active set");
  // Working form: a compound id per active primitive and a label per id.
  std::vector<std::uint32_t> id(s.compound.begin(), s.compound.end());
  std::vector<char> label;
  for (std::size_t c = 0; c < s.labels.size(); ++c) label.push_back(s.labels[c]);
  auto index_in = [](const std::vector<PrimitiveId>& set, PrimitiveId p) {
    const auto it = std::lower_bound(set.begin(), set.end(), p);
    return it != set.end() && *it == p ? static_cast<long>(it - set.begin()) : -1L;
  };
  // 1. Splits, on the old active set: each compound's members on either side part.
  for (const RayCrossing& c : crossings) {
    if (c.merge) continue;
    const auto [first, second] = proposition9_sets(m, c, A);
    for (const auto* part : {&first, &second}) {
      std::vector<std::uint32_t> fresh(label.size(), UINT32_MAX);
      for (PrimitiveId p : *part) {
        const long k = index_in(A, p);
        std::uint32_t& f = fresh[id[static_cast<std::size_t>(k)]];
        if (f == UINT32_MAX) f = static_cast<std::uint32_t>(label.size()), label.push_back(label[id[static_cast<std::size_t>(k)]]);
        id[static_cast<std::size_t>(k)] = f;
      }
    }
  }
  // 2. Primitives that became active are clear; inactive ones leave their compounds.
  const std::vector<PrimitiveId>& B = m.active(to);
  std::vector<std::uint32_t> id2(B.size());
  for (std::size_t k = 0; k < B.size(); ++k) {
    const long a = index_in(A, B[k]);
    if (a >= 0) id2[k] = id[static_cast<std::size_t>(a)];
    else id2[k] = static_cast<std::uint32_t>(label.size()), label.push_back(0);
  }
  // 3. Merges, on the new active set: every compound meeting either set becomes one.
  for (const RayCrossing& c : crossings) {
    if (!c.merge) continue;
    const auto [first, second] = proposition9_sets(m, c, B);
    std::vector<std::uint32_t> ids;
    for (const auto* part : {&first, &second})
      for (PrimitiveId p : *part) ids.push_back(id2[static_cast<std::size_t>(index_in(B, p))]);
    if (ids.empty()) continue;
    const std::uint32_t target = *std::min_element(ids.begin(), ids.end());
    char any = 0;
    for (std::uint32_t x : ids) any |= label[x];
    label[target] = any;
    for (auto& x : id2)
      if (std::find(ids.begin(), ids.end(), x) != ids.end()) x = target;
  }
  // Canonical numbering: compounds by first member.
  CompoundState out;
  std::vector<std::uint32_t> renum(label.size(), UINT32_MAX);
  std::vector<char> labels2;
  for (std::uint32_t x : id2) {
    if (renum[x] == UINT32_MAX) renum[x] = static_cast<std::uint32_t>(labels2.size()), labels2.push_back(label[x]);
    out.compound.push_back(static_cast<std::uint16_t>(renum[x]));
  }
  out.labels = filter::ShadowLabels(labels2.size(), false);
  for (std::size_t c = 0; c < labels2.size(); ++c) out.labels.set(c, labels2[c] != 0);
  return out;
}

std::vector<RayCrossing> crossings_of(const OrderingMap& m, const std::vector<KnownBitangent>& bitangents, std::uint32_t from,
                                      std::uint32_t to) {
  std::vector<RayCrossing> out;
  const std::uint64_t a = m.key(from), b = m.key(to);
  for (const KnownBitangent& t : bitangents)
    for (bool at_j : {false, true}) {
      const std::uint32_t v = at_j ? t.j : t.i, w = at_j ? t.i : t.j;
      const std::uint64_t kv = m.key(m.vertex(v)), kw = m.key(m.vertex(w)), end = at_j ? t.b_ji : t.b_ij;
      // The merged side: the arc between the ray's ends without the other vertex.
      const auto side = arc_without(m, end, kv, kw);
      const bool in_a = m.in_arc(a, side.first, side.second), in_b = m.in_arc(b, side.first, side.second);
      if (in_a != in_b) out.push_back({v, w, at_j ? t.b_ij : t.b_ji, in_b});
    }
  return out;
}

}  // namespace preimage::wallfollow
