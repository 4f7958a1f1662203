// The reduced visibility graph and shortest paths against brute force: every pair of
// vertices tested with the O(n) exact edge scan, and Dijkstra over the complete visibility
// graph (all vertices, no tangency pruning) written separately here.
#include <gtest/gtest.h>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility_graph.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "support/cgal_oracle.hpp"
#include "support/path_oracle.hpp"

using namespace preimage::geometry;

namespace {

std::vector<Environment> environments() {
  std::vector<Environment> envs;
  for (std::uint64_t seed : {1u, 2u, 3u}) envs.push_back(preimage::testing::snapped_random_environment(40 + 4 * seed, seed % 3, seed, 40.0));
  for (std::uint64_t seed : {4u, 5u}) envs.push_back(generators::random_environment(90, 3, seed));
  envs.push_back(generators::random_rectilinear(9, 8, true, 7));
  envs.push_back(generators::office(2, 2));
  envs.push_back(Environment::make(generators::comb(4), {}));
  return envs;
}

double dist(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }


}  // namespace

// Also the lists tangent at the first end only, which the shortest path map's Dijkstra
// takes from the graph (one visibility query per vertex for both).
TEST(VisibilityGraph, EdgesArePairsOfMutuallyVisibleTangentReflexVertices) {
  std::size_t edges = 0, pruned = 0, one_end = 0;
  for (const auto& env : environments()) {
    VisibilityIndex index(env);
    VisibilityGraph g(index);
    for (auto u : g.reflex_vertices()) {
      auto nb = g.neighbours(u);
      auto out = g.tangent_out(u);
      ASSERT_TRUE(std::is_sorted(out.begin(), out.end()));
      for (auto v : g.reflex_vertices()) {
        if (u == v) continue;
        const bool vis = visible(env, env.vertex(u), env.vertex(v));
        const bool at_u = vis && tangent_at(env, u, env.vertex(v));
        const bool want = at_u && tangent_at(env, v, env.vertex(u));
        ASSERT_EQ(std::find(nb.begin(), nb.end(), v) != nb.end(), want) << u << " - " << v;
        ASSERT_EQ(std::find(out.begin(), out.end(), v) != out.end(), at_u) << u << " - " << v;
        edges += want, pruned += vis && !want, one_end += at_u && !want;
      }
    }
  }
  EXPECT_GT(edges, 500u);
  EXPECT_GT(pruned, 500u);   // the tangency test removes many visible pairs
  EXPECT_GT(one_end, 100u);  // and tangent_out keeps those tangent at u alone
}

TEST(VisibilityGraph, VisibleVerticesFromPointsOfAllKinds) {
  std::size_t checked = 0;
  for (const auto& env : environments()) {
    VisibilityIndex index(env);
    VisibilityGraph g(index);
    for (const auto& q : preimage::testing::random_queries(env, 15, 5, 5, 3)) {
      const auto got = index.visible_vertices(q.p);
      std::vector<std::uint32_t> want;
      for (std::uint32_t v = 0; v < env.num_vertices(); ++v)
        if (visible(env, q.p, env.vertex(v))) want.push_back(v);
      ASSERT_EQ(got, want) << format_point(q.p);
      checked += want.size();
    }
  }
  EXPECT_GT(checked, 1000u);
}

TEST(VisibilityGraph, ShortestPathsMatchDijkstraOnTheFullGraph) {
  std::size_t bent = 0;
  for (const auto& env : environments()) {
    VisibilityIndex index(env);
    VisibilityGraph g(index);
    const auto qs = preimage::testing::random_queries(env, 8, 3, 3, 11);
    for (std::size_t i = 0; i < qs.size(); ++i)
      for (std::size_t j = i + 1; j < qs.size(); j += 2) {
        const auto p = g.shortest_path(qs[i].p, qs[j].p);
        ASSERT_TRUE(p.found);
        const double want = preimage::testing::brute_shortest_path(env, qs[i].p, qs[j].p);
        ASSERT_NEAR(p.length, want, 1e-9 * (1 + want)) << format_point(qs[i].p) << " -> " << format_point(qs[j].p);
        double len = 0;
        for (std::size_t k = 0; k + 1 < p.points.size(); ++k) {
          ASSERT_TRUE(visible(env, p.points[k], p.points[k + 1]));  // certified, exactly
          len += dist(p.points[k], p.points[k + 1]);
        }
        EXPECT_NEAR(len, p.length, 1e-9 * (1 + len));
        bent += !p.bends.empty();
      }
  }
  EXPECT_GT(bent, 50u);
}
