// Boustrophedon cells and the Reeb graph: Euler's formula (6.2.5), areas, degenerate
// critical points (vertical walls), and every sweep angle.
#include <gtest/gtest.h>
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/geometry/generators.hpp>

#include "support/cgal_oracle.hpp"

using namespace preimage;
using decompose::BoustrophedonDecomposition;
using geometry::Environment;

namespace {
void check(const Environment& env, double angle, const std::string& what) {
  BoustrophedonDecomposition b(env, angle);
  const auto& cells = b.cells();
  const auto& slices = b.critical_slices();
  // Euler's formula for the Reeb graph: N_cells = N_critical + N_obstacles - 1, one less per
  // merge where holes touch (Environment::contact_merges).
  EXPECT_EQ(cells.size() + env.contact_merges(), slices.size() + env.num_holes() - 1) << what;
  geometry::ExactFT total = 0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    total += b.area(c);
    ASSERT_LT(cells[c].left_slice, slices.size()) << what;
    ASSERT_LT(cells[c].right_slice, slices.size()) << what;
    EXPECT_LT(slices[cells[c].left_slice].x, slices[cells[c].right_slice].x) << what;
  }
  EXPECT_EQ(total, b.sweep_environment().exact_area()) << what;
  // Degrees: each slice is the end of exactly cells_left + cells_right cells.
  std::vector<std::uint32_t> deg_l(slices.size(), 0), deg_r(slices.size(), 0);
  for (auto& c : cells) ++deg_r[c.left_slice], ++deg_l[c.right_slice];
  for (std::size_t s = 0; s < slices.size(); ++s) {
    EXPECT_EQ(deg_l[s], slices[s].cells_left) << what;
    EXPECT_EQ(deg_r[s], slices[s].cells_right) << what;
  }
  // Fewer cells than the trapezoidal decomposition (6.2.1), never more.
  EXPECT_LE(cells.size(), b.trapezoids().cells().size());
}
}  // namespace

TEST(Boustrophedon, SquareWithDiamondHole) {
  auto env = Environment::make({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 2}, {2, 1}, {3, 2}, {2, 3}}});
  BoustrophedonDecomposition b(env);
  // Critical slices: the outer walls x = 0 and x = 4 (birth, death), the split at (1, 2)
  // and the merge at (3, 2): 4 cells.
  EXPECT_EQ(b.critical_slices().size(), 4u);
  EXPECT_EQ(b.cells().size(), 4u);
  check(env, 0, "diamond");
}

TEST(Boustrophedon, EulerOnRandomEnvironmentsAtManyAngles) {
  for (std::uint64_t s = 1; s <= 12; ++s) {
    auto env = geometry::generators::random_environment(120 + 30 * s, s % 6, s);
    for (double angle : {0.0, 90.0, 180.0, 270.0, 30.0, 77.5})
      check(env, angle, "seed " + std::to_string(s) + " angle " + std::to_string(angle));
  }
}

// Holes touching at vertices (issue 29): Euler's formula and areas at many angles.
TEST(Boustrophedon, EulerWithTouchingHoles) {
  for (std::uint64_t s = 1; s <= 8; ++s) {
    auto env = geometry::generators::touching_squares(4 + s % 4, 0.8, s, s % 2 == 0);
    ASSERT_TRUE(env.has_contacts());
    for (double angle : {0.0, 90.0, 45.0, 30.0, 77.5})
      check(env, angle, "touching_squares " + std::to_string(s) + " angle " + std::to_string(angle));
  }
}

TEST(Boustrophedon, DegenerateCriticalPointsOnVerticalWalls) {
  check(geometry::generators::office(2, 3), 0, "office");
  check(geometry::generators::office(3, 3), 90, "office at 90");
  check(Environment::make(geometry::generators::comb(6), {}), 0, "comb");
  for (std::uint64_t s = 1; s <= 10; ++s)
    check(preimage::testing::snapped_random_environment(30 + 2 * s, s % 3, s, 40.0), 0, "snapped " + std::to_string(s));
  // A rectangle with a rectangular hole: all four critical points are walls.
  auto env = Environment::make({{0, 0}, {6, 0}, {6, 4}, {0, 4}}, {{{2, 1}, {4, 1}, {4, 3}, {2, 3}}});
  BoustrophedonDecomposition b(env);
  EXPECT_EQ(b.cells().size(), 4u);
}
