// SPDX-License-Identifier: Apache-2.0
// The generalized Voronoi diagram against CGAL's Segment_Delaunay_graph_2 (test-only GPL
// oracle) on the snapped environment: same topology (chains between the same obstacle
// pairs, nodes matched one to one within the resolution); every edge point's clearance
// equals the brute-force distance to each of its two obstacles; saddles are minima of D
// along their edge, maxima are maxima along theirs; errors for inputs finer than the grid.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/gvd.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/scene.hpp>

#include "support/gvd_oracle.hpp"

#include <cmath>
#include <random>

using namespace preimage;
using namespace preimage::geometry;
using preimage::testing::PlainGvdEdge;

namespace {

std::vector<PlainGvdEdge> plain_edges(const GeneralizedVoronoiDiagram& g) {
  std::vector<PlainGvdEdge> out;
  for (const auto& e : g.edges()) out.push_back({g.vertices()[e.from].p, g.vertices()[e.to].p, {e.sites[0].obstacle, e.sites[1].obstacle}});
  return out;
}

std::vector<std::uint32_t> ring_obstacles(const GeneralizedVoronoiDiagram& g, const Environment& env) {
  std::vector<std::uint32_t> r;
  for (std::size_t i = 0; i < env.num_rings(); ++i) r.push_back(g.obstacle_of_ring(i));
  return r;
}

// Ours against CGAL's SDG on the same snapped segments.
void expect_same_as_cgal(const Environment& env, const std::string& what) {
  SCOPED_TRACE(what);
  const auto g = GeneralizedVoronoiDiagram::build(env);
  const double res = g.resolution();
  const auto theirs = preimage::testing::cgal_gvd_edges(env, g.snapped_vertices(), ring_obstacles(g, env));
  const auto a = preimage::testing::gvd_topology(plain_edges(g), res / 64);
  const auto b = preimage::testing::gvd_topology(theirs, res / 64);
  EXPECT_EQ(a.problem, "");
  EXPECT_EQ(b.problem, "");
  EXPECT_EQ(a.chains, b.chains) << g.edges().size() << " edges against " << theirs.size();
  EXPECT_EQ(preimage::testing::match_nodes(a, b, res, 3), "") << "branch nodes (degree >= 3)";
  EXPECT_EQ(preimage::testing::match_nodes(a, b, res, 0), "") << "all nodes";
  if (env.num_holes() > 0 && g.num_obstacles() > 1) {
    EXPECT_GT(g.edges().size(), 0u);
  }
}

// Clearance along every edge: equidistant to its two obstacles, and nothing nearer.
void expect_clearance(const GeneralizedVoronoiDiagram& g, const std::string& what) {
  SCOPED_TRACE(what);
  const double tol = 4 * g.resolution();
  std::size_t failures = 0;
  for (const auto& e : g.edges()) {
    for (std::size_t k = 0; k < e.polyline.size(); ++k) {
      const Point& p = e.polyline[k];
      const double d0 = g.distance_to_obstacle(p, e.sites[0].obstacle), d1 = g.distance_to_obstacle(p, e.sites[1].obstacle);
      const double D = g.clearance_brute_force(p);
      if (std::fabs(d0 - d1) > tol || std::fabs(D - d0) > tol || std::fabs(g.clearance(p) - D) > 1e-12 * (1 + D)) {
        if (++failures < 5) ADD_FAILURE() << "edge point " << format_point(p) << ": obstacles at " << d0 << " and " << d1 << ", D = " << D;
      }
      if (k == 0) {
        EXPECT_NEAR(e.clearance_from, D, tol);
      }
      if (k + 1 == e.polyline.size()) {
        EXPECT_NEAR(e.clearance_to, D, tol);
      }
    }
  }
  for (const auto& v : g.vertices()) EXPECT_NEAR(v.clearance, g.clearance_brute_force(v.p), tol);
  EXPECT_EQ(failures, 0u);
}

// Saddles: D along the saddle's edge (or its vertex's edges) is nowhere below D there, the
// two nearest points lie at distance D on opposite sides (interior and plateau saddles).
// Maxima: D along every incident edge is nowhere above.
void expect_critical_points(const Environment& env, const GeneralizedVoronoiDiagram& g, const std::string& what) {
  SCOPED_TRACE(what);
  const double tol = 4 * g.resolution();
  auto edge_points = [&](const GvdCriticalPoint& c) {
    std::vector<Point> pts;
    for (std::uint32_t i = 0; i < g.edges().size(); ++i) {
      const auto& e = g.edges()[i];
      if (i == c.edge || (c.vertex != UINT32_MAX && (e.from == c.vertex || e.to == c.vertex))) pts.insert(pts.end(), e.polyline.begin(), e.polyline.end());
    }
    return pts;
  };
  for (const auto& s : g.saddles()) {
    const double D = g.clearance_brute_force(s.p);
    EXPECT_NEAR(D, s.clearance, tol);
    const auto pts = edge_points(s);
    ASSERT_FALSE(pts.empty());
    for (const Point& q : pts) EXPECT_GE(g.clearance_brute_force(q), D - tol) << "saddle " << format_point(s.p) << " against " << format_point(q);
    EXPECT_NEAR(std::hypot(s.p.x() - s.nearest[0].x(), s.p.y() - s.nearest[0].y()), D, tol);
    EXPECT_NEAR(std::hypot(s.p.x() - s.nearest[1].x(), s.p.y() - s.nearest[1].y()), D, tol);
    if (s.kind != GvdCriticalPoint::Kind::Vertex) {
      // opposite: p is the midpoint of the two nearest points
      EXPECT_NEAR((s.nearest[0].x() + s.nearest[1].x()) / 2, s.p.x(), tol);
      EXPECT_NEAR((s.nearest[0].y() + s.nearest[1].y()) / 2, s.p.y(), tol);
    }
  }
  // D along an edge is convex, so a maximum is local: compare with the GVD points within
  // rho of the vertex (straight edges: the point at rho; curved: the samples, dense here).
  const auto box = env.bbox();
  const double extent = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin()), rho = extent * 1e-3;
  const auto dense = GeneralizedVoronoiDiagram::build(env, {extent * 1e-8});
  ASSERT_EQ(dense.maxima().size(), g.maxima().size());
  for (const auto& m : dense.maxima()) {
    const double D = dense.clearance_brute_force(m.p);
    EXPECT_NEAR(D, m.clearance, tol);
    std::size_t compared = 0;
    for (std::uint32_t i = 0; i < dense.edges().size(); ++i) {
      const auto& e = dense.edges()[i];
      if (e.from != m.vertex && e.to != m.vertex) continue;
      // up to half-way to the edge's interior minimum (its saddle), if it has one
      double r = rho;
      for (const auto& s : dense.saddles())
        if (s.edge == i) r = std::min(r, std::hypot(s.p.x() - m.p.x(), s.p.y() - m.p.y()) / 2);
      std::vector<Point> near;
      if (!e.curved) {
        const Point& a = e.from == m.vertex ? e.polyline.front() : e.polyline.back();
        const Point& b = e.from == m.vertex ? e.polyline.back() : e.polyline.front();
        const double len = std::hypot(b.x() - a.x(), b.y() - a.y()), t = std::min(r, len / 2) / len;
        near.emplace_back(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
      } else {
        for (const Point& q : e.polyline)
          if (std::hypot(q.x() - m.p.x(), q.y() - m.p.y()) <= r) near.push_back(q);
      }
      for (const Point& q : near) {
        ++compared;
        EXPECT_LE(dense.clearance_brute_force(q), D + tol) << "maximum " << format_point(m.p) << " against " << format_point(q);
      }
    }
  }
}

void check_all(const Environment& env, const std::string& what) {
  expect_same_as_cgal(env, what);
  const auto g = GeneralizedVoronoiDiagram::build(env);
  expect_clearance(g, what);
  expect_critical_points(env, g, what);
}

Environment houseexpo(const std::string& name) {
  const std::string path = std::string(PREIMAGE_FLOORPLANS) + "/" + name;
  return *scene::import_houseexpo(scene::read_file(path), path).environment;
}

// A floor plan with square pillars of side `side` at random free places (the plans have no holes).
Environment with_pillars(const Environment& plan, std::size_t count, double side, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto box = plan.bbox();
  std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax());
  std::vector<Ring> holes;
  for (std::size_t tries = 0; holes.size() < count && tries < 50 * count; ++tries) {
    const double x = std::round(ux(rng) * 100) / 100, y = std::round(uy(rng) * 100) / 100;
    Ring sq{{x, y}, {x, y + side}, {x + side, y + side}, {x + side, y}};
    auto trial = holes;
    trial.push_back(sq);
    try {
      Environment::make(plan.ring(0), trial);
      holes = trial;
    } catch (const InputError&) {
    }
  }
  return Environment::make(plan.ring(0), holes);
}

}  // namespace

TEST(Gvd, DiamondInASquareHasFourSaddlesAndFourMaxima) {
  const auto env = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{5, 7}, {7, 5}, {5, 3}, {3, 5}}});
  const auto g = GeneralizedVoronoiDiagram::build(env);
  EXPECT_EQ(g.num_obstacles(), 2u);
  EXPECT_EQ(g.resolution_exponent(), 4 - 29);
  ASSERT_EQ(g.saddles().size(), 4u);
  for (const auto& s : g.saddles()) {
    EXPECT_EQ(s.kind, GvdCriticalPoint::Kind::Interior);
    EXPECT_NEAR(s.clearance, 1.5, 1e-9);
    EXPECT_NEAR(std::fabs(s.p.x() - 5) + std::fabs(s.p.y() - 5), 3.5, 1e-9);
  }
  ASSERT_EQ(g.maxima().size(), 4u);
  const double t = (12 + 10 * std::sqrt(2.0)) / (2 + std::sqrt(2.0));  // on the diagonal x = y
  for (const auto& m : g.maxima()) {
    EXPECT_NEAR(std::fabs(m.p.x() - 5), t - 5, 1e-9);
    EXPECT_NEAR(m.clearance, 10 - t, 1e-9);
  }
  // a closed chain around the diamond
  EXPECT_EQ(g.obstacle_pairs().size(), 1u);
  for (const auto& v : g.vertices()) EXPECT_EQ(v.degree, 2u);
  check_all(env, "diamond");
}

TEST(Gvd, DoorBetweenParallelWallEndsIsAPlateauSaddle) {
  // two wall blocks leaving a door of width 2 between their parallel end faces
  const auto env = Environment::make({{0, 0}, {20, 0}, {20, 10}, {0, 10}}, {{{2, 4}, {2, 6}, {9, 6}, {9, 4}}, {{11, 4}, {11, 6}, {18, 6}, {18, 4}}});
  const auto g = GeneralizedVoronoiDiagram::build(env);
  EXPECT_EQ(g.num_obstacles(), 3u);
  bool door = false;
  for (const auto& s : g.saddles())
    if (s.kind == GvdCriticalPoint::Kind::Plateau && std::fabs(s.p.x() - 10) < 1e-9 && std::fabs(s.p.y() - 5) < 1e-9) door = std::fabs(s.clearance - 1.0) < 1e-9;
  EXPECT_TRUE(door);
  check_all(env, "door");
}

TEST(Gvd, PlateauSplitByCollinearVerticesIsOneSaddle) {
  // the floor has a straight vertex at (6, 0) under a partition wall: two parallel edges of
  // the GVD at D = 1.25 in a row, one saddle in the middle of the run
  const auto env = Environment::make({{0, 0}, {6, 0}, {12, 0}, {12, 8}, {0, 8}}, {{{5.8, 2.5}, {5.8, 7}, {6.2, 7}, {6.2, 2.5}}});
  const auto g = GeneralizedVoronoiDiagram::build(env);
  std::size_t found = 0;
  for (const auto& s : g.saddles())
    if (std::fabs(s.p.y() - 1.25) < 1e-6) {
      ++found;
      EXPECT_EQ(s.kind, GvdCriticalPoint::Kind::Plateau);
      EXPECT_NEAR(s.p.x(), 6, 1e-6);
      EXPECT_NEAR(s.clearance, 1.25, 1e-6);
    }
  EXPECT_EQ(found, 1u);
  check_all(env, "split plateau");
}

TEST(Gvd, SimplePolygonHasNoGvd) {
  // one obstacle: nothing is equidistant to two different ones
  const auto env = Environment::make(generators::star(7), {});
  const auto g = GeneralizedVoronoiDiagram::build(env);
  EXPECT_EQ(g.num_obstacles(), 1u);
  EXPECT_TRUE(g.edges().empty());
  EXPECT_TRUE(g.saddles().empty());
}

TEST(Gvd, RandomEnvironmentsMatchCgal) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    check_all(generators::random_environment(200, 5, seed), "random 200/5 seed " + std::to_string(seed));
    check_all(generators::random_environment(1000, 20, seed), "random 1000/20 seed " + std::to_string(seed));
  }
  check_all(generators::random_environment(4000, 50, 7), "random 4000/50");
}

TEST(Gvd, OfficesMatchCgal) {
  check_all(generators::office(2, 2), "office 2x2");
  check_all(generators::office(4, 3), "office 4x3");
  check_all(generators::office(6, 6), "office 6x6");
  for (std::uint64_t seed = 1; seed <= 3; ++seed) check_all(generators::random_rectilinear(12, 10, true, seed), "rectilinear seed " + std::to_string(seed));
}

TEST(Gvd, TouchingSquaresMergeIntoObstacles) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    for (bool sheared : {false, true}) {
      const auto env = generators::touching_squares(8, 0.6, seed, sheared);
      ASSERT_TRUE(env.has_contacts());
      const auto g = GeneralizedVoronoiDiagram::build(env);
      EXPECT_LT(g.num_obstacles(), env.num_rings());
      // rings at a contact are one obstacle
      for (std::size_t v = 0; v < env.num_vertices(); ++v)
        EXPECT_EQ(g.obstacle_of_ring(env.ring_of(v)), g.obstacle_of_ring(env.ring_of(env.same_point_next(v))));
      check_all(env, "touching squares seed " + std::to_string(seed) + (sheared ? " sheared" : ""));
    }
}

TEST(Gvd, FloorPlansMatchCgal) {
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"}) {
    const Environment plan = houseexpo(name);
    const auto plain = GeneralizedVoronoiDiagram::build(plan);
    EXPECT_TRUE(plain.edges().empty()) << name << ": no holes, one obstacle";
    expect_same_as_cgal(plan, name);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const Environment env = with_pillars(plan, 12, 0.3, seed);
      ASSERT_GE(env.num_holes(), 6u);
      check_all(env, std::string(name) + " with pillars, seed " + std::to_string(seed));
    }
  }
}

TEST(Gvd, ClearanceGridEqualsBruteForce) {
  const auto env = generators::random_environment(2000, 20, 3);
  const auto g = GeneralizedVoronoiDiagram::build(env);
  std::mt19937_64 rng(5);
  const auto box = env.bbox();
  std::uniform_real_distribution<double> ux(box.xmin() - 0.1, box.xmax() + 0.1), uy(box.ymin() - 0.1, box.ymax() + 0.1);
  for (int i = 0; i < 2000; ++i) {
    const Point p(ux(rng), uy(rng));
    EXPECT_EQ(g.clearance(p), g.clearance_brute_force(p)) << format_point(p);
  }
}

TEST(Gvd, InputFinerThanTheGridIsAnInputError) {
  // 2^30 wide: the grid is 4, and the hole's vertices 1 apart collapse
  const double W = std::ldexp(1.0, 30);
  try {
    GeneralizedVoronoiDiagram::build(Environment::make({{0, 0}, {W, 0}, {W, W}, {0, W}}, {{{100, 100}, {101, 100}, {100, 101}}}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("gvd: snapped to the grid 2^2 (4)"), std::string::npos) << m;
    EXPECT_NE(m.find("obstacles[0] edge"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos);
  }
  // distinct snapped points that become one: a vertex lands on another ring's vertex
  try {
    GeneralizedVoronoiDiagram::build(Environment::make({{0, 0}, {W, 0}, {W, W}, {0, W}},
                                                       {{{100, 100}, {200, 100}, {200, 200}}, {{201, 201}, {300, 201}, {300, 300}}}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("meet other than at a shared endpoint"), std::string::npos) << e.what();
  }
}

TEST(Gvd, CurvedEdgesAreSampledWithinTheDeviation) {
  const auto env = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{5, 7}, {7, 5}, {5, 3}, {3, 5}}});
  for (double dev : {0.1, 0.01, 0.001}) {
    const auto g = GeneralizedVoronoiDiagram::build(env, {dev});
    EXPECT_EQ(g.max_deviation(), dev);
    std::size_t curved = 0;
    for (const auto& e : g.edges()) {
      if (!e.curved) continue;
      ++curved;
      // the chord midpoints are within dev of the arc: D there differs from the arc's by at most dev
      for (std::size_t k = 0; k + 1 < e.polyline.size(); ++k) {
        const Point m((e.polyline[k].x() + e.polyline[k + 1].x()) / 2, (e.polyline[k].y() + e.polyline[k + 1].y()) / 2);
        const double d0 = g.distance_to_obstacle(m, e.sites[0].obstacle), d1 = g.distance_to_obstacle(m, e.sites[1].obstacle);
        EXPECT_LE(std::fabs(d0 - d1), 2 * dev + 1e-9);
      }
    }
    EXPECT_GT(curved, 0u);
  }
}
