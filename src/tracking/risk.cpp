// SPDX-License-Identifier: Apache-2.0
#include <preimage/tracking/risk.hpp>

#include <algorithm>

namespace preimage::tracking {

EdgeRisk corner_risk(const Point& observer, const Point& corner, const Point& pivot, double P, const RiskParams& rp) {
  EdgeRisk out;
  const Vec2 k = vec(corner), ko = k - vec(observer);
  const double r = ko.norm();
  const Vec2 u = ko * (1.0 / r), t{-u.y, u.x};
  const Vec2 a = vec(pivot) - k;
  const double s = u.dot(a), d = u.cross(a), sgn = d > 0 ? 1.0 : d < 0 ? -1.0 : 0.0;
  double terminal, lever;
  if (s >= rp.delta) {
    out.exit = EdgeRisk::Exit::Perpendicular;
    terminal = std::abs(d);
    lever = s;
  } else {
    out.exit = EdgeRisk::Exit::Corner;
    const double A = std::max(a.norm(), rp.delta);
    const double gamma = std::atan2(std::abs(d), s);  // angle between u and w - k, in [0, pi]
    const double beta0 = rp.delta > 0 ? std::acos(rp.delta / A) : 0.5 * M_PI;
    terminal = std::sqrt(std::max(0.0, A * A - rp.delta * rp.delta)) + rp.delta * std::max(0.0, gamma - beta0);
    lever = rp.delta;
  }
  const double h_raw = P + terminal;
  const double h = std::max(h_raw, rp.min_h);
  const Vec2 grad_h = h_raw > rp.min_h ? t * (sgn * lever / r) : Vec2{};
  const Vec2 grad_r = u * -1.0;
  double hm = 1;  // (1/h)^(m+2) by multiplication: m is a small integer, pow is slow
  for (int i = 0; i < rp.m + 2; ++i) hm /= h;
  out.r_o = r;
  out.h = h;
  out.d = d;
  out.s = s;
  out.phi = rp.c * r * r * hm;
  out.gradient = grad_r * (2 * rp.c * r * hm) - grad_h * ((rp.m + 2) * rp.c * r * r * hm / h);
  return out;
}

std::vector<EdgeRisk> escape_risks(const LocalMap& map, const EscapePathTree& tree, const RiskParams& rp) {
  std::vector<EdgeRisk> out;
  out.reserve(tree.paths.size());
  for (std::uint32_t i = 0; i < tree.paths.size(); ++i) {
    const EscapePath& p = tree.paths[i];
    if (p.kind != EdgeKind::Occlusion) continue;
    const std::uint32_t k = map.corner[p.edge];
    // If the path bends at the corner itself, its last leg starts one pivot earlier.
    std::uint32_t w = p.node;
    if (tree.nodes[w].vertex == k && tree.nodes[w].parent != kNone) w = tree.nodes[w].parent;
    EdgeRisk r = corner_risk(map.observer, map.vertices[k], tree.nodes[w].at, tree.nodes[w].distance, rp);
    r.path = i;
    out.push_back(r);
  }
  return out;
}

RiskAverage plain_average(const std::vector<EdgeRisk>& risks) {
  RiskAverage sum;
  for (auto& r : risks) {
    sum.phi += r.phi;
    sum.gradient = sum.gradient + r.gradient;
  }
  if (risks.empty()) return sum;
  const double k = 1.0 / static_cast<double>(risks.size());
  return {sum.phi * k, sum.gradient * k};
}

RiskAverage recursive_average(const EscapePathTree& tree, const std::vector<EdgeRisk>& risks) {
  const std::size_t n = tree.nodes.size();
  thread_local std::vector<RiskAverage> sum;  // (per-thread scratch: one average per TRACK iteration)
  thread_local std::vector<int> count;
  sum.assign(n, RiskAverage{});
  count.assign(n, 0);
  auto add = [](RiskAverage& to, const RiskAverage& v, double k) {
    to.phi += v.phi * k;
    to.gradient = to.gradient + v.gradient * k;
  };
  for (auto& r : risks) {
    const std::uint32_t v = tree.paths[r.path].node;
    add(sum[v], RiskAverage{r.phi, r.gradient}, 1.0);
    ++count[v];
  }
  // Parents precede children, so one backward pass averages every subtree before its parent.
  for (std::size_t v = n; v-- > 1;) {
    if (count[v] == 0) continue;
    const std::uint32_t p = tree.nodes[v].parent;
    add(sum[p], sum[v], 1.0 / count[v]);
    ++count[p];
  }
  if (!count[0]) return {};
  RiskAverage out;
  add(out, sum[0], 1.0 / count[0]);
  return out;
}

}  // namespace preimage::tracking
