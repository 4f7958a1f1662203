// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/triangulation.hpp>

#include "constrained_delaunay.hpp"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

namespace preimage::geometry {

namespace {

// Is direction p->d in the counter-clockwise range [p->o, p->i) (o != i)?
bool in_ccw_range(const Point& p, const Point& o, const Point& i, const Point& d) {
  const bool from_o = !ccw_less(p, d, o), before_i = ccw_less(p, d, i);
  return ccw_less(p, o, i) ? from_o && before_i : from_o || before_i;
}

}  // namespace

Triangulation::Triangulation(const Environment& env) : env_(&env) {
  const auto triples = constrained_delaunay_triangles(env);
  tris_.reserve(triples.size());
  for (const auto& v : triples) tris_.push_back({v, {kNone, kNone, kNone}, {kNone, kNone, kNone}});
  if (env.has_contacts()) label_wedges();
  link();
}

// A contact point was triangulated once; each triangle corner there is given the id of the
// vertex whose out-edge starts the free wedge the triangle lies in (its clockwise edge at
// the corner lies in [out(v), in(wedge_end(v))) counter-clockwise). Then every corner id
// names one wedge, and the boundary edge (a, b) of a triangle is environment edge a.
void Triangulation::label_wedges() {
  const Environment& E = *env_;
  const auto& P = E.vertices();
  for (Triangle& t : tris_)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t c = t.v[k];
      if (!E.is_contact(c)) continue;
      const Point& d = P[t.v[(k + 1) % 3]];
      std::size_t w = c;
      while (!in_ccw_range(P[c], P[E.next(w)], P[E.prev(E.wedge_end(w))], d)) {
        w = E.same_point_next(w);
        if (w == c) throw std::logic_error("triangulation: a triangle at a contact lies in no free wedge");
      }
      t.v[k] = static_cast<std::uint32_t>(w);
    }
}

// ---------------------------------------------------------------- adjacency
void Triangulation::link() {
  const Environment& E = *env_;
  std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint8_t>> open;
  open.reserve(tris_.size() * 2);
  edge_slot_.assign(E.num_vertices(), {kNone, 0});
  for (std::uint32_t t = 0; t < tris_.size(); ++t) {
    for (std::uint8_t i = 0; i < 3; ++i) {
      std::uint32_t a = tris_[t].v[i], b = tris_[t].v[(i + 1) % 3];
      if (E.wedge_start(E.next(a)) == b) {  // boundary edge, free space on its left as in the triangle
        tris_[t].edge[i] = a;
        edge_slot_[a] = {t, i};
        continue;
      }
      std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      auto it = open.find(key);
      if (it == open.end()) {
        open.emplace(key, std::make_pair(t, i));
      } else {
        auto [u, j] = it->second;
        tris_[t].nbr[i] = u, tris_[u].nbr[j] = t;
        open.erase(it);
      }
    }
  }
  if (!open.empty()) throw std::logic_error("triangulation: unmatched interior edge");
}

std::vector<std::uint32_t> Triangulation::edge_pieces() const {
  const std::size_t n = env_->num_vertices();
  std::vector<std::uint32_t> out(n, 0);
  if (!env_->has_contacts()) return out;
  // Flood fill across interior edges; numbered in the order edges first reach them.
  std::vector<std::uint32_t> piece(tris_.size(), kNone), stack;
  std::uint32_t next = 0;
  for (std::size_t e = 0; e < n; ++e) {
    const std::uint32_t t0 = edge_slot_[e].first;
    if (piece[t0] == kNone) {
      piece[t0] = next++;
      stack.push_back(t0);
      while (!stack.empty()) {
        const std::uint32_t t = stack.back();
        stack.pop_back();
        for (std::uint32_t u : tris_[t].nbr)
          if (u != kNone && piece[u] == kNone) piece[u] = piece[t], stack.push_back(u);
      }
    }
    out[e] = piece[t0];
  }
  return out;
}

std::size_t Triangulation::non_delaunay_edges() const {
  std::size_t bad = 0;
  for (std::uint32_t t = 0; t < tris_.size(); ++t)
    for (int i = 0; i < 3; ++i)
      if (tris_[t].nbr[i] != kNone && tris_[t].nbr[i] > t) {
        const Triangle& T = tris_[t];
        const Triangle& U = tris_[T.nbr[i]];
        int j = 0;
        while (U.nbr[j] != t || U.v[j] != T.v[(i + 1) % 3]) ++j;
        const auto& P = env_->vertices();
        if (CGAL::side_of_oriented_circle(P[T.v[0]], P[T.v[1]], P[T.v[2]], P[U.v[(j + 2) % 3]]) ==
            CGAL::ON_POSITIVE_SIDE)
          ++bad;
      }
  return bad;
}

void Triangulation::check() const {
  const Environment& E = *env_;
  const auto& P = E.vertices();
  auto fail = [](const std::string& m) { throw std::logic_error("triangulation check: " + m); };
  // Euler on the closed free space (connected, h holes: chi = 1 - h) with n boundary edges
  // and n - c distinct points, c = vertices merged at contacts: T = n - 2c + 2h - 2.
  const std::size_t merged = E.contact_merges();
  if (tris_.size() + 2 * merged != E.num_vertices() + 2 * E.num_holes() - 2)
    fail("triangle count " + std::to_string(tris_.size()) + " != n - 2c + 2h - 2");
  std::decay_t<decltype(CGAL::exact(std::declval<ExactFT>()))> area = 0;  // exact type: see Environment::exact_area
  std::vector<int> boundary_seen(E.num_vertices(), 0);
  for (std::uint32_t t = 0; t < tris_.size(); ++t) {
    const Triangle& T = tris_[t];
    if (orientation(P[T.v[0]], P[T.v[1]], P[T.v[2]]) <= 0) fail("triangle " + std::to_string(t) + " not positive");
    ExactKernel::Triangle_2 tri(to_exact(P[T.v[0]]), to_exact(P[T.v[1]]), to_exact(P[T.v[2]]));
    area += CGAL::exact(tri.area());
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = T.v[i], b = T.v[(i + 1) % 3];
      if (T.nbr[i] == kNone) {
        if (T.edge[i] != a || E.wedge_start(E.next(a)) != b) fail("boundary slot without its environment edge");
        ++boundary_seen[a];
      } else {
        const Triangle& U = tris_[T.nbr[i]];
        bool ok = false;
        for (int j = 0; j < 3; ++j) ok |= U.nbr[j] == t && U.v[j] == b && U.v[(j + 1) % 3] == a;
        if (!ok) fail("asymmetric adjacency at triangle " + std::to_string(t));
      }
    }
  }
  for (std::size_t e = 0; e < boundary_seen.size(); ++e)
    if (boundary_seen[e] != 1) fail("environment edge " + std::to_string(e) + " appears " + std::to_string(boundary_seen[e]) + " times");
  if (area != CGAL::exact(E.exact_area())) fail("triangle areas do not sum to the free area");
}

}  // namespace preimage::geometry
