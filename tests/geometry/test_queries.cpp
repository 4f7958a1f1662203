// Point location, ray shooting and two-point visibility against independent definitions.
#include <gtest/gtest.h>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include "support/cgal_oracle.hpp"

#include <random>

using namespace preimage::geometry;
using K = Location::Kind;

TEST(Locate, AgreesWithCgalBoundedSide) {
  auto env = preimage::testing::snapped_random_environment(120, 3, 11, 200.0);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> c(-2, 202);  // integer queries hit vertices and edges often
  int kinds[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    Point q = random_point(rng, c);
    Location loc = locate(env, q);
    ++kinds[static_cast<int>(loc.kind)];
    auto outer = env.ring(0);
    auto side = CGAL::bounded_side_2(outer.begin(), outer.end(), q, Kernel());
    if (side == CGAL::ON_UNBOUNDED_SIDE) {
      EXPECT_EQ(loc.kind, K::Outside);
      continue;
    }
    if (side == CGAL::ON_BOUNDARY) {
      ASSERT_TRUE(loc.kind == K::OnEdge || loc.kind == K::AtVertex);
      EXPECT_EQ(env.ring_of(loc.index), 0u);
      continue;
    }
    int hole_side = -1;
    for (std::size_t h = 1; h < env.num_rings(); ++h) {
      auto ring = env.ring(h);
      auto s = CGAL::bounded_side_2(ring.begin(), ring.end(), q, Kernel());
      if (s == CGAL::ON_BOUNDARY) {
        hole_side = 0;
        EXPECT_EQ(env.ring_of(loc.index), h);
      }
      if (s == CGAL::ON_BOUNDED_SIDE) {
        hole_side = 1;
        EXPECT_EQ(loc.kind, K::InHole);
        EXPECT_EQ(loc.index, h - 1);
      }
    }
    if (hole_side == -1) {
      EXPECT_EQ(loc.kind, K::Interior);
    }
    if (loc.kind == K::OnEdge) {
      EXPECT_TRUE(strictly_inside_segment(env.vertex(loc.index), env.vertex(env.next(loc.index)), q));
    }
    if (loc.kind == K::AtVertex) {
      EXPECT_EQ(env.vertex(loc.index), q);
    }
  }
  for (int k = 0; k < 5; ++k) EXPECT_GT(kinds[k], 0) << "kind " << k << " never exercised";
}

TEST(RayShooting, FirstHitIsNearestCrossingOnTheBoundary) {
  auto env = generators::office(2, 3);
  // From the middle of a room straight right: the nearest wall face.
  auto hit = shoot_ray(env, Point(2, 1), Point(3, 1));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->point, ExactPoint(3.9, 1));
  EXPECT_LT(CGAL::to_double(hit->point.x()), 4.0);
  EXPECT_TRUE(on_segment(env.vertex(hit->edge), env.vertex(env.next(hit->edge)), to_double(hit->point)));
  // Random rays in a random environment: the hit is visible from the origin and on the boundary.
  auto renv = preimage::testing::snapped_random_environment(300, 3, 5, 500.0);
  auto qs = preimage::testing::random_queries(renv, 200, 0, 0, 9);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> d(-1, 1);
  for (auto& q : qs) {
    Point t = q.p + (random_point(rng, d) - CGAL::ORIGIN);
    auto h = shoot_ray(renv, q.p, t);
    ASSERT_TRUE(h);
    const auto a = to_exact(renv.vertex(h->edge)), b = to_exact(renv.vertex(renv.next(h->edge)));
    EXPECT_EQ(CGAL::orientation(a, b, h->point), CGAL::COLLINEAR);
    EXPECT_EQ(CGAL::orientation(to_exact(q.p), to_exact(t), h->point), CGAL::COLLINEAR);
    // No boundary edge crosses the open segment origin -> hit.
    for (std::size_t e = 0; e < renv.num_vertices(); ++e) {
      ExactKernel::Segment_2 s(to_exact(q.p), h->point), edge(to_exact(renv.vertex(e)), to_exact(renv.vertex(renv.next(e))));
      if (!CGAL::do_intersect(s, edge)) continue;
      auto x = CGAL::intersection(s, edge);
      const ExactPoint* p = boost::get<ExactPoint>(&*x);
      ASSERT_TRUE(p) << "collinear overlap on a random ray";
      EXPECT_EQ(*p, h->point);
    }
  }
}

TEST(TwoPointVisibility, AgreesWithVisibilityPolygonMembership) {
  // visible(p, q) is an O(n) edge scan; membership in V(p) comes from the expansion.
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    auto env = preimage::testing::snapped_random_environment(200, seed % 3, seed, 300.0);
    VisibilityIndex index(env);
    auto qs = preimage::testing::random_queries(env, 40, 10, 10, seed);
    auto targets = preimage::testing::random_queries(env, 40, 10, 10, seed + 100);
    int seen = 0, hidden = 0;
    for (auto& p : qs) {
      auto vis = index.compute(p.p);
      auto poly = canonical_cycle(vis.points());
      for (auto& t : targets) {
        auto side = CGAL::bounded_side_2(poly.begin(), poly.end(), to_exact(t.p), ExactKernel());
        const bool in_v = side != CGAL::ON_UNBOUNDED_SIDE;
        ASSERT_EQ(visible(env, p.p, t.p), in_v) << format_point(p.p) << " -> " << format_point(t.p);
        (in_v ? seen : hidden)++;
      }
    }
    EXPECT_GT(seen, 50);
    EXPECT_GT(hidden, 50);
  }
}

// The triangulation walk answers as the O(n) edge scan on every pair of query points of
// all kinds (interior, inside edges, at vertices), on degenerate inputs too: integer-
// snapped environments (segments through vertices, along edges), rectilinear plans with
// collinear runs, offices and combs.
TEST(TwoPointVisibility, TriangulationWalkAgreesWithEdgeScan) {
  std::vector<Environment> envs;
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) envs.push_back(preimage::testing::snapped_random_environment(40 + 4 * seed, seed % 3, seed, 40.0));
  for (std::uint64_t seed : {5u, 6u}) envs.push_back(generators::random_rectilinear(9, 8, true, seed));
  envs.push_back(generators::office(2, 2));
  envs.push_back(Environment::make(generators::comb(5), {}));
  std::size_t seen = 0, hidden = 0, through_vertices = 0;
  for (std::size_t k = 0; k < envs.size(); ++k) {
    const Environment& env = envs[k];
    VisibilityIndex index(env);
    auto qs = preimage::testing::random_queries(env, 30, 15, 25, 10 + k);
    // Segments between vertices run along edges and through other vertices: keep many.
    for (std::size_t v = 0; v < env.num_vertices(); v += 3) qs.push_back({env.vertex(v), {Location::Kind::AtVertex, v}});
    for (auto& p : qs)
      for (auto& t : qs) {
        const bool want = visible(env, p.p, t.p);
        ASSERT_EQ(index.visible(p.p, t.p), want) << "environment " << k << ": " << format_point(p.p) << " -> " << format_point(t.p);
        (want ? seen : hidden)++;
        through_vertices += want && p.loc.kind == Location::Kind::AtVertex && t.loc.kind == Location::Kind::AtVertex;
      }
    // Points outside free space see nothing.
    const auto box = env.bbox();
    EXPECT_FALSE(index.visible(Point(box.xmin() - 1, box.ymin() - 1), qs.front().p));
  }
  EXPECT_GT(seen, 1000u);
  EXPECT_GT(hidden, 1000u);
  EXPECT_GT(through_vertices, 200u);
}
