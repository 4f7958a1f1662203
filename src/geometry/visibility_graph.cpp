// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/visibility_graph.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <thread>

namespace preimage::geometry {

bool tangent_at(const Environment& env, std::uint32_t v, const Point& x) {
  const Point& V = env.vertex(v);
  const int a = orientation(x, V, env.vertex(env.prev(v)));
  const int b = orientation(x, V, env.vertex(env.next(v)));
  return a * b >= 0;
}

namespace {
double dist(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }
}  // namespace

VisibilityGraph::VisibilityGraph(const VisibilityIndex& index) : index_(&index) {
  const Environment& env = index.environment();
  const std::size_t n = env.num_vertices();
  for (std::uint32_t v = 0; v < n; ++v)
    if (env.is_reflex(v)) reflex_.push_back(v);
  // Each reflex vertex's neighbours from its own visibility polygon (the relation is
  // symmetric, so both ends find the edge), in parallel over the vertices.
  std::vector<std::vector<std::uint32_t>> nb(reflex_.size());
  auto work = [&](std::size_t begin, std::size_t step) {
    for (std::size_t i = begin; i < reflex_.size(); i += step) {
      const std::uint32_t u = reflex_[i];
      for (std::uint32_t w : index.visible_vertices(env.vertex(u)))
        if (w != u && env.is_reflex(w) && tangent_at(env, u, env.vertex(w)) && tangent_at(env, w, env.vertex(u)))
          nb[i].push_back(w);
    }
  };
  const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
  if (reflex_.size() < 64 || threads == 1) {
    work(0, 1);
  } else {
    std::vector<std::thread> pool;
    for (std::size_t k = 0; k < threads; ++k) pool.emplace_back(work, k, threads);
    for (auto& th : pool) th.join();
  }
  offset_.assign(n + 1, 0);
  for (std::size_t i = 0; i < reflex_.size(); ++i) offset_[reflex_[i] + 1] = static_cast<std::uint32_t>(nb[i].size());
  for (std::size_t v = 0; v < n; ++v) offset_[v + 1] += offset_[v];
  adj_.resize(offset_.back());
  for (std::size_t i = 0; i < reflex_.size(); ++i) std::copy(nb[i].begin(), nb[i].end(), adj_.begin() + offset_[reflex_[i]]);
}

std::span<const std::uint32_t> VisibilityGraph::neighbours(std::uint32_t v) const {
  return {adj_.data() + offset_[v], offset_[v + 1] - offset_[v]};
}


std::vector<std::uint32_t> VisibilityGraph::tangent_reflex_from(const Point& q) const {
  const Environment& env = environment();
  std::vector<std::uint32_t> out;
  for (std::uint32_t v : index_->visible_vertices(q))
    if (env.is_reflex(v) && env.vertex(v) != q && tangent_at(env, v, q)) out.push_back(v);
  return out;
}

VisibilityGraph::Path VisibilityGraph::shortest_path(const Point& s, const Point& t) const {
  Path out;
  if (!index_->locate(s).in_free_space() || !index_->locate(t).in_free_space()) return out;
  if (index_->visible(s, t)) {
    out.found = true, out.points = {s, t}, out.length = dist(s, t);
    return out;
  }
  const Environment& env = environment();
  const auto from_s = tangent_reflex_from(s), to_t = tangent_reflex_from(t);
  std::vector<char> is_target(env.num_vertices(), 0);
  for (auto v : to_t) is_target[v] = 1;
  // A* over reflex vertices; the Euclidean distance to t is a consistent heuristic.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> g(env.num_vertices(), inf);
  std::vector<std::uint32_t> parent(env.num_vertices(), kNone);
  struct Item {
    double f, g;
    std::uint32_t v;
    bool operator>(const Item& o) const { return f > o.f; }
  };
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  auto h = [&](std::uint32_t v) { return dist(env.vertex(v), t); };
  for (auto v : from_s) {
    const double d = dist(s, env.vertex(v));
    if (d < g[v]) g[v] = d, open.push({d + h(v), d, v});
  }
  double best = inf;
  std::uint32_t last = kNone;
  while (!open.empty()) {
    const Item it = open.top();
    open.pop();
    if (it.f >= best) break;
    if (it.g > g[it.v]) continue;  // superseded
    const std::uint32_t v = it.v;
    if (is_target[v] && g[v] + h(v) < best) best = g[v] + h(v), last = v;
    for (auto w : neighbours(v)) {
      const double nd = g[v] + dist(env.vertex(v), env.vertex(w));
      if (nd < g[w]) g[w] = nd, parent[w] = v, open.push({nd + h(w), nd, w});
    }
  }
  if (last == kNone) return out;
  for (std::uint32_t v = last; v != kNone; v = parent[v]) out.bends.push_back(v);
  std::reverse(out.bends.begin(), out.bends.end());
  out.points.push_back(s);
  for (auto v : out.bends) out.points.push_back(env.vertex(v));
  out.points.push_back(t);
  out.found = true;
  out.length = best;
  return out;
}

}  // namespace preimage::geometry
