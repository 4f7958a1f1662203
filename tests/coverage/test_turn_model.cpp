// Curvature-limited robots (issue 49, item 3), checked independently of the planner:
// - Dubins curves: every word driven piece by piece ends at the goal pose; the shortest is
//   never shorter than the straight line, is symmetric under time reversal, and matches
//   closed forms (straight ahead, a half turn);
// - the arc certificate refuses an arc whose chords keep r from a wall but whose middle
//   does not;
// - drivable coverage paths: every arc has the turning radius about its centre, headings
//   join tangentially (except at cusps, where the robot reverses), and every point of
//   every arc — the exact circle, sampled far more densely than the path's chords — keeps
//   r from every obstacle edge (brute force over all edges), and the floor is covered.
#include <gtest/gtest.h>
#include <preimage/coverage/coverage.hpp>
#include <preimage/coverage/turn_model.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace preimage;
using coverage::DubinsCurve;
using coverage::Pose;
using geometry::Environment;
using geometry::Point;

namespace {

constexpr double kPi = std::numbers::pi;

double angle_diff(double a, double b) { return std::fabs(std::remainder(a - b, 2 * kPi)); }

double seg_dist(const Point& p, const Point& a, const Point& b) {
  const double vx = b.x() - a.x(), vy = b.y() - a.y(), wx = p.x() - a.x(), wy = p.y() - a.y();
  const double l2 = vx * vx + vy * vy;
  const double t = l2 == 0 ? 0 : std::clamp((wx * vx + wy * vy) / l2, 0.0, 1.0);
  return std::hypot(wx - t * vx, wy - t * vy);
}

double clearance(const Environment& env, const Point& p) {
  double d = INFINITY;
  for (std::size_t e = 0; e < env.num_vertices(); ++e) d = std::min(d, seg_dist(p, env.vertex(e), env.vertex(env.next(e))));
  return d;
}

double shortest(const Pose& a, const Pose& b, double R) {
  const auto cs = coverage::dubins_curves(a, b, R);
  return cs.empty() ? INFINITY : cs.front().length();
}

}  // namespace

TEST(Dubins, EveryWordEndsAtTheGoalPose) {
  std::mt19937_64 rng(49);
  std::uniform_real_distribution<double> xy(-5, 5), h(-kPi, kPi), rad(0.1, 3);
  std::size_t words = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Pose a{Point(xy(rng), xy(rng)), h(rng)}, b{Point(xy(rng), xy(rng)), h(rng)};
    const double R = rad(rng);
    const auto curves = coverage::dubins_curves(a, b, R);
    ASSERT_FALSE(curves.empty()) << "trial " << trial;  // a CSC word always exists
    for (const DubinsCurve& c : curves) {
      const Pose end = c.at(c.length());
      EXPECT_LT(std::hypot(end.at.x() - b.at.x(), end.at.y() - b.at.y()), 1e-9) << to_string(c.word) << " trial " << trial;
      EXPECT_LT(angle_diff(end.heading, b.heading), 1e-9) << to_string(c.word) << " trial " << trial;
      for (const auto& piece : c.pieces) {
        EXPECT_GE(piece.length, 0);
        if (piece.turn != 0) {
          EXPECT_NEAR(std::fabs(piece.turn) * R, piece.length, 1e-9 * (1 + piece.length));
        }
      }
      ++words;
    }
    EXPECT_GE(curves.front().length(), std::hypot(b.at.x() - a.at.x(), b.at.y() - a.at.y()) - 1e-9);
    // Time reversal: driving b -> a backwards is a forward path from b turned around.
    const Pose ra{a.at, a.heading + kPi}, rb{b.at, b.heading + kPi};
    EXPECT_NEAR(curves.front().length(), shortest(rb, ra, R), 1e-7) << "trial " << trial;
  }
  EXPECT_GT(words, 8000u);
}

TEST(Dubins, ClosedForms) {
  const double R = 0.7;
  // Straight ahead: the segment.
  EXPECT_NEAR(shortest({Point(1, 2), 0.3}, {Point(1 + 5 * std::cos(0.3), 2 + 5 * std::sin(0.3)), 0.3}, R), 5, 1e-12);
  // A half turn to the left onto the parallel line 2R away: half a circle.
  EXPECT_NEAR(shortest({Point(0, 0), 0}, {Point(0, 2 * R), kPi}, R), kPi * R, 1e-12);
  // A quarter turn: a quarter circle.
  EXPECT_NEAR(shortest({Point(0, 0), 0}, {Point(R, R), kPi / 2}, R), kPi / 2 * R, 1e-12);
  // Turning around onto the same line (U-turn with a gap of 0): the known RLR/LRL bound
  // is longer than the half circle, and no shorter path exists than 2 pi R / 3 + ...: at
  // least the half circle's length.
  EXPECT_GT(shortest({Point(0, 0), 0}, {Point(0, 0), kPi}, R), kPi * R);
}

TEST(ArcCertifier, RefusesAnArcWhoseMiddleComesTooClose) {
  const Environment room = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {});
  const double r = 0.1, R = 1;
  const coverage::ArcCertifier cert(room, r);
  // An arc of 16 degrees about (5, yc): its lowest point is yc - 1 from the floor.
  auto arc = [&](double yc) {
    const double a0 = -kPi / 2 - 8 * kPi / 180, a1 = -kPi / 2 + 8 * kPi / 180;
    const Point p(5 + R * std::cos(a0), yc + R * std::sin(a0)), q(5 + R * std::cos(a1), yc + R * std::sin(a1));
    return std::pair{p, q};
  };
  {
    // Lowest point 0.095 from the floor: the chord's ends are 0.1047 away (clear), the arc is not.
    const auto [p, q] = arc(1.095);
    EXPECT_TRUE(cert.segment(p, q));
    EXPECT_FALSE(cert.arc(p, {q}, R, 16 * kPi / 180));
  }
  {
    const auto [p, q] = arc(1.2);
    EXPECT_TRUE(cert.arc(p, {q}, R, 16 * kPi / 180));
  }
}

namespace {

// The independent checks of a drivable coverage path.
void check_drivable(const Environment& env, double w, double r, double R, const std::string& what, double min_covered) {
  coverage::CoverageOptions o;
  o.width = w, o.robot_radius = r, o.min_turn_radius = R;
  const auto rep = coverage::plan_coverage(env, o);
  ASSERT_GE(rep.path.size(), 2u) << what;
  EXPECT_EQ(rep.min_turn_radius, R);
  EXPECT_FALSE(rep.arcs.empty()) << what;
  std::vector<char> on_arc(rep.path.size(), 0);
  std::size_t dense = 0;
  for (const auto& a : rep.arcs) {
    EXPECT_EQ(a.radius, R) << what;
    for (std::size_t k = a.first; k <= a.last; ++k) {
      EXPECT_NEAR(std::hypot(rep.path[k].x() - a.centre.x(), rep.path[k].y() - a.centre.y()), R, 1e-7 * R) << what << " point " << k;
      if (k > a.first && k < a.last) on_arc[k] = 1;
      EXPECT_EQ(k < a.last ? rep.moves[k] : coverage::Move::Turn, coverage::Move::Turn);
    }
    // The exact circle between the chord ends, 64 points per chord: r from every edge.
    for (std::size_t k = a.first; k < a.last; ++k) {
      const double t0 = std::atan2(rep.path[k].y() - a.centre.y(), rep.path[k].x() - a.centre.x());
      const double dt = std::remainder(std::atan2(rep.path[k + 1].y() - a.centre.y(), rep.path[k + 1].x() - a.centre.x()) - t0, 2 * kPi);
      EXPECT_LE(std::fabs(dt), coverage::ArcCertifier::kChordTurn + 1e-9) << what;
      for (int j = 0; j <= 64; ++j) {
        const double t = t0 + dt * j / 64;
        const Point q(a.centre.x() + R * std::cos(t), a.centre.y() + R * std::sin(t));
        EXPECT_GE(clearance(env, q), r - 1e-9) << what << ": arc through " << geometry::format_point(q);
        ++dense;
      }
    }
  }
  EXPECT_GT(dense, 1000u) << what;
  // Headings join tangentially: between two segments the direction changes by at most one
  // chord's turn (inside an arc) or half of it (where an arc meets a segment), except at a
  // cusp, where the robot stops and drives the other way.
  std::vector<char> cusp(rep.path.size(), 0);
  for (std::size_t c : rep.cusps) cusp.at(c) = 1;
  for (std::size_t k = 1; k + 1 < rep.path.size(); ++k) {
    const double h0 = std::atan2(rep.path[k].y() - rep.path[k - 1].y(), rep.path[k].x() - rep.path[k - 1].x());
    const double h1 = std::atan2(rep.path[k + 1].y() - rep.path[k].y(), rep.path[k + 1].x() - rep.path[k].x());
    const double turn = angle_diff(h0, h1);
    if (cusp[k])
      EXPECT_GE(turn, kPi - coverage::ArcCertifier::kChordTurn - 1e-6) << what << " cusp at " << k;
    else
      EXPECT_LE(turn, coverage::ArcCertifier::kChordTurn + 1e-6) << what << " corner at " << k << " " << geometry::format_point(rep.path[k]);
  }
  // Every segment r from every obstacle (double, brute force: the path points).
  for (const Point& p : rep.path) EXPECT_GE(clearance(env, p), r - 1e-9) << what;
  const auto m = coverage::measure_coverage(env, rep);
  EXPECT_GE(m.covered_fraction, min_covered) << what;
}

}  // namespace

TEST(DrivableCoverage, ArcsKeepTheRadiusJoinTangentiallyAndStayInTheConfigurationSpace) {
  const Environment gallery = Environment::make({{0, 0}, {12, 0}, {12, 8}, {0, 8}},
                                                {{{2, 2}, {3, 2}, {3, 3}, {2, 3}}, {{8, 5}, {9.5, 5}, {9.5, 6.5}, {8, 6.5}}, {{5.8, 2.5}, {6.2, 2.5}, {6.2, 7}, {5.8, 7}}});
  check_drivable(gallery, 0.5, 0.25, 0.3, "gallery R 0.3", 0.995);
  check_drivable(gallery, 0.5, 0.25, 0.6, "gallery R 0.6 (reversing needed)", 0.99);
  for (std::uint64_t s = 1; s <= 3; ++s) {
    const auto env = geometry::generators::random_environment(60, 1 + s % 3, s);
    const auto b = env.bbox();
    const double size = std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin());
    check_drivable(env, 0.04 * size, 0.02 * size, 0.03 * size, "random " + std::to_string(s), 0.98);
  }
}

TEST(DrivableCoverage, TooLargeARadiusOrANegativeOneIsRefused) {
  const Environment room = Environment::make({{0, 0}, {4, 0}, {4, 3}, {0, 3}}, {});
  coverage::CoverageOptions o;
  o.width = 0.5, o.robot_radius = 0.2;
  o.min_turn_radius = 3;
  EXPECT_THROW(coverage::plan_coverage(room, o), InputError);
  o.min_turn_radius = -1;
  EXPECT_THROW(coverage::plan_coverage(room, o), InputError);
  o.min_turn_radius = std::nan("");
  EXPECT_THROW(coverage::plan_coverage(room, o), InputError);
}
