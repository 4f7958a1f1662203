// SPDX-License-Identifier: Apache-2.0
// Strategy 4 (wall-following paper, VI.D): the bitangents and where their rays end,
// learned with the pebble visibility sensor h_p. For every candidate C(i, j): the pebble
// at v_j, the robot at v_i; h_p = 1 there means B(i, j) (a candidate's line is tangent at
// both, so mutual visibility is all that is missing). The ray beyond v_i runs into the
// sector of v_i away from v_j; following the boundary from v_i that way, h_p stays 0
// until b_ij (Proposition 12), so the first follow during which the pebble is seen holds
// b_ij. Its place among the cut endpoints of that edge: from each endpoint c, a follow
// back towards v_i sees the pebble (at c or on the way) iff c lies beyond b_ij, since
// points just beyond b_ij see v_j and points between b_ij and v_i do not. The same with
// the roles of v_i and v_j swapped gives b_ji.
#include "strategies.hpp"

#include <stdexcept>

namespace preimage::wallfollow {
namespace {

// With the pebble at vertex `pebble_vertex` and the robot at v, where the ray beyond v
// away from the pebble's vertex ends (a key strictly between two points).
std::uint64_t locate_ray_end(Navigator& nav, const OrderingMap& m, std::uint32_t v, std::uint32_t pebble_vertex) {
  const std::size_t n = m.n();
  // v_j on v's right side: the ray ends on (l_v, v), clockwise from v.
  const bool clockwise = m.on_right_side(v, pebble_vertex);
  const Action away = clockwise ? Action::LFollow : Action::RFollow, back = clockwise ? Action::RFollow : Action::LFollow;
  std::uint32_t at = v;
  std::optional<std::uint32_t> edge;
  for (std::size_t k = 0; k < n && !edge; ++k) {
    nav.go(m.vertex(at));
    const std::uint32_t next = static_cast<std::uint32_t>(clockwise ? (at + n - 1) % n : (at + 1) % n);
    nav.act(away);
    if (nav.last().pebble_seen) edge = clockwise ? next : at;
    at = next;
  }
  if (!edge) throw std::runtime_error("pebble visibility: the ray beyond v" + std::to_string(v + 1) + " was not found");
  // Cut endpoints of that edge, and how many lie before the ray's end.
  std::uint32_t before = 0;
  for (std::uint32_t c = m.vertex(*edge) + 1; c < m.size() && !m.is_vertex(c); ++c) {
    nav.go(c);
    const bool at_c = nav.last().pebble_visible;
    nav.act(back);
    const bool beyond = at_c || nav.last().pebble_seen;  // c lies beyond b (away from v)
    // Counter-clockwise order on the edge: clockwise search meets b after the endpoints
    // counter-clockwise of it; beyond = counter-clockwise before b.
    if (clockwise ? beyond : !beyond) ++before;
  }
  return m.key(m.vertex(*edge) + before, 2);
}

}  // namespace

std::vector<KnownBitangent> learn_bitangents(Navigator& nav, const OrderingMap& m) {
  std::vector<KnownBitangent> out;
  const std::size_t n = m.n();
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j) {
      if (!bitangent_candidate(m, i, j)) continue;
      nav.go(m.vertex(j));
      nav.drop();
      nav.go(m.vertex(i));
      if (!nav.last().pebble_visible) {
        nav.grab();
        continue;
      }
      KnownBitangent b{i, j, 0, 0};
      b.b_ij = locate_ray_end(nav, m, i, j);
      nav.grab();
      nav.go(m.vertex(i));
      nav.drop();
      b.b_ji = locate_ray_end(nav, m, j, i);
      nav.grab();
      out.push_back(b);
    }
  return out;
}

}  // namespace preimage::wallfollow
