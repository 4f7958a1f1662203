// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/cell_locator.hpp>

#include <algorithm>

namespace preimage::decompose {

using geometry::lex_less_xy;
using geometry::orientation;

namespace {
constexpr std::uint32_t kNil = UINT32_MAX;
}

CellLocator::CellLocator(const TrapezoidalDecomposition& d) {
  const auto& cells = d.cells();
  const auto& env = d.environment();
  auto ends = [&](std::uint32_t e) {
    const Point &p = env.vertex(e), &q = env.vertex(env.next(e));
    return lex_less_xy(p, q) ? std::pair(p, q) : std::pair(q, p);
  };
  bounds_.reserve(cells.size());
  for (const auto& c : cells) {
    auto [fl, fr] = ends(c.floor);
    auto [cl, cr] = ends(c.ceiling);
    bounds_.push_back({fl, fr, cl, cr});
  }
  for (auto& c : cells) xs_.push_back(c.x_left), xs_.push_back(c.x_right);
  std::sort(xs_.begin(), xs_.end());
  xs_.erase(std::unique(xs_.begin(), xs_.end()), xs_.end());
  std::vector<std::uint32_t> by_left(cells.size()), by_right(cells.size());
  for (std::uint32_t i = 0; i < cells.size(); ++i) by_left[i] = by_right[i] = i;
  std::sort(by_left.begin(), by_left.end(), [&](auto a, auto b) { return cells[a].x_left < cells[b].x_left; });
  std::sort(by_right.begin(), by_right.end(), [&](auto a, auto b) { return cells[a].x_right < cells[b].x_right; });
  nodes_.reserve(cells.size() * 24);
  std::uint32_t root = kNil;
  std::size_t li = 0, ri = 0;
  for (std::size_t j = 0; j + 1 < xs_.size(); ++j) {
    // Cells ending at xs_[j] leave (compared in the slab they span), then cells starting enter.
    while (ri < by_right.size() && cells[by_right[ri]].x_right <= xs_[j]) root = erase(root, by_right[ri++]);
    while (li < by_left.size() && cells[by_left[li]].x_left <= xs_[j]) root = insert(root, by_left[li++]);
    roots_.push_back(root);
  }
  if (xs_.size() >= 2) {
    const std::size_t nb = xs_.size();
    bucket_scale_ = static_cast<double>(nb) / (xs_.back() - xs_.front());
    bucket_.resize(nb + 1);
    std::size_t j = 0;
    for (std::size_t b = 0; b <= nb; ++b) {
      const double left = xs_.front() + static_cast<double>(b) / bucket_scale_;
      while (j + 1 < xs_.size() && xs_[j + 1] <= left) ++j;
      bucket_[b] = static_cast<std::uint32_t>(j);
    }
  }
}

bool CellLocator::cell_below(std::uint32_t a, std::uint32_t b) const {
  // Floors of cells crossing one slab do not cross.
  return geometry::segment_below(bounds_[a].floor_l, bounds_[a].floor_r, bounds_[b].floor_l, bounds_[b].floor_r);
}

std::uint32_t CellLocator::copy(std::uint32_t n) {
  nodes_.push_back(nodes_[n]);
  return static_cast<std::uint32_t>(nodes_.size() - 1);
}

std::uint32_t CellLocator::merge(std::uint32_t a, std::uint32_t b) {
  if (a == kNil) return b;
  if (b == kNil) return a;
  if (nodes_[a].prio > nodes_[b].prio) {
    const std::uint32_t c = copy(a);
    const std::uint32_t r = merge(nodes_[a].right, b);
    nodes_[c].right = r;
    return c;
  }
  const std::uint32_t c = copy(b);
  const std::uint32_t l = merge(a, nodes_[b].left);
  nodes_[c].left = l;
  return c;
}

std::uint32_t CellLocator::insert(std::uint32_t root, std::uint32_t cell) {
  rng_ ^= rng_ << 13, rng_ ^= rng_ >> 7, rng_ ^= rng_ << 17;  // xorshift priorities
  const std::uint32_t prio = static_cast<std::uint32_t>(rng_ >> 32);
  // Split the path by key, copying it, and hang the new node where its priority belongs.
  struct Rec {
    CellLocator* self;
    std::uint32_t cell, prio;
    std::uint32_t go(std::uint32_t n) {
      if (n == kNil || self->nodes_[n].prio < prio) {
        std::uint32_t l = kNil, r = kNil;
        split(n, l, r);
        self->nodes_.push_back({cell, prio, l, r});
        return static_cast<std::uint32_t>(self->nodes_.size() - 1);
      }
      const std::uint32_t c = self->copy(n);
      if (self->cell_below(cell, self->nodes_[n].cell)) {
        const std::uint32_t l = go(self->nodes_[n].left);
        self->nodes_[c].left = l;
      } else {
        const std::uint32_t r = go(self->nodes_[n].right);
        self->nodes_[c].right = r;
      }
      return c;
    }
    void split(std::uint32_t n, std::uint32_t& l, std::uint32_t& r) {
      if (n == kNil) { l = r = kNil; return; }
      const std::uint32_t c = self->copy(n);
      if (self->cell_below(cell, self->nodes_[n].cell)) {
        std::uint32_t ll, lr;
        split(self->nodes_[n].left, ll, lr);
        self->nodes_[c].left = lr;
        l = ll, r = c;
      } else {
        std::uint32_t rl, rr;
        split(self->nodes_[n].right, rl, rr);
        self->nodes_[c].right = rl;
        l = c, r = rr;
      }
    }
  };
  return Rec{this, cell, prio}.go(root);
}

std::uint32_t CellLocator::erase(std::uint32_t root, std::uint32_t cell) {
  if (root == kNil) return kNil;
  const Node n = nodes_[root];
  if (n.cell == cell) return merge(n.left, n.right);
  const std::uint32_t c = copy(root);
  if (cell_below(cell, n.cell)) {
    const std::uint32_t l = erase(n.left, cell);
    nodes_[c].left = l;
  } else {
    const std::uint32_t r = erase(n.right, cell);
    nodes_[c].right = r;
  }
  return c;
}

std::optional<std::uint32_t> CellLocator::search(std::uint32_t n, const Point& q) const {
  while (n != kNil) {
    const Node& node = nodes_[n];
    const Bounds& b = bounds_[node.cell];
    if (orientation(b.floor_l, b.floor_r, q) < 0) n = node.left;        // below the floor
    else if (orientation(b.ceil_l, b.ceil_r, q) > 0) n = node.right;   // above the ceiling
    else return node.cell;
  }
  return std::nullopt;
}

std::optional<std::uint32_t> CellLocator::locate(const Point& q) const {
  if (xs_.size() < 2 || q.x() < xs_.front() || q.x() > xs_.back()) return std::nullopt;
  // Slab j: xs_[j] <= q.x < xs_[j + 1]. The bucket gives a start at or before it (the
  // bucket index is only a hint, computed in double; the scan decides exactly).
  const double f = (q.x() - xs_.front()) * bucket_scale_;
  std::size_t j = bucket_[std::min<std::size_t>(bucket_.size() - 1, f > 0 ? static_cast<std::size_t>(f) : 0)];
  while (j > 0 && xs_[j] > q.x()) --j;
  while (j + 1 < xs_.size() && xs_[j + 1] <= q.x()) ++j;
  j = std::min(j, roots_.size() - 1);
  if (auto c = search(roots_[j], q)) return c;
  // On an event line, the closed cell may lie in the slab to the left (e.g. on a wall).
  if (j > 0 && q.x() == xs_[j]) return search(roots_[j - 1], q);
  return std::nullopt;
}

}  // namespace preimage::decompose
