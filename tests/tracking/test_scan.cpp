// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/tracking/escape_path_tree.hpp>
#include <preimage/tracking/scan.hpp>

#include "support/escape_oracle.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace preimage;
using namespace preimage::tracking;
using geometry::Point;

namespace {

// The scan map, moved into the world frame (heading 0: a translation).
LocalMap to_world(LocalMap m, const Point& o) {
  for (auto& p : m.vertices) p = Point(p.x() + o.x(), p.y() + o.y());
  m.observer = o;
  return m;
}

}  // namespace

TEST(ScanMap, MatchesTheExactVisibilityPolygon) {
  // A fine noise-free scan must give nearly the exact V: same area, every exact occlusion
  // corner found by a scan occlusion edge, and nearly the same SDE for a target inside.
  std::mt19937_64 rng(3);
  const auto env = geometry::generators::office(2, 3, 4.0);
  const geometry::VisibilityIndex index(env);
  int corners = 0, sde_checked = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const Point o = preimage::testing::random_free_point(env, rng);
    const LocalMap exact = local_map_from_visibility(index.compute(o));
    LaserSpec spec;
    spec.beams = 7200;
    spec.max_range = 100;
    const Scan scan = simulate_scan(env, Pose{o, 0.0}, spec, std::nullopt);
    MapParams mp;
    mp.simplify = 0.002;
    const LocalMap local = to_world(local_map_from_scan(scan, mp), o);
    EXPECT_NEAR(local.area(), exact.area(), 0.01 * exact.area()) << "trial " << trial;
    for (std::size_t e = 0; e < exact.size(); ++e) {
      if (exact.edges[e] != EdgeKind::Occlusion) continue;
      const Point& k = exact.vertices[exact.corner[e]];
      const Point& far = exact.vertices[exact.corner[e] == e ? exact.next(e) : e];
      if (CGAL::squared_distance(k, far) < 1.0) continue;  // shorter than the gap threshold
      // A wall end seen edge-on splits at a gap on either of its corners: the scan's
      // occlusion edge passes by the exact corner.
      double best = 1e300;
      for (std::size_t f = 0; f < local.size(); ++f)
        if (local.edges[f] == EdgeKind::Occlusion)
          best = std::min(best, CGAL::to_double(CGAL::squared_distance(
                                    geometry::Segment(local.vertices[f], local.vertices[local.next(f)]), k)));
      EXPECT_LT(std::sqrt(best), 0.05) << "trial " << trial << ": exact corner " << k << " not found";
      ++corners;
    }
    // A target inside both maps.
    for (int tries = 0; tries < 50; ++tries) {
      const Point t = preimage::testing::random_free_point(env, rng);
      if (!exact.strictly_contains(t) || !local.strictly_contains(t)) continue;
      const double a = escape_path_tree(exact, t).sde(), b = escape_path_tree(local, t).sde();
      if (std::isfinite(a)) {
        EXPECT_NEAR(b, a, 0.05 + 0.02 * a) << "trial " << trial;
        ++sde_checked;
      }
      break;
    }
  }
  EXPECT_GT(corners, 30);
  EXPECT_GT(sde_checked, 10);
}

TEST(ScanMap, ConeMapsGiveBruteForceEscapePaths) {
  // 180-deg scans with a short range: field-of-view edges, out-of-range gaps and the
  // observer as a vertex all go through the sweep.
  std::mt19937_64 rng(9);
  int checked = 0, range_edges = 0;
  for (std::uint64_t seed = 1; seed <= 25; ++seed) {
    const auto env = geometry::generators::random_environment(40, 3, seed);
    const auto box = env.bbox();
    for (int trial = 0; trial < 4; ++trial) {
      const Point o = preimage::testing::random_free_point(env, rng);
      std::uniform_real_distribution<double> H(-M_PI, M_PI);
      LaserSpec spec;
      spec.fov = M_PI;
      spec.beams = 181;
      spec.max_range = 0.4 * (box.xmax() - box.xmin());
      const Scan scan = simulate_scan(env, Pose{o, H(rng)}, spec, std::nullopt);
      const LocalMap map = local_map_from_scan(scan);
      range_edges += static_cast<int>(map.count(EdgeKind::Range));
      std::uniform_real_distribution<double> A(-M_PI / 2, M_PI / 2), Rr(0.01, spec.max_range);
      for (int k = 0; k < 20; ++k) {
        const double a = A(rng), r = Rr(rng);
        const Point t(r * std::cos(a), r * std::sin(a));
        if (!map.strictly_contains(t)) continue;
        const auto tree = escape_path_tree(map, t);
        const auto oracle = preimage::testing::brute_force_sde(map, t);
        ASSERT_EQ(tree.paths.size(), oracle.size());
        for (std::size_t i = 0; i < oracle.size(); ++i) {
          EXPECT_NEAR(tree.paths[i].length, oracle[i], 1e-9 * (1 + oracle[i])) << "seed " << seed << " trial " << trial;
          ++checked;
        }
        break;
      }
    }
  }
  EXPECT_GT(checked, 200);
  EXPECT_GT(range_edges, 20);
}

TEST(ScanMap, OutOfRangeGapIsClosedByOcclusionRangeOcclusion) {
  // Four readings: two at 1 m, a saturated one between: the gap closes as occlusion,
  // range arc, occlusion, and the occlusion corners are the polyline ends.
  Scan s;
  s.angle_min = -M_PI / 2;
  s.angle_increment = M_PI / 4;
  s.max_range = 5;
  s.ranges = {1, 1, 5, 1, 1};
  const LocalMap m = local_map_from_scan(s);
  std::vector<EdgeKind> kinds(m.edges.begin(), m.edges.end());
  ASSERT_EQ(m.observer_vertex, 0u);
  EXPECT_EQ(kinds.front(), EdgeKind::FieldOfView);
  EXPECT_EQ(kinds.back(), EdgeKind::FieldOfView);
  EXPECT_EQ(m.count(EdgeKind::Occlusion), 2u);
  EXPECT_GE(m.count(EdgeKind::Range), 1u);
  for (std::size_t e = 0; e < m.size(); ++e)
    if (m.edges[e] == EdgeKind::Occlusion) {
      EXPECT_NEAR(std::sqrt(CGAL::to_double(CGAL::squared_distance(m.vertices[m.corner[e]], Point(0, 0)))), 1.0, 1e-12);
    }
}

TEST(ScanMap, FullCircleRunsAcrossTheSeam) {
  // 360-deg scans of concentric arcs: where the walk starts and how the polygon closes
  // depends on whether the run of readings goes on across the seam (last beam -> first).
  // Each case: the free edges expected, and escape paths equal to brute force.
  struct Case {
    const char* name;
    std::vector<std::pair<std::size_t, double>> arcs;  // (first beam, range) up to the next
    std::size_t occlusion, range;
  };
  const double sat = 8;  // max range: out of range
  const std::vector<Case> cases = {
      {"one closed run all round", {{0, 3}}, 0, 0},
      {"nothing in range", {{0, sat}}, 0, 360},
      {"out of range at the start", {{0, sat}, {10, 3}}, 2, 1},
      {"out of range at the end", {{0, 3}, {350, sat}}, 2, 1},
      {"out of range across the seam", {{0, sat}, {5, 3}, {355, sat}}, 2, 1},
      {"occlusion gap at the seam", {{0, 2}, {180, 4}}, 2, 0},
      {"a run continued across the seam", {{0, 2}, {90, 4}, {270, 2}}, 2, 0},
      {"continued run and a range gap", {{0, 2}, {90, sat}, {100, 4}, {270, 2}}, 3, 1},
  };
  for (const auto& c : cases) {
    Scan s;
    s.angle_min = -M_PI;
    s.angle_increment = 2 * M_PI / 360;
    s.max_range = sat;
    s.ranges.assign(360, 0);
    for (std::size_t i = 0; i < c.arcs.size(); ++i)
      for (std::size_t k = c.arcs[i].first; k < (i + 1 < c.arcs.size() ? c.arcs[i + 1].first : 360); ++k)
        s.ranges[k] = c.arcs[i].second;
    const LocalMap m = local_map_from_scan(s);
    EXPECT_EQ(m.count(EdgeKind::Occlusion), c.occlusion) << c.name;
    if (c.range == 360) {
      EXPECT_EQ(m.count(EdgeKind::Range), m.size()) << c.name;
    } else {
      EXPECT_EQ(m.count(EdgeKind::Range) > 0, c.range > 0) << c.name;
    }
    const Point t(0.5, 0.3);
    const auto tree = escape_path_tree(m, t);
    const auto oracle = preimage::testing::brute_force_sde(m, t);
    ASSERT_EQ(tree.paths.size(), oracle.size()) << c.name;
    for (std::size_t i = 0; i < oracle.size(); ++i) EXPECT_NEAR(tree.paths[i].length, oracle[i], 1e-9) << c.name;
  }
}

TEST(ScanMap, BadReadingsAreNamed) {
  Scan s;
  s.angle_min = -M_PI / 2;
  s.angle_increment = M_PI / 4;
  s.ranges = {1, 1, std::nan(""), 1, 1};
  try {
    local_map_from_scan(s);
    FAIL() << "accepted a NaN reading";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("reading 2"), std::string::npos) << e.what();
  }
  s.ranges = {1, 1, 1, 1, 1, 1, 1};  // 270 deg
  EXPECT_THROW(local_map_from_scan(s), InputError);
}
