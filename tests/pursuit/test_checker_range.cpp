// The contamination checker with range-limited pursuers (CheckOptions::range): the sensor
// polygon, cases whose answer is known by hand, the unlimited check beyond the plan's
// diameter, and a brute-force grid simulation of the evader (independent of the checker's
// overlays and events).
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/bounds.hpp>
#include <preimage/pursuit/cells.hpp>
#include <preimage/pursuit/static_cover.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/scene/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <limits>
#include <random>

using namespace preimage;
using geometry::Environment;
using geometry::ExactFT;
using geometry::Point;

namespace {

Environment rect(double w, double h) { return Environment::make({{0, 0}, {w, 0}, {w, h}, {0, h}}, {}); }
Environment pillar_room() { return Environment::make({{0, 0}, {6, 0}, {6, 6}, {0, 6}}, {{{2, 2}, {4, 2}, {4, 4}, {2, 4}}}); }

pursuit::CheckResult check(const Environment& env, const pursuit::Paths& paths, double range, unsigned threads = 0) {
  pursuit::CheckOptions o;
  o.range = range, o.threads = threads;
  return pursuit::check_paths(env, paths, o);
}

// Area of the square [0, s]^2 inside the sensor polygon around c (clipped in doubles).
double square_in_sensor(double s, const Point& c, const std::vector<Point>& q) {
  std::vector<Point> poly{{0, 0}, {s, 0}, {s, s}, {0, s}};
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Point a(c.x() + q[i].x(), c.y() + q[i].y()), b(c.x() + q[(i + 1) % q.size()].x(), c.y() + q[(i + 1) % q.size()].y());
    auto side = [&](const Point& x) { return (b.x() - a.x()) * (x.y() - a.y()) - (b.y() - a.y()) * (x.x() - a.x()); };
    std::vector<Point> out;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Point &x = poly[k], &y = poly[(k + 1) % poly.size()];
      const double sx = side(x), sy = side(y);
      if (sx >= 0) out.push_back(x);
      if ((sx >= 0) != (sy >= 0)) {
        const double t = sx / (sx - sy);
        out.emplace_back(x.x() + t * (y.x() - x.x()), x.y() + t * (y.y() - x.y()));
      }
    }
    poly = out;
  }
  double twice = 0;
  for (std::size_t k = 0; k < poly.size(); ++k)
    twice += poly[k].x() * poly[(k + 1) % poly.size()].y() - poly[(k + 1) % poly.size()].x() * poly[k].y();
  return twice / 2;
}

// The evader on a grid: cells of side h whose centres lie in free space, joined to their
// four neighbours when the segment between the centres is free. The pursuers move in steps
// of at most h / 4; at each step a cell is seen when some pursuer sees its centre (exact
// visibility) and the centre is inside that pursuer's sensor polygon; the contamination
// then floods every hidden cell joined through hidden cells to a contaminated one (an
// arbitrarily fast evader). Returns the contaminated area at the end.
double grid_contaminated_area(const Environment& env, const pursuit::Paths& paths, double range, double h) {
  const geometry::VisibilityIndex vis(env);
  const auto q = pursuit::range_sensor(range, 32);
  const auto box = env.bbox();
  const auto nx = static_cast<std::size_t>(std::ceil((box.xmax() - box.xmin()) / h)), ny = static_cast<std::size_t>(std::ceil((box.ymax() - box.ymin()) / h));
  std::vector<Point> centre;
  std::vector<std::size_t> id(nx * ny, SIZE_MAX);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const Point c(box.xmin() + (static_cast<double>(i) + 0.5) * h, box.ymin() + (static_cast<double>(j) + 0.5) * h);
      if (geometry::locate(env, c).kind != geometry::Location::Kind::Interior) continue;
      id[j * nx + i] = centre.size();
      centre.push_back(c);
    }
  std::vector<std::vector<std::size_t>> adj(centre.size());
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t a = id[j * nx + i];
      if (a == SIZE_MAX) continue;
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (i + di >= nx || j + dj >= ny) continue;
        const std::size_t b = id[(j + dj) * nx + i + di];
        if (b != SIZE_MAX && vis.visible(centre[a], centre[b])) adj[a].push_back(b), adj[b].push_back(a);
      }
    }
  std::vector<char> cont(centre.size(), 1), seen(centre.size());
  auto step = [&](const std::vector<Point>& at) {
    for (std::size_t c = 0; c < centre.size(); ++c) {
      seen[c] = 0;
      for (const Point& p : at) {
        bool inside = true;
        for (std::size_t k = 0; k < q.size() && inside; ++k) {
          const Point a(p.x() + q[k].x(), p.y() + q[k].y()), b(p.x() + q[(k + 1) % q.size()].x(), p.y() + q[(k + 1) % q.size()].y());
          inside = geometry::orientation(a, b, centre[c]) >= 0;
        }
        if (inside && vis.visible(p, centre[c])) {
          seen[c] = 1;
          break;
        }
      }
    }
    std::deque<std::size_t> open;
    std::vector<char> next(centre.size(), 0);
    for (std::size_t c = 0; c < centre.size(); ++c)
      if (cont[c] && !seen[c]) next[c] = 1, open.push_back(c);
    while (!open.empty()) {
      const std::size_t c = open.front();
      open.pop_front();
      for (std::size_t d : adj[c])
        if (!seen[d] && !next[d]) next[d] = 1, open.push_back(d);
    }
    cont = std::move(next);
  };
  for (std::size_t w = 0; w + 1 < paths[0].size() || w == 0; ++w) {
    double longest = 0;
    for (const auto& p : paths)
      if (w + 1 < p.size()) longest = std::max(longest, std::hypot(p[w + 1].x() - p[w].x(), p[w + 1].y() - p[w].y()));
    const auto n = static_cast<std::size_t>(std::ceil(longest / (h / 4)));
    for (std::size_t s = 0; s <= std::max<std::size_t>(n, 0); ++s) {
      if (w > 0 && s == 0) continue;
      const double f = n ? static_cast<double>(s) / static_cast<double>(n) : 0;
      std::vector<Point> at;
      for (const auto& p : paths) {
        const Point &a = p[w], &b = p[std::min(w + 1, p.size() - 1)];
        at.emplace_back(a.x() + f * (b.x() - a.x()), a.y() + f * (b.y() - a.y()));
      }
      step(at);
    }
    if (paths[0].size() == 1) break;
  }
  return static_cast<double>(std::count(cont.begin(), cont.end(), 1)) * h * h;
}

}  // namespace

TEST(PursuitCheckerRange, SensorCornersLieInTheDiscAndAreConvex) {
  for (const double R : {1e-3, 0.7, 3.0, 1e4})
    for (const std::size_t n : {8u, 32u, 100u}) {
      const auto q = pursuit::range_sensor(R, n);
      ASSERT_EQ(q.size(), n);
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_LE(ExactFT(q[i].x()) * ExactFT(q[i].x()) + ExactFT(q[i].y()) * ExactFT(q[i].y()), ExactFT(R) * ExactFT(R));
        EXPECT_GT(std::hypot(q[i].x(), q[i].y()), R * (1 - 1e-12));  // on the circle but for rounding
        EXPECT_GT(geometry::orientation(q[i], q[(i + 1) % n], q[(i + 2) % n]), 0);
      }
    }
  for (const double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(pursuit::range_sensor(bad, 32), InputError) << bad;
  EXPECT_THROW(pursuit::range_sensor(1, 4), InputError);
  EXPECT_THROW(check(rect(4, 4), {{{2, 2}}}, -1), InputError);
}

// A pursuer in the middle of a 10 x 10 room: the corners are 7.07 away. With range 8 the
// inscribed 32-gon (apothem 7.96) holds the room; with 6 the four corners stay
// contaminated, exactly the room outside the polygon.
TEST(PursuitCheckerRange, AStandingPursuerSeesOnlyWithinRange) {
  const Environment room = rect(10, 10);
  EXPECT_TRUE(check(room, {{{5, 5}}}, 8).cleared);
  const auto r = check(room, {{{5, 5}}}, 6);
  EXPECT_FALSE(r.cleared);
  EXPECT_EQ(r.contaminated_at_end.size(), 4u);
  EXPECT_NEAR(r.contaminated_area, 100 - square_in_sensor(10, {5, 5}, pursuit::range_sensor(6, 32)), 1e-9);
}

// Walking down the middle of a corridor 2 wide: a range under 1 never sees the walls, and
// the evader slips past along them; 1.2 sweeps the whole width.
TEST(PursuitCheckerRange, ACorridorIsClearedOnlyWhenTheRangeSpansItsWidth) {
  const Environment corridor = rect(20, 2);
  const pursuit::Paths walk{{{0.5, 1}, {19.5, 1}}};
  EXPECT_TRUE(pursuit::check_paths(corridor, walk).cleared);
  EXPECT_FALSE(check(corridor, walk, 0.9).cleared);
  EXPECT_TRUE(check(corridor, walk, 1.2).cleared);
}

// An L of corridors 2 wide: sweeping one arm and then the other clears it; sweeping one arm
// and walking back lets the other arm's evader out as soon as the corner is out of range
// (unlimited, the corner stays in sight and both plans clear the L).
TEST(PursuitCheckerRange, LeavingAJunctionLetsTheOtherArmBackIn) {
  const Environment L = Environment::make({{0, 0}, {12, 0}, {12, 12}, {10, 12}, {10, 2}, {0, 2}}, {});
  const pursuit::Paths both{{{0.5, 1}, {11, 1}, {11, 11.5}}}, back{{{0.5, 1}, {11, 1}, {0.5, 1}}};
  EXPECT_TRUE(check(L, both, 1.5).cleared);
  const auto r = check(L, back, 1.5);
  EXPECT_FALSE(r.cleared);
  ASSERT_TRUE(r.first_recontamination);
  EXPECT_EQ(r.first_recontamination->waypoint, 1u);
  EXPECT_TRUE(pursuit::check_paths(L, back).cleared);
}

// Beyond the plan's diameter the sensor holds the whole plan: the same moments, verdict
// and contaminated area as the unlimited check, on the example scenes' plans.
TEST(PursuitCheckerRange, BeyondTheDiameterItIsTheUnlimitedCheck) {
  for (const char* name : {"pillar", "three_arms", "corridor_rooms"}) {
    const Environment env = scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/pursuit/" + name + ".json").require_environment();
    const auto cells = pursuit::ConservativeCells::build(env);
    const auto plan = pursuit::search(cells, std::string(name) == "corridor_rooms" ? 1 : 2);
    ASSERT_TRUE(plan.plan) << name;
    const auto box = env.bbox();
    const double diameter = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    const auto a = pursuit::check_paths(env, plan.plan->paths), b = check(env, plan.plan->paths, 2 * diameter);
    EXPECT_EQ(a.cleared, b.cleared) << name;
    EXPECT_EQ(a.moments, b.moments) << name;
    EXPECT_NEAR(a.contaminated_area, b.contaminated_area, 1e-9) << name;
  }
}

TEST(PursuitCheckerRange, TheVerdictDoesNotDependOnTheNumberOfThreads) {
  const Environment env = scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/pursuit/three_arms.json").require_environment();
  const auto cells = pursuit::ConservativeCells::build(env);
  const auto plan = pursuit::search(cells, 2);
  ASSERT_TRUE(plan.plan);
  for (const double R : {2.0, 3.0, 5.0}) {
    const auto one = check(env, plan.plan->paths, R, 1), two = check(env, plan.plan->paths, R, 2);
    EXPECT_EQ(one.cleared, two.cleared) << R;
    EXPECT_EQ(one.moments, two.moments) << R;
    EXPECT_EQ(one.contaminated_area, two.contaminated_area) << R;
  }
}

// Against the grid simulation: the room with a pillar (two pursuers on the search's plan,
// one on random walks between visible points), the L of corridors and a corridor, at
// several ranges. The grid's area differs from the exact one by the cells along the
// contaminated region's boundary.
TEST(PursuitCheckerRange, AgreesWithAGridSimulation) {
  struct Case {
    const Environment* env;
    pursuit::Paths paths;
    double range;
  };
  const Environment room = pillar_room(), corridor = rect(20, 2);
  const Environment L = Environment::make({{0, 0}, {12, 0}, {12, 12}, {10, 12}, {10, 2}, {0, 2}}, {});
  std::vector<Case> cases;
  const auto cells = pursuit::ConservativeCells::build(room);
  const auto plan = pursuit::search(cells, 2);
  ASSERT_TRUE(plan.plan);
  for (const double R : {1.5, 2.5, 4.0}) cases.push_back({&room, plan.plan->paths, R});
  std::mt19937_64 rng(4821);
  std::uniform_real_distribution<double> u(0.3, 5.7);
  for (int w = 0; w < 3; ++w) {
    std::vector<Point> path;
    while (path.size() < 5) {
      const Point p(std::round(u(rng) * 8) / 8, std::round(u(rng) * 8) / 8);
      if (geometry::locate(room, p).kind != geometry::Location::Kind::Interior) continue;
      if (!path.empty() && !geometry::visible(room, path.back(), p)) continue;
      path.push_back(p);
    }
    for (const double R : {1.5, 3.0}) cases.push_back({&room, {path}, R});
  }
  for (const double R : {1.5, 2.5}) {
    cases.push_back({&L, {{{0.5, 1}, {11, 1}, {11, 11.5}}}, R});
    cases.push_back({&L, {{{0.5, 1}, {11, 1}, {0.5, 1}}}, R});
  }
  for (const double R : {0.9, 1.2}) cases.push_back({&corridor, {{{0.5, 1}, {19.5, 1}}}, R});
  const double h = 0.1;
  std::size_t cleared = 0, n = 0;
  for (const auto& c : cases) {
    const auto exact = check(*c.env, c.paths, c.range);
    const double grid = grid_contaminated_area(*c.env, c.paths, c.range, h);
    const auto box = c.env->bbox();
    const double perimeter = 2 * (box.xmax() - box.xmin() + box.ymax() - box.ymin());
    // A tenth of a cell either way along a boundary as long as the plan's box's perimeter
    // (the largest difference is 0.06 m² at h = 0.1).
    EXPECT_NEAR(exact.contaminated_area, grid, h * perimeter / 10) << "case " << n << ", range " << c.range;
    EXPECT_EQ(exact.cleared, grid == 0) << "case " << n << ", range " << c.range;
    cleared += exact.cleared, ++n;
  }
  EXPECT_GE(cleared, 3u);
  EXPECT_LT(cleared, cases.size() - 3);
}

// The pillar's shadow reaches the far walls, which are out of range: one hidden region, not
// two pieces either side of the sensor's edge that crosses the shadow (where neither side
// is seen, the edge separates nothing).
TEST(PursuitCheckerRange, ShadowAndOutOfRangeAreOneRegion) {
  const auto r = check(pillar_room(), {{{1, 1}}}, 4);
  EXPECT_FALSE(r.cleared);
  EXPECT_EQ(r.contaminated_at_end.size(), 1u);
}

// The planner with a range: the lower end of the interval stands (a weaker sensor never
// needs fewer pursuers), the upper end is a plan the range check clears — the plan for
// unlimited sight where it clears, else a static cover — and the plan is re-checked here.
TEST(PursuitCheckerRange, BoundsWithARangeAreCertifiedWithIt) {
  const Environment room = pillar_room();
  pursuit::BoundsOptions o;
  o.range = 50;
  const auto far = pursuit::pursuer_bounds(room, o);
  EXPECT_EQ(far.lower, 2u);
  EXPECT_EQ(far.upper, 2u);
  EXPECT_EQ(far.plan_source, "strategy");
  for (const double R : {3.0, 1.5}) {
    o.range = R;
    const auto b = pursuit::pursuer_bounds(room, o);
    EXPECT_EQ(b.lower, 2u) << R;
    EXPECT_EQ(b.plan_source, "range cover") << R;
    EXPECT_EQ(b.upper, b.plan->paths.size()) << R;
    EXPECT_EQ(b.guard_points().size(), b.upper) << R;
    ASSERT_TRUE(b.check && b.check->cleared) << R;
    EXPECT_TRUE(check(room, b.plan->paths, R).cleared) << R;
    EXPECT_FALSE(check(room, b.plan->paths, R / 2).cleared) << R;  // the range matters
  }
  o.range = -1;
  EXPECT_THROW(pursuit::pursuer_bounds(room, o), InputError);
}

// In a 10 x 10 room with range 12 (inner radius 11.94, samples 5.97 apart) one guard sees
// it all; with 6 the corners need more, and the cover walks them from a start one at a time.
TEST(PursuitCheckerRange, StaticCoverOfARoom) {
  const Environment room = rect(10, 10);
  EXPECT_EQ(pursuit::static_range_cover(room, 12).guards.size(), 1u);
  const auto c = pursuit::static_range_cover(room, 6, 32, Point(1, 1));
  EXPECT_GE(c.guards.size(), 2u);
  EXPECT_TRUE(c.check.cleared);
  for (const auto& p : c.plan.paths) EXPECT_EQ(p.front(), Point(1, 1));
  EXPECT_TRUE(check(room, c.plan.paths, 6).cleared);
}

// Far from the origin (UTM-like coordinates) the cover is the one at the origin, moved: the
// samples and the greedy choice run in the plan's canonical frame.
TEST(PursuitCheckerRange, StaticCoverDoesNotDependOnWhereThePlanSits) {
  auto shifted = [](double dx, double dy) {
    return Environment::make({{dx, dy}, {dx + 6, dy}, {dx + 6, dy + 6}, {dx, dy + 6}},
                             {{{dx + 2, dy + 2}, {dx + 4, dy + 2}, {dx + 4, dy + 4}, {dx + 2, dy + 4}}});
  };
  const auto at0 = pursuit::static_range_cover(shifted(0, 0), 2.5);
  for (const auto& [dx, dy] : {std::pair{5e5, 4e6}, std::pair{-2e7, 1e7}}) {
    const auto far = pursuit::static_range_cover(shifted(dx, dy), 2.5);
    ASSERT_EQ(far.guards.size(), at0.guards.size()) << dx;
    for (std::size_t i = 0; i < far.guards.size(); ++i) {
      EXPECT_NEAR(far.guards[i].x() - dx, at0.guards[i].x(), 1e-6) << dx;
      EXPECT_NEAR(far.guards[i].y() - dy, at0.guards[i].y(), 1e-6) << dx;
    }
    EXPECT_TRUE(far.check.cleared);
  }
}
