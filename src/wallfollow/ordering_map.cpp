// SPDX-License-Identifier: Apache-2.0
// The cut ordering as a map for planning (pursuit.hpp): moves of III.A predicted from the
// ordering alone, cyclic boundary keys, and the primitives of VI.C with their active sets.
#include <preimage/wallfollow/pursuit.hpp>

#include <algorithm>
#include <stdexcept>

namespace preimage::wallfollow {

OrderingMap::OrderingMap(CutOrdering o) : o_(std::move(o)) {
  const std::size_t n = o_.n;
  vertex_at_.assign(n, 0);
  cut_at_.assign(2 * n, UINT32_MAX);
  edge_of_.assign(o_.points.size(), 0);
  std::uint32_t edge = 0;
  for (std::uint32_t k = 0; k < o_.points.size(); ++k) {
    const CutPoint& p = o_.points[k];
    if (p.kind == CutPoint::Kind::Vertex) vertex_at_[p.vertex] = edge = k;
    else cut_at_[2 * p.vertex + (p.kind == CutPoint::Kind::Left ? 0 : 1)] = k;
    edge_of_[k] = o_.points[edge].vertex;
  }
  if (o_.points.empty() || o_.points[0].kind != CutPoint::Kind::Vertex)
    throw std::invalid_argument("cut ordering: it must start at a vertex");
  for (std::uint32_t v = 0; v < n; ++v) {
    if (!o_.reflex[v]) continue;
    if (cut_at_[2 * v] == UINT32_MAX || cut_at_[2 * v + 1] == UINT32_MAX)
      throw std::invalid_argument("cut ordering: reflex vertex v" + std::to_string(v + 1) + " lacks a cut endpoint");
    // R_v needs a convex vertex before v, L_v one after it (the inflections of VI.B).
    if (!o_.reflex[(v + n - 1) % n]) primitives_.push_back(2 * v + 1);
    if (!o_.reflex[(v + 1) % n]) primitives_.push_back(2 * v);
  }
  std::sort(primitives_.begin(), primitives_.end());
  active_.resize(o_.points.size());
  for (std::uint32_t k = 0; k < o_.points.size(); ++k) {
    const std::uint64_t x = key(k);
    for (PrimitiveId p : primitives_) {
      const std::uint32_t v = p / 2;
      const bool on = p % 2 ? in_arc(x, key(vertex(v)), key(cut(v, false))) : in_arc(x, key(cut(v, true)), key(vertex(v)));
      if (on) active_[k].push_back(p);
    }
  }
}

std::string OrderingMap::name(std::uint32_t k) const {
  const CutPoint& p = o_.points[k];
  const char* c = p.kind == CutPoint::Kind::Vertex ? "v" : p.kind == CutPoint::Kind::Left ? "l" : "r";
  return std::string(c).append(std::to_string(p.vertex + 1));
}

Touch OrderingMap::touch_at(std::uint32_t k) const {
  if (!is_vertex(k)) return Touch::Edge;
  return o_.reflex[o_.points[k].vertex] ? Touch::Reflex : Touch::Convex;
}

std::optional<Position> OrderingMap::move(const Position& p, Action u, std::optional<std::uint32_t> pebble) const {
  const std::size_t N = size(), n = o_.n;
  if (u == Action::Jump) {
    if (!is_vertex(p.at) || p.arrived == 0) return std::nullopt;
    const std::uint32_t v = o_.points[p.at].vertex;
    if (!o_.reflex[v]) return std::nullopt;
    return Position{cut(v, p.arrived < 0), 0};
  }
  if (u != Action::RFollow && u != Action::LFollow) return std::nullopt;
  const bool ccw = u == Action::RFollow;
  // The next vertex in that direction, and the cut endpoints passed on the way.
  const std::uint32_t e = edge_of(p.at);
  std::uint32_t target;
  if (is_vertex(p.at)) target = vertex(static_cast<std::uint32_t>(ccw ? (e + 1) % n : (e + n - 1) % n));
  else target = vertex(static_cast<std::uint32_t>(ccw ? (e + 1) % n : e));
  if (pebble) {
    for (std::uint32_t k = static_cast<std::uint32_t>(ccw ? (p.at + 1) % N : (p.at + N - 1) % N); k != target;
         k = static_cast<std::uint32_t>(ccw ? (k + 1) % N : (k + N - 1) % N))
      if (k == *pebble) return Position{k, static_cast<std::int8_t>(ccw ? 1 : -1)};
  }
  return Position{target, static_cast<std::int8_t>(ccw ? 1 : -1)};
}

bool OrderingMap::in_arc(std::uint64_t x, std::uint64_t a, std::uint64_t b) const {
  const std::uint64_t ax = ccw(a, x);
  return ax > 0 && ax < ccw(a, b);
}


bool OrderingMap::on_right_side(std::uint32_t i, std::uint32_t j) const {
  return in_arc(key(vertex(j)), key(vertex(i)), key(cut(i, false)));
}

}  // namespace preimage::wallfollow
