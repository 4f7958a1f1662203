// One test per bug found, each on the input that exposed it (tests/fixtures/).
#include <gtest/gtest.h>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/scene.hpp>

#include <random>

using namespace preimage;
using geometry::Location;
using geometry::Point;

// locate() tested "q on the closed edge" before "q is the next vertex", so the apex
// (2, 5), reached as the end of edge 2 (4,3)->(2,5), came back as OnEdge.
TEST(Regression, LocateVertexAtEdgeEndIsAVertex) {
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/locate_vertex_at_edge_end.json");
  const auto& env = s.require_environment();
  for (std::size_t v = 0; v < env.num_vertices(); ++v) {
    const Location loc = geometry::locate(env, env.vertex(v));
    EXPECT_EQ(loc.kind, Location::Kind::AtVertex) << "vertex " << v;
    EXPECT_EQ(loc.index, v);
  }
  // And the visibility index agrees, so vertex queries take the fan-expansion path.
  const geometry::VisibilityIndex index(env);
  EXPECT_EQ(index.locate(Point(2, 5)).kind, Location::Kind::AtVertex);
  EXPECT_EQ(index.compute(Point(2, 5)).location.kind, Location::Kind::AtVertex);
}

// random_simple_polygon drew its points as Point(coord(rng), coord(rng)): g++ evaluates the
// two arguments right to left, clang++ left to right, so a seed gave another polygon under
// each compiler (under clang++ this polygon started at (0x1.05be8b80e9834p-2,
// 0x1.623a331ce3d18p-1)). geometry::random_point draws y, then x, in sequenced statements:
// the order g++ always used, so every seed-pinned result made with g++ holds. Pinned as
// hex-float literals, which are exact.
TEST(Regression, RandomPolygonOfASeedIsTheSameUnderEveryCompiler) {
  const geometry::Ring r = geometry::generators::random_simple_polygon(12, 2026);
  ASSERT_EQ(r.size(), 12u);
  const Point want[] = {{0x1.dac5a5c9cf03fp-3, 0x1.292caf9fcc974p-1},
                        {0x1.b23e69c1eda14p-5, 0x1.86d45e76b5a25p-1},
                        {0x1.50d957fd93779p-2, 0x1.2da5c79d38f6fp-2},
                        {0x1.f02e7914f11c1p-2, 0x1.76e040f140725p-2}};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(r[i].x(), want[i].x()) << "vertex " << i;
    EXPECT_EQ(r[i].y(), want[i].y()) << "vertex " << i;
  }
  // The helper itself: y is the first draw, x the second.
  std::mt19937_64 rng(5), ref(5);
  std::uniform_real_distribution<double> u(0, 1);
  const double first = u(ref), second = u(ref);
  const Point p = geometry::random_point(rng, u);
  EXPECT_EQ(p.y(), first);
  EXPECT_EQ(p.x(), second);
}
