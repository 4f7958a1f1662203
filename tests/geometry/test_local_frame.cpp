// SPDX-License-Identifier: Apache-2.0
// The local frame: a plan far from the origin gives the answers it gives at the origin,
// moved (issue 49: a 10 x 10 room with a hole shifted by 1e10 had target area -32768 and
// 18 % covered, exit 0).
#include <preimage/coverage/coverage.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/local_frame.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace preimage::geometry {
namespace {

Environment room_with_hole(double off) {
  auto s = [&](double x, double y) { return Point(x + off, y + off); };
  return Environment::make({s(0, 0), s(10, 0), s(10, 10), s(0, 10)}, {{s(4, 4), s(4, 6), s(6, 6), s(6, 4)}});
}

TEST(LocalFrame, IdentityNearTheOriginExactTranslationFarFromIt) {
  EXPECT_TRUE(LocalFrame::of(room_with_hole(0)).identity());
  EXPECT_TRUE(LocalFrame::of(room_with_hole(100)).identity());  // 100 is less than 16 extents away
  for (const double off : {5e5, 4e6, 2e7, 1e10, 1e12 - 64}) {
    const Environment env = room_with_hole(off);
    const LocalFrame f = LocalFrame::of(env);
    ASSERT_FALSE(f.identity()) << off;
    const Environment local = f.to_local(env);
    const Environment origin = room_with_hole(0);
    for (std::size_t v = 0; v < env.num_vertices(); ++v) EXPECT_EQ(local.vertex(v), origin.vertex(v)) << off;
    EXPECT_GE(f.margin(), 2 * (std::nextafter(off, 2 * off) - off)) << off;  // covers rounding back
  }
}

// The canonical frame is the same for every exact translate of a plan, near the origin as
// well as far from it (with of() alone, merged bends differed between office 302 as is and
// shifted by 4e6, as only the shifted plan was translated); where the translation to the box
// would round, it is of()'s.
TEST(LocalFrame, EveryExactTranslateGetsTheSameCanonicalEnvironment) {
  EXPECT_TRUE(LocalFrame::canonical(room_with_hole(0)).identity());
  const Environment origin = room_with_hole(0);
  for (const double off : {0.375, 100.0, -7.25, 5e5, 4e6, 2e7, 1e10, 1e12 - 64}) {
    const Environment env = room_with_hole(off);
    const LocalFrame f = LocalFrame::canonical(env);
    ASSERT_FALSE(f.identity()) << off;
    const Environment local = f.to_local(env);
    for (std::size_t v = 0; v < env.num_vertices(); ++v) EXPECT_EQ(local.vertex(v), origin.vertex(v)) << off;
    EXPECT_GE(f.margin(), 2 * (std::nextafter(std::fabs(off), 2 * std::fabs(off)) - std::fabs(off))) << off;
  }
  // 1 - 1e-20 is not a double: no translation to 1e-20 (near 0, of() is the identity).
  const Environment inexact = Environment::make({Point(1e-20, 0), Point(1, 0), Point(1, 1), Point(1e-20, 1)}, {});
  EXPECT_EQ(LocalFrame::canonical(inexact).dx(), 0);
  EXPECT_EQ(LocalFrame::canonical(inexact).dy(), 0);
}

TEST(LocalFrame, AreasDoNotDependOnWhereThePlanSits) {
  for (const double off : {0.0, 5e5, 4e6, 2e7, 1e10, 1e12 - 64}) EXPECT_EQ(room_with_hole(off).area(), 96) << off;
}

TEST(LocalFrame, ConfigurationSpaceFarFromTheOriginIsTheOriginsMoved) {
  const Environment origin = room_with_hole(0);
  const ConfigurationSpace at_origin(origin, 0.25);
  for (const double off : {5e5, 1e10}) {
    const Environment env = room_with_hole(off);
    const ConfigurationSpace cs(env, 0.25);
    ASSERT_EQ(cs.components().size(), at_origin.components().size());
    EXPECT_NEAR(cs.components()[0].area(), at_origin.components()[0].area(), 1e-9 * 100 + 64 * LocalFrame::of(env).margin()) << off;
    EXPECT_EQ(cs.components()[0].num_vertices(), at_origin.components()[0].num_vertices()) << off;
  }
}

// The case of the issue: cover's path at 1e10 is the origin's moved, within the margins
// that rounding back needs; the target area is the origin's.
TEST(LocalFrame, CoverageFarFromTheOriginIsTheOriginsMoved) {
  coverage::CoverageOptions o;
  o.robot_radius = 0.25, o.angle_deg = 0;
  const Environment origin = room_with_hole(0);
  const auto a = coverage::plan_coverage(origin, o);
  for (const double off : {5e5, 1e10}) {
    const Environment env = room_with_hole(off);
    const auto b = coverage::plan_coverage(env, o);
    const double tol = 16 * LocalFrame::of(env).margin();
    ASSERT_EQ(a.path.size(), b.path.size()) << off;
    for (std::size_t i = 0; i < a.path.size(); ++i) {
      EXPECT_NEAR(b.path[i].x() - off, a.path[i].x(), tol) << off << " point " << i;
      EXPECT_NEAR(b.path[i].y() - off, a.path[i].y(), tol) << off << " point " << i;
    }
    EXPECT_EQ(a.laps, b.laps);
    EXPECT_NEAR(b.target_area, a.target_area, 1e-9 * a.target_area) << off;
    EXPECT_NEAR(coverage::measure_coverage(env, b).covered_fraction, coverage::measure_coverage(origin, a).covered_fraction, 1e-3) << off;
  }
}

}  // namespace
}  // namespace preimage::geometry
