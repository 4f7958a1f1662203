// SPDX-License-Identifier: Apache-2.0
// What the cut ordering alone says about bitangents (wall-following paper, VI.D-E):
// the candidates C(i, j) of Proposition 11, and for Strategy 6 conservative
// approximations of where their rays end.
//
// The ray beyond v runs into the sector of v away from the other vertex w: if w lies on
// v's right side (v, r_v), the ray ends on (l_v, v), else on (v, r_v) — so l_v or r_v
// bounds it (the first half of Proposition 13). Every mutually visible pair (s, t) with t
// on the arc from v to w (w included) and s between that bound and v tightens it to s
// (Proposition 14; with t = w and s = l_w it is the second half of Proposition 13, and
// mirrored it is Proposition 15): the segment st would otherwise cross the bitangent's
// line twice. The cuts are the pairs the robot knows. The paper states the bounds for
// right-handed candidates (both obstacles on one side of the line); the same argument
// holds for separating ones (v_j on v_i's right side and v_i on v_j's right side, or
// both left), which the paper's canonical form cannot express, so the rule is applied to
// every candidate ray.
#include <preimage/wallfollow/pursuit.hpp>

namespace preimage::wallfollow {

bool bitangent_candidate(const OrderingMap& m, std::uint32_t i, std::uint32_t j) {
  const std::size_t n = m.n();
  const auto& R = m.ordering().reflex;
  if (i == j || !R[i] || !R[j]) return false;
  // Neighbours on the boundary share an edge, not a bitangent.
  if ((i + 1) % n == j || (j + 1) % n == i) return false;
  const auto between_cuts = [&](std::uint32_t v, std::uint32_t w) {  // v in (r_w, l_w)
    return m.in_arc(m.key(m.vertex(v)), m.key(m.cut(w, false)), m.key(m.cut(w, true)));
  };
  return !between_cuts(i, j) && !between_cuts(j, i);
}

std::vector<KnownBitangent> approximate_bitangents(const OrderingMap& m) {
  std::vector<KnownBitangent> out;
  const std::size_t n = m.n();
  const auto& R = m.ordering().reflex;
  // Every cut as (its reflex vertex, its endpoint), point indices.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cuts;
  for (std::uint32_t w = 0; w < n; ++w)
    if (R[w])
      for (bool left : {true, false}) cuts.push_back({m.vertex(w), m.cut(w, left)});
  // The bound of the ray beyond v (other vertex w), as a point index.
  auto bound = [&](std::uint32_t v, std::uint32_t w) {
    const bool clockwise = m.on_right_side(v, w);  // the ray ends on (l_v, v)
    const std::uint64_t kv = m.key(m.vertex(v)), kw = m.key(m.vertex(w));
    std::uint32_t best = m.cut(v, clockwise);
    auto nearer = [&](std::uint32_t s) {  // s strictly between the bound and v, or the bound itself
      const std::uint64_t ks = m.key(s), kb = m.key(best);
      return clockwise ? m.in_arc(ks, kb, kv) : m.in_arc(ks, kv, kb);
    };
    for (auto [a, b] : cuts)
      for (auto [t, s] : {std::make_pair(a, b), std::make_pair(b, a)}) {
        const std::uint64_t kt = m.key(t);
        const bool t_on_arc = clockwise ? (m.in_arc(kt, kv, kw) || kt == kw) : (m.in_arc(kt, kw, kv) || kt == kw);
        if (t_on_arc && nearer(s)) best = s;
      }
    return m.key(best);
  };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      if (bitangent_candidate(m, i, j)) out.push_back({i, j, bound(i, j), bound(j, i)});
  return out;
}

}  // namespace preimage::wallfollow
