// Coverage paths: an independent rasterised oracle (every free point farther than r from
// the boundary lies within r of the path), exact collision checks, and the 6.2.5 bound.
#include <gtest/gtest.h>
#include <preimage/decompose/coverage.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/scene/import.hpp>

#include <cmath>
#include <fstream>

using namespace preimage;
using geometry::Environment;
using geometry::Point;

namespace {
double seg_dist(const Point& p, const Point& a, const Point& b) {
  const double vx = b.x() - a.x(), vy = b.y() - a.y(), wx = p.x() - a.x(), wy = p.y() - a.y();
  const double l2 = vx * vx + vy * vy;
  const double t = l2 == 0 ? 0 : std::clamp((wx * vx + wy * vy) / l2, 0.0, 1.0);
  return std::hypot(wx - t * vx, wy - t * vy);
}

void check(const Environment& env, double r, std::optional<double> angle, const std::string& what, int raster = 120) {
  decompose::CoverageOptions o{r, std::nullopt, angle};
  const auto rep = decompose::plan_coverage(env, o);
  ASSERT_GE(rep.path.size(), 2u) << what;
  EXPECT_LE(rep.length, rep.bound) << what;
  // Exact: every segment stays in closed free space, at every angle.
  for (std::size_t i = 0; i + 1 < rep.path.size(); ++i)
    ASSERT_TRUE(geometry::visible(env, rep.path[i], rep.path[i + 1])) << what << ": segment " << i << " crosses an obstacle";
  // Rasterised oracle, in double with a relative margin.
  const auto box = env.bbox();
  const double margin = 1e-9 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  int tested = 0;
  for (int i = 0; i <= raster; ++i)
    for (int j = 0; j <= raster; ++j) {
      const Point p(box.xmin() + (box.xmax() - box.xmin()) * i / raster, box.ymin() + (box.ymax() - box.ymin()) * j / raster);
      if (geometry::locate(env, p).kind != geometry::Location::Kind::Interior) continue;
      double to_boundary = INFINITY;
      for (std::size_t e = 0; e < env.num_vertices(); ++e)
        to_boundary = std::min(to_boundary, seg_dist(p, env.vertex(e), env.vertex(env.next(e))));
      if (to_boundary <= r + margin) continue;
      double to_path = INFINITY;
      for (std::size_t k = 0; k + 1 < rep.path.size() && to_path > r; ++k) to_path = std::min(to_path, seg_dist(p, rep.path[k], rep.path[k + 1]));
      ASSERT_LE(to_path, r + margin) << what << ": " << geometry::format_point(p) << " is not covered";
      ++tested;
    }
  EXPECT_GT(tested, 100) << what;
}
}  // namespace

TEST(Coverage, RoomWithObstaclesAtQuarterTurns) {
  auto env = Environment::make({{0, 0}, {12, 0}, {12, 8}, {0, 8}},
                               {{{2, 2}, {3, 2}, {3, 3}, {2, 3}}, {{8, 5}, {9.5, 5}, {9.5, 6.5}, {8, 6.5}}, {{5.8, 2.5}, {6.2, 2.5}, {6.2, 7}, {5.8, 7}}});
  for (double a : {0.0, 90.0, 180.0, 270.0}) check(env, 0.3, a, "gallery at " + std::to_string(a));
}

TEST(Coverage, RandomEnvironmentsAndFloorPlans) {
  for (std::uint64_t s = 1; s <= 4; ++s) check(geometry::generators::random_environment(80 + 20 * s, s % 4, s), 2.0, 0.0, "seed " + std::to_string(s));
  check(geometry::generators::office(2, 2), 0.2, 90.0, "office", 100);
  check(Environment::make(geometry::generators::comb(5), {}), 0.25, 0.0, "comb");
}

TEST(Coverage, OtherAnglesAndAutomaticChoice) {
  auto env = geometry::generators::random_environment(120, 2, 9);
  check(env, 2.5, 35.0, "35 degrees");
  check(env, 2.5, std::nullopt, "auto");
  auto rep_auto = decompose::plan_coverage(env, {2.5, std::nullopt, std::nullopt});
  auto rep_0 = decompose::plan_coverage(env, {2.5, std::nullopt, 0.0});
  EXPECT_LE(rep_auto.length, rep_0.length);  // 0 degrees is among the candidates
}

TEST(Coverage, RejectsBadInput) {
  auto env = geometry::generators::office(1, 1);
  EXPECT_THROW(decompose::plan_coverage(env, {0.0, std::nullopt, 0.0}), InputError);
  EXPECT_THROW(decompose::plan_coverage(env, {0.2, Point(-5, -5), 0.0}), InputError);
  // A start point is where the path begins.
  auto rep = decompose::plan_coverage(env, {0.2, Point(1, 1), 0.0});
  EXPECT_EQ(rep.path.front(), Point(1, 1));
}

TEST(Coverage, RealHouseExpoFloorPlan) {
  const std::string path = std::string(PREIMAGE_SHARED_DATA) + "/floorplans/house_expo_room_0000.json";
  if (!std::ifstream(path)) GTEST_SKIP() << "shared data not found beside the checkout: " << path;
  const auto s = scene::import_houseexpo(scene::read_file(path), path);
  check(*s.environment, 0.2, 0.0, "house_expo_room_0000", 150);
  check(*s.environment, 0.2, 90.0, "house_expo_room_0000 at 90", 150);
}

TEST(Boustrophedon, StackedVerticalVerticesFixture) {
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/stacked_vertical_vertices.json");
  const auto& env = *s.environment;
  decompose::BoustrophedonDecomposition b(env);
  EXPECT_EQ(b.cells().size(), b.critical_slices().size() + env.num_holes() - 1);
  check(env, 0.15, 0.0, "stacked vertical vertices");
}
