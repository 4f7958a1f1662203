// SPDX-License-Identifier: Apache-2.0
#include <preimage/coverage/sweep_order.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

namespace preimage::coverage {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double euclid(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

// Settled transit costs by (from, to) node pair: open addressing with linear probing, since
// the search looks up many pairs that were never settled and misses must be cheap.
class PairCosts {
 public:
  const double* find(std::uint64_t key) const {
    if (keys_.empty()) return nullptr;
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return &values_[i];
      if (keys_[i] == kEmpty) return nullptr;
    }
  }
  // Inserts key (value 0) if absent; returns the value and whether it was inserted.
  std::pair<double*, bool> insert(std::uint64_t key) {
    if ((size_ + 1) * 2 > keys_.size()) grow();
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return {&values_[i], false};
      if (keys_[i] == kEmpty) {
        keys_[i] = key, values_[i] = 0, ++size_;
        return {&values_[i], true};
      }
    }
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::size_t slot(std::uint64_t key) const { return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & mask_; }
  void grow() {
    std::vector<std::uint64_t> keys(std::max<std::size_t>(64, keys_.size() * 2), kEmpty);
    std::vector<double> values(keys.size());
    keys.swap(keys_), values.swap(values_), mask_ = keys_.size() - 1, size_ = 0;
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] != kEmpty) *insert(keys[i]).first = values[i];
  }
  std::vector<std::uint64_t> keys_;
  std::vector<double> values_;
  std::size_t mask_ = 0, size_ = 0;
};

constexpr std::size_t kMaxSweeps = 4;

// Transit costs between sweeps, computed once each. While searching, a cost not computed
// yet is estimated by the straight-line distance (a lower bound); the search is repeated
// with the true costs of every pair its result uses until the result uses only true costs.
// Settled costs are kept sparsely: a search settles O(cells) of the (4 cells)^2 pairs.
class Costs {
 public:
  static constexpr std::uint32_t kStart = UINT32_MAX - 1;  // the start point (as a tail)
  static constexpr std::uint32_t kNone = UINT32_MAX;       // nothing (the walk's ends)

  Costs(const std::vector<std::vector<Sweep>>& cells, const std::optional<Point>& start,
        const std::function<double(const Point&, const Point&)>& transit)
      : start_(start), transit_(transit) {
    for (const auto& c : cells) {
      if (c.empty() || c.size() > kMaxSweeps) throw std::invalid_argument("order_sweeps: every cell needs 1 to 4 sweeps");
      first_.push_back(static_cast<std::uint32_t>(nodes_.size()));
      nodes_.insert(nodes_.end(), c.begin(), c.end());
      count_.push_back(static_cast<std::uint8_t>(c.size()));
    }
    for (const auto& s : nodes_) xy_.push_back({s.entry.x(), s.entry.y(), s.exit.x(), s.exit.y()});
    start_cost_.resize(nodes_.size()), start_settled_.assign(nodes_.size(), 0);
    for (std::size_t b = 0; b < nodes_.size(); ++b) start_cost_[b] = start ? euclid(*start, nodes_[b].entry) : 0;
  }
  std::uint32_t node(std::uint32_t cell, std::uint8_t sweep) const { return first_[cell] + sweep; }
  double own(std::uint32_t node) const { return nodes_[node].length; }
  // Estimated (straight line) or true cost from a's exit to b's entry; a may be kStart or
  // kNone, b may be kNone (both cost nothing but the start's transit).
  double estimate(std::uint32_t a, std::uint32_t b) const {
    if (b == kNone || a == kNone) return 0;
    if (a == kStart) return start_cost_[b];
    if (const double* c = settled_.find(key(a, b))) return *c;
    return straight(a, b);
  }
  // Makes the cost exact; returns true if it was only an estimate before and changed.
  bool settle(std::uint32_t a, std::uint32_t b) {
    if (a == kNone || b == kNone) return false;
    if (a == kStart) {
      if (!start_ || start_settled_[b]) return false;
      start_settled_[b] = 1;
      const double c = transit_(*start_, nodes_[b].entry);
      const bool changed = longer(c, start_cost_[b]);
      start_cost_[b] = c;
      return changed;
    }
    const auto [value, fresh] = settled_.insert(key(a, b));
    if (!fresh) return false;
    *value = transit_(nodes_[a].exit, nodes_[b].entry);
    return longer(*value, straight(a, b));
  }
  std::size_t sweeps_of(std::uint32_t cell) const { return count_[cell]; }
  std::size_t num_cells() const { return count_.size(); }

 private:
  // A transit longer than its straight-line estimate by more than rounding (the two are
  // computed by different formulas): only then can the search's answer change.
  static bool longer(double transit, double estimate) { return transit > estimate * (1 + 1e-12); }
  static std::uint64_t key(std::uint32_t a, std::uint32_t b) { return std::uint64_t{a} << 32 | b; }
  double straight(std::uint32_t a, std::uint32_t b) const {
    const auto& p = xy_[a];
    const auto& q = xy_[b];
    return std::sqrt((p[2] - q[0]) * (p[2] - q[0]) + (p[3] - q[1]) * (p[3] - q[1]));
  }
  std::optional<Point> start_;
  const std::function<double(const Point&, const Point&)>& transit_;
  std::vector<Sweep> nodes_;
  std::vector<std::array<double, 4>> xy_;  // entry x, y, exit x, y
  std::vector<std::uint32_t> first_;
  std::vector<std::uint8_t> count_;
  PairCosts settled_;
  std::vector<double> start_cost_;
  std::vector<char> start_settled_;
};

// Best sweeps for the cells `cells` (in this order) between the fixed sweeps `a` (a node,
// kStart or kNone) and `b` (a node or kNone): a shortest path through the layers of sweeps
// (Costs::estimate). Writes the chosen nodes to `out` when given.
template <class CellAt>
double best_between(const Costs& C, std::uint32_t a, std::uint32_t b, std::size_t n, CellAt cell_at,
                    std::vector<std::uint32_t>* out) {
  std::array<double, kMaxSweeps> f{}, g{};
  std::vector<std::array<std::uint8_t, kMaxSweeps>> from(out ? n : 0);
  std::size_t S_prev = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t cell = cell_at(i);
    const std::size_t S = C.sweeps_of(cell);
    for (std::uint8_t w = 0; w < S; ++w) {
      const std::uint32_t node = C.node(cell, w);
      const double own = C.own(node);
      if (i == 0) {
        g[w] = C.estimate(a, node) + own;
        continue;
      }
      g[w] = kInf;
      for (std::uint8_t v = 0; v < S_prev; ++v) {
        const double c = f[v] + C.estimate(C.node(cell_at(i - 1), v), node) + own;
        if (c < g[w]) {
          g[w] = c;
          if (out) from[i][w] = v;
        }
      }
    }
    f = g, S_prev = S;
  }
  std::uint8_t w = 0;
  for (std::uint8_t v = 0; v < S_prev; ++v) {
    f[v] += C.estimate(C.node(cell_at(n - 1), v), b);
    if (f[v] < f[w]) w = v;
  }
  const double best = f[w];
  if (out) {
    out->resize(n);
    for (std::size_t i = n; i-- > 0;) (*out)[i] = C.node(cell_at(i), w), w = from[i][w];
  }
  return best;
}

// The walk: cells in visiting order and the sweep (node) used in each.
struct Tour {
  std::vector<std::uint32_t> cell, node;
  double cost(const Costs& C) const {
    double c = 0;
    for (std::size_t i = 0; i < node.size(); ++i) c += C.estimate(i ? node[i - 1] : Costs::kStart, node[i]) + C.own(node[i]);
    return c;
  }
  // Best sweeps for this cell order.
  void choose_sweeps(const Costs& C) {
    best_between(C, Costs::kStart, Costs::kNone, cell.size(), [&](std::size_t i) { return cell[i]; }, &node);
  }
};

// Settles every cost the tour uses; returns the positions whose incoming cost changed.
std::vector<std::size_t> settle_tour(Costs& C, const Tour& t) {
  std::vector<std::size_t> changed;
  for (std::size_t i = 0; i < t.node.size(); ++i)
    if (C.settle(i ? t.node[i - 1] : Costs::kStart, t.node[i])) changed.push_back(i);
  return changed;
}

// Exact: dynamic programming over (set of cells covered, last sweep), true costs only.
SweepOrder exact(Costs& C) {
  const std::size_t N = C.num_cells();
  std::vector<std::uint32_t> nodes, cell_of;
  for (std::uint32_t c = 0; c < N; ++c)
    for (std::uint8_t w = 0; w < C.sweeps_of(c); ++w) nodes.push_back(C.node(c, w)), cell_of.push_back(c);
  const std::size_t M = nodes.size(), full = (std::size_t{1} << N) - 1;
  std::vector<double> T(M * M, kInf), from_start(M);
  for (std::uint32_t a = 0; a < M; ++a) {
    C.settle(Costs::kStart, nodes[a]);
    from_start[a] = C.estimate(Costs::kStart, nodes[a]) + C.own(nodes[a]);
    for (std::uint32_t b = 0; b < M; ++b)
      if (cell_of[a] != cell_of[b]) C.settle(nodes[a], nodes[b]), T[a * M + b] = C.estimate(nodes[a], nodes[b]) + C.own(nodes[b]);
  }
  std::vector<double> dp((full + 1) * M, kInf);
  std::vector<std::uint32_t> prev((full + 1) * M, UINT32_MAX);
  for (std::uint32_t a = 0; a < M; ++a) dp[(std::size_t{1} << cell_of[a]) * M + a] = from_start[a];
  for (std::size_t mask = 1; mask <= full; ++mask)
    for (std::uint32_t a = 0; a < M; ++a) {
      const double here = dp[mask * M + a];
      if (std::isinf(here)) continue;
      for (std::uint32_t b = 0; b < M; ++b) {
        if (mask >> cell_of[b] & 1) continue;
        const std::size_t to = (mask | std::size_t{1} << cell_of[b]) * M + b;
        const double c = here + T[a * M + b];
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

// Local search under the current (partly estimated) costs, each move evaluated in time
// independent of the number of cells: the sweeps outside the cells a move touches stay as
// they are, the moved cells get their best sweeps between their new neighbours
// (best_between), and when no move is left all sweeps are re-chosen for the order (a
// layered shortest path). Or-opt moves a run of 1-3 cells (either way round) next to one of
// the nearest cells of its ends; 2-opt reverses a stretch of up to kMaxReversal cells so
// that a cell comes next to one of its nearest cells — candidate lists, as usual for large
// TSPs. Only cells near a change are looked at again ("don't look bits").
constexpr std::size_t kMaxReversal = 40;
constexpr std::size_t kCandidates = 5;
constexpr int kMaxSweepRounds = 20;
constexpr int kMaxSettleRounds = 4;
constexpr int kKicks = 20;                    // iterated local search: double bridges tried
constexpr std::size_t kMaxKickStretch = 30;   // cells per stretch a double bridge moves
constexpr std::size_t kMaxKickCells = 1000;   // no kicks beyond this many cells

class LocalSearch {
 public:
  LocalSearch(const Costs& C, const std::vector<std::vector<std::uint32_t>>& near, Tour& t)
      : C_(C), near_(near), t_(t), n_(t.cell.size()), pos_(n_), queued_(n_, 0) {
    reindex();
  }
  void activate(std::uint32_t cell) {
    if (!queued_[cell]) queued_[cell] = 1, queue_.push_back(cell);
  }
  // After the tour was changed from outside (a kick): positions again, nothing queued.
  void reset() {
    reindex();
    for (const std::uint32_t c : queue_) queued_[c] = 0;
    queue_.clear();
  }
  // Activates the cells at positions i - 1 .. i + 1.
  void activate_around(std::size_t i) {
    for (std::size_t k = i ? i - 1 : 0; k <= i + 1 && k < n_; ++k) activate(t_.cell[k]);
  }
  void run() {
    for (int round = 0; round < kMaxSweepRounds; ++round) {
      while (!queue_.empty()) {
        const std::uint32_t c = queue_.back();
        queue_.pop_back(), queued_[c] = 0;
        const std::size_t i = pos_[c];
        for (std::size_t len = 1; len <= 3 && len < n_; ++len)
          if (i + len <= n_ && or_opt(i, len)) break;
        if (pos_[c] == i) two_opt(i);
      }
      const std::vector<std::uint32_t> before = t_.node;
      t_.choose_sweeps(C_);
      for (std::size_t i = 0; i < n_; ++i)
        if (t_.node[i] != before[i]) activate_around(i);
      if (queue_.empty()) break;
    }
  }

 private:
  static constexpr double kGain = 1e-9;
  std::uint32_t tail(std::size_t i) const { return i == 0 ? Costs::kStart : t_.node[i - 1]; }  // before position i
  std::uint32_t head(std::size_t i) const { return i >= n_ ? Costs::kNone : t_.node[i]; }     // at position i
  // Cost of positions [i, j) as they are, with their links to i - 1 and j.
  double span(std::size_t i, std::size_t j) const {
    double c = C_.estimate(tail(i), t_.node[i]) + C_.estimate(t_.node[j - 1], head(j));
    for (std::size_t k = i; k < j; ++k) c += C_.own(t_.node[k]) + (k > i ? C_.estimate(t_.node[k - 1], t_.node[k]) : 0);
    return c;
  }
  void reindex() {
    for (std::size_t k = 0; k < n_; ++k) pos_[t_.cell[k]] = k;
  }
  // Moves positions [i, i + len) to the best place next to a nearest cell of its ends.
  bool or_opt(std::size_t i, std::size_t len) {
    const double removed = span(i, i + len) - C_.estimate(tail(i), head(i + len));
    double best_gain = kGain;
    std::size_t best_at = 0;
    bool best_rev = false;
    targets_.clear();
    for (const std::uint32_t end : {t_.cell[i], t_.cell[i + len - 1]})
      for (const std::uint32_t m : near_[end])
        for (const std::size_t at : {pos_[m], pos_[m] + 1})  // insert before position `at`
          if ((at < i || at > i + len) && std::find(targets_.begin(), targets_.end(), at) == targets_.end()) targets_.push_back(at);
    for (const std::size_t at : targets_) {
          const std::uint32_t a = tail(at), b = head(at);
          const double link = C_.estimate(a, b);
          for (const bool rev : {false, true}) {
            const double added =
                best_between(C_, a, b, len, [&](std::size_t k) { return t_.cell[rev ? i + len - 1 - k : i + k]; }, nullptr) - link;
            if (removed - added > best_gain) best_gain = removed - added, best_at = at, best_rev = rev;
          }
    }
    if (best_gain <= kGain) return false;
    best_between(C_, tail(best_at), head(best_at), len, [&](std::size_t k) { return t_.cell[best_rev ? i + len - 1 - k : i + k]; },
                 &seg_);
    // Rotate the stretch between the run and its new place; only that stretch moves.
    const std::uint32_t left = i ? t_.cell[i - 1] : UINT32_MAX, right = i + len < n_ ? t_.cell[i + len] : UINT32_MAX;
    if (best_rev) std::reverse(t_.cell.begin() + static_cast<long>(i), t_.cell.begin() + static_cast<long>(i + len));
    std::copy(seg_.begin(), seg_.end(), t_.node.begin() + static_cast<long>(i));
    const auto b = static_cast<long>(std::min(i, best_at)), e = static_cast<long>(std::max(i + len, best_at));
    const long mid = best_at < i ? static_cast<long>(i) : static_cast<long>(i + len);
    std::rotate(t_.cell.begin() + b, t_.cell.begin() + mid, t_.cell.begin() + e);
    std::rotate(t_.node.begin() + b, t_.node.begin() + mid, t_.node.begin() + e);
    for (auto k = static_cast<std::size_t>(b); k < static_cast<std::size_t>(e); ++k) pos_[t_.cell[k]] = k;
    for (const std::uint32_t c : {left, right})
      if (c != UINT32_MAX) activate_around(pos_[c]);
    const std::size_t at = best_at < i ? best_at : best_at - len;
    for (std::size_t k = at; k < at + len; ++k) activate_around(k);
    return true;
  }
  // Reverses a stretch so that the cell at i gets one of its nearest cells as a neighbour.
  bool two_opt(std::size_t i) {
    for (const std::uint32_t m : near_[t_.cell[i]]) {
      const std::size_t j = pos_[m];
      if (j > i + 1 ? reverse(i + 1, j) : j + 1 < i && reverse(j, i - 1)) return true;
    }
    return false;
  }
  bool reverse(std::size_t i, std::size_t j) {
    if (j - i + 1 > kMaxReversal) return false;
    const double now = span(i, j + 1);
    const double then = best_between(C_, tail(i), head(j + 1), j - i + 1, [&](std::size_t k) { return t_.cell[j - k]; }, &seg_);
    if (now - then <= kGain) return false;
    std::reverse(t_.cell.begin() + static_cast<long>(i), t_.cell.begin() + static_cast<long>(j + 1));
    std::copy(seg_.begin(), seg_.end(), t_.node.begin() + static_cast<long>(i));
    for (std::size_t k = i; k <= j; ++k) pos_[t_.cell[k]] = k;
    activate_around(i), activate_around(j);
    return true;
  }

  const Costs& C_;
  const std::vector<std::vector<std::uint32_t>>& near_;
  Tour& t_;
  std::size_t n_;
  std::vector<std::size_t> pos_;
  std::vector<char> queued_;
  std::vector<std::uint32_t> queue_, seg_;
  std::vector<std::size_t> targets_;
};

// Nearest-point queries among points that belong to cells, excluding one cell's own: a
// uniform grid of about one point per bucket, searched in growing rings.
class PointGrid {
 public:
  struct P {
    double x, y;
    std::uint32_t cell;
  };
  explicit PointGrid(std::vector<P> pts) : pts_(std::move(pts)) {
    double x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
    for (const P& p : pts_) x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    if (pts_.empty()) x0 = y0 = x1 = y1 = 0;
    const double side = std::max({x1 - x0, y1 - y0, 1e-300});
    k_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(pts_.size()))));
    x0_ = x0, y0_ = y0, h_ = side / static_cast<double>(k_) * (1 + 1e-12);
    bucket_.assign(k_ * k_, {});
    for (std::uint32_t i = 0; i < pts_.size(); ++i) bucket_[col(pts_[i].y, y0_) * k_ + col(pts_[i].x, x0_)].push_back(i);
  }
  // The (up to) k nearest points of cells other than `cell`, nearest first, as (distance, point).
  std::vector<std::pair<double, std::uint32_t>> nearest(double x, double y, std::uint32_t cell, std::size_t k) const {
    std::vector<std::pair<double, std::uint32_t>> heap;  // max-heap of the best k so far
    const long cx = static_cast<long>(col(x, x0_)), cy = static_cast<long>(col(y, y0_)), K = static_cast<long>(k_);
    for (long r = 0; r <= K; ++r) {
      // Points in ring r are at least (r - 1) * h away (also for a query outside the box,
      // which is clamped to its nearest bucket).
      if (heap.size() == k && static_cast<double>(r - 1) * h_ > heap.front().first) break;
      for (long gy = cy - r; gy <= cy + r; ++gy)
        for (long gx = cx - r; gx <= cx + r; ++gx) {
          if (std::max(std::abs(gx - cx), std::abs(gy - cy)) != r || gx < 0 || gy < 0 || gx >= K || gy >= K) continue;
          for (const std::uint32_t i : bucket_[static_cast<std::size_t>(gy) * k_ + static_cast<std::size_t>(gx)]) {
            if (pts_[i].cell == cell) continue;
            const double d = std::hypot(pts_[i].x - x, pts_[i].y - y);
            if (heap.size() < k) {
              heap.emplace_back(d, i), std::push_heap(heap.begin(), heap.end());
            } else if (d < heap.front().first) {
              std::pop_heap(heap.begin(), heap.end()), heap.back() = {d, i}, std::push_heap(heap.begin(), heap.end());
            }
          }
        }
    }
    std::sort_heap(heap.begin(), heap.end());
    return heap;
  }
  const P& point(std::uint32_t i) const { return pts_[i]; }

 private:
  std::size_t col(double v, double origin) const {
    const double f = std::floor((v - origin) / h_);
    return f <= 0 ? 0 : std::min(k_ - 1, static_cast<std::size_t>(f));
  }
  std::vector<P> pts_;
  std::vector<std::vector<std::uint32_t>> bucket_;
  std::size_t k_ = 1;
  double x0_ = 0, y0_ = 0, h_ = 1;
};

// Lower bound: every sweep's own length at its cheapest, plus every transit at its
// cheapest: the walk enters every cell but the first from another cell's exit, no closer
// than the nearest such exit (straight line), and the first from the start, if any.
double lower_bound(const std::vector<std::vector<Sweep>>& cells, const std::optional<Point>& start) {
  std::vector<PointGrid::P> exits;
  for (std::uint32_t c = 0; c < cells.size(); ++c)
    for (const auto& s : cells[c]) exits.push_back({s.exit.x(), s.exit.y(), c});
  const PointGrid grid(std::move(exits));
  double own = 0, in_sum = 0, in_max = 0, from_start = start ? kInf : 0;
  for (std::uint32_t c = 0; c < cells.size(); ++c) {
    double m = kInf, in = kInf;
    for (const auto& s : cells[c]) {
      m = std::min(m, s.length);
      const auto near = grid.nearest(s.entry.x(), s.entry.y(), c, 1);
      if (!near.empty()) in = std::min(in, near.front().first);
      if (start) from_start = std::min(from_start, euclid(*start, s.entry));
    }
    own += m;
    if (in < kInf) in_sum += in, in_max = std::max(in_max, in);
  }
  return own + in_sum - in_max + from_start;
}

}  // namespace

SweepOrder order_sweeps(const std::vector<std::vector<Sweep>>& cells, const std::optional<Point>& start,
                        const std::function<double(const Point&, const Point&)>& transit, std::size_t exact_up_to) {
  SweepOrder out;
  if (cells.empty()) return out;
  Costs C(cells, start, transit);
  if (cells.size() <= std::min(exact_up_to, kExactClusters)) return exact(C);
  const std::size_t N = cells.size();
  // Each cell stands for its sweeps' ends' centre when choosing the first order and the
  // candidate lists (squared distances: O(N^2) cheap steps, no transit).
  std::vector<std::array<double, 2>> centre(N, {0.0, 0.0});
  for (std::size_t c = 0; c < N; ++c) {
    for (const auto& s : cells[c]) centre[c][0] += s.entry.x() + s.exit.x(), centre[c][1] += s.entry.y() + s.exit.y();
    centre[c][0] /= 2.0 * static_cast<double>(cells[c].size()), centre[c][1] /= 2.0 * static_cast<double>(cells[c].size());
  }
  const auto d2 = [&](std::size_t a, std::size_t b) {
    const double dx = centre[a][0] - centre[b][0], dy = centre[a][1] - centre[b][1];
    return dx * dx + dy * dy;
  };
  // Greedy start: from the cell nearest the start (or cell 0), always the nearest cell left.
  Tour t;
  {
    std::size_t at = 0;
    if (start) {
      double best = kInf;
      for (std::size_t c = 0; c < N; ++c) {
        const double dx = centre[c][0] - start->x(), dy = centre[c][1] - start->y();
        if (dx * dx + dy * dy < best) best = dx * dx + dy * dy, at = c;
      }
    }
    std::vector<char> used(N, 0);
    for (std::size_t k = 0; k < N; ++k) {
      used[at] = 1, t.cell.push_back(static_cast<std::uint32_t>(at));
      std::size_t next = N;
      double best = kInf;
      for (std::size_t c = 0; c < N; ++c)
        if (!used[c] && d2(at, c) < best) best = d2(at, c), next = c;
      at = next;
    }
  }
  // Candidate lists: the kCandidates nearest cells.
  std::vector<std::vector<std::uint32_t>> near(N);
  {
    std::vector<PointGrid::P> pts(N);
    for (std::uint32_t c = 0; c < N; ++c) pts[c] = {centre[c][0], centre[c][1], c};
    const PointGrid grid(std::move(pts));
    for (std::uint32_t a = 0; a < N; ++a)
      for (const auto& [d, i] : grid.nearest(centre[a][0], centre[a][1], a, kCandidates)) near[a].push_back(grid.point(i).cell);
  }
  // Improve under estimates, make the costs the result uses exact, and look again where an
  // estimate was wrong, until the result uses exact costs only (each round settles at least
  // one estimate, and estimates only rise) or kMaxSettleRounds rounds; the cost reported is
  // always the true cost of the walk returned.
  t.choose_sweeps(C);
  LocalSearch search(C, near, t);
  for (std::uint32_t c = 0; c < N; ++c) search.activate(t.cell[N - 1 - c]);
  const auto improve = [&] {
    for (int round = 0; round < kMaxSettleRounds; ++round) {
      search.run();
      const auto changed = settle_tour(C, t);
      if (changed.empty()) break;
      for (const std::size_t i : changed) search.activate_around(i);
    }
    settle_tour(C, t);
  };
  improve();
  // Iterated local search: Or-opt and 2-opt stop in a local optimum. A double bridge (the
  // order A B C D becomes A C B D, B and C short) is a move neither undoes; after
  // each, the local search runs again where the order was cut, and the walk is kept when
  // its true cost (every cost it uses settled) drops. kKicks of them, from a generator
  // seeded by N, so the answer is reproducible. Up to kMaxKickCells cells (floor plans
  // have tens to hundreds): on the 10^4-vertex benchmark field's 4,447 regions the kicks
  // took 44 s, settling transits the kicked walks used.
  if (N >= 8 && N <= kMaxKickCells) {
    Tour best = t;
    double best_cost = t.cost(C);
    std::mt19937_64 rng(N);
    const std::size_t span = std::min<std::size_t>(kMaxKickStretch, N / 3);
    for (int k = 0; k < kKicks; ++k) {
      t = best;
      const std::size_t p1 = 1 + rng() % (N - 3);
      const std::size_t p2 = p1 + 1 + rng() % std::min(span, N - p1 - 2);
      const std::size_t p3 = p2 + 1 + rng() % std::min(span, N - p2 - 1);
      std::rotate(t.cell.begin() + static_cast<long>(p1), t.cell.begin() + static_cast<long>(p2), t.cell.begin() + static_cast<long>(p3));
      t.choose_sweeps(C);
      search.reset();
      for (const std::size_t at : {p1, p1 + (p3 - p2), p3}) search.activate_around(at - 1), search.activate_around(at);
      // Under estimates first: they never exceed the true costs, so a walk no cheaper than
      // the best by them is no cheaper at all, and its transits need not be settled.
      search.run();
      if (t.cost(C) >= best_cost - 1e-9 * (1 + best_cost)) continue;
      improve();
      if (const double c = t.cost(C); c < best_cost - 1e-9 * (1 + best_cost)) best = t, best_cost = c;
    }
    t = best;
  }
  out.cells = t.cell;
  for (std::size_t i = 0; i < N; ++i) out.sweeps.push_back(static_cast<std::uint8_t>(t.node[i] - C.node(t.cell[i], 0)));
  out.cost = t.cost(C);
  out.lower_bound = lower_bound(cells, start);
  return out;
}

}  // namespace preimage::coverage
