// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/tracking/risk.hpp>

#include <gtest/gtest.h>

#include <map>
#include <random>

using namespace preimage;
using namespace preimage::tracking;
using geometry::Point;

namespace {

// Central differences of phi in x and y.
Vec2 numeric_gradient(const std::function<double(const Point&)>& phi, const Point& o, double eps) {
  const double gx = (phi(Point(o.x() + eps, o.y())) - phi(Point(o.x() - eps, o.y()))) / (2 * eps);
  const double gy = (phi(Point(o.x(), o.y() + eps)) - phi(Point(o.x(), o.y() - eps))) / (2 * eps);
  return {gx, gy};
}

}  // namespace

TEST(EscapeRisk, ClosedFormGradientMatchesFiniteDifferencesForBothExits) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-5, 5);
  int tested[2] = {0, 0};
  for (int trial = 0; trial < 4000; ++trial) {
    const Point o = geometry::random_point(rng, U), k = geometry::random_point(rng, U), w = geometry::random_point(rng, U);
    RiskParams rp;
    rp.m = trial % 3;
    rp.delta = 0.1 + 0.4 * (trial % 5) / 4.0;
    const double P = std::abs(U(rng));
    auto phi = [&](const Point& q) { return corner_risk(q, k, w, P, rp).phi; };
    const EdgeRisk r = corner_risk(o, k, w, P, rp);
    // Stay away from the places where the formula is only C^1 or undefined: the switch
    // s = delta, the line d = 0, the corner itself.
    const Vec2 u = (vec(k) - vec(o)) * (1.0 / r.r_o), a = vec(w) - vec(k);
    if (r.r_o < 0.5 || std::abs(u.dot(a) - rp.delta) < 0.05 || std::abs(u.cross(a)) < 0.05 || a.norm() < rp.delta + 0.05) continue;
    const Vec2 g = numeric_gradient(phi, o, 1e-6);
    const double scale = std::max(1e-3, r.gradient.norm());
    ASSERT_NEAR(r.gradient.x, g.x, 2e-5 * scale) << "trial " << trial;
    ASSERT_NEAR(r.gradient.y, g.y, 2e-5 * scale) << "trial " << trial;
    ++tested[r.exit == EdgeRisk::Exit::Corner];
  }
  EXPECT_GT(tested[0], 500);
  EXPECT_GT(tested[1], 500);
}

TEST(EscapeRisk, CornerExitWithMZeroIsEquationFour) {
  // Observer at the origin, corner straight ahead on +y, target's last pivot beside it:
  // (p, t) is the frame of (4): p from the corner to the observer, t perpendicular.
  RiskParams rp;
  rp.m = 0; rp.c = 2.0; rp.delta = 0.3;
  const Point o(0, 0), k(0, 4), w(-1.5, 3.0);
  const EdgeRisk r = corner_risk(o, k, w, 2.0, rp);
  ASSERT_EQ(r.exit, EdgeRisk::Exit::Corner);
  const Vec2 p{0, -1}, t{-1, 0};  // u = (0, 1); t = u turned +90 deg
  const double h = r.h, ro = 4.0;
  // Equation (4): grad phi = 2 c r_o h^-2 p - 2 c delta r_o h^-3 t, with t oriented
  // towards the side of the pivot (here d = u x (w - k) = 1.5 > 0, so t as is).
  const Vec2 expected = p * (2 * rp.c * ro / (h * h)) - t * (2 * rp.c * rp.delta * ro / (h * h * h));
  EXPECT_NEAR(r.gradient.x, expected.x, 1e-12);
  EXPECT_NEAR(r.gradient.y, expected.y, 1e-12);
}

TEST(EscapeRisk, PipelineGradientMatchesFiniteDifferencesOfRecomputedTrees) {
  // Recompute V, the tree and phi^e from scratch at displaced observers; wherever the
  // combinatorial structure (corner and last pivot) is unchanged, the closed form must
  // match the difference quotient.
  std::mt19937_64 rng(5);
  int compared = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const auto env = geometry::generators::random_environment(30 + seed % 10, 2 + seed % 3, seed);
    const geometry::VisibilityIndex index(env);
    const auto box = env.bbox();
    std::uniform_real_distribution<double> X(box.xmin(), box.xmax()), Y(box.ymin(), box.ymax());
    for (int trial = 0; trial < 6; ++trial) {
      Point o = geometry::random_point(rng, X, Y);
      if (geometry::locate(env, o).kind != geometry::Location::Kind::Interior) continue;
      const LocalMap map = local_map_from_visibility(index.compute(o));
      Point t = geometry::random_point(rng, X, Y);
      if (!map.strictly_contains(t) || !geometry::visible(env, o, t)) continue;
      RiskParams rp;
      rp.delta = 0.5;
      rp.m = trial % 2;
      auto risks_at = [&](const Point& q) {
        std::map<std::pair<double, double>, std::pair<double, Point>> by_corner;  // corner -> (phi, pivot)
        const LocalMap m = local_map_from_visibility(index.compute(q));
        if (!m.strictly_contains(t)) return by_corner;
        const EscapePathTree tr = escape_path_tree(m, t);
        for (auto& r : escape_risks(m, tr, rp)) {
          const Point& k = m.vertices[m.corner[tr.paths[r.path].edge]];
          by_corner[{k.x(), k.y()}] = {r.phi, tr.nodes[tr.paths[r.path].node].at};
        }
        return by_corner;
      };
      const EscapePathTree tree = escape_path_tree(map, t);
      const auto risks = escape_risks(map, tree, rp);
      const double eps = 1e-6;
      const auto px = risks_at(Point(o.x() + eps, o.y())), mx = risks_at(Point(o.x() - eps, o.y()));
      const auto py = risks_at(Point(o.x(), o.y() + eps)), my = risks_at(Point(o.x(), o.y() - eps));
      for (auto& r : risks) {
        const Point& k = map.vertices[map.corner[tree.paths[r.path].edge]];
        const Point& pivot = tree.nodes[tree.paths[r.path].node].at;
        const std::pair<double, double> key{k.x(), k.y()};
        bool same = true;
        for (auto* side : {&px, &mx, &py, &my}) {
          auto it = side->find(key);
          same = same && it != side->end() && it->second.second == pivot;
        }
        if (!same) continue;
        const Vec2 g{(px.at(key).first - mx.at(key).first) / (2 * eps), (py.at(key).first - my.at(key).first) / (2 * eps)};
        const double scale = std::max(1e-6, r.gradient.norm());
        EXPECT_NEAR(r.gradient.x, g.x, 1e-4 * scale) << "seed " << seed << " trial " << trial;
        EXPECT_NEAR(r.gradient.y, g.y, 1e-4 * scale) << "seed " << seed << " trial " << trial;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 100);
}
