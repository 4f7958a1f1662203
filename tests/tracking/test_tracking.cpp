// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/tracking/replay.hpp>
#include <preimage/tracking/simulation.hpp>

#include "support/escape_oracle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

using namespace preimage;
using namespace preimage::tracking;
using geometry::Point;

namespace {
std::string example(const std::string& name) { return std::string(PREIMAGE_EXAMPLES) + "/tracking/" + name; }
}  // namespace

TEST(TrackingFixtures, TargetOnARoundedRadialEdge) {
  // Scan 49 of the ACES log: replay put the target straight ahead, on the ray of a radial
  // occlusion edge whose rounded far end fell clockwise of it; V was not star-shaped and
  // the sweep missed two free edges ("escape edge 43 was not reached").
  std::ifstream in(std::string(PREIMAGE_FIXTURES) + "/scans/aces_scan49_target_on_radial_edge.log");
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  auto scan = parse_log_line(line, 50, "fixture");
  ASSERT_TRUE(scan.has_value());
  scan->angle_increment = M_PI / 179;  // the spacing replay gave 180 beams then (now CARMEN's pi/180)
  const LocalMap map = local_map_from_scan(*scan);
  const Point t(std::cos(scan->angle(90)), std::sin(scan->angle(90)));
  const EscapePathTree tree = escape_path_tree(map, t);
  const auto oracle = preimage::testing::brute_force_sde(map, t);
  ASSERT_EQ(tree.paths.size(), oracle.size());
  for (std::size_t i = 0; i < oracle.size(); ++i) EXPECT_NEAR(tree.paths[i].length, oracle[i], 1e-9 * (1 + oracle[i]));
  EXPECT_TRUE(replay_scan(*scan, TrackerParams{}).has_tree);
}

TEST(TrackingFixtures, ObserverInLineWithObstacleVerticesIsRejectedClearly) {
  // In the lab, (3, 7.8) is in line with the vertices (4.5, 7) and (12, 3): the rays
  // through them hit the far wall within 2e-15 m of each other, and rounded to doubles
  // the two hits swap order, so V is not star-shaped. Found by a sweep of observers along
  // obstacle edges' lines (19 of 2,148 in the lab). Not repaired (a zero-width sliver);
  // rejected with an error that says why and what to do.
  const auto sc = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/lab_observer_in_line_with_vertices.json");
  const geometry::VisibilityIndex index(sc.require_environment());
  try {
    local_map_from_visibility(index.compute(*sc.tracking->observer));
    FAIL() << "accepted a visibility polygon that is not star-shaped";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("in line with obstacle vertices"), std::string::npos) << e.what();
  }
  // A hair off the line the map is fine.
  EXPECT_NO_THROW(local_map_from_visibility(index.compute(Point(3.001, 7.8))));
}

TEST(TrackingFixtures, SolidEdgeSeenEdgeOnIsStraightened) {
  // In the lab, (12, 6.55) is on the line of an obstacle edge: V has a solid edge seen
  // edge-on (radial), and rounded to doubles it turned clockwise, so V was rejected.
  // Straightening solid edges like occlusion edges fixed it (found by evaluate on the lab,
  // pinned down by a sweep of observers along obstacle edges' lines).
  const auto sc = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/lab_solid_edge_seen_edge_on.json");
  const geometry::VisibilityIndex index(sc.require_environment());
  const LocalMap map = local_map_from_visibility(index.compute(*sc.tracking->observer));
  const Point t = *sc.tracking->target;
  ASSERT_TRUE(map.strictly_contains(t));
  const EscapePathTree tree = escape_path_tree(map, t);
  const auto oracle = preimage::testing::brute_force_sde(map, t);
  ASSERT_EQ(tree.paths.size(), oracle.size());
  for (std::size_t i = 0; i < oracle.size(); ++i) EXPECT_NEAR(tree.paths[i].length, oracle[i], 1e-9 * (1 + oracle[i]));
}

TEST(TrackingAggregation, ChairSceneRecursiveAverageDiffersFromPlain) {
  // Figs. 4-5: the chair's legs give many free edges on one branch (around the
  // partition's corner). The plain average is pulled towards them (left, behind the
  // chair); the recursive average weighs that branch once and points the other way.
  const scene::Scene sc = scene::load_scene(example("chair.json"));
  const geometry::VisibilityIndex index(sc.require_environment());
  const LocalMap map = exact_local_map(index, *sc.tracking->observer);
  const EscapePathTree tree = escape_path_tree(map, *sc.tracking->target);
  RiskParams rp;
  rp.delta = sc.tracking->target_radius;
  const auto risks = escape_risks(map, tree, rp);
  // The branch: one node holding the chair's edges.
  std::size_t largest = 0;
  for (auto& c : tree.child_paths()) largest = std::max(largest, c.size());
  EXPECT_GE(largest, 6u);
  const Vec2 plain = plain_average(risks).gradient * -1.0, rec = recursive_average(tree, risks).gradient * -1.0;
  EXPECT_LT(plain.x, 0) << "plain average should point left, towards the chair";
  EXPECT_GT(rec.x, 0) << "recursive average should point right";
  const double angle = std::acos(plain.dot(rec) / (plain.norm() * rec.norm()));
  EXPECT_GT(angle, 5 * M_PI / 180);
}

TEST(TrackingSimulation, RunsAreConsistentAndStayInFreeSpace) {
  for (const char* name : {"corridor.json", "box.json", "lab.json"}) {
    const scene::Scene sc = scene::load_scene(example(name));
    const TrackingScenario s = TrackingScenario::from_scene(sc);
    for (auto strategy : {Strategy::Risk, Strategy::Sde, Strategy::Naive}) {
      for (auto policy : {TargetPolicy::Scripted, TargetPolicy::Random, TargetPolicy::Adversarial}) {
        SimulationParams p;
        p.strategy = strategy;
        p.policy = policy;
        p.steps = 80;
        p.seed = 3;
        const SimulationResult r = simulate(s, p);
        ASSERT_EQ(r.observer.size(), 81u);
        double len = 0, tlen = 0;
        std::size_t seen = 0;
        int first_lost = -1;
        for (std::size_t i = 0; i < r.observer.size(); ++i) {
          EXPECT_EQ(geometry::locate(*s.environment, r.observer[i].position).kind, geometry::Location::Kind::Interior);
          EXPECT_TRUE(geometry::locate(*s.environment, r.target[i]).in_free_space());
          const bool vis = geometry::visible(*s.environment, r.observer[i].position, r.target[i]) &&
                           std::hypot(r.target[i].x() - r.observer[i].position.x(), r.target[i].y() - r.observer[i].position.y()) <= p.laser.max_range;
          EXPECT_EQ(vis, static_cast<bool>(r.visible[i]));
          seen += vis;
          if (!vis && first_lost < 0) first_lost = static_cast<int>(i);
          if (i) {
            len += std::hypot(r.observer[i].position.x() - r.observer[i - 1].position.x(), r.observer[i].position.y() - r.observer[i - 1].position.y());
            tlen += std::hypot(r.target[i].x() - r.target[i - 1].x(), r.target[i].y() - r.target[i - 1].y());
            // kinematic limits: at most v_max dt per step
            EXPECT_LE(std::hypot(r.observer[i].position.x() - r.observer[i - 1].position.x(),
                                 r.observer[i].position.y() - r.observer[i - 1].position.y()),
                      p.tracker.control.v_max * p.dt + 1e-12);
          }
        }
        EXPECT_NEAR(r.observer_length, len, 1e-9);
        EXPECT_NEAR(r.target_length, tlen, 1e-9);
        EXPECT_DOUBLE_EQ(r.escape_time, first_lost < 0 ? -1.0 : first_lost * p.dt);
        EXPECT_DOUBLE_EQ(r.visible_fraction, static_cast<double>(seen) / 81.0);
        // Same seed, same run.
        EXPECT_EQ(simulate(s, p).observer.back().position, r.observer.back().position);
      }
    }
  }
}

// With dynamics the acceleration is bounded as a vector: between two periods the
// executed world-frame velocity changes by at most accel dt, turning at speed included,
// for the unicycles (risk, sde) and the holonomic game strategy alike; and the bound is
// what limits them (without it the risk controller's velocity turns faster).
TEST(TrackingSimulation, WithDynamicsTheWorldFrameAccelerationIsBounded) {
  const scene::Scene sc = scene::load_scene(example("lab.json"));
  const TrackingScenario scenario = TrackingScenario::from_scene(sc);
  auto largest_change = [&](Strategy strategy, double accel, std::uint64_t seed) {
    SimulationParams p;
    p.strategy = strategy;
    p.policy = TargetPolicy::Adversarial;
    p.steps = 150;
    p.seed = seed;
    p.start_spread = 0.5;
    p.accel = accel;
    p.alpha = 1.5;
    if (strategy == Strategy::Game) p.game = std::make_shared<const VisibilityGame>(*scenario.environment, game_params(scenario, p, 0.5));
    std::vector<Vec2> w;
    p.on_step = [&](const StepRecord& r) {
      // The velocity executed this period, in the world frame at the heading it ends on.
      const double th = r.observer.heading + r.velocity.omega * p.dt;
      w.push_back(Vec2{std::cos(th) * r.velocity.v - std::sin(th) * r.velocity.lateral,
                       std::sin(th) * r.velocity.v + std::cos(th) * r.velocity.lateral});
    };
    simulate(scenario, p);
    double most = 0;
    for (std::size_t i = 1; i < w.size(); ++i) {
      const bool collision = w[i].norm() == 0 && w[i - 1].norm() > accel * p.dt;  // a blocked move stops dead
      if (!collision) most = std::max(most, (w[i] - w[i - 1]).norm());
    }
    EXPECT_GT(w.size(), 20u);
    return most;
  };
  for (std::uint64_t seed : {1, 2, 3})
    for (Strategy s : {Strategy::Risk, Strategy::Sde, Strategy::Game}) EXPECT_LE(largest_change(s, 0.5, seed), 0.05 + 1e-9) << seed;
  // The bound bites: with a looser one (5 m/s^2, still turning at most 1.5 rad/s^2) risk's
  // velocity turns by more than 0.05 m/s in some period.
  double loose = 0;
  for (std::uint64_t seed : {1, 2, 3}) loose = std::max(loose, largest_change(Strategy::Risk, 5, seed));
  EXPECT_GT(loose, 0.05);
}

TEST(TrackingSimulation, TheObserverFollowsAScriptedTargetRoundTheCorridor) {
  // The target walks 31 m round two corners at 0.6 m/s; TRACK must keep it in sight.
  const scene::Scene sc = scene::load_scene(example("corridor.json"));
  SimulationParams p;
  p.steps = 500;
  const SimulationResult r = simulate(TrackingScenario::from_scene(sc), p);
  EXPECT_DOUBLE_EQ(r.escape_time, -1.0);
  EXPECT_GT(r.target_length, 25.0);
}

namespace {
// A scan of discs in a round room of radius 6 (no environment needed): beam i hits the
// nearest disc, else the wall.
Scan scan_of_discs(const std::vector<Disc>& discs, std::size_t beams, double fov, std::mt19937_64& rng) {
  Scan s;
  s.max_range = 8;
  const bool full = fov >= 2 * M_PI;
  s.angle_increment = full ? 2 * M_PI / static_cast<double>(beams) : fov / static_cast<double>(beams - 1);
  s.angle_min = full ? -M_PI : -fov / 2;
  std::normal_distribution<double> noise(0, 0.005);
  for (std::size_t i = 0; i < beams; ++i) {
    const double dx = std::cos(s.angle(i)), dy = std::sin(s.angle(i));
    double r = 6;
    for (const Disc& d : discs) {
      const double b = d.center.x() * dx + d.center.y() * dy;
      const double c = d.center.x() * d.center.x() + d.center.y() * d.center.y() - d.radius * d.radius;
      if (b * b - c >= 0 && b - std::sqrt(b * b - c) > 0) r = std::min(r, b - std::sqrt(b * b - c));
    }
    s.ranges.push_back(r + noise(rng));
  }
  return s;
}
}  // namespace

TEST(TrackingDetection, PriorWindowFindsTheDiscNearestThePriorAnywhereRound) {
  // With a prior, detection looks only at the beams that can see within the gate of it:
  // the window must wrap across the seam of a full circle (bearings near +-180 deg) and
  // clip to a cone, and still find the disc by the prior, not the other one.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> bearing(-M_PI, M_PI), range(3.0, 5.5), jitter(-0.3, 0.3);
  DetectParams dp;
  int found = 0, seam = 0, none = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const bool cone = trial % 2 == 1;
    const double fov = cone ? M_PI : 2 * M_PI;
    double a0 = trial % 8 == 0 ? M_PI - 0.05 : bearing(rng);  // often by the seam
    if (cone) a0 = std::clamp(a0, -1.4, 1.4);
    const double a1 = cone ? a0 - std::copysign(1.4, a0) : a0 + (trial % 3 == 0 ? 1.4 : -1.4);
    // Each coordinate its own range draw, y first (geometry::random_point's order).
    const Point r0 = geometry::random_point(rng, range), r1 = geometry::random_point(rng, range);
    const Disc d0{Point(r0.x() * std::cos(a0), r0.y() * std::sin(a0)), dp.radius};
    const Disc d1{Point(r1.x() * std::cos(a1), r1.y() * std::sin(a1)), dp.radius};
    if (std::sqrt(CGAL::to_double(CGAL::squared_distance(d0.center, d1.center))) < 2 * dp.gate + 0.7) continue;
    const Scan s = scan_of_discs({d0, d1}, cone ? 361 : 720, fov, rng);
    for (const Disc& want : {d0, d1}) {
      const double wb = std::atan2(want.center.y(), want.center.x());
      if (cone && std::abs(wb) > M_PI / 2 - 0.15) continue;  // at the cone's edge: half seen
      const Point prior = want.center + (geometry::random_point(rng, jitter) - CGAL::ORIGIN);
      const Detection d = detect_target(s, dp, prior);
      ASSERT_TRUE(d.found) << "trial " << trial << " disc at " << want.center;
      EXPECT_LT(std::sqrt(CGAL::to_double(CGAL::squared_distance(d.center, want.center))), 0.03) << "trial " << trial;
      ++found;
      seam += std::abs(wb) > M_PI - 0.3;
    }
    // A prior where there is nothing: behind a cone, or between the discs.
    const Point nothing = cone ? Point(-3, 0.2) : Point(-(d0.center.x() + d1.center.x()), -(d0.center.y() + d1.center.y()));
    const Detection d = detect_target(s, dp, nothing);
    bool near_disc = false;
    for (const Disc& o : {d0, d1})
      near_disc = near_disc || std::sqrt(CGAL::to_double(CGAL::squared_distance(o.center, nothing))) < dp.gate + 0.1;
    if (!near_disc) {
      EXPECT_FALSE(d.found) << "trial " << trial;
      ++none;
    }
  }
  EXPECT_GT(found, 400);
  EXPECT_GT(seam, 40);
  EXPECT_GT(none, 100);
}

TEST(TrackingReplay, LogLinesAreParsedOrNamed) {
  const auto s = parse_log_line("12.5 -1.5707963 0.0174533 1 2 3 4", 8, "log:3");
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->ranges.size(), 4u);
  EXPECT_DOUBLE_EQ(s->timestamp, 12.5);
  EXPECT_FALSE(parse_log_line("ODOM 0 0 0 0 0 0 0.1 pippo 0.1", 50, "log:1").has_value());
  EXPECT_FALSE(parse_log_line("# comment", 50, "log:1").has_value());
  try {
    parse_log_line("FLASER 3 1.0 x 1.0 0 0 0 0 0 0 7.5 host 7.5", 50, "aces.log:12");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "aces.log:12: token 4 (\"x\"): expected a number");
  }
  EXPECT_THROW(parse_log_line("FLASER 180 1 2", 50, "l"), InputError);
}


TEST(TrackingReplay, FlaserBeamsAreSpacedAsCarmenDoes) {
  // carmen_laser_get_angle_increment: 180 and 181 beams 1 deg apart, 360 and 361 half a
  // degree, 400 and 401 a quarter; other counts spread over 180 deg. Replay used
  // pi / (n - 1), turning the 180-beam scans of the Intel and ACES logs by up to 1 deg.
  auto line = [](std::size_t n) {
    std::string l = "FLASER " + std::to_string(n);
    for (std::size_t i = 0; i < n; ++i) l += " 1.5";
    return l + " 0 0 0 0 0 0 12.5 host 12.5";
  };
  const std::pair<std::size_t, double> cases[] = {{180, M_PI / 180}, {181, M_PI / 180}, {360, M_PI / 360}, {361, M_PI / 360},
                                                  {400, M_PI / 720}, {401, M_PI / 720}, {100, M_PI / 99}};
  for (const auto& [n, inc] : cases) {
    const auto s = parse_log_line(line(n), 50, "log:1");
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->ranges.size(), n);
    EXPECT_DOUBLE_EQ(s->angle_increment, inc) << n << " beams";
    EXPECT_DOUBLE_EQ(s->angle_min, -M_PI / 2);
  }
  // The ACES scan of the fixture: 180 beams, the last at +89 deg, the 91st straight ahead.
  std::ifstream in(std::string(PREIMAGE_FIXTURES) + "/scans/aces_scan49_target_on_radial_edge.log");
  std::string l;
  ASSERT_TRUE(std::getline(in, l));
  const auto aces = parse_log_line(l, 50, "fixture");
  ASSERT_TRUE(aces.has_value());
  EXPECT_NEAR(aces->angle(179), 89 * M_PI / 180, 1e-12);
  EXPECT_NEAR(aces->angle(90), 0, 1e-12);
}

TEST(TrackingFixtures, CoincidentVisibilityVerticesAreMerged) {
  // From (2, 6) in the lab, the ray through one chair corner meets another corner: V has
  // two symbolic vertices at one point, which the local map rejected as a zero-length
  // edge ("visibility polygon: edge 36 (vertices 36-37) has zero length").
  const scene::Scene sc = scene::load_scene(example("lab.json"));
  const geometry::VisibilityIndex index(sc.require_environment());
  const LocalMap map = exact_local_map(index, Point(2, 6));
  const Point t(5, 5.5);
  const auto tree = escape_path_tree(map, t);
  const auto oracle = preimage::testing::brute_force_sde(map, t);
  ASSERT_EQ(tree.paths.size(), oracle.size());
  for (std::size_t i = 0; i < oracle.size(); ++i) EXPECT_NEAR(tree.paths[i].length, oracle[i], 1e-9 * (1 + oracle[i]));
}

TEST(TrackingReplay, GeometryIsWhatTheCountsDescribe) {
  // track replay --json and --svg draw from ReplayScan's geometry: it must be the map and
  // tree the counts were taken from, every escape path running from the target to a
  // point of its free edge, every return short of max range.
  std::ifstream in(example("corridor_scans.txt"));
  std::string line;
  std::size_t scans = 0, trees = 0;
  while (std::getline(in, line)) {
    const auto scan = parse_log_line(line, 50, "corridor");
    if (!scan) continue;
    ++scans;
    const ReplayScan r = replay_scan(*scan, TrackerParams{});
    std::size_t hits = 0;
    for (double d : scan->ranges) hits += d < scan->max_range;
    EXPECT_EQ(r.points.size(), hits);
    EXPECT_EQ(r.map.size(), r.vertices);
    EXPECT_EQ(r.map.count(EdgeKind::Occlusion), r.occlusion);
    ASSERT_EQ(r.tree.has_value(), r.has_tree);
    if (!r.tree) continue;
    ++trees;
    ASSERT_EQ(r.tree->paths.size(), r.escape_paths);
    EXPECT_TRUE(r.map.strictly_contains(r.tree->target));
    for (std::size_t i = 0; i < r.tree->paths.size(); ++i) {
      const auto pl = r.tree->polyline(i);
      EXPECT_EQ(pl.front(), r.tree->target);
      const std::size_t e = r.tree->paths[i].edge;
      EXPECT_NE(r.map.edges[e], EdgeKind::Solid);
      // The escape point is a constructed (rounded) point: on its edge up to rounding.
      const preimage::geometry::Kernel::Segment_2 edge(r.map.vertices[e], r.map.vertices[r.map.next(e)]);
      EXPECT_LT(CGAL::squared_distance(edge, pl.back()), 1e-18);
    }
  }
  EXPECT_GE(scans, 10u);
  EXPECT_GE(trees, 10u);
}
