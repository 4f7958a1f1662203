// Strategy 7 (navigation to a cyclic permutation) and Strategy 9 (the whole swap graph)
// against the swap cell decomposition from coordinates, exhaustively: every cell meeting
// the hull is a goal the robot must reach from several starts, every other cyclic
// permutation must be reported unrealizable, on random and grid-snapped landmark sets
// (the grids have parallel swap lines and concurrent crossings). Issue 31.
//
// PREIMAGE_LANDMARK_CONFIGS=k runs k configurations of each kind per n (default 2) for a
// longer exhaustive run; the counts are printed.
#include <preimage/error.hpp>
#include <preimage/landmarks/figures.hpp>
#include <preimage/landmarks/strategies.hpp>
#include <preimage/landmarks/swap_cells.hpp>
#include <preimage/scene/scene.hpp>

#include <gtest/gtest.h>
#include <support/landmark_robot.hpp>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>

using namespace preimage;
using geometry::Point;
using landmarks::OrderType;
using landmarks::Reading;
using landmarks::Simulator;
using landmarks::SwapCellDecomposition;
using preimage::testing::generic_start;

namespace {

landmarks::Chirotope truth(const OrderType& T) {
  return [&T](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return T.chi(i, j, k); };
}

std::size_t configs_per_kind() {
  const char* e = std::getenv("PREIMAGE_LANDMARK_CONFIGS");
  return e ? std::max<std::size_t>(1, std::strtoul(e, nullptr, 10)) : 3;
}

// Grid-snapped sets: a grid barely larger than needed for n points with no three in a
// line, so many pairs of swap lines are parallel and many crossings concurrent.
std::vector<Point> grid_landmarks(std::size_t n, std::uint64_t seed) {
  return landmarks::random_landmarks(n, seed, static_cast<int>(n / 2));
}

// f(n, seed, P) for n in [lo, hi] and `sets` landmark sets of each size, random and
// grid-snapped in turn.
template <class F>
void for_each_set(std::size_t lo, std::size_t hi, std::uint64_t sets, std::uint64_t salt, F&& f) {
  for (std::size_t n = lo; n <= hi; ++n)
    for (std::uint64_t seed = 1; seed <= sets; ++seed) {
      const std::uint64_t s = seed * salt + n;
      f(n, seed, seed % 2 ? landmarks::random_landmarks(n, s, 1000) : grid_landmarks(n, s));
    }
}

struct Degeneracies {
  std::size_t parallel = 0, concurrent = 0;
};
Degeneracies degeneracies(const std::vector<Point>& P, const SwapCellDecomposition& D) {
  Degeneracies d;
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = i + 1; k < n; ++k)
        for (std::size_t l = k + 1; l < n; ++l)
          if (k != j && l != j) {
            const geometry::ExactPoint O = CGAL::ORIGIN;
            const auto u = geometry::to_exact(P[j]) - geometry::to_exact(P[i]), v = geometry::to_exact(P[l]) - geometry::to_exact(P[k]);
            d.parallel += CGAL::orientation(O, O + u, O + v) == CGAL::COLLINEAR;
          }
  for (std::uint32_t v = 0; v < D.vertices().size(); ++v)
    if (D.vertices()[v].kind == SwapCellDecomposition::Vertex::Kind::Crossing && D.vertex_key(v).size() >= 3) ++d.concurrent;
  return d;
}

// A grid-snapped set with parallel swap lines and, from six landmarks on (three lines
// through one crossing need six), a concurrent crossing: the first such draw from `seed`.
std::vector<Point> degenerate_landmarks(std::size_t n, std::uint64_t seed) {
  for (std::uint64_t q = 0;; ++q) {
    auto P = grid_landmarks(n, seed + 100003 * q);
    const auto d = degeneracies(P, SwapCellDecomposition::of(P));
    if (d.parallel > 0 && (n < 6 || d.concurrent > 0)) return P;
  }
}

// Starts around the landmarks, inside and outside their hull.
double start_range(const std::vector<Point>& P) {
  double r = 1;
  for (const auto& p : P) r = std::max({r, std::abs(p.x()), std::abs(p.y())});
  return 1.5 * r;
}

// A start inside cell c: off the middle of one of its swap ray pieces, to its side, by a
// step halved until the rounded point reads the cell's permutation.
Point point_in_cell(const std::vector<Point>& P, const SwapCellDecomposition& D, std::uint32_t c) {
  std::vector<geometry::ExactPoint> E;
  for (const auto& p : P) E.push_back(geometry::to_exact(p));
  for (std::uint32_t h = 0; h < D.half_edges().size(); ++h) {
    const auto& e = D.half_edges()[h];
    if (e.cell != c || e.ray == SwapCellDecomposition::kNone) continue;
    const auto &a = D.vertices()[e.origin].p, &b = D.vertices()[e.target].p;
    const auto d = b - a;
    const auto mid = CGAL::midpoint(a, b);
    geometry::ExactFT step = 1;
    for (int k = 0; k < 80; ++k, step /= 2) {
      const Point q = geometry::to_double(mid + geometry::ExactKernel::Vector_2(-d.y(), d.x()) * step);
      try {
        Simulator probe(P, q);  // rejects a point on a line through two landmarks
        if (landmarks::normalized(probe.lcd()) == D.cells()[c].permutation) return q;
      } catch (const InputError&) {
      }
    }
  }
  throw std::logic_error("no start found inside the cell");
}

// Every cyclic permutation of 0..n-1, normalized (0 first).
std::vector<Reading> all_cyclic_permutations(std::size_t n) {
  Reading r(n);
  std::iota(r.begin(), r.end(), 0u);
  std::vector<Reading> out;
  do out.push_back(r);
  while (std::next_permutation(r.begin() + 1, r.end()));
  return out;
}

struct Counts {
  std::size_t configs = 0, goals = 0, runs = 0, reached = 0, others = 0, rejected = 0, by_lemma = 0, parallel = 0, concurrent = 0;
  std::size_t paper_rejects = 0;  // hull cells the paper's Lemma 10 rejects: a polar line that meets no other
};

// One configuration: every hull cell from `starts` starts, every other permutation once
// (all of them for n <= max_all, else a random sample).
void exhaust(const std::vector<Point>& P, std::uint64_t seed, std::size_t starts, std::size_t max_all, Counts& c) {
  const std::size_t n = P.size();
  const auto D = SwapCellDecomposition::of(P);
  const OrderType T = OrderType::of(P);
  std::set<Reading> inside;
  for (const auto& cell : D.cells())
    if (cell.meets_hull) inside.insert(cell.permutation);
  const auto deg = degeneracies(P, D);
  c.parallel += deg.parallel;
  c.concurrent += deg.concurrent;
  ++c.configs;
  c.goals += inside.size();
  std::vector<geometry::ExactPoint> E;
  for (const auto& p : P) E.push_back(geometry::to_exact(p));
  // The robot learns the order type once per start; each goal runs on a copy.
  std::vector<Simulator> learned;
  std::vector<landmarks::HullTour> tours;
  for (std::size_t s = 0; s < starts; ++s) {
    Simulator robot(P, generic_start(P, seed * 1000 + s, start_range(P)));
    robot.set_self_check(true);
    tours.push_back(landmarks::learn_by_hull_tour(robot));
    learned.push_back(robot);
  }
  for (const auto& g : inside)
    c.paper_rejects += landmarks::meeting_polar_lines(n, truth(T), g).size() < landmarks::polar_pairs(n, truth(T), g).size();
  for (const auto& g : inside)
    for (std::size_t s = 0; s < starts; ++s) {
      Simulator robot = learned[s];
      const auto r = landmarks::navigate(robot, tours[s].order_type.chirotope(), tours[s].hull, g);
      ++c.runs;
      ASSERT_TRUE(r.reached) << "n " << n << " seed " << seed << " goal " << landmarks::format_reading(g) << ": " << r.reason;
      EXPECT_EQ(landmarks::normalized(robot.lcd()), g);
      EXPECT_EQ(landmarks::normalized(landmarks::angular_reading(E, robot.position(), robot.at(), nullptr, {})), g);
      ++c.reached;
    }
  std::vector<Reading> others;
  if (n <= max_all) {
    for (auto& g : all_cyclic_permutations(n))
      if (!inside.count(g)) others.push_back(std::move(g));
  } else {
    std::mt19937_64 rng(seed);
    while (others.size() < 300) {
      Reading g(n);
      std::iota(g.begin(), g.end(), 0u);
      std::shuffle(g.begin() + 1, g.end(), rng);
      if (!inside.count(g)) others.push_back(g);
    }
    // And every permutation read only outside the hull.
    for (const auto& cell : D.cells())
      if (!inside.count(cell.permutation)) others.push_back(cell.permutation);
  }
  for (const auto& g : others) {
    ++c.others;
    if (landmarks::unrealizable_reason(n, truth(T), T.hull(), g)) {
      ++c.by_lemma, ++c.rejected;  // decided without moving
      continue;
    }
    Simulator robot = learned[0];
    const auto r = landmarks::navigate(robot, tours[0].order_type.chirotope(), tours[0].hull, g);
    ASSERT_FALSE(r.reached) << "n " << n << " seed " << seed << " goal " << landmarks::format_reading(g);
    EXPECT_FALSE(r.reason.empty());
    ++c.rejected;
  }
}

}  // namespace

TEST(LandmarkNavigation, EveryHullCellIsReachedAndEveryOtherPermutationRejected) {
  const std::size_t k = configs_per_kind();
  for (std::size_t n = 4; n <= 9; ++n) {
    Counts random, grid;
    for (std::size_t q = 0; q < k; ++q) {
      const std::uint64_t seed = 7919 * n + q;
      exhaust(landmarks::random_landmarks(n, seed, 1000), seed, 3, 9, random);
      exhaust(degenerate_landmarks(n, seed), seed, 3, 9, grid);
      if (HasFatalFailure()) return;
    }
    for (const auto& [kind, c] : {std::pair{"random", random}, std::pair{"grid", grid}}) {
      std::cout << "n = " << n << ", " << kind << ": " << c.configs << " configurations (" << c.parallel << " parallel line pairs, "
                << c.concurrent << " concurrent crossings); " << c.goals << " hull cells (" << c.paper_rejects
                << " that the paper's Lemma 10 rejects), " << c.runs << " runs, " << c.reached
                << " reached; " << c.others << " other permutations, " << c.rejected << " rejected (" << c.by_lemma
                << " before moving)\n";
      EXPECT_EQ(c.reached, c.runs);
      EXPECT_EQ(c.rejected, c.others);
    }
    // The grids are what they are for: degenerate arrangements (three swap lines through
    // one crossing need six landmarks).
    EXPECT_GT(grid.parallel, 0u) << n;
    if (n >= 6) {
      EXPECT_GT(grid.concurrent, 0u) << n;
    }
  }
}

TEST(LandmarkNavigation, Lemma10AsItHoldsBoundsEveryCellOnMeetingPolarLines) {
  // The fact the fast path and the search rest on: the swap lines on the boundary of any
  // cell (inside the hull or not) are polar lines that meet another polar line. (The
  // paper's stronger "every polar line meets another" fails rarely: the fixture of
  // Lemma10CounterexampleGoalIsReachedFromEveryStart.)
  std::size_t cells = 0;
  for_each_set(4, 9, 6, 31, [&](std::size_t n, std::uint64_t seed, const std::vector<Point>& P) {
    const auto D = SwapCellDecomposition::of(P);
    const OrderType T = OrderType::of(P);
    std::vector<std::set<std::pair<std::uint32_t, std::uint32_t>>> lines(D.cells().size());
    for (const auto& h : D.half_edges())
      if (h.ray != SwapCellDecomposition::kNone && h.cell != SwapCellDecomposition::kNone)
        lines[h.cell].insert(std::minmax(D.rays()[h.ray].from, D.rays()[h.ray].away));
    for (std::uint32_t c = 0; c < D.cells().size(); ++c) {
      const auto& g = D.cells()[c].permutation;
      std::set<std::pair<std::uint32_t, std::uint32_t>> meeting;
      for (auto [i, j] : landmarks::meeting_polar_lines(n, truth(T), g)) meeting.insert(std::minmax(i, j));
      ASSERT_GE(lines[c].size(), 2u);
      for (const auto& l : lines[c]) ASSERT_TRUE(meeting.count(l)) << "n " << n << " seed " << seed << " cell " << c;
      if (D.cells()[c].meets_hull) {
        EXPECT_FALSE(landmarks::unrealizable_reason(n, truth(T), T.hull(), g)) << "n " << n << " cell " << c;
      }
      ++cells;
    }
  });
  EXPECT_GT(cells, 1000u);
}

TEST(LandmarkNavigation, Lemma10CounterexampleGoalIsReachedFromEveryStart) {
  // Issue 31: the polar line of 5 and 1 meets no other polar line, yet 1 4 6 3 2 5 is read
  // in a cell meeting the hull; the robot used to reject it by the paper's Lemma 10.
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES).append("/scenes/landmarks_lemma10_counterexample.json"));
  const auto L = landmarks::landmark_set(s);
  const auto lab = [&](const std::string& x) { return static_cast<std::uint32_t>(std::find(L.labels.begin(), L.labels.end(), x) - L.labels.begin()); };
  const Reading g = landmarks::normalized({lab("1"), lab("4"), lab("6"), lab("3"), lab("2"), lab("5")});
  const auto D = SwapCellDecomposition::of(L.points);
  const OrderType T = OrderType::of(L.points);
  std::uint32_t goal_cell = SwapCellDecomposition::kNone;
  for (std::uint32_t c = 0; c < D.cells().size(); ++c)
    if (D.cells()[c].permutation == g) goal_cell = c;
  ASSERT_NE(goal_cell, SwapCellDecomposition::kNone);
  ASSERT_TRUE(D.cells()[goal_cell].meets_hull);
  const auto polar = landmarks::polar_pairs(L.size(), truth(T), g);
  const auto meeting = landmarks::meeting_polar_lines(L.size(), truth(T), g);
  EXPECT_LT(meeting.size(), polar.size());  // the paper's Lemma 10 would reject g
  // Starts: landmarks, random points, and a point inside the goal cell.
  std::vector<Simulator> robots;
  for (std::uint32_t k = 0; k < L.size(); ++k) robots.emplace_back(L.points, k);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) robots.emplace_back(L.points, generic_start(L.points, seed, 10));
  robots.emplace_back(L.points, point_in_cell(L.points, D, goal_cell));
  for (auto& robot : robots) {
    robot.set_self_check(true);
    const auto tour = landmarks::learn_by_hull_tour(robot);
    const auto r = landmarks::navigate(robot, tour.order_type.chirotope(), tour.hull, g, L.labels);
    ASSERT_TRUE(r.reached) << r.reason;
    EXPECT_EQ(landmarks::normalized(robot.lcd()), g);
  }
}

TEST(LandmarkNavigation, UnrealizableReasonsNameLandmarksByLabel) {
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES).append("/scenes/landmarks_lemma10_counterexample.json"));
  auto L = landmarks::landmark_set(s);
  for (auto& l : L.labels) l = "L" + l;
  const OrderType T = OrderType::of(L.points);
  std::size_t named = 0;
  for (const auto& g : all_cyclic_permutations(L.size()))
    if (const auto why = landmarks::unrealizable_reason(L.size(), truth(T), T.hull(), g, L.labels); why && why->find(" polar line") != std::string::npos) {
      // Every landmark named is a label; no bare index appears as a landmark.
      EXPECT_EQ(why->find("-0"), std::string::npos) << *why;
      if (why->find(" (L") != std::string::npos) ++named;
    }
  EXPECT_GT(named, 0u);
}

TEST(LandmarkNavigation, Strategy9LearnsOneEdgePerPairOfCellsOnTheTriangle) {
  // Issue 31: on three landmarks each outside cell borders the inside cell along both swap
  // lines of its landmark; the robot counted two edges there. Every labelling and shape.
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES).append("/scenes/landmarks_triangle.json"));
  const auto L = landmarks::landmark_set(s);
  std::vector<std::vector<Point>> shapes{L.points,
                                         {Point(0, 0), Point(0, 1), Point(1, 0)},       // clockwise
                                         {Point(0, 0), Point(4, 0), Point(2, 3)},       // acute
                                         {Point(0, 0), Point(10, 0), Point(1, 1)},      // obtuse
                                         {Point(0, 0), Point(1000, 1), Point(-1000, 2)}};  // nearly flat
  for (const auto& P : shapes) {
    const auto D = SwapCellDecomposition::of(P);
    Simulator robot(P, generic_start(P, 3, 5));
    robot.set_self_check(true);
    const auto tour = landmarks::learn_by_hull_tour(robot);
    const auto in = landmarks::learn_inside_swap_graph(robot, tour.order_type.chirotope(), tour.hull);
    const auto all = landmarks::learn_swap_graph(robot, in);
    ASSERT_EQ(all.cells.size(), 4u);
    ASSERT_EQ(D.swap_graph().size(), 3u);
    ASSERT_EQ(all.edges.size(), 3u);
    std::multiset<std::tuple<Reading, Reading, std::uint32_t, std::uint32_t>> learned, real;
    for (const auto& e : all.edges) {
      const auto [a, b] = std::minmax(all.cells[e.a].permutation, all.cells[e.b].permutation);
      learned.emplace(a, b, e.i, e.j);
    }
    for (const auto& e : D.swap_graph()) {
      const auto [a, b] = std::minmax(D.cells()[e.a].permutation, D.cells()[e.b].permutation);
      real.emplace(a, b, e.i, e.j);
    }
    EXPECT_EQ(learned, real);
  }
}

TEST(LandmarkNavigation, Strategy9LearnsTheSwapGraphOnRandomAndGridSets) {
  std::size_t configs = 0;
  for_each_set(4, 8, 4, 13, [&](std::size_t n, std::uint64_t seed, const std::vector<Point>& P) {
    const auto D = SwapCellDecomposition::of(P);
    Simulator robot(P, generic_start(P, seed, 20));
    const auto tour = landmarks::learn_by_hull_tour(robot);
    const auto in = landmarks::learn_inside_swap_graph(robot, tour.order_type.chirotope(), tour.hull);
    const auto all = landmarks::learn_swap_graph(robot, in);
    // Cells one to one (same permutation, the vertices seen among the cell's), then
    // the same labelled edges.
    ASSERT_EQ(all.cells.size(), D.cells().size()) << "n " << n << " seed " << seed;
    std::vector<std::uint32_t> to_true(all.cells.size());
    std::set<std::uint32_t> used;
    for (std::uint32_t c = 0; c < all.cells.size(); ++c) {
      std::vector<std::uint32_t> match;
      for (std::uint32_t t = 0; t < D.cells().size(); ++t) {
        if (D.cells()[t].permutation != all.cells[c].permutation) continue;
        const auto keys = D.vertex_keys(t);
        if (std::includes(keys.begin(), keys.end(), all.cells[c].vertex_keys.begin(), all.cells[c].vertex_keys.end())) match.push_back(t);
      }
      ASSERT_EQ(match.size(), 1u) << "n " << n << " seed " << seed << " cell " << c;
      to_true[c] = match[0];
      used.insert(match[0]);
    }
    EXPECT_EQ(used.size(), D.cells().size());
    std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>> te, le;
    for (const auto& e : D.swap_graph()) te.emplace(std::min(e.a, e.b), std::max(e.a, e.b), e.i, e.j);
    for (const auto& e : all.edges) le.emplace(std::min(to_true[e.a], to_true[e.b]), std::max(to_true[e.a], to_true[e.b]), e.i, e.j);
    EXPECT_EQ(le, te) << "n " << n << " seed " << seed;
    ++configs;
  });
  EXPECT_EQ(configs, 20u);
}
