// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/triangulation.hpp>

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>
#include <unordered_map>

namespace preimage::geometry {
namespace {

// Sweep order, top to bottom: a before b if a.y > b.y, ties by smaller x first.
// This is a sweep line rotated by an infinitesimal angle, so no two vertices are
// ever "level" and horizontal edges need no special case (de Berg 3.2).
inline bool above(const Point& a, const Point& b) {
  return a.y() > b.y() || (a.y() == b.y() && a.x() < b.x());
}

enum class VertexType : std::uint8_t { Start, Split, End, Merge, RegularDown, RegularUp };

// Counter-clockwise angular order of directions c->a, c->b (exact), starting at +x.
inline bool ccw_before(const Point& c, const Point& a, const Point& b) {
  auto half = [&](const Point& p) { return (p.y() > c.y() || (p.y() == c.y() && p.x() > c.x())) ? 0 : 1; };
  int ha = half(a), hb = half(b);
  if (ha != hb) return ha < hb;
  return orientation(c, a, b) > 0;
}

}  // namespace

Triangulation::Triangulation(const Environment& env) : env_(&env) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> diagonals;
  monotone_partition(diagonals);
  triangulate_pieces(diagonals);
  link();
  make_delaunay();
}

// ---------------------------------------------------------------- 1. monotone partition
void Triangulation::monotone_partition(std::vector<std::pair<std::uint32_t, std::uint32_t>>& diagonals) const {
  const Environment& E = *env_;
  const auto& P = E.vertices();
  const std::uint32_t n = static_cast<std::uint32_t>(P.size());

  std::vector<VertexType> type(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    const Point &u = P[E.prev(v)], &c = P[v], &w = P[E.next(v)];
    const bool u_below = above(c, u), w_below = above(c, w);
    const int turn = orientation(u, c, w);
    if (u_below && w_below) type[v] = turn > 0 ? VertexType::Start : VertexType::Split;
    else if (!u_below && !w_below) type[v] = turn > 0 ? VertexType::End : VertexType::Merge;
    else type[v] = u_below ? VertexType::RegularUp : VertexType::RegularDown;
  }

  // Status: edges going down (free space to their east), ordered west to east.
  // An edge is named by its upper vertex e (edge e -> next(e)).
  struct VertexKey { std::uint32_t v; };
  struct West {
    using is_transparent = void;
    const Environment* E;
    bool operator()(std::uint32_t a, std::uint32_t b) const {
      if (a == b) return false;
      const auto& P = E->vertices();
      const Point &ua = P[a], &la = P[E->next(a)], &ub = P[b], &lb = P[E->next(b)];
      if (above(ub, ua)) return orientation(ub, lb, ua) < 0;  // locate a's top against b
      return orientation(ua, la, ub) > 0;                    // locate b's top against a
    }
    bool operator()(std::uint32_t e, VertexKey k) const {  // edge west of vertex
      const auto& P = E->vertices();
      return orientation(P[e], P[E->next(e)], P[k.v]) > 0;
    }
    bool operator()(VertexKey k, std::uint32_t e) const {  // vertex west of edge
      const auto& P = E->vertices();
      return orientation(P[e], P[E->next(e)], P[k.v]) < 0;
    }
  };
  std::set<std::uint32_t, West> status(West{&E});
  std::vector<std::uint32_t> helper(n, kNone);

  auto left_of = [&](std::uint32_t v) -> std::uint32_t {
    auto it = status.lower_bound(VertexKey{v});
    if (it == status.begin()) throw std::logic_error("monotone partition: no edge west of a vertex");
    return *std::prev(it);
  };
  auto connect_if_merge = [&](std::uint32_t v, std::uint32_t e) {
    if (type[helper[e]] == VertexType::Merge) diagonals.emplace_back(v, helper[e]);
  };

  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return above(P[a], P[b]); });

  for (std::uint32_t v : order) {
    const std::uint32_t in = static_cast<std::uint32_t>(E.prev(v));  // edge prev(v) -> v
    switch (type[v]) {
      case VertexType::Start:
        status.insert(v), helper[v] = v;
        break;
      case VertexType::End:
        connect_if_merge(v, in);
        status.erase(in);
        break;
      case VertexType::Split: {
        auto e = left_of(v);
        diagonals.emplace_back(v, helper[e]);
        helper[e] = v;
        status.insert(v), helper[v] = v;
        break;
      }
      case VertexType::Merge: {
        connect_if_merge(v, in);
        status.erase(in);
        auto e = left_of(v);
        connect_if_merge(v, e);
        helper[e] = v;
        break;
      }
      case VertexType::RegularDown:  // boundary runs down through v, free space east
        connect_if_merge(v, in);
        status.erase(in);
        status.insert(v), helper[v] = v;
        break;
      case VertexType::RegularUp: {  // boundary runs up through v, free space west
        auto e = left_of(v);
        connect_if_merge(v, e);
        helper[e] = v;
        break;
      }
    }
  }
}

// ---------------------------------------------------------------- 2. pieces and ears
void Triangulation::triangulate_pieces(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& diagonals) {
  const Environment& E = *env_;
  const auto& P = E.vertices();
  const std::uint32_t n = static_cast<std::uint32_t>(P.size());

  // Neighbours of each vertex (ring edges + diagonals), counter-clockwise.
  std::vector<std::uint32_t> off(n + 1, 2);
  off[0] = 0;
  for (auto [a, b] : diagonals) ++off[a + 1], ++off[b + 1];
  std::partial_sum(off.begin(), off.end(), off.begin());
  std::vector<std::uint32_t> adj(off[n]);
  {
    std::vector<std::uint32_t> fill(off.begin(), off.end() - 1);
    for (std::uint32_t v = 0; v < n; ++v) {
      adj[fill[v]++] = static_cast<std::uint32_t>(E.next(v));
      adj[fill[v]++] = static_cast<std::uint32_t>(E.prev(v));
    }
    for (auto [a, b] : diagonals) adj[fill[a]++] = b, adj[fill[b]++] = a;
  }
  for (std::uint32_t v = 0; v < n; ++v)
    std::sort(adj.begin() + off[v], adj.begin() + off[v + 1],
              [&](auto a, auto b) { return ccw_before(P[v], P[a], P[b]); });
  auto slot_of = [&](std::uint32_t v, std::uint32_t w) {
    for (auto k = off[v]; k < off[v + 1]; ++k)
      if (adj[k] == w) return k;
    throw std::logic_error("triangulation: half-edge not found");
  };
  // Face to the left of a->b continues with b->c, c the neighbour of b just clockwise of a.
  auto successor = [&](std::uint32_t a, std::uint32_t b) {
    auto k = slot_of(b, a);
    return adj[k == off[b] ? off[b + 1] - 1 : k - 1];
  };

  std::vector<char> used(adj.size(), 0);
  std::vector<std::uint32_t> piece;
  tris_.reserve(n + 2 * E.num_holes());
  auto walk = [&](std::uint32_t a, std::uint32_t b) {
    auto k = slot_of(a, b);
    if (used[k]) return;
    piece.clear();
    std::uint32_t x = a, y = b;
    do {
      used[slot_of(x, y)] = 1;
      piece.push_back(x);
      std::uint32_t z = successor(x, y);
      x = y, y = z;
      if (piece.size() > n) throw std::logic_error("triangulation: face walk did not close");
    } while (x != a || y != b);
    // Ear clipping of the monotone piece. An ear is a strictly convex corner whose
    // closed triangle holds no other reflex or straight vertex (only those can make
    // a diagonal leave the piece or pass through a vertex).
    const std::size_t m = piece.size();
    std::vector<std::uint32_t> nx(m), pv(m);
    for (std::size_t i = 0; i < m; ++i) nx[i] = static_cast<std::uint32_t>((i + 1) % m), pv[i] = static_cast<std::uint32_t>((i + m - 1) % m);
    auto pt = [&](std::uint32_t i) -> const Point& { return P[piece[i]]; };
    auto convex = [&](std::uint32_t i) { return orientation(pt(pv[i]), pt(i), pt(nx[i])) > 0; };
    std::vector<std::uint32_t> nonconvex;
    for (std::uint32_t i = 0; i < m; ++i)
      if (!convex(i)) nonconvex.push_back(i);
    std::vector<char> alive(m, 1);
    auto is_ear = [&](std::uint32_t i) {
      if (!convex(i)) return false;
      const Point &a = pt(pv[i]), &b = pt(i), &c = pt(nx[i]);
      for (auto r : nonconvex) {
        if (!alive[r] || r == pv[i] || r == nx[i] || r == i) continue;
        const Point& p = pt(r);
        if (orientation(a, b, p) >= 0 && orientation(b, c, p) >= 0 && orientation(c, a, p) >= 0) return false;
      }
      return true;
    };
    std::size_t left = m;
    std::uint32_t i = 0, since_clip = 0;
    while (left > 3) {
      if (is_ear(i)) {
        tris_.push_back({{piece[pv[i]], piece[i], piece[nx[i]]}, {kNone, kNone, kNone}, {kNone, kNone, kNone}});
        alive[i] = 0;
        nx[pv[i]] = nx[i], pv[nx[i]] = pv[i];
        --left;
        i = pv[i];  // the previous corner may have become an ear
        since_clip = 0;
        if (nonconvex.size() > 64 && nonconvex.size() > 2 * left)  // keep the reflex list short
          nonconvex.erase(std::remove_if(nonconvex.begin(), nonconvex.end(),
                                         [&](auto r) { return !alive[r] || convex(r); }), nonconvex.end());
      } else {
        i = nx[i];
        if (++since_clip > left) throw std::logic_error("triangulation: no ear in a monotone piece");
      }
    }
    tris_.push_back({{piece[pv[i]], piece[i], piece[nx[i]]}, {kNone, kNone, kNone}, {kNone, kNone, kNone}});
  };
  for (std::uint32_t v = 0; v < n; ++v) walk(v, static_cast<std::uint32_t>(E.next(v)));
  for (auto [a, b] : diagonals) walk(a, b), walk(b, a);
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
      if (E.next(a) == b) {  // boundary edge, free space on its left as in the triangle
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

// ---------------------------------------------------------------- 3. Lawson flips
bool Triangulation::illegal(std::uint32_t t, int i) const {
  const Triangle& T = tris_[t];
  std::uint32_t u = T.nbr[i];
  if (u == kNone) return false;
  const Triangle& U = tris_[u];
  int j = 0;
  while (U.nbr[j] != t || U.v[j] != T.v[(i + 1) % 3]) ++j;
  const auto& P = env_->vertices();
  const Point &a = P[T.v[i]], &b = P[T.v[(i + 1) % 3]], &c = P[T.v[(i + 2) % 3]], &d = P[U.v[(j + 2) % 3]];
  if (CGAL::side_of_oriented_circle(a, b, c, d) != CGAL::ON_POSITIVE_SIDE) return false;
  // Strictly convex quadrilateral a, d, b, c (always true for an illegal edge; kept as a guard).
  return orientation(c, a, d) > 0 && orientation(d, b, c) > 0;
}

void Triangulation::flip(std::uint32_t t, int i) {
  // Triangles t = (a, b, c) and u = (b, a, d) become t = (a, d, c) and u = (d, b, c).
  Triangle T = tris_[t];
  const std::uint32_t u = T.nbr[i];
  Triangle U = tris_[u];
  int j = 0;
  while (U.nbr[j] != t || U.v[j] != T.v[(i + 1) % 3]) ++j;
  const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
  const std::uint32_t a = T.v[i], b = T.v[i1], c = T.v[i2], d = U.v[j2];
  const std::uint32_t n_bc = T.nbr[i1], n_ca = T.nbr[i2], n_ad = U.nbr[j1], n_db = U.nbr[j2];
  const std::uint32_t e_bc = T.edge[i1], e_ca = T.edge[i2], e_ad = U.edge[j1], e_db = U.edge[j2];
  tris_[t] = {{a, d, c}, {n_ad, u, n_ca}, {e_ad, kNone, e_ca}};
  tris_[u] = {{d, b, c}, {n_db, n_bc, t}, {e_db, e_bc, kNone}};
  auto repoint = [&](std::uint32_t x, std::uint32_t from, std::uint32_t to) {
    if (x == kNone) return;
    for (auto& k : tris_[x].nbr)
      if (k == from) { k = to; return; }
  };
  repoint(n_ad, u, t);
  repoint(n_bc, t, u);
  if (e_ad != kNone) edge_slot_[e_ad] = {t, 0};
  if (e_ca != kNone) edge_slot_[e_ca] = {t, 2};
  if (e_db != kNone) edge_slot_[e_db] = {u, 0};
  if (e_bc != kNone) edge_slot_[e_bc] = {u, 1};
}

void Triangulation::make_delaunay() {
  std::vector<std::pair<std::uint32_t, std::uint8_t>> stack;
  for (std::uint32_t t = 0; t < tris_.size(); ++t)
    for (std::uint8_t i = 0; i < 3; ++i)
      if (tris_[t].nbr[i] != kNone && tris_[t].nbr[i] > t) stack.emplace_back(t, i);
  while (!stack.empty()) {
    auto [t, i] = stack.back();
    stack.pop_back();
    if (!illegal(t, i)) continue;
    const std::uint32_t u = tris_[t].nbr[i];
    flip(t, i);
    stack.emplace_back(t, 0), stack.emplace_back(t, 2), stack.emplace_back(u, 0), stack.emplace_back(u, 1);
  }
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
  if (tris_.size() != E.num_vertices() + 2 * E.num_holes() - 2)
    fail("triangle count " + std::to_string(tris_.size()) + " != n + 2h - 2");
  ExactFT area = 0;
  std::vector<int> boundary_seen(E.num_vertices(), 0);
  for (std::uint32_t t = 0; t < tris_.size(); ++t) {
    const Triangle& T = tris_[t];
    if (orientation(P[T.v[0]], P[T.v[1]], P[T.v[2]]) <= 0) fail("triangle " + std::to_string(t) + " not positive");
    ExactKernel::Triangle_2 tri(to_exact(P[T.v[0]]), to_exact(P[T.v[1]]), to_exact(P[T.v[2]]));
    area += tri.area();
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = T.v[i], b = T.v[(i + 1) % 3];
      if (T.nbr[i] == kNone) {
        if (T.edge[i] != a || E.next(a) != b) fail("boundary slot without its environment edge");
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
  if (area != E.exact_area()) fail("triangle areas do not sum to the free area");
}

}  // namespace preimage::geometry
