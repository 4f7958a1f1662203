// SPDX-License-Identifier: Apache-2.0
// The visibility game with the observer's velocity in the state: against a brute-force
// value iteration written from its definition (both observer steps), against the game
// without dynamics (equal when the acceleration reaches every velocity in one step,
// contained in it otherwise), an observer too fast to stop before a wall, a parabola whose
// hull holds a pillar, and refused resolutions and steps.
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/tracking/dynamic_visibility_game.hpp>

#include <gtest/gtest.h>
#include <support/rooms.hpp>

#include <cmath>
#include <random>

using namespace preimage;
using namespace preimage::tracking;
using geometry::Environment;
using geometry::Point;

namespace {

constexpr std::uint32_t kForever = VisibilityGame::kForever;

using test::box;
using test::rect_room;

// A 6 x 4 room with a 1 m pillar in the middle, at 0.5 m and a 3 m range.
GameParams pillar_game_params() {
  GameParams p;
  p.resolution = 0.5;
  p.range = 3;
  return p;
}

// At resolution h, half speed and v_max 1, one grid step per step squared is
// 0.25 / (2 h) m/s^2.
double unit_accel(double h) { return 0.25 / (2 * h); }

// V_0 = 0 where the game without dynamics has lost (its sight, separation and target
// points are checked against brute force in test_visibility_game.cpp); V_{k+1}(o, v, t) =
// 1 + min over target moves t' of max over the observer's allowed choices w, which take it
// to moves[(o V + v) V + w], of V_k(that point, w, t').
std::vector<std::uint32_t> value_iteration(const VisibilityGame& g, std::size_t V, const std::vector<std::uint32_t>& moves) {
  const std::size_t n = g.num_points();
  std::vector<std::uint32_t> val(n * n * V);
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::size_t v = 0; v < V; ++v)
      for (std::uint32_t t = 0; t < n; ++t) val[(o * V + v) * n + t] = g.escape_steps(o, t) == 0 ? 0 : kForever;
  for (bool changed = true; changed;) {
    changed = false;
    auto nv = val;
    for (std::uint32_t o = 0; o < n; ++o)
      for (std::size_t v = 0; v < V; ++v)
        for (std::uint32_t t = 0; t < n; ++t) {
          if (g.escape_steps(o, t) == 0) continue;
          std::uint32_t worst = kForever;
          for (std::uint32_t tp : g.target_moves(t)) {
            std::uint32_t best = 0;
            for (std::size_t w = 0; w < V; ++w)
              if (const std::uint32_t q = moves[(o * V + v) * V + w]; q != VisibilityGame::kNoPoint)
                best = std::max(best, val[(q * V + w) * n + tp]);
            worst = std::min(worst, best);
          }
          const std::uint32_t value = worst == kForever ? kForever : worst + 1;
          if (value != nv[(o * V + v) * n + t]) nv[(o * V + v) * n + t] = value, changed = true;
        }
    val.swap(nv);
  }
  return val;
}

// Every state of d equals want; true when some are kept and some lost after a step or more.
bool expect_equal_states(const DynamicVisibilityGame& d, const std::vector<std::uint32_t>& want, int trial) {
  const std::size_t n = d.game().num_points(), V = d.num_velocities();
  std::size_t keep = 0, lose = 0;
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::uint32_t v = 0; v < V; ++v)
      for (std::uint32_t t = 0; t < n; ++t) {
        const std::uint32_t w = want[(o * V + v) * n + t];
        EXPECT_EQ(d.escape_steps(o, v, t), w) << "trial " << trial << " o " << o << " v " << v << " t " << t;
        if (d.escape_steps(o, v, t) != w) return false;
        keep += w == kForever;
        lose += w != kForever && w > 1;
      }
  EXPECT_EQ(d.stats().winning, keep);
  return keep > 0 && lose > 0;
}

// The semi-implicit step: velocities v' integer, |v'|^2 <= 8, each component within `a`
// of v's; allowed when the point o + v' h exists and is seen from o (geometry::visible).
std::vector<std::uint32_t> brute_force(const Environment& env, const VisibilityGame& g, int a) {
  const std::size_t n = g.num_points();
  const double h = g.params().resolution;
  std::vector<std::array<int, 2>> vel{{0, 0}};
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i)
      if ((i || j) && i * i + j * j <= 8) vel.push_back({i, j});
  const std::size_t V = vel.size();
  auto point_at = [&](const Point& p) {
    for (std::uint32_t q = 0; q < n; ++q)
      if (std::abs(g.point(q).x() - p.x()) < 1e-9 && std::abs(g.point(q).y() - p.y()) < 1e-9) return q;
    return VisibilityGame::kNoPoint;
  };
  std::vector<std::uint32_t> moves(n * V * V, VisibilityGame::kNoPoint);
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::size_t w = 0; w < V; ++w) {
      const std::uint32_t q = point_at(Point(g.point(o).x() + vel[w][0] * h, g.point(o).y() + vel[w][1] * h));
      if (q == VisibilityGame::kNoPoint || !geometry::visible(env, g.point(o), g.point(q))) continue;
      for (std::size_t v = 0; v < V; ++v)
        if (std::abs(vel[w][0] - vel[v][0]) <= a && std::abs(vel[w][1] - vel[v][1]) <= a) moves[(o * V + v) * V + w] = q;
    }
  return value_iteration(g, V, moves);
}

// The same with ObserverStep::ConstantAcceleration: velocities W with |W| <= 2 (units of
// 2h per step, h = 0.5 m, step 2 s, v_max 1 m/s), W' with each component within 1 of W's;
// the observer goes from o to o + (W + W') h, allowed when the points o + W h and
// o + (W + W') h exist, the three sides of the triangle o, o + W h, o + (W + W') h are
// seen (geometry::visible) and no environment vertex lies in the closed triangle.
// `moves` gets where each (o, W, W') goes: moves[(o * V + W) * V + W']; `hull_refusals`
// counts the moves refused only for a vertex in the triangle.
std::vector<std::uint32_t> brute_force_constant_acceleration(const Environment& env, const VisibilityGame& g,
                                                             std::vector<std::uint32_t>& moves, std::size_t& hull_refusals) {
  const std::size_t n = g.num_points();
  const double h = g.params().resolution;
  std::vector<std::array<int, 2>> vel{{0, 0}};
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i)
      if ((i || j) && i * i + j * j <= 4) vel.push_back({i, j});
  const std::size_t V = vel.size();
  auto point_at = [&](double x, double y) {
    for (std::uint32_t q = 0; q < n; ++q)
      if (std::abs(g.point(q).x() - x) < 1e-9 && std::abs(g.point(q).y() - y) < 1e-9) return q;
    return VisibilityGame::kNoPoint;
  };
  auto in_closed_triangle = [](const Point& a, const Point& b, const Point& c, const Point& x) {
    const int s = geometry::orientation(a, b, c);
    return s != 0 && geometry::orientation(a, b, x) * s >= 0 && geometry::orientation(b, c, x) * s >= 0 &&
           geometry::orientation(c, a, x) * s >= 0;
  };
  // dest[(o * V + v) * V + w]
  std::vector<std::uint32_t> dest(n * V * V, VisibilityGame::kNoPoint);
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::size_t v = 0; v < V; ++v)
      for (std::size_t w = 0; w < V; ++w) {
        if (std::abs(vel[w][0] - vel[v][0]) > 1 || std::abs(vel[w][1] - vel[v][1]) > 1) continue;
        const Point& a = g.point(o);
        const std::uint32_t q1 = point_at(a.x() + vel[v][0] * h, a.y() + vel[v][1] * h);
        if (q1 == VisibilityGame::kNoPoint) continue;
        const std::uint32_t q2 = point_at(a.x() + (vel[v][0] + vel[w][0]) * h, a.y() + (vel[v][1] + vel[w][1]) * h);
        if (q2 == VisibilityGame::kNoPoint) continue;
        const Point &b = g.point(q1), &c = g.point(q2);
        if (!geometry::visible(env, a, b) || !geometry::visible(env, b, c) || !geometry::visible(env, a, c)) continue;
        bool clear = true;
        for (const Point& x : env.vertices()) clear = clear && !in_closed_triangle(a, b, c, x);
        if (clear) dest[(o * V + v) * V + w] = q2;
        else ++hull_refusals;
      }
  moves = dest;
  return value_iteration(g, V, moves);
}

// The game at h = 0.5 m for the constant-acceleration step at `accel`.
std::shared_ptr<const VisibilityGame> constant_acceleration_base(const Environment& env, GameParams p, double accel) {
  p.step_time = DynamicVisibilityGame::constant_acceleration_step(p.resolution, accel);
  return std::make_shared<const VisibilityGame>(env, p);
}

std::uint32_t velocity_index(const DynamicVisibilityGame& d, std::array<int, 2> w) {
  for (std::uint32_t v = 0; v < d.num_velocities(); ++v)
    if (d.velocity(v) == w) return v;
  return DynamicVisibilityGame::kNone;
}

}  // namespace

TEST(DynamicVisibilityGame, MatchesBruteForceValueIterationOnRandomRooms) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.4, 3.0);
  int with_both = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const double x = U(rng), y = U(rng) * 0.6;
    const Environment env = rect_room(4.5, 3, {box(x, y, x + 0.4 + 0.2 * (trial % 3), y + 0.3 + 0.3 * (trial % 2))});
    GameParams p;
    p.resolution = 0.5;
    p.range = trial % 2 ? 2.5 : std::numeric_limits<double>::infinity();
    p.target_radius = trial % 3 == 2 ? 0 : 0.2;
    auto g = std::make_shared<const VisibilityGame>(env, p);
    const int a = 1 + trial % 2;
    DynamicGameParams dp;
    dp.accel = a * unit_accel(p.resolution);
    dp.threads = 1 + trial % 2;
    const DynamicVisibilityGame d(g, dp);
    ASSERT_EQ(d.accel_steps(), a);
    ASSERT_EQ(d.num_velocities(), 25u);
    with_both += expect_equal_states(d, brute_force(env, *g, a), trial);
    if (HasFailure()) return;
  }
  EXPECT_GE(with_both, 4);
}

// Bounded acceleration only takes choices away: kept with dynamics implies kept without,
// and an acceleration that reaches every velocity in one step gives the game without
// dynamics, whatever the velocity.
TEST(DynamicVisibilityGame, AgreesWithTheGameWithoutDynamicsInTheLimitAndIsContainedInIt) {
  const Environment env = rect_room(6, 4, {box(2.5, 1.5, 3.5, 2.5)});
  const GameParams p = pillar_game_params();
  auto g = std::make_shared<const VisibilityGame>(env, p);
  DynamicGameParams slow, free;
  slow.accel = unit_accel(p.resolution);
  free.accel = 4 * unit_accel(p.resolution);  // velocities span -2..2 per axis
  const DynamicVisibilityGame ds(g, slow), df(g, free);
  const std::size_t n = g->num_points();
  std::size_t fewer = 0;
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::uint32_t v = 0; v < ds.num_velocities(); ++v)
      for (std::uint32_t t = 0; t < n; ++t) {
        ASSERT_EQ(df.escape_steps(o, v, t), g->escape_steps(o, t)) << o << " " << v << " " << t;
        if (ds.keeps(o, v, t)) {
          ASSERT_TRUE(g->keeps(o, t)) << o << " " << v << " " << t;
        }
        ASSERT_LE(std::min(ds.escape_steps(o, v, t), 1000u), std::min(g->escape_steps(o, t), 1000u));
        fewer += g->keeps(o, t) && !ds.keeps(o, v, t);
      }
  EXPECT_GT(fewer, 0u) << "the bound on acceleration never mattered";
  EXPECT_LT(ds.stats().winning, df.stats().winning);
}

// An observer beside a wall moving into it at full speed cannot stop: every state is lost
// after the target's move, wherever the target is.
TEST(DynamicVisibilityGame, AnObserverTooFastToStopBeforeAWallLoses) {
  const Environment env = rect_room(6, 4);
  GameParams p;
  p.resolution = 0.5;
  auto g = std::make_shared<const VisibilityGame>(env, p);
  DynamicGameParams dp;
  dp.accel = unit_accel(p.resolution);
  const DynamicVisibilityGame d(g, dp);
  std::uint32_t o = g->nearest(Point(5.5, 2)), fast = DynamicVisibilityGame::kNone;
  for (std::uint32_t v = 0; v < d.num_velocities(); ++v)
    if (d.velocity(v) == std::array<int, 2>{2, 0}) fast = v;
  ASSERT_NE(fast, DynamicVisibilityGame::kNone);
  EXPECT_EQ(d.velocity(0), (std::array<int, 2>{0, 0}));
  std::size_t seen = 0;
  for (std::uint32_t t = 0; t < g->num_points(); ++t) {
    if (g->escape_steps(o, t) == 0) continue;
    ++seen;
    EXPECT_EQ(d.escape_steps(o, fast, t), 1u) << "target " << t;
  }
  EXPECT_GT(seen, 10u);
  EXPECT_EQ(d.observer_policy(o, fast, g->nearest(Point(3, 2))), DynamicVisibilityGame::kNone);
}

TEST(DynamicVisibilityGame, RefusesResolutionsThatDoNotCarryGridPointsToGridPoints) {
  const Environment env = rect_room(3, 3);
  GameParams p;
  p.resolution = 0.5;
  auto g = std::make_shared<const VisibilityGame>(env, p);
  DynamicGameParams dp;
  dp.accel = 0.3;  // 1.2 grid steps per step squared at 0.5 m
  try {
    DynamicVisibilityGame d(g, dp);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("multiple of 0.416667 m"), std::string::npos) << e.what();
  }
  dp.accel = -1;
  EXPECT_THROW(DynamicVisibilityGame(g, dp), InputError);
}

// The policies realise the values: from a kept state, the observer's policy against the
// target's stays kept (for 40 steps); from a state with escape time e, the target's policy
// wins within exactly e steps against the observer's.
namespace {
void expect_policies_realise_values(const DynamicVisibilityGame& d) {
  const VisibilityGame& g = d.game();
  std::mt19937_64 rng(3);
  const std::size_t n = g.num_points();
  std::size_t kept = 0, lost = 0;
  for (int trial = 0; trial < 4000 && (kept < 150 || lost < 150); ++trial) {
    std::uint32_t o = static_cast<std::uint32_t>(rng() % n), t = static_cast<std::uint32_t>(rng() % n);
    std::uint32_t v = static_cast<std::uint32_t>(rng() % d.num_velocities());
    const std::uint32_t e = d.escape_steps(o, v, t);
    if (e == 0) continue;
    std::uint32_t steps = 0;
    bool alive = true;
    for (; steps < (e == kForever ? 40u : e) && alive; ++steps) {
      t = d.target_policy(o, v, t);
      const std::uint32_t w = d.observer_policy(o, v, t);
      if (w == DynamicVisibilityGame::kNone) alive = false;
      else o = d.destination(o, v, w), v = w, alive = d.escape_steps(o, v, t) != 0;
    }
    if (e == kForever) {
      ++kept;
      EXPECT_TRUE(alive) << "kept state lost after " << steps << " steps";
    } else {
      ++lost;
      EXPECT_FALSE(alive) << "escape in " << e << " steps not realised";
      EXPECT_EQ(steps, e);
    }
  }
  EXPECT_GE(kept, 150u);
  EXPECT_GE(lost, 150u);
}
}  // namespace

TEST(DynamicVisibilityGame, ItsPoliciesRealiseTheValues) {
  const Environment env = rect_room(6, 4, {box(2.5, 1.5, 3.5, 2.5)});
  const GameParams p = pillar_game_params();
  DynamicGameParams dp;
  dp.accel = unit_accel(p.resolution);
  expect_policies_realise_values(DynamicVisibilityGame(std::make_shared<const VisibilityGame>(env, p), dp));
  dp.accel = 0.25;
  dp.step = ObserverStep::ConstantAcceleration;
  expect_policies_realise_values(DynamicVisibilityGame(constant_acceleration_base(env, p, dp.accel), dp));
}

// With the constant-acceleration step (the robot's own motion) every state equals a
// brute-force value iteration written from the definition, on rooms with boxes and, in
// some, a small pillar a parabola's hull can hold.
TEST(DynamicVisibilityGame, ConstantAccelerationMatchesBruteForceOnRandomRooms) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> U(0.4, 3.0);
  int with_both = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const double x = U(rng), y = U(rng) * 0.6;
    std::vector<geometry::Ring> holes{box(x, y, x + 0.4 + 0.2 * (trial % 3), y + 0.3 + 0.3 * (trial % 2))};
    if (trial % 2) holes.push_back(box(3.6, 2.1, 3.72, 2.22));  // between grid points: only a hull can hold it
    const Environment env = rect_room(4.5, 3, holes);
    GameParams p;
    p.resolution = 0.5;
    p.range = trial % 2 ? 2.5 : std::numeric_limits<double>::infinity();
    p.target_radius = trial % 3 == 2 ? 0 : 0.2;
    const double accel = 0.25;  // step 2 s: velocities in units of 0.5 m/s, reach 2 m
    auto g = constant_acceleration_base(env, p, accel);
    ASSERT_DOUBLE_EQ(g->step_time(), 2.0);
    DynamicGameParams dp;
    dp.accel = accel;
    dp.step = ObserverStep::ConstantAcceleration;
    dp.threads = 1 + trial % 2;
    const DynamicVisibilityGame d(g, dp);
    ASSERT_EQ(d.accel_steps(), 1);
    ASSERT_EQ(d.num_velocities(), 13u);
    ASSERT_EQ(d.velocity(2), (std::array<int, 2>{-1, -1}));  // the brute force's order: rows of j, then i
    ASSERT_DOUBLE_EQ(d.velocity_unit(), 0.5);
    std::vector<std::uint32_t> moves;
    std::size_t hull_refusals = 0;
    const auto want = brute_force_constant_acceleration(env, *g, moves, hull_refusals);
    const std::size_t n = g->num_points(), V = d.num_velocities();
    for (std::uint32_t o = 0; o < n; ++o)
      for (std::uint32_t v = 0; v < V; ++v)
        for (std::uint32_t w = 0; w < V; ++w)
          ASSERT_EQ(d.destination(o, v, w), moves[(o * V + v) * V + w]) << "trial " << trial << " o " << o << " v " << v << " w " << w;
    if (trial % 2) {
      EXPECT_GT(hull_refusals, 0u) << "trial " << trial << ": the pillar lies in no parabola's hull";
    }
    with_both += expect_equal_states(d, want, trial);
    if (HasFailure()) return;
  }
  EXPECT_GE(with_both, 3);
}

// A move whose three sides are free but whose parabola's hull holds a pillar is refused;
// the same move without the pillar lands where o + (W + W') h says.
TEST(DynamicVisibilityGame, ConstantAccelerationRefusesAParabolaWhoseHullHoldsAPillar) {
  GameParams p;
  p.resolution = 0.5;
  DynamicGameParams dp;
  dp.accel = 0.25;
  dp.step = ObserverStep::ConstantAcceleration;
  // From (1, 1) at W = (1, 0) choosing W' = (0, 1): the triangle (1, 1), (1.5, 1), (1.5, 1.5).
  const Environment open = rect_room(4, 3), pillar = rect_room(4, 3, {box(1.35, 1.05, 1.45, 1.15)});
  for (const Environment* env : {&open, &pillar}) {
    auto g = constant_acceleration_base(*env, p, dp.accel);
    const DynamicVisibilityGame d(g, dp);
    const std::uint32_t o = g->nearest(Point(1, 1)), v = velocity_index(d, {1, 0}), w = velocity_index(d, {0, 1});
    ASSERT_NE(v, DynamicVisibilityGame::kNone);
    ASSERT_NE(w, DynamicVisibilityGame::kNone);
    const std::uint32_t q = d.destination(o, v, w);
    if (env == &open) {
      ASSERT_NE(q, DynamicVisibilityGame::kNone);
      EXPECT_EQ(g->point(q), Point(1.5, 1.5));
      EXPECT_EQ(d.destination(o, v, velocity_index(d, {-1, 0})), DynamicVisibilityGame::kNone) << "not next to (1, 0)";
    } else {
      EXPECT_EQ(q, DynamicVisibilityGame::kNone) << "the parabola passes the pillar";
      EXPECT_TRUE(geometry::visible(*env, Point(1, 1), Point(1.5, 1.5))) << "all three sides are free";
    }
  }
}

TEST(DynamicVisibilityGame, ConstantAccelerationRefusesAStepTheAccelerationDoesNotMakeWhole) {
  const Environment env = rect_room(3, 3);
  GameParams p;
  p.resolution = 0.5;
  auto g = std::make_shared<const VisibilityGame>(env, p);  // the usual step, 2.83 s at 0.5 m
  DynamicGameParams dp;
  dp.accel = 0.25;
  dp.step = ObserverStep::ConstantAcceleration;
  try {
    DynamicVisibilityGame d(g, dp);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("2 s"), std::string::npos) << e.what();
  }
  p.step_time = 2;
  p.speed_ratio = 0.5;
  auto ok = std::make_shared<const VisibilityGame>(env, p);
  EXPECT_NO_THROW(DynamicVisibilityGame(ok, dp));
  EXPECT_DOUBLE_EQ(ok->target_reach(), 1.0);
  EXPECT_DOUBLE_EQ(ok->observer_reach(), 2.0);
  p.step_time = -1;
  EXPECT_THROW(VisibilityGame(env, p), InputError);
  p.step_time = 0.5;  // the target would move 0.25 m, half a grid step: it could not move at all
  EXPECT_THROW(VisibilityGame(env, p), InputError);
}

// The constant-acceleration game of a plan moved by an exact offset (coordinates in
// eighths of a metre) has the same moves and values, state for state: the hull test
// compares grid points and vertices that move together.
TEST(DynamicVisibilityGame, ConstantAccelerationGivesTheSameAnswersWhereverThePlanSits) {
  auto room = [](double d) {
    auto at = [d](double x, double y) { return Point(x + d, y + d); };
    return Environment::make({at(0, 0), at(4.5, 0), at(4.5, 3), at(0, 3)},
                             {{at(1.875, 0.5), at(2.5, 0.5), at(2.5, 1.125), at(1.875, 1.125)},
                              {at(3.625, 2.125), at(3.75, 2.125), at(3.75, 2.25), at(3.625, 2.25)}});
  };
  GameParams p;
  p.resolution = 0.5;
  p.range = std::numeric_limits<double>::infinity();
  DynamicGameParams dp;
  dp.accel = 0.25;
  dp.step = ObserverStep::ConstantAcceleration;
  const Environment here = room(0);
  const DynamicVisibilityGame origin(constant_acceleration_base(here, p, dp.accel), dp);
  ASSERT_GT(origin.stats().winning, 0u);
  ASSERT_LT(origin.stats().winning, origin.stats().seen);
  const std::size_t n = origin.game().num_points(), V = origin.num_velocities();
  for (double d : {5e5, 4e6, 2e7, 1e10, 1e12 - 16}) {
    const Environment there = room(d);
    const DynamicVisibilityGame moved(constant_acceleration_base(there, p, dp.accel), dp);
    ASSERT_EQ(moved.game().num_points(), n) << d;
    for (std::uint32_t o = 0; o < n; ++o)
      for (std::uint32_t v = 0; v < V; ++v) {
        for (std::uint32_t w = 0; w < V; ++w) ASSERT_EQ(moved.destination(o, v, w), origin.destination(o, v, w)) << d;
        for (std::uint32_t t = 0; t < n; ++t) ASSERT_EQ(moved.escape_steps(o, v, t), origin.escape_steps(o, v, t)) << d;
      }
  }
}
