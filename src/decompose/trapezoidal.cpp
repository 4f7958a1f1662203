// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/trapezoidal.hpp>

#include <algorithm>
#include <numeric>
#include <set>
#include <stdexcept>

namespace preimage::decompose {

using geometry::lex_less_xy;
using geometry::orientation;

namespace {
constexpr std::uint32_t kNoneId = UINT32_MAX;
}

TrapezoidalDecomposition::TrapezoidalDecomposition(const Environment& env) : env_(&env) {
  const auto& P = env.vertices();
  const std::uint32_t n = static_cast<std::uint32_t>(P.size());
  // Left and right end of each edge (lexicographic); vertical edges never enter the status.
  std::vector<std::uint32_t> lo(n), hi(n);
  for (std::uint32_t e = 0; e < n; ++e) {
    const std::uint32_t a = e, b = static_cast<std::uint32_t>(env.next(e));
    if (lex_less_xy(P[a], P[b])) lo[e] = a, hi[e] = b;
    else lo[e] = b, hi[e] = a;
  }
  auto vertical = [&](std::uint32_t e) { return P[lo[e]].x() == P[hi[e]].x(); };
  // Free space is left of e -> next(e); for a rightward edge that is above it.
  auto is_floor = [&](std::uint32_t e) { return lo[e] == e; };

  // Status: non-vertical edges crossing the sweep line, bottom to top (valid just left of
  // the current event before removals, just right of it after insertions).
  struct Key { std::uint32_t v; };
  struct Below {
    using is_transparent = void;
    const std::vector<Point>* P;
    const std::vector<std::uint32_t>* lo;
    const std::vector<std::uint32_t>* hi;
    bool operator()(std::uint32_t a, std::uint32_t b) const {
      if (a == b) return false;
      const auto& Q = *P;
      return geometry::segment_below(Q[(*lo)[a]], Q[(*hi)[a]], Q[(*lo)[b]], Q[(*hi)[b]]);
    }
    // An edge ending or starting at the vertex is level with it. Deciding that by index
    // matters for speed: the orientation would be exactly zero, which no floating-point
    // filter can certify, so it would fall back to exact arithmetic every time.
    bool operator()(std::uint32_t e, Key k) const {  // edge strictly below vertex
      if ((*hi)[e] == k.v || (*lo)[e] == k.v) return false;
      return orientation((*P)[(*lo)[e]], (*P)[(*hi)[e]], (*P)[k.v]) > 0;
    }
    bool operator()(Key k, std::uint32_t e) const {  // vertex strictly below edge
      if ((*hi)[e] == k.v || (*lo)[e] == k.v) return false;
      return orientation((*P)[(*lo)[e]], (*P)[(*hi)[e]], (*P)[k.v]) < 0;
    }
  };
  std::set<std::uint32_t, Below> status(Below{&P, &lo, &hi});
  std::vector<std::uint32_t> open_cell(n, kNoneId);  // cell whose floor is edge e, while open

  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return lex_less_xy(P[a], P[b]); });

  // Entries on the sweep line x = c, bottom to top: vertices at c and edges crossing it.
  struct Entry { bool is_vertex; std::uint32_t id; };
  std::vector<Entry> Q;
  std::vector<std::uint32_t> rank_of_vertex(n, kNoneId), rank_of_crossing(n, kNoneId);
  std::vector<std::uint32_t> L, R, vertex_prefix;
  std::vector<std::uint32_t> left_closed, right_opened;  // cell per gap, or kNoneId
  std::vector<std::pair<std::uint32_t, std::uint32_t>> aliases;  // (vertex, the contact's entry)

  for (std::size_t g = 0; g < order.size();) {
    std::size_t g_end = g;
    const double c = P[order[g]].x();
    while (g_end < order.size() && P[order[g_end]].x() == c) ++g_end;
    const std::uint32_t vmin = order[g], vmax = order[g_end - 1];  // sorted by y within the group

    auto it_lo = status.lower_bound(Key{vmin});
    auto it_hi = status.upper_bound(Key{vmax});
    // B and T bound the touched range and survive the update (set iterators are stable).
    const auto it_B = it_lo == status.begin() ? status.end() : std::prev(it_lo);
    const auto it_T = it_hi;
    const std::uint32_t B = it_B == status.end() ? kNoneId : *it_B;
    const std::uint32_t T = it_T == status.end() ? kNoneId : *it_T;

    // Q: [B] + vertices at c merged with the edges crossing x = c strictly + [T]. The
    // vertices of a contact (rings touching at one point) are one entry: every edge ending
    // or starting there must get the same rank.
    Q.clear();
    aliases.clear();
    auto push_vertex = [&](std::uint32_t v) {
      if (!Q.empty() && Q.back().is_vertex && P[Q.back().id] == P[v]) aliases.emplace_back(v, Q.back().id);
      else Q.push_back({true, v});
    };
    if (B != kNoneId) Q.push_back({false, B});
    {
      std::size_t vi = g;
      for (auto it = it_lo; it != it_hi; ++it) {
        const std::uint32_t e = *it;
        if (P[hi[e]].x() == c) continue;  // ends here: represented by its end vertex
        while (vi < g_end && orientation(P[lo[e]], P[hi[e]], P[order[vi]]) < 0) push_vertex(order[vi++]);
        Q.push_back({false, e});
      }
      while (vi < g_end) push_vertex(order[vi++]);
    }
    if (T != kNoneId) Q.push_back({false, T});
    vertex_prefix.assign(Q.size() + 1, 0);
    for (std::size_t k = 0; k < Q.size(); ++k) {
      (Q[k].is_vertex ? rank_of_vertex : rank_of_crossing)[Q[k].id] = static_cast<std::uint32_t>(k);
      vertex_prefix[k + 1] = vertex_prefix[k] + (Q[k].is_vertex ? 1 : 0);
    }
    for (auto [v, head] : aliases) rank_of_vertex[v] = rank_of_vertex[head];
    auto has_vertex = [&](std::uint32_t r0, std::uint32_t r1) { return vertex_prefix[r1 + 1] > vertex_prefix[r0]; };
    // Rank on the line of an edge of the left (ending) or right (starting) side.
    auto left_rank = [&](std::uint32_t e) { return P[hi[e]].x() == c ? rank_of_vertex[hi[e]] : rank_of_crossing[e]; };
    auto right_rank = [&](std::uint32_t e) { return P[lo[e]].x() == c ? rank_of_vertex[lo[e]] : rank_of_crossing[e]; };

    // The edges on the sweep line from B to T, bottom to top (before or after the update).
    auto bounded_range = [&](std::vector<std::uint32_t>& out) {
      out.clear();
      if (B != kNoneId) out.push_back(B);
      for (auto it = it_lo; it != it_hi; ++it) out.push_back(*it);
      if (T != kNoneId) out.push_back(T);
    };

    // Left side: close every free gap that touches a vertex at c.
    bounded_range(L);
    left_closed.assign(L.size(), kNoneId);
    for (std::size_t i = 0; i + 1 < L.size(); ++i) {
      if (!is_floor(L[i])) continue;
      if (!has_vertex(left_rank(L[i]), left_rank(L[i + 1]))) continue;
      const std::uint32_t cell = open_cell[L[i]];
      if (cell == kNoneId) throw std::logic_error("trapezoidal decomposition: free gap without an open cell");
      cells_[cell].x_right = c;
      cells_[cell].ceiling = L[i + 1];
      open_cell[L[i]] = kNoneId;
      left_closed[i] = cell;
    }

    // Update the status: edges ending at c leave, edges starting at c enter.
    for (auto it = it_lo; it != it_hi;) {
      if (P[hi[*it]].x() == c) it = status.erase(it);
      else ++it;
    }
    for (std::size_t k = g; k < g_end; ++k) {
      const std::uint32_t v = order[k];
      for (std::uint32_t e : {v, static_cast<std::uint32_t>(env.prev(v))})
        if (lo[e] == v && !vertical(e)) status.insert(it_T, e);  // new edges lie below T
    }
    it_lo = it_B == status.end() ? status.begin() : std::next(it_B);
    it_hi = it_T;

    // Right side: open a cell in every free gap that touches a vertex at c.
    bounded_range(R);
    right_opened.assign(R.size(), kNoneId);
    for (std::size_t i = 0; i + 1 < R.size(); ++i) {
      if (!is_floor(R[i])) continue;
      if (!has_vertex(right_rank(R[i]), right_rank(R[i + 1]))) {
        if (open_cell[R[i]] == kNoneId) throw std::logic_error("trapezoidal decomposition: lost a continuing cell");
        continue;
      }
      const std::uint32_t cell = static_cast<std::uint32_t>(cells_.size());
      cells_.push_back({R[i], R[i + 1], c, c});
      open_cell[R[i]] = cell;
      right_opened[i] = cell;
    }

    // Extensions: free segments of x = c between consecutive entries, one end a vertex.
    std::size_t li = 0, ri = 0;
    for (std::size_t k = 0; k + 1 < Q.size(); ++k) {
      const Entry &a = Q[k], &b = Q[k + 1];
      if (!a.is_vertex && !b.is_vertex) continue;
      if (a.is_vertex && b.is_vertex && (env.edge_between(a.id, b.id) != SIZE_MAX || env.edge_between(b.id, a.id) != SIZE_MAX))
        continue;  // a wall
      while (li + 1 < L.size() && left_rank(L[li + 1]) <= k) ++li;
      while (ri + 1 < R.size() && right_rank(R[ri + 1]) <= k) ++ri;
      if (li + 1 >= L.size() || ri + 1 >= R.size()) continue;
      if (left_rank(L[li]) > k || right_rank(R[ri]) > k) continue;  // below every edge: outside
      const std::uint32_t lc = left_closed[li], rc = right_opened[ri];
      if (lc == kNoneId || rc == kNoneId) continue;  // not free space
      extensions_.push_back({lc, rc, c, a.is_vertex, b.is_vertex, a.id, b.id});
    }
    for (auto& q : Q) (q.is_vertex ? rank_of_vertex : rank_of_crossing)[q.id] = kNoneId;
    for (auto [v, head] : aliases) rank_of_vertex[v] = kNoneId;
    g = g_end;
  }
  for (std::uint32_t e = 0; e < n; ++e)
    if (open_cell[e] != kNoneId) throw std::logic_error("trapezoidal decomposition: cell left open");

  // Adjacency as one flat array with offsets per cell.
  cell_ext_offset_.assign(cells_.size() + 1, 0);
  for (const auto& x : extensions_) ++cell_ext_offset_[x.left_cell + 1], ++cell_ext_offset_[x.right_cell + 1];
  std::partial_sum(cell_ext_offset_.begin(), cell_ext_offset_.end(), cell_ext_offset_.begin());
  cell_ext_.resize(cell_ext_offset_.back());
  std::vector<std::uint32_t> fill(cell_ext_offset_.begin(), cell_ext_offset_.end() - 1);
  for (std::uint32_t x = 0; x < extensions_.size(); ++x) {
    cell_ext_[fill[extensions_[x].left_cell]++] = x;
    cell_ext_[fill[extensions_[x].right_cell]++] = x;
  }
}

ExactFT TrapezoidalDecomposition::edge_y(std::uint32_t e, double x) const {
  const Point &a = env_->vertex(e), &b = env_->vertex(env_->next(e));
  if (x == a.x()) return a.y();
  if (x == b.x()) return b.y();
  return ExactFT(a.y()) + (ExactFT(x) - a.x()) * (ExactFT(b.y()) - a.y()) / (ExactFT(b.x()) - a.x());
}

std::vector<ExactPoint> TrapezoidalDecomposition::polygon(std::size_t c) const {
  const Trapezoid& t = cells_[c];
  const ExactPoint corners[4] = {ExactPoint(t.x_left, edge_y(t.floor, t.x_left)), ExactPoint(t.x_right, edge_y(t.floor, t.x_right)),
                                 ExactPoint(t.x_right, edge_y(t.ceiling, t.x_right)), ExactPoint(t.x_left, edge_y(t.ceiling, t.x_left))};
  std::vector<ExactPoint> out;
  for (const auto& p : corners)
    if (out.empty() || out.back() != p) out.push_back(p);
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

ExactFT TrapezoidalDecomposition::area(std::size_t c) const {
  const Trapezoid& t = cells_[c];
  const ExactFT hl = edge_y(t.ceiling, t.x_left) - edge_y(t.floor, t.x_left);
  const ExactFT hr = edge_y(t.ceiling, t.x_right) - edge_y(t.floor, t.x_right);
  return (ExactFT(t.x_right) - t.x_left) * (hl + hr) / 2;
}

std::pair<ExactPoint, ExactPoint> TrapezoidalDecomposition::segment(std::size_t i) const {
  const Extension& x = extensions_[i];
  auto end = [&](bool is_vertex, std::uint32_t id) {
    return is_vertex ? env_->exact_vertex(id) : ExactPoint(x.x, edge_y(id, x.x));
  };
  return {end(x.bottom_is_vertex, x.bottom), end(x.top_is_vertex, x.top)};
}

}  // namespace preimage::decompose
