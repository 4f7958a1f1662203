// The swap cell decomposition (landmark paper, 6.1 and 7) against CGAL's Arrangement_2,
// independent angular sorts, and Theorems 7, 13 and 14.
#include <preimage/error.hpp>
#include <preimage/landmarks/figures.hpp>
#include <preimage/landmarks/swap_cells.hpp>
#include <preimage/scene/scene.hpp>

#include <gtest/gtest.h>
#include <support/cgal_oracle.hpp>

#include <limits>
#include <map>
#include <set>

using namespace preimage;
using geometry::Point;
using landmarks::Reading;
using landmarks::SwapCellDecomposition;

namespace {

// Every piece of every swap ray, read on its left by an exact angular sort (the tie of
// its two landmarks broken towards that side), must show its cell's permutation.
void expect_permutations_read_everywhere(const SwapCellDecomposition& D, const std::vector<Point>& P) {
  std::vector<geometry::ExactPoint> E;
  for (const auto& p : P) E.push_back(geometry::to_exact(p));
  const auto& H = D.half_edges();
  for (std::uint32_t h = 0; h < H.size(); ++h) {
    if (H[h].ray == SwapCellDecomposition::kNone || H[h].cell == SwapCellDecomposition::kNone) continue;
    const auto& a = D.vertices()[H[h].origin].p;
    const auto& b = D.vertices()[H[h].target].p;
    const auto mid = CGAL::midpoint(a, b);
    const auto d = b - a;
    const auto left = mid + geometry::ExactKernel::Vector_2(-d.y(), d.x());
    const Reading r = landmarks::normalized(landmarks::angular_reading(E, mid, std::nullopt, &left, {}));
    ASSERT_EQ(r, D.cells()[H[h].cell].permutation) << "half-edge " << h;
  }
}

// The same arrangement up to scale: cells, their permutations, hull cells and edges.
void expect_same_decomposition(const std::vector<Point>& P, const std::vector<Point>& Q) {
  const auto A = SwapCellDecomposition::of(P), B = SwapCellDecomposition::of(Q);
  auto summary = [](const SwapCellDecomposition& D) {
    std::multiset<std::pair<Reading, bool>> cells;
    for (const auto& c : D.cells()) cells.emplace(c.permutation, c.meets_hull);
    return std::pair{cells, D.swap_graph().size()};
  };
  EXPECT_EQ(summary(A), summary(B));
  expect_permutations_read_everywhere(A, P);
}

std::vector<Point> fixture_landmarks(const std::string& name) {
  return landmarks::landmark_set(scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/" + name)).points;
}

}  // namespace

TEST(SwapCells, ThreeLandmarksHaveOneInsideCellAndThreeEqualOutsideCells) {
  const std::vector<Point> P{Point(0, 0), Point(4, 0), Point(1, 3)};
  const auto D = SwapCellDecomposition::of(P);
  ASSERT_EQ(D.cells().size(), 4u);
  std::map<Reading, int> count;
  int inside = 0;
  for (const auto& c : D.cells()) {
    ++count[c.permutation];
    inside += c.meets_hull;
  }
  EXPECT_EQ(inside, 1);
  EXPECT_EQ((count[Reading{0, 1, 2}]), 1);  // counter-clockwise triangle, seen from inside
  EXPECT_EQ((count[Reading{0, 2, 1}]), 3);  // Theorem 13 at n = 3: the note after Theorem 7
  EXPECT_EQ(D.swap_graph().size(), 3u);
  expect_permutations_read_everywhere(D, P);
}

TEST(SwapCells, CellCountsMatchCgalArrangementAndReadingsMatchAngularSorts) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const std::size_t n = 3 + seed % 6;
    const auto P = landmarks::random_landmarks(n, seed, 1000);
    const auto D = SwapCellDecomposition::of(P);
    EXPECT_EQ(D.cells().size(), preimage::testing::cgal_swap_cell_count(P, 1e12)) << "seed " << seed;
    expect_permutations_read_everywhere(D, P);
    // Each dual edge joins permutations that differ by its transposition (Lemma 6).
    for (const auto& e : D.swap_graph())
      EXPECT_EQ(landmarks::normalized(landmarks::transposed(D.cells()[e.a].permutation, e.i, e.j)), D.cells()[e.b].permutation);
  }
}

TEST(SwapCells, Theorems7And14InsideTheHullEachPermutationNamesOneCell) {
  for (std::uint64_t seed = 20; seed < 40; ++seed) {
    const std::size_t n = 4 + seed % 6;
    const auto P = landmarks::random_landmarks(n, seed, 1 << 12);
    const auto D = SwapCellDecomposition::of(P);
    std::map<Reading, int> all;
    for (const auto& c : D.cells()) ++all[c.permutation];
    int inside = 0;
    for (const auto& c : D.cells())
      if (c.meets_hull) {
        ++inside;
        EXPECT_EQ(all[c.permutation], 1) << "seed " << seed;  // Theorem 14 (hence Theorem 7)
      }
    EXPECT_GE(inside, 1);
  }
}

TEST(SwapCells, ConvexPositionHasOneInsideCell) {
  // No swap ray enters the hull: its interior is a single cell.
  const std::vector<Point> P{Point(0, 0), Point(10, 1), Point(12, 9), Point(3, 11), Point(-2, 6)};
  const auto D = SwapCellDecomposition::of(P);
  int inside = 0;
  for (const auto& c : D.cells()) inside += c.meets_hull;
  EXPECT_EQ(inside, 1);
  EXPECT_EQ(D.cells().size(), preimage::testing::cgal_swap_cell_count(P, 1e12));
}

TEST(SwapCells, Fig09ExampleHasSevenPairsOfOutsideCellsWithOnePermutation) {
  // Theorem 13 beyond n = 3: found by search, see examples/landmarks/README.
  const auto s = scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/landmarks/fig09_equal_outside.json");
  const auto L = landmarks::landmark_set(s);
  ASSERT_GE(L.size(), 6u);
  const auto D = SwapCellDecomposition::of(L.points);
  std::map<Reading, std::vector<std::uint32_t>> outside;
  for (std::uint32_t c = 0; c < D.cells().size(); ++c)
    if (!D.cells()[c].meets_hull) outside[D.cells()[c].permutation].push_back(c);
  std::size_t pairs = 0;
  for (const auto& [p, cells] : outside) {
    EXPECT_LE(cells.size(), 2u);
    pairs += cells.size() == 2;
  }
  EXPECT_EQ(pairs, 7u);  // 14 cells, as the CLI counts them (docs/landmarks.md)
  EXPECT_EQ(D.cells().size(), 55u);
}

TEST(SwapCells, RejectsCollinearLandmarks) {
  const std::vector<Point> P{Point(0, 0), Point(1, 1), Point(2, 2), Point(5, 0)};
  EXPECT_THROW(SwapCellDecomposition::of(P), InputError);
}

// Issue 26: the clipping box was computed in doubles. At 1e308 its margin overflowed, with
// tiny or subnormal coordinates the interval boxes of crossings were infinite, and GMP
// raised SIGFPE converting infinity. The library takes any doubles: these decompositions
// must equal the same shapes at ordinary scale.
TEST(SwapCells, BoxStaysExactAt1e308AndSubnormalCoordinates) {
  const double big = 1e308, tiny = std::numeric_limits<double>::denorm_min();
  expect_same_decomposition({Point(0, 0), Point(big, 0), Point(0, big), Point(-big, -big)},
                            {Point(0, 0), Point(1, 0), Point(0, 1), Point(-1, -1)});
  expect_same_decomposition({Point(0, 0), Point(tiny, 0), Point(0, tiny), Point(1e-320, 1e-320)},
                            {Point(0, 0), Point(1, 0), Point(0, 1), Point(2024, 2024)});
}

TEST(SwapCells, BoxStaysExactAtTheTinyScaleFixture) {
  expect_same_decomposition(fixture_landmarks("landmarks_tiny_scale.json"), {Point(0, 0), Point(1, 0), Point(0, 1), Point(2024, 2024)});
  expect_same_decomposition(fixture_landmarks("landmarks_scale_1e12.json"), {Point(0, 0), Point(1, 0), Point(0, 1), Point(-1, -1)});
}

TEST(SwapCells, BoxStaysExactAroundACrossingBeyondTheRangeOfDoubles) {
  // Lines ab and cd cross near x = 4.5e331; at ordinary scale the same shape crosses at 100.
  const auto P = fixture_landmarks("landmarks_far_crossing.json");
  expect_same_decomposition(P, {Point(0, 0), Point(10, 0.1), Point(0, 10), Point(10, 10)});
  // The figure clips cells and rays exactly to its frame: nothing infinite is drawn.
  landmarks::LandmarkSet L{{"a", "b", "c", "d"}, P};
  const std::string svg = landmarks::swap_cell_figure(L, SwapCellDecomposition::of(P)).str();
  EXPECT_EQ(svg.find("inf"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);
}
