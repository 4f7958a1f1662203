// SPDX-License-Identifier: Apache-2.0
#include "support/path_oracle.hpp"

#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace preimage::testing {

double brute_shortest_path(const geometry::Environment& env, const geometry::Point& s, const geometry::Point& t) {
  std::vector<geometry::Point> nodes{s, t};
  for (std::size_t v = 0; v < env.num_vertices(); ++v) nodes.push_back(env.vertex(v));
  const std::size_t n = nodes.size();
  std::vector<double> d(n, std::numeric_limits<double>::infinity());
  std::vector<char> done(n, 0);
  d[0] = 0;
  for (std::size_t it = 0; it < n; ++it) {
    std::size_t u = n;
    for (std::size_t k = 0; k < n; ++k)
      if (!done[k] && (u == n || d[k] < d[u])) u = k;
    if (u == n || std::isinf(d[u]) || u == 1) break;
    done[u] = 1;
    for (std::size_t k = 0; k < n; ++k) {
      const double c = d[u] + std::hypot(nodes[u].x() - nodes[k].x(), nodes[u].y() - nodes[k].y());
      if (!done[k] && c < d[k] && geometry::visible(env, nodes[u], nodes[k])) d[k] = c;
    }
  }
  return d[1];
}

double brute_clearance(const geometry::Environment& env, const geometry::Point& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    const geometry::Point a = env.vertex(e), b = env.vertex(env.next(e));
    const double ex = b.x() - a.x(), ey = b.y() - a.y(), L2 = ex * ex + ey * ey;
    const double t = L2 > 0 ? std::clamp(((p.x() - a.x()) * ex + (p.y() - a.y()) * ey) / L2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(a.x() + t * ex - p.x(), a.y() + t * ey - p.y()));
  }
  return best;
}

}  // namespace preimage::testing
