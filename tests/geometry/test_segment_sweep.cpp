// The Shamos–Hoey sweep against its O(n^2) definition, on inputs full of degeneracies.
#include <gtest/gtest.h>
#include <preimage/geometry/segment_sweep.hpp>
#include <preimage/geometry/random_point.hpp>

#include <random>

using namespace preimage::geometry;

namespace {
// Random segments on a tiny integer grid: collinear overlaps, T-junctions, shared
// endpoints, vertical and horizontal segments are all frequent.
void random_case(std::mt19937_64& rng, int grid, std::size_t m, std::vector<Point>& pts, std::vector<IndexedSegment>& segs) {
  std::uniform_int_distribution<int> c(0, grid);
  pts.clear(), segs.clear();
  for (std::size_t i = 0; i < m; ++i) {
    pts.push_back(random_point(rng, c));
    pts.push_back(random_point(rng, c));
    if (pts[2 * i] == pts[2 * i + 1]) pts[2 * i + 1] = Point(pts[2 * i].x() + 1, pts[2 * i].y());
    segs.push_back({static_cast<std::uint32_t>(2 * i), static_cast<std::uint32_t>(2 * i + 1)});
  }
}
}  // namespace

TEST(SegmentSweep, AgreesWithBruteForceOnDegenerateGrids) {
  std::mt19937_64 rng(12345);
  int with_contact = 0, without = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<Point> pts;
    std::vector<IndexedSegment> segs;
    random_case(rng, trial % 3 == 0 ? 40 : 12, 2 + trial % 7, pts, segs);
    auto fast = find_segment_contact(pts, segs);
    auto slow = find_segment_contact_brute_force(pts, segs);
    ASSERT_EQ(fast.has_value(), slow.has_value()) << "trial " << trial;
    if (fast) {
      ++with_contact;
      // The reported pair must really touch.
      auto [s, t] = std::pair(fast->first, fast->second);
      std::vector<IndexedSegment> pair{segs[s], segs[t]};
      EXPECT_TRUE(find_segment_contact_brute_force(pts, pair).has_value()) << "trial " << trial;
    } else {
      ++without;
    }
  }
  EXPECT_GT(with_contact, 500);
  EXPECT_GT(without, 500);
}

TEST(SegmentSweep, PolygonChainsMayShareEndpointsOnly) {
  // A closed square: consecutive edges share vertices, nothing else touches.
  std::vector<Point> pts{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<IndexedSegment> segs{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  EXPECT_FALSE(find_segment_contact(pts, segs));
  // Fold back: edge 2 runs back over edge 1 (collinear overlap at a shared vertex).
  std::vector<Point> fold{{0, 0}, {2, 0}, {1, 0}, {1, 1}};
  std::vector<IndexedSegment> fsegs{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  auto c = find_segment_contact(fold, fsegs);
  ASSERT_TRUE(c);
}
