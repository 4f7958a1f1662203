// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/tracking/escape_path_tree.hpp>

#include "support/escape_oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace preimage;
using namespace preimage::tracking;
using geometry::Point;

namespace {

// A point strictly inside `map`, drawn uniformly from its bounding box.
Point random_inside(const LocalMap& map, std::mt19937_64& rng) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (auto& p : map.vertices) {
    x0 = std::min(x0, p.x()); y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x()); y1 = std::max(y1, p.y());
  }
  std::uniform_real_distribution<double> X(x0, x1), Y(y0, y1);
  for (;;) {
    Point p = geometry::random_point(rng, X, Y);
    if (map.strictly_contains(p) && p != map.observer) return p;
  }
}

}  // namespace

TEST(EscapePathTree, EverySepMatchesBruteForceOnRandomEnvironments) {
  std::mt19937_64 rng(7);
  int checked = 0, bent = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto env = geometry::generators::random_environment(30 + seed % 20, seed % 4, seed);
    const geometry::VisibilityIndex index(env);
    for (int trial = 0; trial < 5; ++trial) {
      const Point o = preimage::testing::random_free_point(env, rng);
      const LocalMap map = local_map_from_visibility(index.compute(o));
      const Point t = random_inside(map, rng);
      const EscapePathTree tree = escape_path_tree(map, t);
      const auto oracle = preimage::testing::brute_force_sde(map, t);
      ASSERT_EQ(tree.paths.size(), oracle.size());
      for (std::size_t i = 0; i < oracle.size(); ++i) {
        EXPECT_NEAR(tree.paths[i].length, oracle[i], 1e-9 * (1 + oracle[i]))
            << "seed " << seed << " trial " << trial << " edge " << tree.paths[i].edge;
        ++checked;
        bent += tree.paths[i].node != 0;
      }
    }
  }
  EXPECT_GT(checked, 300);
  EXPECT_GT(bent, 50);  // the test must exercise pivots, not only straight escapes
}
