// SPDX-License-Identifier: Apache-2.0
#include "car_search.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <unordered_set>

namespace preimage::coverage::detail {

bool certify_curve(const ArcCertifier& cert, const DubinsCurve& curve, const Pose& arrive, double tolerance,
                   std::vector<std::vector<Point>>& samples) {
  samples.clear();
  const Pose end = curve.at(curve.length());
  if (std::hypot(end.at.x() - arrive.at.x(), end.at.y() - arrive.at.y()) > tolerance) return false;
  std::size_t last = 0;  // the last piece that moves ends at the arrival point exactly
  for (std::size_t k = 0; k < 3; ++k)
    if (curve.pieces[k].length > 0) last = k;
  Pose p = curve.from;
  for (std::size_t k = 0; k < 3; ++k) {
    const DrivePiece& piece = curve.pieces[k];
    std::vector<Point> s;
    if (piece.length <= 0) {
      samples.push_back({});
      continue;
    }
    if (piece.turn == 0) {
      s.push_back(k == last ? arrive.at : drive(p, piece, curve.radius).at);
      if (!cert.segment(p.at, s.back())) return false;
    } else {
      s = ArcCertifier::sample_arc(p, curve.radius, piece.turn);
      if (k == last) s.back() = arrive.at;
      if (!cert.arc(p.at, s, curve.radius, piece.turn)) return false;
    }
    p = drive(p, piece, curve.radius);
    p.at = s.back();
    samples.push_back(std::move(s));
  }
  return true;
}

std::vector<Point> step_samples(const Pose& p, const CarStep& s, double radius, Pose& after) {
  // Backwards: the same arc or segment driven forward from the pose turned around.
  const Pose q = s.reverse ? Pose{p.at, p.heading + std::numbers::pi} : p;
  const Pose e = drive(q, s.piece, radius);
  after = s.reverse ? Pose{e.at, e.heading - std::numbers::pi} : e;
  if (s.piece.turn == 0) return {e.at};
  return ArcCertifier::sample_arc(q, radius, s.piece.turn);
}

CarSearch::CarSearch(const geometry::Environment& E, const geometry::Clearance& clear, const ArcCertifier& cert, double radius, double cell,
                     double tolerance)
    : cert_(cert), R_(radius), cell_(cell), tol_(tolerance) {
  const auto box = E.bbox();
  const double wx = box.xmax() - box.xmin(), wy = box.ymax() - box.ymin();
  while ((wx / cell_ + 1) * (wy / cell_ + 1) > 4e6) cell_ *= 2;  // memory: at most ~4 million cells
  x0_ = box.xmin(), y0_ = box.ymin();
  nx_ = static_cast<std::size_t>(wx / cell_) + 1, ny_ = static_cast<std::size_t>(wy / cell_) + 1;
  free_.assign(nx_ * ny_, 0);
  for (std::size_t j = 0; j < ny_; ++j)
    for (std::size_t i = 0; i < nx_; ++i)
      free_[j * nx_ + i] = clear.admits(Point(x0_ + (static_cast<double>(i) + 0.5) * cell_, y0_ + (static_cast<double>(j) + 0.5) * cell_));
}

long CarSearch::cell_of(const Point& p) const {
  const double fi = std::floor((p.x() - x0_) / cell_), fj = std::floor((p.y() - y0_) / cell_);
  if (!(fi >= 0 && fj >= 0 && fi < static_cast<double>(nx_) && fj < static_cast<double>(ny_))) return -1;
  return static_cast<long>(fj) * static_cast<long>(nx_) + static_cast<long>(fi);
}

// Distance on the guiding grid (8-neighbour moves between admitted cell centres) to the
// goals: the heuristic, aware of walls (a guide; the steps are certified on their own).
std::vector<double> CarSearch::distance_to(const std::vector<Pose>& goals) const {
  std::vector<double> d(free_.size(), INFINITY);
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> q;
  for (const Pose& g : goals) {
    const long c = cell_of(g.at);
    if (c >= 0 && d[static_cast<std::size_t>(c)] > 0) d[static_cast<std::size_t>(c)] = 0, q.push({0.0, static_cast<std::size_t>(c)});
  }
  const double diag = cell_ * std::numbers::sqrt2;
  while (!q.empty()) {
    const auto [dc, c] = q.top();
    q.pop();
    if (dc > d[c]) continue;
    const long i = static_cast<long>(c % nx_), j = static_cast<long>(c / nx_);
    for (long dj = -1; dj <= 1; ++dj)
      for (long di = -1; di <= 1; ++di) {
        const long a = i + di, b = j + dj;
        if ((di == 0 && dj == 0) || a < 0 || b < 0 || a >= static_cast<long>(nx_) || b >= static_cast<long>(ny_)) continue;
        const std::size_t n = static_cast<std::size_t>(b) * nx_ + static_cast<std::size_t>(a);
        if (!free_[n]) continue;
        const double nd = dc + (di != 0 && dj != 0 ? diag : cell_);
        if (nd < d[n]) d[n] = nd, q.push({nd, n});
      }
  }
  return d;
}

CarSearch::Result CarSearch::search(const std::vector<Pose>& starts, const std::vector<Pose>& goals, std::size_t max_expansions) const {
  Result res;
  if (starts.empty() || goals.empty()) return res;
  const std::vector<double> guide = distance_to(goals);
  auto h = [&](const Pose& p) {
    const long c = cell_of(p.at);
    double e = INFINITY;
    for (const Pose& g : goals) e = std::min(e, std::hypot(g.at.x() - p.at.x(), g.at.y() - p.at.y()));
    if (c >= 0 && std::isfinite(guide[static_cast<std::size_t>(c)])) return std::max(e, guide[static_cast<std::size_t>(c)] - cell_);
    return 2 * e + 4 * R_;  // off the guide (a pocket narrower than its cells)
  };
  // Steps of an eighth of a quarter turn, and straight steps as long.
  const double turn = std::numbers::pi / 8, len = R_ * turn;
  std::vector<CarStep> steps;
  for (const bool rev : {false, true})
    for (const double t : {turn, 0.0, -turn}) steps.push_back({{t, len}, rev});
  struct Node {
    Pose pose;
    double g;
    std::size_t parent;
    CarStep step;
    std::size_t start;
  };
  std::vector<Node> nodes;
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  std::unordered_set<std::uint64_t> closed;
  const double state_cell = 0.75 * len;
  auto key = [&](const Pose& p) {
    const auto ix = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor((p.at.x() - x0_) / state_cell)) & 0xFFFFFF);
    const auto iy = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor((p.at.y() - y0_) / state_cell)) & 0xFFFFFF);
    const auto ih = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::lround(p.heading / turn)) & 15);
    return ix << 28 | iy << 4 | ih;
  };
  for (std::size_t s = 0; s < starts.size(); ++s) {
    nodes.push_back({starts[s], 0, SIZE_MAX, {}, s});
    open.push({h(starts[s]), nodes.size() - 1});
  }
  std::vector<std::vector<Point>> samples;
  while (!open.empty() && res.expansions < max_expansions) {
    const std::size_t id = open.top().second;
    open.pop();
    const Node node = nodes[id];
    if (!closed.insert(key(node.pose)).second) continue;
    ++res.expansions;
    // Finish with a Dubins curve when one fits (tried near the goal, and every few poses).
    const double hn = h(node.pose);
    if (hn < 6 * R_ || res.expansions % 8 == 1) {
      std::vector<std::pair<DubinsCurve, std::size_t>> finishes;
      for (std::size_t g = 0; g < goals.size(); ++g)
        for (const DubinsCurve& c : dubins_curves(node.pose, goals[g], R_)) finishes.push_back({c, g});
      std::sort(finishes.begin(), finishes.end(), [](const auto& a, const auto& b) { return a.first.length() < b.first.length(); });
      for (std::size_t k = 0; k < finishes.size() && k < 6; ++k) {
        if (!certify_curve(cert_, finishes[k].first, goals[finishes[k].second], tol_, samples)) continue;
        res.found = true, res.goal = finishes[k].second, res.start = node.start;
        res.finish = finishes[k].first, res.finish_samples = samples;
        for (std::size_t n = id; nodes[n].parent != SIZE_MAX; n = nodes[n].parent) res.steps.push_back(nodes[n].step);
        std::reverse(res.steps.begin(), res.steps.end());
        return res;
      }
    }
    for (const CarStep& s : steps) {
      Pose after;
      const std::vector<Point> pts = step_samples(node.pose, s, R_, after);
      if (closed.count(key(after))) continue;
      const bool ok = s.piece.turn == 0 ? cert_.segment(node.pose.at, pts.back()) : cert_.arc(node.pose.at, pts, R_, s.piece.turn);
      if (!ok) continue;
      // Reversing costs more than driving forward, and every change of direction a stop.
      const bool cusp = node.parent != SIZE_MAX ? node.step.reverse != s.reverse : s.reverse;
      const double g = node.g + len * (s.reverse ? 2.0 : 1.0) + (cusp ? 2 * R_ : 0.0) + (s.piece.turn != 0 ? 0.05 * len : 0.0);
      nodes.push_back({after, g, id, s, node.start});
      open.push({g + 1.5 * h(after), nodes.size() - 1});
    }
  }
  return res;
}

}  // namespace preimage::coverage::detail
