// Full visibility graphs (vertex–vertex, point–point, point–vertex) against brute force:
// every pair is decided by geometry::visible (the O(n) exact edge scan, independent of the
// triangulation) and an edge must be present iff the pair sees each other. Also ray
// shooting from a point against the nearest exact intersection with every edge.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/visibility_graphs.hpp>

#include <optional>
#include <random>
#include <set>

#include "support/cgal_oracle.hpp"

using namespace preimage::geometry;

namespace {

std::vector<Environment> graph_environments() {
  std::vector<Environment> envs;
  for (std::uint64_t seed : {1u, 2u, 3u}) envs.push_back(preimage::testing::snapped_random_environment(40 + 10 * seed, seed, seed, 40.0));
  envs.push_back(generators::random_environment(80, 3, 9));
  envs.push_back(generators::random_rectilinear(7, 6, true, 4));  // collinear runs: segments along edges, through vertices
  envs.push_back(generators::office(2, 2));
  envs.push_back(Environment::make(generators::comb(4), {}));
  return envs;
}

std::set<std::pair<std::uint32_t, std::uint32_t>> as_set(const GraphEdges& e) { return {e.begin(), e.end()}; }

}  // namespace

TEST(VisibilityGraphs, VertexGraphIsEveryMutuallyVisiblePair) {
  std::size_t edges = 0, non_edges = 0;
  for (const Environment& env : graph_environments()) {
    VisibilityIndex index(env);
    const GraphEdges g = vertex_visibility_graph(index, 1);
    EXPECT_TRUE(std::is_sorted(g.begin(), g.end()));
    EXPECT_EQ(vertex_visibility_graph(index, 2), g) << "threads change the answer";
    const auto set = as_set(g);
    ASSERT_EQ(set.size(), g.size()) << "repeated edge";
    std::size_t here = 0;
    for (std::uint32_t u = 0; u < env.num_vertices(); ++u)
      for (std::uint32_t v = u + 1; v < env.num_vertices(); ++v) {
        const bool want = visible(env, env.vertex(u), env.vertex(v));
        ASSERT_EQ(set.count({u, v}) == 1, want) << describe_vertex(env, u) << " - " << describe_vertex(env, v);
        (want ? edges : non_edges)++;
        here += want;
      }
    EXPECT_EQ(g.size(), here) << "edges that are no pair u < v (loops, reversed pairs)";
    // Every boundary edge is a graph edge.
    for (std::uint32_t u = 0; u < env.num_vertices(); ++u) {
      const std::uint32_t w = static_cast<std::uint32_t>(env.next(u));
      EXPECT_EQ(set.count({std::min(u, w), std::max(u, w)}), 1u);
    }
  }
  EXPECT_GT(edges, 2000u);
  EXPECT_GT(non_edges, 2000u);
}

TEST(VisibilityGraphs, PointGraphsAgreeWithPairwiseChecks) {
  std::size_t pp_edges = 0, pp_non = 0, pv_edges = 0, pv_non = 0;
  const auto envs = graph_environments();
  for (std::size_t k = 0; k < envs.size(); ++k) {
    const Environment& env = envs[k];
    VisibilityIndex index(env);
    std::vector<Point> pts;
    for (const auto& q : preimage::testing::random_queries(env, 25, 10, 10, 40 + k)) pts.push_back(q.p);
    pts.push_back(pts.front());  // a repeated point sees its twin
    const GraphEdges pp = point_visibility_graph(index, pts, 1);
    EXPECT_EQ(point_visibility_graph(index, pts, 2), pp);
    EXPECT_TRUE(std::is_sorted(pp.begin(), pp.end()));
    const auto pps = as_set(pp);
    std::size_t here = 0;
    for (std::uint32_t i = 0; i < pts.size(); ++i)
      for (std::uint32_t j = i + 1; j < pts.size(); ++j) {
        const bool want = visible(env, pts[i], pts[j]);
        ASSERT_EQ(pps.count({i, j}) == 1, want) << "environment " << k << ": " << format_point(pts[i]) << " - " << format_point(pts[j]);
        (want ? pp_edges : pp_non)++;
        here += want;
      }
    EXPECT_EQ(pp.size(), here) << "edges that are no pair i < j";
    EXPECT_EQ(pps.count({0u, static_cast<std::uint32_t>(pts.size() - 1)}), 1u);
    const GraphEdges pv = point_vertex_visibility_graph(index, pts, 1);
    EXPECT_EQ(point_vertex_visibility_graph(index, pts, 2), pv);
    EXPECT_TRUE(std::is_sorted(pv.begin(), pv.end()));
    const auto pvs = as_set(pv);
    ASSERT_EQ(pvs.size(), pv.size()) << "repeated edge";
    here = 0;
    for (std::uint32_t i = 0; i < pts.size(); ++i)
      for (std::uint32_t v = 0; v < env.num_vertices(); ++v) {
        const bool want = visible(env, pts[i], env.vertex(v));
        ASSERT_EQ(pvs.count({i, v}) == 1, want) << "environment " << k << ": " << format_point(pts[i]) << " - " << describe_vertex(env, v);
        (want ? pv_edges : pv_non)++;
        here += want;
      }
    EXPECT_EQ(pv.size(), here);
  }
  EXPECT_GT(pp_edges, 1000u);
  EXPECT_GT(pp_non, 1000u);
  EXPECT_GT(pv_edges, 1000u);
  EXPECT_GT(pv_non, 1000u);
}

TEST(VisibilityGraphs, PointOutsideFreeSpaceIsNamed) {
  const Environment env = generators::office(1, 2);
  VisibilityIndex index(env);
  const std::vector<Point> pts{{1, 1}, {-3, -3}};
  try {
    point_visibility_graph(index, pts);
    FAIL() << "no error";
  } catch (const preimage::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("point 1 (-3, -3) is not in free space"), std::string::npos) << e.what();
  }
  EXPECT_THROW(point_vertex_visibility_graph(index, pts), preimage::InputError);
  EXPECT_TRUE(point_visibility_graph(index, std::vector<Point>{}).empty());
}

// shoot_ray is public (queries.hpp): the first boundary point strictly beyond the origin,
// checked against every edge's exact intersection with the ray, from origins of all kinds
// (interior, on edges, at vertices) towards vertices (rays through vertices and along
// edges) and in random directions.
TEST(RayShooting, NearestIntersectionOverAllEdges) {
  std::size_t at_vertex = 0, along = 0, total = 0;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> d(-1, 1);
  std::vector<Environment> envs = graph_environments();
  for (std::size_t k = 0; k < envs.size(); ++k) {
    const Environment& env = envs[k];
    const auto qs = preimage::testing::random_queries(env, 8, 6, 6, 70 + k);
    for (const auto& q : qs) {
      std::vector<Point> targets;
      for (std::size_t v = 0; v < env.num_vertices(); v += 1 + env.num_vertices() / 15) targets.push_back(env.vertex(v));
      for (int r = 0; r < 5; ++r) targets.push_back(q.p + (random_point(rng, d) - CGAL::ORIGIN));
      if (q.loc.kind == Location::Kind::AtVertex) {  // along both edges at the vertex
        targets.push_back(env.vertex(env.next(q.loc.index)));
        targets.push_back(env.vertex(env.prev(q.loc.index)));
      }
      for (const Point& t : targets) {
        if (t == q.p) continue;
        const ExactPoint o = to_exact(q.p);
        const ExactKernel::Vector_2 dir = to_exact(t) - o;
        const ExactKernel::Ray_2 ray(o, dir);
        // Brute force: the nearest intersection point beyond o; a collinear overlap that
        // starts at o counts from its far end (shoot_ray's "along an edge" contact).
        std::optional<ExactFT> best;
        std::optional<ExactPoint> best_point;
        auto offer = [&](const ExactPoint& p) {
          if (p == o) return;
          const ExactFT s = (p - o) * dir;
          if (!best || s < *best) best = s, best_point = p;
        };
        for (std::size_t e = 0; e < env.num_vertices(); ++e) {
          const ExactPoint &a = env.exact_vertex(e), &b = env.exact_vertex(env.next(e));
          if (CGAL::collinear(o, o + dir, a) && CGAL::collinear(o, o + dir, b)) {
            // On the ray's line: the part ahead of o, by parameters along dir.
            const ExactFT sa = (a - o) * dir, sb = (b - o) * dir;
            const ExactPoint& near = sa < sb ? a : b;
            const ExactPoint& far = sa < sb ? b : a;
            const ExactFT s_near = CGAL::min(sa, sb), s_far = CGAL::max(sa, sb);
            if (s_far <= 0) continue;
            offer(s_near <= 0 ? far : near);
            continue;
          }
          const auto x = CGAL::intersection(ray, ExactKernel::Segment_2(a, b));
          if (!x) continue;
          const ExactPoint* p = boost::get<ExactPoint>(&*x);
          ASSERT_TRUE(p) << "an overlap with an edge not on the ray's line";
          offer(*p);
        }
        const auto hit = shoot_ray(env, o, dir);
        ASSERT_EQ(hit.has_value(), best.has_value()) << format_point(q.p) << " towards " << format_point(t);
        if (!hit) continue;
        ++total;
        ASSERT_EQ(hit->point, *best_point) << "environment " << k << ": " << format_point(q.p) << " towards " << format_point(t);
        // The vertex flag is set exactly when the contact is a vertex.
        bool is_vertex = false;
        for (std::size_t v = 0; v < env.num_vertices(); ++v) is_vertex |= env.exact_vertex(v) == hit->point;
        EXPECT_EQ(hit->vertex.has_value(), is_vertex);
        if (hit->vertex) {
          EXPECT_EQ(env.exact_vertex(*hit->vertex), hit->point);
        }
        at_vertex += is_vertex;
        along += hit->along_edge;
      }
    }
  }
  EXPECT_GT(total, 1000u);
  EXPECT_GT(at_vertex, 300u);
  EXPECT_GT(along, 10u);
}
