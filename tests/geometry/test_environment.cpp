#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>

#include <cmath>
#include <limits>

using namespace preimage;
using namespace preimage::geometry;

namespace {
std::string error_of(Ring outer, std::vector<Ring> holes = {}) {
  try {
    Environment::make(std::move(outer), std::move(holes));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
}  // namespace

TEST(Environment, NormalisesOrientation) {
  Ring cw(square.rbegin(), square.rend());
  Ring hole_ccw{{2, 2}, {4, 2}, {4, 4}, {2, 4}};
  auto env = Environment::make(cw, {hole_ccw});
  EXPECT_EQ(env.num_holes(), 1u);
  EXPECT_EQ(env.exact_area(), ExactFT(96));
  for (std::size_t v = 0; v < env.num_vertices(); ++v) EXPECT_GE(env.turn(v), env.ring_of(v) == 0 ? 1 : -1);
  // Input indices survive the reversal.
  EXPECT_EQ(env.vertex(env.ring_begin(0) + 1), cw[env.input_index(env.ring_begin(0) + 1)]);
}

TEST(Environment, ErrorsNameTheElement) {
  EXPECT_EQ(error_of({{0, 0}, {1, 0}}), "boundary: a polygon needs at least 3 vertices, got 2");
  EXPECT_EQ(error_of({{0, 0}, {2, 0}, {0, 2}, {2, 2}}), "boundary: edges 1 and 3 intersect near (1, 1)");
  EXPECT_EQ(error_of({{0, 0}, {1, 0}, {1, 0}, {0, 1}}), "boundary: vertices 1 and 2 are repeated at (1, 0)");
  EXPECT_EQ(error_of({{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}, {0, 1}}),
            "boundary: vertex 1: number is not finite");
  // The supported range (geometry/coordinates.hpp): huge and subnormal values are refused
  // where they enter, naming the vertex (they crashed visibility and landmarks, issue 26).
  EXPECT_NE(error_of({{-1e308, -1e308}, {1e308, -1e308}, {1e308, 1e308}}).find("boundary: vertex 0: coordinate"), std::string::npos);
  EXPECT_NE(error_of({{0, 0}, {5e-324, 0}, {0, 1}}).find("boundary: vertex 1: coordinate is subnormal"), std::string::npos);
  EXPECT_EQ(error_of({{0, 0}, {1e12, 0}, {0, 1e-300}}), "");
  EXPECT_EQ(error_of(square, {{{20, 20}, {21, 20}, {21, 21}}}), "obstacles[0]: lies outside boundary");
  EXPECT_EQ(error_of(square, {{{1, 1}, {9, 1}, {9, 9}, {1, 9}}, {{2, 2}, {3, 2}, {3, 3}}}),
            "obstacles[1]: lies inside obstacles[0]");
  auto touching = error_of(square, {{{0, 5}, {5, 4}, {5, 6}}});
  EXPECT_NE(touching.find("obstacles[0] edge"), std::string::npos) << touching;
  EXPECT_NE(touching.find("touches boundary edge 3"), std::string::npos) << touching;
  auto holes_touch = error_of(square, {{{1, 1}, {3, 1}, {3, 3}}, {{3, 3}, {5, 3}, {5, 5}}});
  EXPECT_EQ(holes_touch, "obstacles[1] vertex 0 touches obstacles[0] vertex 2 at (3, 3)");
  auto bowtie_hole = error_of(square, {{{1, 1}, {3, 3}, {3, 1}, {1, 3}}});
  EXPECT_EQ(bowtie_hole, "obstacles[0]: edges 0 and 2 intersect near (2, 2)");
  auto spike = error_of({{0, 0}, {4, 0}, {2, 0}, {2, 3}});
  EXPECT_NE(spike.find("intersect"), std::string::npos) << spike;
}

TEST(Environment, NamedShapesAreValid) {
  EXPECT_NO_THROW(Environment::make(generators::star(7), {}));
  EXPECT_NO_THROW(Environment::make(generators::comb(10), {}));
  EXPECT_NO_THROW(Environment::make(generators::spiral(4.5), {}));
  auto office = generators::office(3, 4);
  EXPECT_GT(office.num_holes(), 10u);
}

TEST(Environment, RandomPolygonsAreSimpleUpToTenToTheFive) {
  for (std::size_t n : {3u, 4u, 10u, 1000u, 100000u}) {
    Ring r = generators::random_simple_polygon(n, n);
    ASSERT_EQ(r.size(), n);
    EXPECT_NO_THROW(Environment::make(r, {})) << n;
  }
  for (std::size_t h : {1u, 5u, 30u}) EXPECT_NO_THROW(generators::random_environment(2000, h, h));
}

TEST(Environment, EdgesKeepTheirInputNumbersWhenARingIsReversed) {
  // Boundary given clockwise and a hole given counter-clockwise: both get reversed.
  const Ring outer{{0, 0}, {0, 10}, {10, 10}, {10, 0}}, hole{{2, 2}, {4, 2}, {4, 4}, {2, 4}};
  auto env = Environment::make(outer, {hole});
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    const Ring& in = env.ring_of(e) == 0 ? outer : hole;
    const std::size_t k = env.input_edge_index(e);
    const Point &a = in[k], &b = in[(k + 1) % in.size()];
    const Point &p = env.vertex(e), &q = env.vertex(env.next(e));
    EXPECT_TRUE((a == p && b == q) || (a == q && b == p)) << "edge " << e << " reported as input edge " << k;
  }
}
