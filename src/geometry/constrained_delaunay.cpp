// SPDX-License-Identifier: Apache-2.0
// Constrained Delaunay triangulation of free space, O(n log n) expected:
//   1. Delaunay triangulation of the vertices inside a far triangle by incremental
//      insertion with Lawson flips (Guibas, Knuth & Sharir), in a biased randomised
//      insertion order (Amenta, Choi & Rote) so each walk to the next point is short;
//   2. every environment edge forced in: the triangles it crosses removed and the two
//      pseudo-polygons on either side re-triangulated by the Delaunay vertex of each base
//      (Anglada 1997);
//   3. the triangles of free space kept: crossing an environment edge toggles between
//      outside and inside, counted from the far triangle.
// A monotone partition with triangulated pieces, flipped to Delaunay afterwards, needed
// quadratically many flips on long collinear runs (a minute for 10^5 vertices).
// At a contact (rings touching at a point) the point is inserted once, under the smallest
// vertex id there; the caller (Triangulation) relabels each corner with its wedge.
#include "constrained_delaunay.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <unordered_map>

namespace preimage::geometry {
namespace {

constexpr std::uint32_t kNo = UINT32_MAX;

struct Tri {
  std::array<std::uint32_t, 3> v;    // counter-clockwise
  std::array<std::uint32_t, 3> nbr;  // nbr[i]: across edge (v[i], v[i+1]), kNo on the far triangle's sides
  bool dead = false;
};

inline int next3(int i) { return i == 2 ? 0 : i + 1; }
inline int prev3(int i) { return i == 0 ? 2 : i - 1; }

// Index along a Hilbert curve of order 16 (a cell of a 65536 x 65536 grid).
std::uint64_t hilbert(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) x = s - 1 - (x & (s - 1)) + (x & ~(s - 1)), y = s - 1 - (y & (s - 1)) + (y & ~(s - 1));
      std::swap(x, y);
    }
  }
  return d;
}

class Builder {
 public:
  explicit Builder(const Environment& env) : env_(env), n_(static_cast<std::uint32_t>(env.num_vertices())) {
    rep_.resize(n_);
    for (std::uint32_t v = 0; v < n_; ++v) {
      rep_[v] = v;
      for (std::size_t w = env.same_point_next(v); w != v; w = env.same_point_next(w))
        rep_[v] = std::min(rep_[v], static_cast<std::uint32_t>(w));
    }
  }

  std::vector<std::array<std::uint32_t, 3>> run() {
    make_far_triangle();
    for (std::uint32_t v : insertion_order()) insert(v);
    for (std::uint32_t e = 0; e < n_; ++e) force_edge(rep_[e], rep_[env_.next(e)]);
    return free_space_triangles();
  }

 private:
  const Environment& env_;
  const std::uint32_t n_;    // environment vertices are 0..n-1, the far triangle's n..n+2
  std::vector<std::uint32_t> rep_;  // smallest vertex id at each vertex's point (contacts)
  std::vector<Point> p_;
  std::vector<Tri> t_;
  std::vector<std::uint32_t> vt_;  // a live triangle at each vertex
  std::uint32_t last_ = 0;         // where the next walk starts

  int orient(std::uint32_t a, std::uint32_t b, std::uint32_t c) const { return orientation(p_[a], p_[b], p_[c]); }
  // d strictly inside the circle through the counter-clockwise a, b, c.
  bool in_circle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) const {
    return CGAL::side_of_oriented_circle(p_[a], p_[b], p_[c], p_[d]) == CGAL::ON_POSITIVE_SIDE;
  }

  std::uint32_t make(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::array<std::uint32_t, 3> nbr, std::uint32_t slot = kNo) {
    if (slot == kNo) slot = static_cast<std::uint32_t>(t_.size()), t_.emplace_back();
    t_[slot] = {{a, b, c}, nbr, false};
    vt_[a] = vt_[b] = vt_[c] = slot;
    return slot;
  }
  void repoint(std::uint32_t x, std::uint32_t from, std::uint32_t to) {
    if (x == kNo) return;
    for (auto& k : t_[x].nbr)
      if (k == from) {
        k = to;
        return;
      }
    throw std::logic_error("constrained Delaunay: broken adjacency");
  }
  int slot_of(std::uint32_t t, std::uint32_t v) const {
    for (int i = 0; i < 3; ++i)
      if (t_[t].v[i] == v) return i;
    throw std::logic_error("constrained Delaunay: vertex not in triangle");
  }

  void make_far_triangle() {
    p_ = env_.vertices();
    const CGAL::Bbox_2 b = env_.bbox();  // the outer boundary holds every vertex
    const double cx = (b.xmin() + b.xmax()) / 2, cy = (b.ymin() + b.ymax()) / 2;
    const double m = 1024 * std::max({b.xmax() - b.xmin(), b.ymax() - b.ymin(), 1.0});
    p_.emplace_back(cx - m, cy - m);
    p_.emplace_back(cx + m, cy - m);
    p_.emplace_back(cx, cy + m);
    vt_.assign(n_ + 3, kNo);
    t_.reserve(2 * std::size_t(n_) + 16);
    last_ = make(n_, n_ + 1, n_ + 2, {kNo, kNo, kNo});
  }

  // Random order, then the last half, the quarter before it, ... each sorted along a
  // Hilbert curve (BRIO): expected O(log n) flips per point and short walks.
  std::vector<std::uint32_t> insertion_order() const {
    std::vector<std::uint32_t> order(n_);
    std::iota(order.begin(), order.end(), 0u);
    if (env_.has_contacts()) std::erase_if(order, [&](std::uint32_t v) { return rep_[v] != v; });
    std::mt19937_64 rng(0x5eed);
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[rng() % i]);
    const CGAL::Bbox_2 b = env_.bbox();
    const double sx = 65535 / std::max(b.xmax() - b.xmin(), 1e-300), sy = 65535 / std::max(b.ymax() - b.ymin(), 1e-300);
    std::vector<std::uint64_t> key(n_);
    for (std::uint32_t v = 0; v < n_; ++v)
      key[v] = hilbert(static_cast<std::uint32_t>(std::clamp((p_[v].x() - b.xmin()) * sx, 0.0, 65535.0)),
                       static_cast<std::uint32_t>(std::clamp((p_[v].y() - b.ymin()) * sy, 0.0, 65535.0)));
    for (std::size_t hi = order.size(); hi > 0;) {
      const std::size_t lo = hi <= 64 ? 0 : hi / 2;
      std::sort(order.begin() + static_cast<std::ptrdiff_t>(lo), order.begin() + static_cast<std::ptrdiff_t>(hi),
                [&](auto a, auto c) { return key[a] < key[c]; });
      hi = lo;
    }
    return order;
  }

  // ---------------------------------------------------------------- 1. insertion
  void insert(std::uint32_t q) {
    // Visibility walk: it ends in a Delaunay triangulation (Edelsbrunner).
    std::uint32_t t = last_;
    for (bool moved = true; moved;) {
      moved = false;
      for (int i = 0; i < 3; ++i)
        if (orient(t_[t].v[i], t_[t].v[next3(i)], q) < 0) {
          t = t_[t].nbr[i];
          if (t == kNo) throw std::logic_error("constrained Delaunay: a vertex outside the far triangle");
          moved = true;
          break;
        }
    }
    int on = -1;
    for (int i = 0; i < 3; ++i)
      if (orient(t_[t].v[i], t_[t].v[next3(i)], q) == 0) on = i;  // distinct points: on one edge at most
    std::vector<std::pair<std::uint32_t, int>> stack;
    if (on < 0) {
      const auto [a, b, c] = t_[t].v;
      const auto [na, nb, nc] = t_[t].nbr;
      const std::uint32_t t1 = static_cast<std::uint32_t>(t_.size()), t2 = t1 + 1;
      make(a, b, q, {na, t1, t2}, t);
      make(b, c, q, {nb, t2, t}, kNo);
      make(c, a, q, {nc, t, t1}, kNo);
      repoint(nb, t, t1);
      repoint(nc, t, t2);
      stack = {{t, 0}, {t1, 0}, {t2, 0}};
    } else {
      // q inside edge (a, b) of t = (a, b, c) and of u = (b, a, d): four triangles.
      const Tri T = t_[t];
      const std::uint32_t a = T.v[on], b = T.v[next3(on)], c = T.v[prev3(on)];
      const std::uint32_t u = T.nbr[on];
      if (u == kNo) throw std::logic_error("constrained Delaunay: a vertex on the far triangle");
      const Tri U = t_[u];
      const int j = slot_of(u, b);
      const std::uint32_t d = U.v[prev3(j)];
      const std::uint32_t n_bc = T.nbr[next3(on)], n_ca = T.nbr[prev3(on)], n_ad = U.nbr[next3(j)], n_db = U.nbr[prev3(j)];
      const std::uint32_t t2 = static_cast<std::uint32_t>(t_.size()), t4 = t2 + 1;
      make(c, a, q, {n_ca, t4, t2}, t);
      make(b, c, q, {n_bc, t, u}, kNo);
      make(d, b, q, {n_db, t2, t4}, u);
      make(a, d, q, {n_ad, u, t}, kNo);
      repoint(n_bc, t, t2);
      repoint(n_ad, u, t4);
      stack = {{t, 0}, {t2, 0}, {u, 0}, {t4, 0}};
    }
    last_ = t;
    // Lawson: each triangle on the stack has q at slot 2; its edge 0 faces q.
    while (!stack.empty()) {
      auto [x, i] = stack.back();
      stack.pop_back();
      const std::uint32_t y = t_[x].nbr[i];
      if (y == kNo) continue;
      const int j = slot_of(y, t_[x].v[next3(i)]);
      if (!in_circle(t_[x].v[0], t_[x].v[1], t_[x].v[2], t_[y].v[prev3(j)])) continue;
      flip(x, i);
      stack.emplace_back(x, 0);
      stack.emplace_back(y, 0);
    }
  }

  // t = (a, b, c) and its neighbour u = (b, a, d) across edge i become t = (a, d, c) and
  // u = (d, b, c): c stays at slot 2 of both.
  void flip(std::uint32_t t, int i) {
    const Tri T = t_[t];
    const std::uint32_t u = T.nbr[i];
    const Tri U = t_[u];
    const std::uint32_t a = T.v[i], b = T.v[next3(i)], c = T.v[prev3(i)];
    const int j = slot_of(u, b);
    const std::uint32_t d = U.v[prev3(j)];
    const std::uint32_t n_bc = T.nbr[next3(i)], n_ca = T.nbr[prev3(i)], n_ad = U.nbr[next3(j)], n_db = U.nbr[prev3(j)];
    make(a, d, c, {n_ad, u, n_ca}, t);
    make(d, b, c, {n_db, n_bc, t}, u);
    repoint(n_ad, u, t);
    repoint(n_bc, t, u);
  }

  // ---------------------------------------------------------------- 2. constraints
  void force_edge(std::uint32_t a, std::uint32_t b) {
    // Around a, the triangle (a, x, y) whose open wedge holds b, unless ab is an edge.
    std::uint32_t t = vt_[a];
    int i = slot_of(t, a);
    for (std::size_t guard = 0;; ++guard) {
      const std::uint32_t x = t_[t].v[next3(i)], y = t_[t].v[prev3(i)];
      if (x == b || y == b) return;
      if (orient(a, x, b) > 0 && orient(a, y, b) < 0) break;
      t = t_[t].nbr[prev3(i)];  // across (y, a): the next triangle counter-clockwise
      if (t == kNo || guard > t_.size()) throw std::logic_error("constrained Delaunay: no triangle at a vertex sees the edge");
      i = slot_of(t, a);
    }
    // Walk along ab; a vertex never lies inside it (the environment is valid).
    std::vector<std::uint32_t> crossed{t}, left, right;
    std::uint32_t l = t_[t].v[prev3(i)], r = t_[t].v[next3(i)];
    left.push_back(l), right.push_back(r);
    for (std::uint32_t cur = t;;) {
      const std::uint32_t u = t_[cur].nbr[slot_of(cur, r)];  // across (r, l)
      if (u == kNo) throw std::logic_error("constrained Delaunay: an edge leaves the far triangle");
      crossed.push_back(u);
      const std::uint32_t z = t_[u].v[prev3(slot_of(u, l))];
      if (z == b) break;
      const int s = orient(a, b, z);
      if (s == 0) throw std::logic_error("constrained Delaunay: a vertex inside an environment edge");
      if (s > 0) left.push_back(l = z);
      else right.push_back(r = z);
      cur = u;
    }
    // The cavity's boundary half-edges (as the crossed triangles have them) and the
    // triangles beyond them.
    std::unordered_map<std::uint64_t, std::uint32_t> beyond;
    auto key = [](std::uint32_t x, std::uint32_t y) { return (std::uint64_t(x) << 32) | y; };
    for (std::uint32_t c : crossed) t_[c].dead = true;
    for (std::uint32_t c : crossed)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t o = t_[c].nbr[k];
        if (o == kNo || !t_[o].dead) beyond[key(t_[c].v[k], t_[c].v[next3(k)])] = o;
      }
    for (std::uint32_t c : crossed) t_[c].dead = false;
    // Re-triangulate both sides; reuse the crossed slots first.
    std::vector<std::uint32_t> free_slots(crossed.rbegin(), crossed.rend()), made;
    auto emit = [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
      std::uint32_t slot = kNo;
      if (!free_slots.empty()) slot = free_slots.back(), free_slots.pop_back();
      made.push_back(make(x, y, z, {kNo, kNo, kNo}, slot));
    };
    std::reverse(left.begin(), left.end());  // left of a -> b, counter-clockwise: a, b, then back to a
    fill_pseudo_polygon(a, b, left, emit);
    fill_pseudo_polygon(b, a, right, emit);
    if (!free_slots.empty()) throw std::logic_error("constrained Delaunay: cavity triangle count");
    // Link: half-edges of new triangles pair with each other or with the cavity's boundary.
    std::unordered_map<std::uint64_t, std::pair<std::uint32_t, int>> open;
    for (std::uint32_t m : made)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t x = t_[m].v[k], y = t_[m].v[next3(k)];
        if (auto it = beyond.find(key(x, y)); it != beyond.end()) {
          t_[m].nbr[k] = it->second;
          if (it->second != kNo) set_neighbour_across(it->second, y, x, m);
        } else if (auto jt = open.find(key(y, x)); jt != open.end()) {
          t_[m].nbr[k] = jt->second.first;
          t_[jt->second.first].nbr[jt->second.second] = m;
          open.erase(jt);
        } else {
          open[key(x, y)] = {m, k};
        }
      }
    if (!open.empty()) throw std::logic_error("constrained Delaunay: cavity left unmatched edges");
  }

  // In triangle o, the neighbour across its edge (x, y) becomes m.
  void set_neighbour_across(std::uint32_t o, std::uint32_t x, std::uint32_t y, std::uint32_t m) {
    const int k = slot_of(o, x);
    if (t_[o].v[next3(k)] != y) throw std::logic_error("constrained Delaunay: cavity boundary mismatch");
    t_[o].nbr[k] = m;
  }

  // The region left of p -> q bounded by the chain q ... p (counter-clockwise: p, q,
  // chain[0], ..., chain[m-1]): the chain vertex whose circle with p and q holds no other
  // chain vertex makes a triangle with them, and both sides recurse (Anglada).
  template <class Emit>
  void fill_pseudo_polygon(std::uint32_t p, std::uint32_t q, const std::vector<std::uint32_t>& chain, Emit&& emit) {
    struct Job {
      std::uint32_t p, q;
      std::size_t lo, hi;  // chain[lo, hi)
    };
    std::vector<Job> jobs{{p, q, 0, chain.size()}};
    while (!jobs.empty()) {
      const Job J = jobs.back();
      jobs.pop_back();
      if (J.lo == J.hi) continue;
      std::size_t c = J.lo;
      for (std::size_t k = J.lo + 1; k < J.hi; ++k)
        if (in_circle(J.p, J.q, chain[c], chain[k])) c = k;
      emit(J.p, J.q, chain[c]);
      jobs.push_back({chain[c], J.q, J.lo, c});    // left of c -> q: q, chain[lo..c), c
      jobs.push_back({J.p, chain[c], c + 1, J.hi});  // left of p -> c: c, chain(c..hi), p
    }
  }

  // ---------------------------------------------------------------- 3. free space
  bool environment_edge(std::uint32_t x, std::uint32_t y) const {
    if (x >= n_ || y >= n_) return false;
    if (!env_.has_contacts()) return env_.next(x) == y || env_.next(y) == x;
    return env_.edge_between(x, y) != SIZE_MAX || env_.edge_between(y, x) != SIZE_MAX;
  }

  std::vector<std::array<std::uint32_t, 3>> free_space_triangles() {
    // Parity of environment edges crossed from the far triangle: 1 in free space.
    std::vector<std::int8_t> side(t_.size(), -1);
    std::vector<std::uint32_t> queue{vt_[n_]};
    side[vt_[n_]] = 0;
    for (std::size_t h = 0; h < queue.size(); ++h) {
      const std::uint32_t x = queue[h];
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t y = t_[x].nbr[k];
        if (y == kNo || side[y] >= 0) continue;
        side[y] = static_cast<std::int8_t>(side[x] ^ (environment_edge(t_[x].v[k], t_[x].v[next3(k)]) ? 1 : 0));
        queue.push_back(y);
      }
    }
    std::vector<std::uint32_t> index(t_.size(), kNo);
    std::vector<std::array<std::uint32_t, 3>> out;
    for (std::uint32_t x = 0; x < t_.size(); ++x)
      if (side[x] == 1) index[x] = static_cast<std::uint32_t>(out.size()), out.push_back(t_[x].v);
    if (queue.size() != t_.size()) throw std::logic_error("constrained Delaunay: triangles not reached");
    // Lawson over free space with environment edges fixed: a guard, Anglada's fill is
    // already constrained Delaunay, so this finds nothing to flip.
    for (std::uint32_t x = 0; x < t_.size(); ++x)
      if (side[x] == 1)
        for (auto& y : t_[x].nbr)
          if (y != kNo && side[y] != 1) y = kNo;
    std::vector<std::pair<std::uint32_t, int>> stack;
    for (std::uint32_t x = 0; x < t_.size(); ++x)
      if (side[x] == 1)
        for (int k = 0; k < 3; ++k)
          if (!environment_edge(t_[x].v[k], t_[x].v[next3(k)])) stack.emplace_back(x, k);
    while (!stack.empty()) {
      auto [x, i] = stack.back();
      stack.pop_back();
      const std::uint32_t y = t_[x].nbr[i];
      if (y == kNo || environment_edge(t_[x].v[i], t_[x].v[next3(i)])) continue;
      const int j = slot_of(y, t_[x].v[next3(i)]);
      if (!in_circle(t_[x].v[0], t_[x].v[1], t_[x].v[2], t_[y].v[prev3(j)])) continue;
      flip(x, i);
      for (int k = 0; k < 3; ++k) stack.emplace_back(x, k), stack.emplace_back(y, k);
    }
    for (std::uint32_t x = 0; x < t_.size(); ++x)
      if (index[x] != kNo) out[index[x]] = t_[x].v;
    return out;
  }
};

}  // namespace

std::vector<std::array<std::uint32_t, 3>> constrained_delaunay_triangles(const Environment& env) {
  return Builder(env).run();
}

}  // namespace preimage::geometry
