// SPDX-License-Identifier: Apache-2.0
// The visibility game with the observer's velocity in the state: against a brute-force
// value iteration written from its definition, against the game without dynamics (equal
// when the acceleration reaches every velocity in one step, contained in it otherwise),
// an observer too fast to stop before a wall, and refused resolutions.
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
// 1 + min over target moves t' of max over velocities v' (integer, |v'|^2 <= 8, each
// component within `a` of v's) whose point o + v' h exists and is seen from o
// (geometry::visible) of V_k(o + v', v', t').
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
  std::vector<std::uint32_t> dest(n * V);
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::size_t v = 0; v < V; ++v) {
      const std::uint32_t q = point_at(Point(g.point(o).x() + vel[v][0] * h, g.point(o).y() + vel[v][1] * h));
      dest[o * V + v] = q != VisibilityGame::kNoPoint && geometry::visible(env, g.point(o), g.point(q)) ? q : VisibilityGame::kNoPoint;
    }
  std::vector<std::uint32_t> val(n * n * V);
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::size_t v = 0; v < V; ++v)
      for (std::uint32_t t = 0; t < n; ++t) val[(o * V + v) * n + t] = g.escape_steps(o, t) == 0 ? 0 : kForever;
  for (bool changed = true; changed;) {
    changed = false;
    auto w = val;
    for (std::uint32_t o = 0; o < n; ++o)
      for (std::size_t v = 0; v < V; ++v)
        for (std::uint32_t t = 0; t < n; ++t) {
          if (g.escape_steps(o, t) == 0) continue;
          std::uint32_t worst = kForever;
          for (std::uint32_t tp : g.target_moves(t)) {
            std::uint32_t best = 0;
            for (std::size_t u = 0; u < V; ++u) {
              if (std::abs(vel[u][0] - vel[v][0]) > a || std::abs(vel[u][1] - vel[v][1]) > a) continue;
              const std::uint32_t q = dest[o * V + u];
              if (q != VisibilityGame::kNoPoint) best = std::max(best, val[(q * V + u) * n + tp]);
            }
            worst = std::min(worst, best);
          }
          const std::uint32_t value = worst == kForever ? kForever : worst + 1;
          if (value != w[(o * V + v) * n + t]) w[(o * V + v) * n + t] = value, changed = true;
        }
    val.swap(w);
  }
  return val;
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
    const auto want = brute_force(env, *g, a);
    const std::size_t n = g->num_points(), V = d.num_velocities();
    std::size_t keep = 0, lose = 0;
    for (std::uint32_t o = 0; o < n; ++o)
      for (std::uint32_t v = 0; v < V; ++v)
        for (std::uint32_t t = 0; t < n; ++t) {
          const std::uint32_t w = want[(o * V + v) * n + t];
          ASSERT_EQ(d.escape_steps(o, v, t), w) << "trial " << trial << " o " << o << " v " << v << " t " << t;
          keep += w == kForever;
          lose += w != kForever && w > 1;
        }
    with_both += keep > 0 && lose > 0;
    EXPECT_EQ(d.stats().winning, keep);
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
TEST(DynamicVisibilityGame, ItsPoliciesRealiseTheValues) {
  const Environment env = rect_room(6, 4, {box(2.5, 1.5, 3.5, 2.5)});
  const GameParams p = pillar_game_params();
  auto g = std::make_shared<const VisibilityGame>(env, p);
  DynamicGameParams dp;
  dp.accel = unit_accel(p.resolution);
  const DynamicVisibilityGame d(g, dp);
  std::mt19937_64 rng(3);
  const std::size_t n = g->num_points();
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
      else o = d.destination(o, w), v = w, alive = d.escape_steps(o, v, t) != 0;
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
