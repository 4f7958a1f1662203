// The landmark robot's strategies 2, 3, 6 and 8 against the ground truth from
// coordinates (OrderType, SwapCellDecomposition, brute force). The strategies see only
// RobotInterface; the simulator checks its own event bookkeeping by angular sorts.
#include <preimage/error.hpp>
#include <preimage/landmarks/strategies.hpp>
#include <preimage/landmarks/swap_cells.hpp>

#include <gtest/gtest.h>
#include <support/landmark_robot.hpp>

#include <cmath>
#include <map>
#include <random>
#include <set>

using namespace preimage;
using geometry::Point;
using landmarks::OrderType;
using landmarks::Reading;
using landmarks::Simulator;
using landmarks::StopRule;
using preimage::testing::generic_start;

namespace {

Simulator checked_robot(const std::vector<Point>& P, std::uint64_t seed) {
  Simulator robot(P, generic_start(P, seed));
  robot.set_self_check(true);
  return robot;
}

landmarks::Chirotope truth(const OrderType& T) {
  return [&T](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return T.chi(i, j, k); };
}

}  // namespace

TEST(LandmarkStrategies, TracesAgreeWithAngularSortsAndSwapsAreAdjacent) {
  // Self-checking simulator: every reading of every piece is recomputed by a sort.
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const std::size_t n = 4 + seed;
    const auto P = landmarks::random_landmarks(n, seed, 1000);
    Simulator robot = checked_robot(P, seed);
    std::mt19937_64 rng(seed);
    for (int step = 0; step < 30; ++step) {
      const std::uint32_t i = static_cast<std::uint32_t>(rng() % n);
      std::uint32_t j = static_cast<std::uint32_t>(rng() % n);
      if (j == i) j = (j + 1) % n;
      const auto t = robot.track(i, StopRule::arrive());
      ASSERT_EQ(t.readings.size(), t.events.size() + 1);
      if (step % 3 == 0) {
        const auto r = robot.repel(i, j, StopRule::arrive());
        // Along the swap line i and j stay aligned, next to each other.
        for (const auto& x : r.readings) EXPECT_TRUE(landmarks::follows(x, i, j) || landmarks::follows(x, j, i));
      }
    }
  }
}

TEST(LandmarkStrategies, Strategy2IsRobustBelowAQuarterTurn) {
  std::mt19937_64 rng(5);
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto P = landmarks::random_landmarks(6, seed, 1000);
    const OrderType T = OrderType::of(P);
    Simulator robot(P, std::uint32_t{0});
    std::uniform_real_distribution<double> e(-1.55, 1.55);  // below pi / 2
    robot.set_heading_error([&] { return e(rng); });
    EXPECT_EQ(landmarks::triangle_orientation(robot, 0, 1, 2), T.chi(0, 1, 2)) << "seed " << seed;
  }
}

TEST(LandmarkStrategies, Strategy2CanFailBetweenAQuarterAndOneThirdTurn) {
  // Angles 72, 72, 36 degrees: with an error of 110 degrees (below the paper's 2 pi / 3)
  // both base vertices can vote wrong; at 80 degrees no signs can fool the vote.
  const double h = std::tan(72.0 * M_PI / 180.0);
  const std::vector<Point> P{Point(0, 0), Point(2, 0), Point(1, h)};
  auto fooled = [&](double degrees) {
    for (int signs = 0; signs < 8; ++signs) {
      Simulator robot(P, std::uint32_t{0});
      int call = 0;
      robot.set_heading_error([&] { return ((signs >> (call++ % 3)) & 1 ? 1 : -1) * degrees * M_PI / 180.0; });
      if (landmarks::triangle_orientation(robot, 0, 1, 2) != 1) return true;
    }
    return false;
  };
  EXPECT_TRUE(fooled(110));
  EXPECT_FALSE(fooled(80));
}

TEST(LandmarkStrategies, Strategy3TellsTheNearerLandmarkOfASwapLine) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const std::size_t n = 4 + seed % 5;
    const auto P = landmarks::random_landmarks(n, seed, 1000);
    const OrderType T = OrderType::of(P);
    const std::uint32_t i = 0, j = 1;
    std::uint32_t k = 2;
    while (T.chi(i, j, k) < 0 && k + 1 < n) ++k;
    // On the swap line beyond p_i, and on the one beyond p_j.
    Reading beyond_i, beyond_j;
    {
      Simulator robot(P, i);
      robot.repel(i, j, StopRule::arrive());
      beyond_i = robot.track(k, StopRule::arrive()).readings.front();
      robot.track(i);
      robot.repel(i, j, StopRule::arrive());
      EXPECT_EQ(landmarks::nearer_on_swap_line(robot, i, j), i);
    }
    {
      Simulator robot(P, j);
      robot.repel(j, i, StopRule::arrive());
      beyond_j = robot.track(k, StopRule::arrive()).readings.front();
      robot.track(j);
      robot.repel(j, i, StopRule::arrive());
      EXPECT_EQ(landmarks::nearer_on_swap_line(robot, i, j), j);
    }
    // The paper's reading after stepping towards k: the pair's order is the same on both
    // lines (it depends only on the side), so it cannot tell.
    EXPECT_EQ(landmarks::follows(beyond_i, i, j), landmarks::follows(beyond_j, i, j));
  }
}

TEST(LandmarkStrategies, HullTourLearnsTheWholeOrderTypeWithLinearlyManyTracks) {
  for (std::size_t n : {3, 4, 7, 15, 40, 90}) {
    const auto P = landmarks::random_landmarks(n, n, 1 << 16);
    const OrderType T = OrderType::of(P);
    Simulator robot(P, generic_start(P, n, 1 << 17));
    const auto tour = landmarks::learn_by_hull_tour(robot);
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t k = 0; k < n; ++k) ASSERT_EQ(tour.order_type.chi(i, j, k), T.chi(i, j, k)) << n;
    EXPECT_LE(robot.primitives(), 4 * n + 4) << n;  // Strategies 4-5 (3n + 4) and one tour
    // Lemma 4 on the dual permutations: first and last are hull landmarks.
    const auto hull = T.hull();
    for (const auto& p : tour.permutations) {
      EXPECT_NE(std::find(hull.begin(), hull.end(), p.front()), hull.end());
      EXPECT_NE(std::find(hull.begin(), hull.end(), p.back()), hull.end());
    }
  }
}

TEST(LandmarkStrategies, PatrolRouteIsTheSmallestEnclosingSet) {
  int checked = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const std::size_t n = 7 + seed % 4;
    const auto P = landmarks::random_landmarks(n, seed, 1000);
    const OrderType T = OrderType::of(P);
    const auto hull = T.hull();
    std::vector<std::uint32_t> interior;
    for (std::uint32_t k = 0; k < n; ++k)
      if (std::find(hull.begin(), hull.end(), k) == hull.end()) interior.push_back(k);
    if (interior.empty()) continue;
    std::mt19937_64 rng(seed);
    std::vector<std::uint32_t> W{interior[rng() % interior.size()]};
    if (interior.size() > 2 && seed % 2) W.push_back(interior[(std::find(interior.begin(), interior.end(), W[0]) - interior.begin() + 1) % interior.size()]);
    const auto plan = landmarks::patrol_route(n, truth(T), hull, W);
    // Brute force: the fewest landmarks (not watched) with every watched one strictly
    // inside their hull.
    std::vector<std::uint32_t> others;
    for (std::uint32_t k = 0; k < n; ++k)
      if (std::find(W.begin(), W.end(), k) == W.end()) others.push_back(k);
    std::size_t best = others.size() + 1;
    for (std::uint32_t mask = 1; mask < (1U << others.size()); ++mask) {
      std::vector<Point> S;
      for (std::size_t q = 0; q < others.size(); ++q)
        if (mask >> q & 1) S.push_back(P[others[q]]);
      if (S.size() < 3 || S.size() >= best) continue;
      const auto H = OrderType::of(S).hull();
      bool all = true;
      for (auto w : W)
        for (std::size_t q = 0; q < H.size() && all; ++q) all = geometry::orientation(S[H[q]], S[H[(q + 1) % H.size()]], P[w]) > 0;
      if (all) best = S.size();
    }
    EXPECT_EQ(plan.route.size(), best) << "seed " << seed;
    // The route is the hull of M, counter-clockwise, and keeps W strictly inside.
    for (std::size_t q = 0; q < plan.route.size(); ++q)
      for (auto w : W) EXPECT_GT(T.chi(plan.route[q], plan.route[(q + 1) % plan.route.size()], w), 0);
    // Learned from the hull tour, the robot plans the same route.
    Simulator robot(P, generic_start(P, seed));
    const auto tour = landmarks::learn_by_hull_tour(robot);
    EXPECT_EQ(landmarks::patrol_route(n, tour.order_type.chirotope(), tour.hull, W).route, plan.route);
    ++checked;
  }
  EXPECT_GE(checked, 20);
  const auto P = landmarks::random_landmarks(8, 3, 1000);
  const OrderType T = OrderType::of(P);
  EXPECT_THROW(landmarks::patrol_route(8, truth(T), T.hull(), std::vector<std::uint32_t>{T.hull()[0]}), InputError);
}

// Strategies 7 and 9: test_navigation.cpp.
TEST(LandmarkStrategies, Strategy8LearnsTheSwapGraphInsideTheHull) {
  for (std::uint64_t seed = 1; seed <= 14; ++seed) {
    const std::size_t n = 3 + seed % 7;
    const auto P = landmarks::random_landmarks(n, seed, 1000);
    const auto D = landmarks::SwapCellDecomposition::of(P);
    Simulator robot = checked_robot(P, seed);
    const auto tour = landmarks::learn_by_hull_tour(robot);
    const auto inside = landmarks::learn_inside_swap_graph(robot, tour.order_type.chirotope(), tour.hull);
    // Strategy 8: exactly the cells meeting the hull, and the edges across pieces inside.
    std::set<Reading> true_inside, learned_inside;
    for (const auto& c : D.cells())
      if (c.meets_hull) true_inside.insert(c.permutation);
    for (const auto& c : inside.cells) learned_inside.insert(c.permutation);
    EXPECT_EQ(learned_inside, true_inside) << "seed " << seed;
    std::set<std::pair<Reading, Reading>> true_edges, learned_edges;
    for (const auto& e : D.swap_graph())
      if (e.meets_hull) true_edges.insert(std::minmax(D.cells()[e.a].permutation, D.cells()[e.b].permutation));
    for (const auto& e : inside.edges) learned_edges.insert(std::minmax(inside.cells[e.a].permutation, inside.cells[e.b].permutation));
    EXPECT_EQ(learned_edges, true_edges) << "seed " << seed;
  }
}
