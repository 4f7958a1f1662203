// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/sweep_order.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace preimage::decompose {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double euclid(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

// Transit costs between sweeps, computed once each. While searching, a cost not computed
// yet is estimated by the straight-line distance (a lower bound); the search is repeated
// with the true costs of every pair its result uses until the result uses only true costs.
class Costs {
 public:
  Costs(const std::vector<std::vector<Sweep>>& cells, const std::optional<Point>& start,
        const std::function<double(const Point&, const Point&)>& transit)
      : cells_(cells), start_(start), transit_(transit) {
    for (const auto& c : cells) first_.push_back(static_cast<std::uint32_t>(nodes_.size())), nodes_.insert(nodes_.end(), c.begin(), c.end());
    const std::size_t n = nodes_.size();
    cost_.resize(n * n), settled_.assign(n * n, 0);
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b) cost_[a * n + b] = euclid(nodes_[a].exit, nodes_[b].entry);
    start_cost_.resize(n), start_settled_.assign(n, 0);
    for (std::size_t b = 0; b < n; ++b) start_cost_[b] = start ? euclid(*start, nodes_[b].entry) : 0;
  }
  std::uint32_t node(std::uint32_t cell, std::uint8_t sweep) const { return first_[cell] + sweep; }
  const Sweep& sweep(std::uint32_t node) const { return nodes_[node]; }
  // Estimated (straight line) or true cost of the transit from a's exit to b's entry.
  double estimate(std::uint32_t a, std::uint32_t b) const { return cost_[a * nodes_.size() + b]; }
  double estimate_start(std::uint32_t b) const { return start_cost_[b]; }
  // Makes the cost exact; returns true if it was only an estimate before.
  bool settle(std::uint32_t a, std::uint32_t b) {
    const std::size_t k = a * nodes_.size() + b;
    if (settled_[k]) return false;
    settled_[k] = 1;
    const double c = transit_(nodes_[a].exit, nodes_[b].entry);
    const bool changed = c != cost_[k];
    cost_[k] = c;
    return changed;
  }
  bool settle_start(std::uint32_t b) {
    if (!start_ || start_settled_[b]) return false;
    start_settled_[b] = 1;
    const double c = transit_(*start_, nodes_[b].entry);
    const bool changed = c != start_cost_[b];
    start_cost_[b] = c;
    return changed;
  }
  std::size_t sweeps_of(std::uint32_t cell) const { return cells_[cell].size(); }
  std::size_t num_cells() const { return cells_.size(); }

 private:
  const std::vector<std::vector<Sweep>>& cells_;
  std::optional<Point> start_;
  const std::function<double(const Point&, const Point&)>& transit_;
  std::vector<Sweep> nodes_;
  std::vector<std::uint32_t> first_;
  std::vector<double> cost_, start_cost_;
  std::vector<char> settled_, start_settled_;
};

constexpr std::size_t kMaxSweeps = 4;

// Best sweeps for a fixed cell order: a shortest path through the layers of sweeps.
double best_sweeps(const Costs& C, const std::vector<std::uint32_t>& order, std::vector<std::uint8_t>* choice) {
  const std::size_t n = order.size();
  std::array<double, kMaxSweeps> f{}, g{};
  std::vector<std::array<std::uint8_t, kMaxSweeps>> from(choice ? n : 0);
  std::size_t S_prev = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t S = C.sweeps_of(order[i]);
    for (std::uint8_t w = 0; w < S; ++w) {
      const std::uint32_t node = C.node(order[i], w);
      const double own = C.sweep(node).length;
      if (i == 0) {
        g[w] = C.estimate_start(node) + own;
        continue;
      }
      g[w] = kInf;
      for (std::uint8_t v = 0; v < S_prev; ++v) {
        const double c = f[v] + C.estimate(C.node(order[i - 1], v), node) + own;
        if (c < g[w]) {
          g[w] = c;
          if (choice) from[i][w] = v;
        }
      }
    }
    f = g, S_prev = S;
  }
  std::uint8_t w = 0;
  for (std::uint8_t v = 1; v < S_prev; ++v)
    if (f[v] < f[w]) w = v;
  const double best = f[w];
  if (choice) {
    choice->assign(n, 0);
    for (std::size_t i = n; i-- > 0;) (*choice)[i] = w, w = from[i][w];
  }
  return best;
}

// Settles every cost the order's best-sweep computation reads; true if any changed.
bool settle_order(Costs& C, const std::vector<std::uint32_t>& order) {
  bool changed = false;
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::uint8_t w = 0; w < C.sweeps_of(order[i]); ++w) {
      const std::uint32_t node = C.node(order[i], w);
      if (i == 0) changed |= C.settle_start(node);
      else
        for (std::uint8_t v = 0; v < C.sweeps_of(order[i - 1]); ++v) changed |= C.settle(C.node(order[i - 1], v), node);
    }
  return changed;
}

// Exact: dynamic programming over (set of cells covered, last sweep), true costs only.
SweepOrder exact(Costs& C) {
  const std::size_t N = C.num_cells();
  std::vector<std::uint32_t> nodes;
  for (std::uint32_t c = 0; c < N; ++c)
    for (std::uint8_t w = 0; w < C.sweeps_of(c); ++w) nodes.push_back(C.node(c, w));
  std::vector<std::uint32_t> cell_of;
  for (std::uint32_t c = 0; c < N; ++c) cell_of.insert(cell_of.end(), C.sweeps_of(c), c);
  for (auto a : nodes) {
    C.settle_start(a);
    for (auto b : nodes)
      if (cell_of[a] != cell_of[b]) C.settle(a, b);
  }
  const std::size_t M = nodes.size(), full = (std::size_t{1} << N) - 1;
  std::vector<double> dp((full + 1) * M, kInf);
  std::vector<std::uint32_t> prev((full + 1) * M, UINT32_MAX);
  for (std::uint32_t a = 0; a < M; ++a) dp[(std::size_t{1} << cell_of[a]) * M + a] = C.estimate_start(nodes[a]) + C.sweep(nodes[a]).length;
  for (std::size_t mask = 1; mask <= full; ++mask)
    for (std::uint32_t a = 0; a < M; ++a) {
      const double here = dp[mask * M + a];
      if (std::isinf(here)) continue;
      for (std::uint32_t b = 0; b < M; ++b) {
        if (mask >> cell_of[b] & 1) continue;
        const std::size_t to = (mask | std::size_t{1} << cell_of[b]) * M + b;
        const double c = here + C.estimate(nodes[a], nodes[b]) + C.sweep(nodes[b]).length;
        if (c < dp[to]) dp[to] = c, prev[to] = static_cast<std::uint32_t>(mask * M + a);
      }
    }
  std::uint32_t last = 0;
  for (std::uint32_t a = 1; a < M; ++a)
    if (dp[full * M + a] < dp[full * M + last]) last = a;
  SweepOrder out;
  out.cost = dp[full * M + last];
  for (std::size_t at = full * M + last; at != UINT32_MAX; at = prev[at]) {
    const std::uint32_t a = static_cast<std::uint32_t>(at % M);
    out.cells.push_back(cell_of[a]);
    out.sweeps.push_back(static_cast<std::uint8_t>(nodes[a] - C.node(cell_of[a], 0)));
  }
  std::reverse(out.cells.begin(), out.cells.end());
  std::reverse(out.sweeps.begin(), out.sweeps.end());
  out.optimal = true;
  out.lower_bound = out.cost;
  return out;
}

// Local search under the current (partly estimated) costs. Or-opt moves a run of 1-3
// cells (possibly reversed) next to another cell, 2-opt reverses a stretch; on large
// instances only next to the cell's nearest cells (candidate lists), as usual for TSPs.
void improve(const Costs& C, const std::vector<std::vector<std::uint32_t>>& near, std::vector<std::uint32_t>& order) {
  const std::size_t n = order.size();
  double best = best_sweeps(C, order, nullptr);
  std::vector<std::size_t> pos(n);
  auto try_order = [&](std::vector<std::uint32_t>& cand) {
    const double c = best_sweeps(C, cand, nullptr);
    if (c < best - 1e-12 * (1 + best)) {
      best = c, order.swap(cand);
      return true;
    }
    return false;
  };
  for (int pass = 0; pass < 100; ++pass) {
    bool better = false;
    for (std::size_t k = 0; k < n; ++k) pos[order[k]] = k;
    for (std::size_t len = 1; len <= 3 && len < n; ++len)
      for (std::size_t i = 0; i + len <= n; ++i) {
        // Insertion points: next to the nearest cells of the run's ends.
        std::vector<std::size_t> targets;
        for (std::uint32_t end : {order[i], order[i + len - 1]})
          for (std::uint32_t m : near[end]) targets.push_back(pos[m]), targets.push_back(pos[m] + 1);
        for (std::size_t t : targets) {
          if (t >= i && t <= i + len) continue;
          for (int rev = 0; rev < 2; ++rev) {
            std::vector<std::uint32_t> seg(order.begin() + static_cast<long>(i), order.begin() + static_cast<long>(i + len));
            if (rev) std::reverse(seg.begin(), seg.end());
            std::vector<std::uint32_t> cand;
            cand.reserve(n);
            for (std::size_t k = 0; k <= n; ++k) {
              if (k == t) cand.insert(cand.end(), seg.begin(), seg.end());
              if (k < n && (k < i || k >= i + len)) cand.push_back(order[k]);
            }
            if (try_order(cand)) {
              better = true;
              for (std::size_t k = 0; k < n; ++k) pos[order[k]] = k;
              break;
            }
          }
        }
      }
    for (std::size_t i = 0; i + 1 < n; ++i)
      for (std::uint32_t m : near[order[i]]) {
        const std::size_t j = pos[m];
        if (j <= i) continue;
        std::vector<std::uint32_t> cand = order;
        std::reverse(cand.begin() + static_cast<long>(i), cand.begin() + static_cast<long>(j + 1));
        if (try_order(cand)) {
          better = true;
          for (std::size_t k = 0; k < n; ++k) pos[order[k]] = k;
        }
      }
    if (!better) break;
  }
}

// Lower bound: every sweep's own length at its cheapest, plus a minimum spanning tree over
// the cells (and the start) with straight-line distances between their closest ends — the
// transits of any order form a spanning path, and no transit is shorter than a straight line.
double lower_bound(const std::vector<std::vector<Sweep>>& cells, const std::optional<Point>& start) {
  const std::size_t N = cells.size(), V = N + (start ? 1 : 0);
  double own = 0;
  for (const auto& c : cells) {
    double m = kInf;
    for (const auto& s : c) m = std::min(m, s.length);
    own += m;
  }
  auto gap = [&](std::size_t a, std::size_t b) {
    double m = kInf;
    if (a == N || b == N) {
      for (const auto& s : cells[a == N ? b : a]) m = std::min(m, euclid(*start, s.entry));
      return m;
    }
    for (const auto& s : cells[a])
      for (const auto& t : cells[b]) m = std::min({m, euclid(s.exit, t.entry), euclid(t.exit, s.entry)});
    return m;
  };
  std::vector<double> key(V, kInf);
  std::vector<char> in(V, 0);
  key[0] = 0;
  double tree = 0;
  for (std::size_t it = 0; it < V; ++it) {
    std::size_t u = V;
    for (std::size_t k = 0; k < V; ++k)
      if (!in[k] && (u == V || key[k] < key[u])) u = k;
    in[u] = 1, tree += key[u];
    for (std::size_t k = 0; k < V; ++k)
      if (!in[k]) key[k] = std::min(key[k], gap(u, k));
  }
  return own + tree;
}

}  // namespace

SweepOrder order_sweeps(const std::vector<std::vector<Sweep>>& cells, const std::optional<Point>& start,
                        const std::function<double(const Point&, const Point&)>& transit) {
  SweepOrder out;
  if (cells.empty()) return out;
  Costs C(cells, start, transit);
  if (cells.size() <= kExactClusters) return exact(C);
  // Greedy start: from the start (or the first cell), always the nearest sweep entry.
  const std::size_t N = cells.size();
  std::vector<char> used(N, 0);
  std::vector<std::uint32_t> order;
  std::optional<Point> at = start;
  for (std::size_t k = 0; k < N; ++k) {
    std::uint32_t pick = UINT32_MAX;
    double best = kInf;
    for (std::uint32_t c = 0; c < N; ++c) {
      if (used[c]) continue;
      for (const auto& s : cells[c]) {
        const double d = at ? euclid(*at, s.entry) : 0;
        if (d < best) best = d, pick = c;
      }
      if (!at) break;
    }
    used[pick] = 1, order.push_back(pick);
    std::uint8_t w = 0;
    if (at)
      for (std::uint8_t v = 1; v < cells[pick].size(); ++v)
        if (euclid(*at, cells[pick][v].entry) < euclid(*at, cells[pick][w].entry)) w = v;
    at = cells[pick][w].exit;
  }
  // Candidate lists: the 8 nearest cells (straight line between their closest ends).
  std::vector<std::vector<std::uint32_t>> near(N);
  for (std::uint32_t a = 0; a < N; ++a) {
    std::vector<std::pair<double, std::uint32_t>> d;
    for (std::uint32_t b = 0; b < N; ++b) {
      if (a == b) continue;
      double m = kInf;
      for (const auto& s : cells[a])
        for (const auto& t : cells[b]) m = std::min({m, euclid(s.exit, t.entry), euclid(t.exit, s.entry)});
      d.emplace_back(m, b);
    }
    const std::size_t keep = std::min<std::size_t>(8, d.size());
    std::partial_sort(d.begin(), d.begin() + static_cast<long>(keep), d.end());
    for (std::size_t k = 0; k < keep; ++k) near[a].push_back(d[k].second);
  }
  // Improve under estimates, make the costs the result uses exact, repeat until it uses
  // exact costs only (each round settles at least one estimate, and estimates only rise).
  do improve(C, near, order);
  while (settle_order(C, order));
  out.cells = order;
  out.cost = best_sweeps(C, order, &out.sweeps);
  out.lower_bound = lower_bound(cells, start);
  return out;
}

}  // namespace preimage::decompose
