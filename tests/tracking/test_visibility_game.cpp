// SPDX-License-Identifier: Apache-2.0
// The visibility game against a brute-force value iteration, known answers (an open room,
// one convex obstacle, a thin wall), its own policies played out, and refinement.
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/tracking/evaluation.hpp>
#include <preimage/tracking/dynamic_visibility_game.hpp>
#include <preimage/tracking/visibility_game.hpp>

#include <gtest/gtest.h>
#include <support/rooms.hpp>

#include <algorithm>
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

double dist(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

// Synchronous value iteration, written from the game's definition alone: V_0 = 0 where
// the observer does not see the target, infinity elsewhere; V_{k+1}(o, t) = 0 if not
// seen, else 1 + min over target moves t' of max over observer moves o' of V_k(o', t').
// Moves and sight from geometry::visible and distances, not from the solver's tables.
std::vector<std::uint32_t> brute_force(const Environment& env, const VisibilityGame& g) {
  const std::size_t n = g.num_points();
  const GameParams& p = g.params();
  auto moves = [&](double reach) {
    std::vector<std::vector<std::uint32_t>> m(n);
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = 0; b < n; ++b)
        if (dist(g.point(a), g.point(b)) <= reach * (1 + 1e-9) && geometry::visible(env, g.point(a), g.point(b)))
          m[a].push_back(b);
    return m;
  };
  // Where the target's disc fits: its centre at least target_radius from every edge,
  // from CGAL's exact squared distance.
  std::vector<char> fits(n, 1);
  const geometry::ExactFT r2 = geometry::ExactFT(p.target_radius) * geometry::ExactFT(p.target_radius);
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::size_t e = 0; e < env.num_vertices(); ++e)
      if (CGAL::squared_distance(geometry::to_exact(g.point(a)),
                                 geometry::ExactKernel::Segment_2(env.exact_vertex(e), env.exact_vertex(env.next(e)))) < r2)
        fits[a] = 0;
  for (std::uint32_t a = 0; a < n; ++a) EXPECT_EQ(g.target_may_stand(a), fits[a] != 0) << "point " << a;
  auto mo = moves(g.observer_reach()), mt = moves(g.target_reach());
  for (std::uint32_t a = 0; a < n; ++a) {
    if (!fits[a]) mt[a].clear();
    std::erase_if(mt[a], [&](std::uint32_t b) { return !fits[b]; });
  }
  std::vector<char> seen(n * n);
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::uint32_t t = 0; t < n; ++t) {
      const double d = dist(g.point(o), g.point(t));
      bool grazes = false;  // a sight line through an obstacle corner does not count
      for (const Point& v : env.vertices()) grazes = grazes || (CGAL::collinear(g.point(o), v, g.point(t)) && CGAL::collinear_are_strictly_ordered_along_line(g.point(o), v, g.point(t)));
      seen[o * n + t] = fits[t] && d >= p.separation && d <= p.range && geometry::visible(env, g.point(o), g.point(t)) && !grazes;
    }
  std::vector<std::uint32_t> v(n * n);
  for (std::size_t s = 0; s < n * n; ++s) v[s] = seen[s] ? kForever : 0;
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<std::uint32_t> w = v;
    for (std::uint32_t o = 0; o < n; ++o)
      for (std::uint32_t t = 0; t < n; ++t) {
        if (!seen[o * n + t]) continue;
        std::uint32_t worst = kForever;
        for (std::uint32_t tp : mt[t]) {
          std::uint32_t best = 0;
          for (std::uint32_t op : mo[o]) best = std::max(best, v[op * n + tp]);
          worst = std::min(worst, best);
        }
        const std::uint32_t value = worst == kForever ? kForever : worst + 1;
        if (value != w[o * n + t]) {
          w[o * n + t] = value;
          changed = true;
        }
      }
    v.swap(w);
  }
  return v;
}

}  // namespace

TEST(VisibilityGame, MatchesBruteForceValueIterationOnRandomRooms) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0.3, 4.2);
  int with_both = 0;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<geometry::Ring> holes;
    for (int b = 0; b < 1 + trial % 3; ++b) {
      const double x = U(rng), y = U(rng) * 0.7;
      const auto hole = box(x, y, x + 0.3 + 0.1 * (trial % 4), y + 0.2 + 0.3 * (b % 2));
      bool clear = hole[2].x() < 4.8 && hole[2].y() < 3.3;
      for (const auto& h : holes) clear = clear && (hole[0].x() > h[2].x() + 0.1 || hole[2].x() < h[0].x() - 0.1 ||
                                                     hole[0].y() > h[2].y() + 0.1 || hole[2].y() < h[0].y() - 0.1);
      if (clear) holes.push_back(hole);
    }
    const Environment env = rect_room(5, 3.5, holes);
    GameParams p;
    p.resolution = 0.5;
    p.speed_ratio = trial % 2 ? 0.5 : 1.0;
    p.range = trial % 3 == 0 ? std::numeric_limits<double>::infinity() : 2.5;
    p.threads = 1 + trial % 2;
    p.target_radius = trial % 4 == 3 ? 0 : 0.2 + 0.1 * (trial % 2);
    const VisibilityGame g(env, p);
    const auto want = brute_force(env, g);
    const std::size_t n = g.num_points();
    std::size_t keep = 0, lose = 0;
    for (std::uint32_t o = 0; o < n; ++o)
      for (std::uint32_t t = 0; t < n; ++t) {
        ASSERT_EQ(g.escape_steps(o, t), want[o * n + t]) << "trial " << trial << " o " << o << " t " << t;
        keep += want[o * n + t] == kForever;
        lose += want[o * n + t] != kForever && want[o * n + t] > 1;
      }
    with_both += keep > 0 && lose > 0;
    EXPECT_EQ(g.stats().winning, keep);
  }
  EXPECT_GE(with_both, 6);  // the comparison saw both kinds of state with escape times > 1
}

TEST(VisibilityGame, EveryFreeGridPointIsAPlayerPosition) {
  const Environment env = rect_room(5, 3.5, {box(1, 1, 2, 2)});
  GameParams p;
  p.resolution = 0.25;
  const VisibilityGame g(env, p);
  std::size_t free = 0;
  for (int j = 0; j * 0.25 <= 3.5; ++j)
    for (int i = 0; i * 0.25 <= 5; ++i) {
      const Point q(i * 0.25, j * 0.25);
      if (geometry::locate(env, q).kind != geometry::Location::Kind::Interior) continue;
      ++free;
      const std::uint32_t k = g.nearest(q);
      ASSERT_NE(k, VisibilityGame::kNoPoint);
      EXPECT_EQ(g.point(k), q);
    }
  EXPECT_EQ(g.num_points(), free);
}

TEST(VisibilityGame, AnOpenRoomIsKeptForeverAtAnySpeedRatioUpToOne) {
  const Environment env = rect_room(6, 4);
  for (double ratio : {0.5, 1.0}) {
    GameParams p;
    p.resolution = 0.25;
    p.speed_ratio = ratio;
    p.range = std::numeric_limits<double>::infinity();
    const VisibilityGame g(env, p);
    // Nothing blocks the view: every state that is not already a loss is kept.
    EXPECT_EQ(g.stats().winning, g.stats().seen) << "ratio " << ratio;
    EXPECT_GT(g.stats().winning, g.stats().states * 9 / 10);
  }
}

TEST(VisibilityGame, AnOpenRoomWithALimitedRangeIsKeptWellInsideTheRange) {
  const Environment env = rect_room(8, 6);
  GameParams p;
  p.resolution = 0.25;
  p.speed_ratio = 0.5;
  p.range = 2.0;
  const VisibilityGame g(env, p);
  std::size_t inside = 0, kept = 0, outside_kept = 0;
  for (std::uint32_t o = 0; o < g.num_points(); ++o)
    for (std::uint32_t t = 0; t < g.num_points(); ++t) {
      const double d = dist(g.point(o), g.point(t));
      // The observer, twice as fast, closes in as the target leaves: every state with
      // room for one target step before the range and one observer step before the
      // separation is kept.
      if (d >= p.separation + g.observer_reach() && d <= p.range - g.target_reach()) {
        ++inside;
        kept += g.keeps(o, t);
      }
      if (d > p.range) outside_kept += g.keeps(o, t);
    }
  EXPECT_GT(inside, 0u);
  EXPECT_EQ(kept, inside);
  EXPECT_EQ(outside_kept, 0u);
}

TEST(VisibilityGame, OneConvexObstacleFarFromTheWallsIsKeptAtHalfSpeed) {
  // A 2 x 2 m box in the middle of a 14 x 14 m room: the observer, twice as fast, circles
  // outside the target. Wherever the target stands, some observer position keeps it.
  const Environment env = rect_room(14, 14, {box(6, 6, 8, 8)});
  GameParams p;
  p.resolution = 0.5;
  p.speed_ratio = 0.5;
  p.range = std::numeric_limits<double>::infinity();
  const VisibilityGame g(env, p);
  for (std::uint32_t t = 0; t < g.num_points(); ++t) EXPECT_FALSE(g.keeping_observers(t).empty()) << "target " << t;
  // A target hugging the box's side, the observer across the room in line with that side:
  // kept (the observer is on the far side of the line the target would need to cross).
  const std::uint32_t t = g.nearest(Point(7, 8.5)), o = g.nearest(Point(7, 13));
  EXPECT_TRUE(g.keeps(o, t));
  // At speed ratio 2 (the target twice as fast) the same scene has escapes from most states.
  p.speed_ratio = 2.0;
  const VisibilityGame fast(env, p);
  EXPECT_LT(fast.stats().winning, g.stats().winning);
}

TEST(VisibilityGame, ATargetBesideTheEndOfAThinWallEscapesInOneStep) {
  // A wall 0.1 m thick from y = 1 to y = 4 at x = 5. The observer at (1, 2.5) sees the
  // target at (5.25, 4.25), just past the wall's top end; one diagonal step to (5.5, 4)
  // puts the wall in between, and no observer move of 0.71 m sees round it.
  const Environment env = rect_room(10, 6, {box(4.95, 1, 5.05, 4)});
  GameParams p;
  p.resolution = 0.25;
  p.speed_ratio = 0.5;
  const VisibilityGame g(env, p);
  const std::uint32_t o = g.nearest(Point(1, 2.5)), t = g.nearest(Point(5.25, 4.25));
  ASSERT_EQ(g.point(o), Point(1, 2.5));
  ASSERT_EQ(g.point(t), Point(5.25, 4.25));
  EXPECT_EQ(g.escape_steps(o, t), 1u);
  const std::uint32_t escape = g.target_policy(o, t);
  EXPECT_EQ(g.answer_value(o, escape), 0u);
  // Seen from above the wall's end instead, the same target is kept.
  EXPECT_TRUE(g.keeps(g.nearest(Point(5.25, 5.5)), t));
}

TEST(VisibilityGame, ItsPoliciesRealiseTheValues) {
  // In the tracking example box scene: from every kept state the game's observer keeps the
  // target 200 steps against the game's target and a random one; from every other state
  // the game's target escapes in exactly escape_steps against the game's observer.
  const auto sc = scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/tracking/box.json");
  GameParams p;
  p.resolution = 0.5;
  const VisibilityGame g(sc.require_environment(), p);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<std::uint32_t> P(0, static_cast<std::uint32_t>(g.num_points() - 1));
  std::size_t kept = 0, lost = 0;
  for (int k = 0; k < 4000; ++k) {
    const std::uint32_t o = P(rng), t = P(rng);
    const std::uint32_t value = g.escape_steps(o, t);
    const auto optimal = [&](std::uint32_t a, std::uint32_t b) { return g.target_policy(a, b); };
    const auto random = [&](std::uint32_t, std::uint32_t b) {
      const auto m = g.target_moves(b);
      return m[std::uniform_int_distribution<std::size_t>(0, m.size() - 1)(rng)];
    };
    if (value == kForever) {
      ASSERT_EQ(play(g, o, t, 200, optimal), kForever) << o << " " << t;
      ASSERT_EQ(play(g, o, t, 200, random), kForever) << o << " " << t;
      ++kept;
    } else {
      ASSERT_EQ(play(g, o, t, 100000, optimal), value) << o << " " << t;
      ++lost;
    }
  }
  EXPECT_GT(kept, 100u);
  EXPECT_GT(lost, 100u);
}

TEST(VisibilityGame, RefiningTheGridKeepsTheWinningRegionUpToTheResolution) {
  // Every state kept on the 0.5 m grid (whose points are also points of the 0.25 m grid)
  // has, on the finer grid, a keeping observer within one coarse observer step: refining
  // moves the region's border by about the resolution, it does not make it vanish. Every
  // gap between obstacles is at least twice the coarse resolution: a passage narrower than
  // that has no coarse grid point in it, so the coarse target cannot use it (a gap of
  // 0.5 m under the second box made the fine game lose states 2 m from any fine keeper).
  const Environment env = rect_room(6, 4, {box(2, 1.5, 3, 2.5), box(4.2, 1.0, 4.6, 2.2)});
  GameParams p;
  p.resolution = 0.5;
  p.range = 4;
  const VisibilityGame coarse(env, p);
  p.resolution = 0.25;
  const VisibilityGame fine(env, p);
  std::size_t kept = 0, same = 0;
  for (std::uint32_t o = 0; o < coarse.num_points(); ++o)
    for (std::uint32_t t = 0; t < coarse.num_points(); ++t) {
      if (!coarse.keeps(o, t)) continue;
      ++kept;
      const std::uint32_t fo = fine.nearest(coarse.point(o)), ft = fine.nearest(coarse.point(t));
      ASSERT_EQ(fine.point(fo), coarse.point(o));
      same += fine.keeps(fo, ft);
      bool near = false;
      for (std::uint32_t a : fine.keeping_observers(ft)) near = near || dist(fine.point(a), coarse.point(o)) <= coarse.observer_reach();
      EXPECT_TRUE(near) << "coarse state (" << o << ", " << t << ")";
    }
  EXPECT_GT(kept, 1000u);
  EXPECT_GT(same, kept * 4 / 5);  // 2,075 of 2,307 (90 %) keep the very same state
}

TEST(VisibilityGame, RefusesBadParametersAndHugeGrids) {
  const Environment env = rect_room(6, 4);
  GameParams p;
  p.resolution = 0;
  EXPECT_THROW(VisibilityGame(env, p), InputError);
  p.resolution = 0.25;
  p.speed_ratio = -1;
  EXPECT_THROW(VisibilityGame(env, p), InputError);
  p.speed_ratio = 0.5;
  p.max_states = 1000;
  EXPECT_THROW(VisibilityGame(env, p), InputError);
}

TEST(GameStrategy, KeepsTheAdversaryFromTheBoxsWinnableStarts) {
  // The finding behind the game strategy's design (docs/tracking.md, "Ground truth"): on
  // the 0.125 m grid, the holonomic observer that steers for the deepest keeping grid
  // point keeps the shortest-escape-path adversary from every start the game keeps
  // (before depth, it lost them all in 2-7 s), where TRACK's risk controller keeps none.
  const auto sc = scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/tracking/box.json");
  const TrackingScenario scenario = TrackingScenario::from_scene(sc);
  SimulationParams p;
  p.policy = TargetPolicy::Adversarial;
  p.steps = 300;
  p.start_spread = 0.5;
  p.heading_spread = 15 * M_PI / 180;
  p.stop_at_escape = true;
  GameParams gp = game_params(scenario, p, 0.125);
  p.game = std::make_shared<const VisibilityGame>(*scenario.environment, gp);
  std::size_t winnable = 0, kept_game = 0, kept_risk = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    p.seed = seed;
    p.strategy = Strategy::Game;
    const SimulationResult game = simulate(scenario, p);
    const std::uint32_t o = p.game->nearest(game.observer.front().position), t = p.game->nearest(game.target.front());
    if (!p.game->keeps(o, t)) continue;
    ++winnable;
    kept_game += game.escape_time < 0;
    p.strategy = Strategy::Risk;
    kept_risk += simulate(scenario, p).escape_time < 0;
  }
  EXPECT_GE(winnable, 3u);
  EXPECT_EQ(kept_game, winnable);
  EXPECT_LT(kept_risk, winnable);
}

TEST(GameStrategy, EvaluationCountsWinnableStartsAndTheGridPolicyKeepsThemAll) {
  const auto sc = scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/tracking/box.json");
  EvaluationParams ep;
  ep.seeds = 6;
  ep.steps = 30;
  ep.fovs = {360};
  ep.dynamics = {false};
  ep.policies = {TargetPolicy::Game};
  ep.strategies = {Strategy::Risk, Strategy::Game};
  ep.game_resolution = 0.5;
  ep.jobs = 2;
  const auto cells = evaluate({TrackingScenario::from_scene(sc)}, ep);
  ASSERT_EQ(cells.size(), 2u);
  for (const auto& c : cells) {
    ASSERT_EQ(c.winnable.size(), 6u);
    EXPECT_EQ(c.winnable_runs, static_cast<std::size_t>(std::count(c.winnable.begin(), c.winnable.end(), 1)));
    EXPECT_GT(c.winnable_runs, 0u);
    EXPECT_EQ(c.grid_kept, c.winnable_runs);  // the game's own policy, on its own grid
    EXPECT_LE(c.kept_winnable, c.winnable_runs);
    EXPECT_EQ(c.winnable, cells.front().winnable);  // the same starts for every strategy
  }
}

// With dynamics the evaluation judges each start in the game with the observer's
// velocity in the state (the robot's own constant-acceleration step, at rest at the
// start), the same starts for every strategy, and that game's own policies keep every
// start it calls winnable on its grid; the cells without dynamics keep the game without.
TEST(GameStrategy, WithDynamicsTheEvaluationJudgesStartsWithTheObserversVelocity) {
  const auto sc = scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/tracking/box.json");
  const TrackingScenario scenario = TrackingScenario::from_scene(sc);
  EvaluationParams ep;
  ep.seeds = 6;
  ep.steps = 30;
  ep.fovs = {360};
  ep.dynamics = {false, true};
  ep.policies = {TargetPolicy::Adversarial};
  ep.strategies = {Strategy::Risk};
  ep.game_resolution = 0.5;
  ep.dynamic_game_resolution = 0.5;
  ep.accel = 1;  // a 1 s step at 0.5 m: the target may move one grid step
  ep.jobs = 2;
  const auto cells = evaluate({scenario}, ep);
  ASSERT_EQ(cells.size(), 2u);
  EXPECT_FALSE(cells[0].observer_dynamics);
  ASSERT_TRUE(cells[1].observer_dynamics);
  EXPECT_EQ(cells[1].game_resolution, 0.5);
  // The same game, solved here: a point target, as the evaluation's.
  SimulationParams p;
  p.policy = TargetPolicy::Adversarial;
  p.steps = 1;
  p.start_spread = ep.start_spread;
  p.heading_spread = ep.heading_spread;
  GameParams gp = game_params(scenario, p, 0.5);
  gp.step_time = DynamicVisibilityGame::constant_acceleration_step(0.5, ep.accel);
  DynamicGameParams dp;
  dp.accel = ep.accel;
  dp.step = ObserverStep::ConstantAcceleration;
  const DynamicVisibilityGame d(std::make_shared<const VisibilityGame>(*scenario.environment, gp), dp);
  std::size_t winnable = 0;
  for (std::uint64_t seed = 1; seed <= ep.seeds; ++seed) {
    p.seed = seed;
    const SimulationResult r = simulate(scenario, p);
    const bool win = d.keeps(d.game().nearest(r.observer.front().position), 0, d.game().nearest_target(r.target.front()));
    EXPECT_EQ(cells[1].winnable[seed - 1] != 0, win) << "seed " << seed;
    winnable += win;
  }
  EXPECT_GT(winnable, 0u);
  EXPECT_EQ(cells[1].winnable_runs, winnable);
  EXPECT_EQ(cells[1].grid_kept, winnable);  // the game's own policies, on its own grid
  // At the evaluation's 0.5 m/s^2 the same starts are all lost: the point target hugs the box.
  ep.accel = 0.5;
  ep.dynamics = {true};
  EXPECT_EQ(evaluate({scenario}, ep).front().winnable_runs, 0u);
}

TEST(VisibilityGame, GivesTheSameAnswersWhereverThePlanSits) {
  // The grid starts at the plan's lower-left corner, so a plan moved by an exact offset
  // (coordinates in eighths of a metre stay exact up to the supported 1e12) gives the same grid points
  // moved, the same sight and clearance decisions and the same values, state for state.
  auto room = [](double d) {
    auto at = [d](double x, double y) { return Point(x + d, y + d); };
    return Environment::make({at(0, 0), at(9, 0), at(9, 6), at(0, 6)},
                             {{at(2.875, 2.25), at(3.5, 2.25), at(3.5, 3.875), at(2.875, 3.875)},
                              {at(5.5, 3.5), at(7.625, 3.5), at(7.625, 3.75), at(5.5, 3.75)}});
  };
  GameParams p;
  p.resolution = 0.25;
  const Environment here = room(0);
  const VisibilityGame origin(here, p);
  ASSERT_GT(origin.stats().winning, 0u);
  ASSERT_LT(origin.stats().winning, origin.stats().seen);
  for (double d : {5e5, 4e6, 2e7, 1e10, 1e12 - 16}) {  // the last just inside the supported range
    const Environment there = room(d);
    const VisibilityGame moved(there, p);
    ASSERT_EQ(moved.num_points(), origin.num_points()) << d;
    for (std::uint32_t i = 0; i < origin.num_points(); ++i) {
      ASSERT_EQ(moved.point(i), Point(origin.point(i).x() + d, origin.point(i).y() + d)) << d;
      ASSERT_EQ(moved.target_may_stand(i), origin.target_may_stand(i)) << d;
    }
    for (std::uint32_t o = 0; o < origin.num_points(); ++o)
      for (std::uint32_t t = 0; t < origin.num_points(); ++t) ASSERT_EQ(moved.escape_steps(o, t), origin.escape_steps(o, t)) << d;
  }
}
