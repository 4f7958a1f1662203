// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/visibility_graph.hpp>

#include <preimage/parallel_for.hpp>

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
  for (std::uint32_t v = 0; v < env.num_vertices(); ++v)
    if (env.is_reflex(v)) reflex_.push_back(v);
  adj_.resize(env.num_vertices());
}

const VisibilityGraph::Lists& VisibilityGraph::lists(std::uint32_t u) const {
  {
    std::lock_guard lock(mutex_);
    if (adj_[u]) return *adj_[u];
  }
  auto L = std::make_unique<Lists>();
  const Environment& env = environment();
  if (env.is_reflex(u))
    for (std::uint32_t w : index_->visible_vertices(env.vertex(u)))
      if (w != u && env.is_reflex(w) && tangent_at(env, u, env.vertex(w))) {
        L->tangent_out.push_back(w);
        if (tangent_at(env, w, env.vertex(u))) L->neighbours.push_back(w);
      }
  std::lock_guard lock(mutex_);
  if (!adj_[u]) adj_[u] = std::move(L);  // another thread may have been first: the same lists
  return *adj_[u];
}

std::span<const std::uint32_t> VisibilityGraph::neighbours(std::uint32_t v) const { return lists(v).neighbours; }

std::span<const std::uint32_t> VisibilityGraph::tangent_out(std::uint32_t v) const { return lists(v).tangent_out; }

void VisibilityGraph::build_all() const {
  const unsigned threads = reflex_.size() < 64 ? 1 : std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
  parallel_for(reflex_.size(), threads, [&](std::size_t i) { lists(reflex_[i]); });
}

std::size_t VisibilityGraph::num_edges() const {
  build_all();
  std::size_t twice = 0;
  for (auto v : reflex_) twice += neighbours(v).size();
  return twice / 2;
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
  if (!index_->in_free_space(s) || !index_->in_free_space(t)) return out;
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
