// Structural checks of the library's own constrained Delaunay triangulation on random,
// named, degenerate (axis-aligned, collinear) and real floor-plan environments.
#include <gtest/gtest.h>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/triangulation.hpp>

#include "support/cgal_oracle.hpp"
#include "support/large_scenes.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <random>

using namespace preimage::geometry;

namespace {
void expect_valid(const Environment& env, const std::string& what) {
  Triangulation t(env);
  EXPECT_NO_THROW(t.check()) << what;
  EXPECT_EQ(t.non_delaunay_edges(), 0u) << what;
}

// Random orthogonal polygon on a coarse grid: union of cells grown from one cell, traced.
// Almost every vertex shares x or y with many others; long collinear runs.
Ring staircase(std::mt19937_64& rng, int steps) {
  Ring up, down;
  double x = 0, y = 0, h = 5;
  std::uniform_int_distribution<int> d(1, 3);
  for (int i = 0; i < steps; ++i) {
    up.emplace_back(x, y + h);
    down.emplace_back(x, y);
    x += d(rng);
    up.emplace_back(x, y + h);
    down.emplace_back(x, y);
    y += d(rng) - 2;  // equal heights are common: collinear vertices
  }
  Ring r(down.begin(), down.end());
  r.insert(r.end(), up.rbegin(), up.rend());
  // Drop exact duplicates produced by zero steps.
  Ring clean;
  for (auto& p : r)
    if (clean.empty() || clean.back() != p) clean.push_back(p);
  if (clean.front() == clean.back()) clean.pop_back();
  return clean;
}
}  // namespace

TEST(Triangulation, RandomPolygons) {
  for (std::uint64_t s = 1; s <= 60; ++s) expect_valid(Environment::make(generators::random_simple_polygon(5 + s * 7, s), {}), "seed " + std::to_string(s));
  expect_valid(Environment::make(generators::random_simple_polygon(20000, 99), {}), "20000 vertices");
}

TEST(Triangulation, RandomEnvironmentsWithHoles) {
  for (std::uint64_t s = 1; s <= 20; ++s) expect_valid(generators::random_environment(300 + 50 * s, 1 + s % 9, s), "seed " + std::to_string(s));
}

TEST(Triangulation, IntegerSnappedEnvironments) {
  // Snapping to a grid creates collinear triples and equal coordinates everywhere.
  for (std::uint64_t s = 1; s <= 40; ++s)
    expect_valid(preimage::testing::snapped_random_environment(30 + s, s % 3, s, 40.0), "seed " + std::to_string(s));
}

TEST(Triangulation, AxisAlignedAndNamedShapes) {
  expect_valid(generators::office(3, 5), "office 3x5");
  expect_valid(generators::office(1, 1), "office 1x1");
  expect_valid(Environment::make(generators::comb(25), {}), "comb");
  expect_valid(Environment::make(generators::spiral(6), {}), "spiral");
  expect_valid(Environment::make(generators::star(40), {}), "star");
  std::mt19937_64 rng(7);
  for (int i = 0; i < 50; ++i) expect_valid(Environment::make(staircase(rng, 3 + i), {}), "staircase " + std::to_string(i));
  // Square with collinear vertices on every side and a hole with them too.
  Ring outer{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3}, {0, 2}, {0, 1}};
  Ring hole{{1, 1}, {1.5, 1}, {2, 1}, {2, 2}, {1, 2}};
  expect_valid(Environment::make(outer, {hole}), "collinear square");
}

TEST(Triangulation, CountsMatchEulerOnHoles) {
  auto env = generators::random_environment(1000, 12, 3);
  Triangulation t(env);
  EXPECT_EQ(t.size(), env.num_vertices() + 2 * env.num_holes() - 2);
}

// The ~10^5-vertex scenes of the scale tests (issue 26): a monotone partition with Lawson
// flips afterwards needed quadratically many flips on the square's collinear runs (a
// minute). The check compares the triangles' exact area with the environment's, two sums
// 10^5 terms long (formed in the exact number type, not as lazy chains that overflowed the
// stack when evaluated).
TEST(Triangulation, ScaleScenesOfTenToTheFiveVertices) {
  for (const auto& s : preimage::testing::large_scenes()) {
    const Environment& env = *s.scene.environment;
    Triangulation t(env);
    EXPECT_NO_THROW(t.check()) << s.name;
    EXPECT_EQ(t.non_delaunay_edges(), 0u) << s.name;
  }
}

// Vertices in line and on common circles: points landing on edges during insertion (split
// into four), edges forced through runs of collinear vertices, cocircular cavities.
TEST(Triangulation, CollinearChainsAndCocircularVertices) {
  // A zigzag floor under a ceiling of collinear vertices, floor and ceiling on one grid.
  Ring zig;
  for (int i = 0; i <= 40; ++i) zig.emplace_back(i, i % 2 ? 1.0 : 0.0);
  for (int i = 40; i >= 0; --i) zig.emplace_back(i, 5.0);
  expect_valid(Environment::make(zig, {}), "zigzag under a collinear ceiling");
  // Many vertices on one diagonal line.
  Ring diag;
  for (int i = 0; i <= 30; ++i) diag.emplace_back(i, i);
  diag.emplace_back(30, 40);
  for (int i = 29; i >= 0; --i) diag.emplace_back(i, 40 - (i % 3 == 0 ? 0.0 : 0.5));
  expect_valid(Environment::make(diag, {}), "diagonal run");
  // Twelve integer points of the circle of radius 5 (all cocircular) around the same
  // points halved: every empty-circle test on a rim is a tie.
  Ring outer, hole;
  const double rim[12][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for (auto& p : rim) outer.emplace_back(p[0], p[1]);
  for (int k = 11; k >= 0; --k) hole.emplace_back(rim[k][0] / 2, rim[k][1] / 2);
  expect_valid(Environment::make(outer, {hole}), "cocircular rims");
  // Fan apexes in line with other vertices of the chain.
  Ring fan{{0, 0}, {10, 0}, {10, 10}, {6, 6}, {5, 7}, {4, 4}, {3, 5}, {2, 2}, {0, 10}};
  expect_valid(Environment::make(fan, {}), "apexes in line with the chain");
}

// Against CGAL's constrained Delaunay triangulation (GPL, a test oracle): random polygons
// and environments with holes have no four cocircular vertices, so the constrained
// Delaunay triangulation is unique and every edge of ours must be one of CGAL's.
TEST(Triangulation, EdgesAreCgalsConstrainedDelaunayEdges) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag>;
  auto compare = [](const Environment& env, const std::string& what) {
    CDT cdt;
    std::vector<CDT::Vertex_handle> vh;
    for (std::size_t v = 0; v < env.num_vertices(); ++v) vh.push_back(cdt.insert(env.vertex(v)));
    for (std::size_t v = 0; v < env.num_vertices(); ++v) cdt.insert_constraint(vh[v], vh[env.next(v)]);
    Triangulation t(env);
    std::size_t missing = 0;
    for (const auto& tr : t.triangles())
      for (int i = 0; i < 3; ++i) missing += !cdt.is_edge(vh[tr.v[i]], vh[tr.v[(i + 1) % 3]]);
    EXPECT_EQ(missing, 0u) << what;
  };
  for (std::uint64_t s = 1; s <= 30; ++s)
    compare(Environment::make(generators::random_simple_polygon(10 + 40 * s, s), {}), "polygon seed " + std::to_string(s));
  for (std::uint64_t s = 1; s <= 10; ++s)
    compare(generators::random_environment(500 + 100 * s, 2 + s, s), "environment seed " + std::to_string(s));
}
