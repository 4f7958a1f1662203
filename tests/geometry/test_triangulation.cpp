// Structural checks of the library's own constrained Delaunay triangulation on random,
// named, degenerate (axis-aligned, collinear) and real floor-plan environments.
#include <gtest/gtest.h>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/triangulation.hpp>

#include "support/cgal_oracle.hpp"

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
