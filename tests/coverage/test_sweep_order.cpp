// SPDX-License-Identifier: Apache-2.0
// The generalised TSP over sweeps: the exact DP against enumeration of every order and
// choice of sweeps; the local search against the exact optimum, and its reported cost and
// lower bound against the walk it returns.
#include <preimage/coverage/sweep_order.hpp>
#include <preimage/geometry/random_point.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

using namespace preimage;
using coverage::Sweep;

namespace {

double euclid(const geometry::Point& a, const geometry::Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

// Transits that are not straight lines: crossing x = 0 costs a detour, as a wall would.
double transit(const geometry::Point& a, const geometry::Point& b) {
  return euclid(a, b) + ((a.x() < 0) != (b.x() < 0) ? 7.5 : 0.0);
}

// Cells scattered in a square, each with up to four sweeps between points near its centre.
std::vector<std::vector<Sweep>> random_cells(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(-50, 50), D(-3, 3);
  std::uniform_int_distribution<int> S(1, 4);
  std::vector<std::vector<Sweep>> cells(n);
  for (auto& c : cells) {
    const double cx = U(rng), cy = U(rng);
    for (int k = S(rng); k-- > 0;) {
      const geometry::Vector centre(cx, cy);
      const geometry::Point a = geometry::random_point(rng, D) + centre, b = geometry::random_point(rng, D) + centre;
      c.push_back({a, b, euclid(a, b) + 10 + D(rng)});
    }
  }
  return cells;
}

double walk_cost(const std::vector<std::vector<Sweep>>& cells, const std::optional<geometry::Point>& start,
                 const std::vector<std::uint32_t>& order, const std::vector<std::uint8_t>& sweeps) {
  double c = 0;
  std::optional<geometry::Point> at = start;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Sweep& s = cells[order[i]][sweeps[i]];
    if (at) c += transit(*at, s.entry);
    c += s.length, at = s.exit;
  }
  return c;
}

// Every order, every choice of sweeps.
double brute_force(const std::vector<std::vector<Sweep>>& cells, const std::optional<geometry::Point>& start) {
  std::vector<std::uint32_t> order(cells.size());
  std::iota(order.begin(), order.end(), 0u);
  double best = INFINITY;
  do {
    std::vector<std::uint8_t> sw(order.size(), 0);
    while (true) {
      best = std::min(best, walk_cost(cells, start, order, sw));
      std::size_t k = 0;
      while (k < sw.size() && ++sw[k] == cells[order[k]].size()) sw[k++] = 0;
      if (k == sw.size()) break;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  return best;
}

void expect_valid(const std::vector<std::vector<Sweep>>& cells, const std::optional<geometry::Point>& start,
                  const coverage::SweepOrder& so) {
  ASSERT_EQ(so.cells.size(), cells.size());
  ASSERT_EQ(so.sweeps.size(), cells.size());
  std::vector<std::uint32_t> sorted = so.cells;
  std::sort(sorted.begin(), sorted.end());
  for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i) << "not a permutation of the cells";
  for (std::size_t i = 0; i < cells.size(); ++i) ASSERT_LT(so.sweeps[i], cells[so.cells[i]].size());
  EXPECT_NEAR(so.cost, walk_cost(cells, start, so.cells, so.sweeps), 1e-9 * (1 + so.cost)) << "reported cost is not the walk's";
  EXPECT_LE(so.lower_bound, so.cost * (1 + 1e-12));
}

}  // namespace

TEST(SweepOrder, ExactDpMatchesEnumeration) {
  std::mt19937_64 rng(41);
  for (int trial = 0; trial < 60; ++trial) {
    const auto cells = random_cells(1 + trial % 6, rng);
    const std::optional<geometry::Point> start =
        trial % 2 ? std::optional<geometry::Point>(geometry::Point(-60, 10)) : std::nullopt;
    const auto so = coverage::order_sweeps(cells, start, transit);
    expect_valid(cells, start, so);
    EXPECT_TRUE(so.optimal);
    EXPECT_NEAR(so.cost, brute_force(cells, start), 1e-9 * (1 + so.cost)) << "trial " << trial;
  }
}

TEST(SweepOrder, LocalSearchIsCloseToTheOptimumAndItsBoundIsBelowIt) {
  std::mt19937_64 rng(43);
  double ratio_sum = 0;
  int trials = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const auto cells = random_cells(8 + trial % 5, rng);
    const std::optional<geometry::Point> start(geometry::Point(0.5, -55));
    const auto opt = coverage::order_sweeps(cells, start, transit);
    const auto heur = coverage::order_sweeps(cells, start, transit, 0);
    expect_valid(cells, start, heur);
    EXPECT_FALSE(heur.optimal);
    EXPECT_GE(heur.cost, opt.cost * (1 - 1e-12)) << "better than the exact optimum: one of them is wrong";
    EXPECT_LE(heur.lower_bound, opt.cost * (1 + 1e-12)) << "the lower bound exceeds the optimum";
    EXPECT_LE(heur.cost, 1.35 * opt.cost) << "trial " << trial;
    ratio_sum += heur.cost / opt.cost, ++trials;
  }
  // 1.016 before the double bridges (iterated local search), 1.0002 with them.
  EXPECT_LE(ratio_sum / trials, 1.005) << "the local search averages far from the optimum";
}

TEST(SweepOrder, LargeInstancesGiveAValidWalkBetterThanTheInputOrder) {
  std::mt19937_64 rng(47);
  for (const std::size_t n : {40u, 300u, 2000u}) {
    const auto cells = random_cells(n, rng);
    const auto so = coverage::order_sweeps(cells, std::nullopt, transit);
    expect_valid(cells, std::nullopt, so);
    // The cells come in random order: the input order with its cheapest sweeps is a poor walk.
    std::vector<std::uint32_t> identity(n);
    std::iota(identity.begin(), identity.end(), 0u);
    std::vector<std::uint8_t> first(n, 0);
    EXPECT_LT(so.cost, 0.5 * walk_cost(cells, std::nullopt, identity, first)) << n << " cells";
  }
}
