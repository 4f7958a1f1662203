// SPDX-License-Identifier: Apache-2.0
#include "support/escape_oracle.hpp"

#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/random_point.hpp>

#include <cmath>
#include <limits>
#include <queue>

namespace preimage::testing {

using geometry::Point;

std::vector<double> brute_force_sde(const tracking::LocalMap& map, const Point& target) {
  const auto env = geometry::Environment::make(map.vertices, {}, "local map", "holes");
  const std::size_t n = map.size();
  std::vector<Point> nodes = map.vertices;
  nodes.push_back(target);
  const std::size_t m = nodes.size(), root = n;
  auto len = [](const Point& a, const Point& b) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))); };
  std::vector<double> d(m, std::numeric_limits<double>::infinity());
  d[root] = 0;
  std::vector<char> done(m, 0);
  for (std::size_t round = 0; round < m; ++round) {  // dense Dijkstra
    std::size_t u = m;
    for (std::size_t i = 0; i < m; ++i)
      if (!done[i] && (u == m || d[i] < d[u])) u = i;
    if (u == m || !std::isfinite(d[u])) break;
    done[u] = 1;
    for (std::size_t v = 0; v < m; ++v)
      if (!done[v] && geometry::visible(env, nodes[u], nodes[v])) d[v] = std::min(d[v], d[u] + len(nodes[u], nodes[v]));
  }
  std::vector<double> out;
  for (std::size_t e = 0; e < n; ++e) {
    if (!tracking::is_escape(map.edges[e])) continue;
    const Point& a = map.vertices[e];
    const Point& b = map.vertices[map.next(e)];
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t u = 0; u < m; ++u) {
      if (!std::isfinite(d[u])) continue;
      std::vector<Point> cands{a, b};
      const double dx = b.x() - a.x(), dy = b.y() - a.y();
      const double t = ((nodes[u].x() - a.x()) * dx + (nodes[u].y() - a.y()) * dy) / (dx * dx + dy * dy);
      if (t > 0 && t < 1) cands.emplace_back(a.x() + t * dx, a.y() + t * dy);
      for (std::size_t c = 0; c < cands.size(); ++c) {
        // The foot is rounded and may lie just outside V: test the segment up to a point a
        // hair short of it (2^-30 of its length; the lengths compared are not affected).
        const Point& w = nodes[u];
        const Point& q = cands[c];
        const double f = c < 2 ? 1.0 : 1.0 - std::ldexp(1.0, -30);
        const Point qi(w.x() + f * (q.x() - w.x()), w.y() + f * (q.y() - w.y()));
        if (geometry::visible(env, w, c < 2 ? q : qi)) best = std::min(best, d[u] + len(w, q));
      }
    }
    out.push_back(best);
  }
  return out;
}

Point random_free_point(const geometry::Environment& env, std::mt19937_64& rng) {
  const auto box = env.bbox();
  std::uniform_real_distribution<double> X(box.xmin(), box.xmax()), Y(box.ymin(), box.ymax());
  for (;;) {
    const Point p = geometry::random_point(rng, X, Y);
    if (geometry::locate(env, p).kind == geometry::Location::Kind::Interior) return p;
  }
}

}  // namespace preimage::testing
