// SPDX-License-Identifier: Apache-2.0
// What the diagnosis of the box scene (issue 30) found, each as a property: the risk
// gradient and its mapping to the unicycle (eq. 5-6), the detector's phantom free edges
// and lost targets, the adversary that stalled at corners, and the new look-ahead target,
// dynamics and evaluation statistics.
#include <preimage/error.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/tracking/evaluation.hpp>
#include <preimage/tracking/simulation.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace preimage;
using namespace preimage::tracking;
using geometry::Point;

namespace {

std::string example(const std::string& name) { return std::string(PREIMAGE_EXAMPLES) + "/tracking/" + name; }
std::string fixture(const std::string& name) { return std::string(PREIMAGE_FIXTURES) + "/scenes/" + name; }
double dist(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

// The risk of one corner as TRACK sees it, turned into the sensor frame of an observer
// heading along -grad phi (so that eq. (6) has nothing to turn).
struct Aligned {
  RiskAverage risk;
  Point target;  // sensor frame
};
Aligned aligned(const Point& o, const Point& corner, const Point& target, const RiskParams& rp) {
  const EdgeRisk r = corner_risk(o, corner, target, 0.0, rp);
  const Vec2 d = r.gradient * (-1.0 / r.gradient.norm());
  const Pose pose{o, std::atan2(d.y, d.x)};
  const Vec2 g{d.x * r.gradient.x + d.y * r.gradient.y, -d.y * r.gradient.x + d.x * r.gradient.y};
  return {RiskAverage{r.phi, g}, to_sensor(pose, target)};
}

// The fixture box_target_touching_the_box.json with the target swept round the box corner
// (3.5, 3.9) at its radius + 5 mm, wherever its centre is in view: f(observer, target, a
// noisy scan of it). Returns how many positions were tried.
template <class F>
int around_the_box_corner(const scene::Scene& sc, F f) {
  const auto& env = sc.require_environment();
  const Pose o{*sc.tracking->observer, sc.tracking->heading * M_PI / 180};
  const Point corner(3.5, 3.9);
  int tried = 0;
  for (double a = 0; a <= M_PI / 2 + 1e-9; a += M_PI / 40) {
    const Point t(corner.x() + 0.205 * std::cos(a), corner.y() + 0.205 * std::sin(a));
    if (!geometry::visible(env, o.position, t)) continue;
    LaserSpec laser;
    laser.noise_sigma = 0.01;
    std::mt19937_64 noise(static_cast<std::uint64_t>(a * 1000));
    f(o, t, simulate_scan(env, o, laser, Disc{t, 0.2}, &noise));
    ++tried;
  }
  return tried;
}

}  // namespace

TEST(RiskControl, SpeedDoesNotVanishNearTheOccludingCorner) {
  // The box run: the observer came within 0.4 m of the box corner while the target was
  // 0.5 m from escaping past it, and stopped. |grad phi^e| is proportional to r_o, so eq.
  // (6)'s speed k_v n.(-grad phi) went to 0.05 m/s there (the line of sight past the
  // corner sweeps fastest exactly then). Heading down the gradient with the target 0.5 m
  // from its free edge, the speed must not fall as the observer nears the corner.
  RiskParams rp;
  ControlParams cp;
  cp.k_distance = 0;  // the regulator's pull aside: eq. (6) alone
  const Point corner(0, 0), target(0.5, 1.0);  // h = 0.5 past the line of sight along +y
  double v_far = 0;
  for (double r_o : {4.0, 2.0, 1.0, 0.5, 0.25, 0.1}) {
    const Aligned a = aligned(Point(0, -r_o), corner, target, rp);
    const Command c = risk_control(a.risk, a.target, cp).command;
    if (r_o == 4.0) v_far = c.v;
    EXPECT_GE(c.v, v_far - 1e-12) << "r_o " << r_o;
    EXPECT_GE(c.v, 0.5 * cp.v_max) << "r_o " << r_o << ": eq. (6) on grad phi gave k_v |grad phi| = "
                                   << cp.k_v * a.risk.gradient.norm();
  }
}

TEST(RiskControl, SpeedSaturatesWhenTheTargetIsAboutToEscape) {
  RiskParams rp;
  ControlParams cp;
  cp.k_distance = 0;
  for (double h : {0.2, 0.1, 0.05, 0.02}) {
    const Aligned a = aligned(Point(0, -2), Point(0, 0), Point(h, 1.5), rp);
    EXPECT_DOUBLE_EQ(risk_control(a.risk, a.target, cp).command.v, cp.v_max) << "h " << h;
  }
}

TEST(RiskControl, CommandDoesNotDependOnTheScaleOfTheRisk) {
  // c in eq. (3) is an arbitrary positive constant: it must not change the motion.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> U(-4, 4);
  ControlParams cp;
  for (int trial = 0; trial < 200; ++trial) {
    const Point o = geometry::random_point(rng, U), k = geometry::random_point(rng, U), w = geometry::random_point(rng, U), t = geometry::random_point(rng, U);
    RiskParams a, b;
    b.c = a.c * 37;
    const EdgeRisk ra = corner_risk(o, k, w, 1.0, a), rb = corner_risk(o, k, w, 1.0, b);
    const Command ca = risk_control({ra.phi, ra.gradient}, t, cp).command, cb = risk_control({rb.phi, rb.gradient}, t, cp).command;
    EXPECT_NEAR(ca.v, cb.v, 1e-9) << trial;
    EXPECT_NEAR(ca.omega, cb.omega, 1e-9) << trial;
  }
}

TEST(RiskControl, EquationSixMapsTheDesiredMotionToTheUnicycle) {
  // With a 360-deg sensor: v = n . D and omega = k_omega (n x D)/|D| for D = descent +
  // pull, clamped. In the box run the centring term (k_bearing x the target's bearing)
  // was added as well and turned the observer back to the target, cancelling the turn
  // towards -grad phi: the observer then moved sideways to its descent direction.
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(-3, 3);
  ControlParams cp;
  cp.reverse = true;
  for (int trial = 0; trial < 500; ++trial) {
    const RiskAverage risk{0.5 + std::abs(U(rng)), Vec2{U(rng), U(rng)}};
    const Point t = geometry::random_point(rng, U);
    const ControlTerms c = risk_control(risk, t, cp);
    const Vec2 D = c.descent + c.pull;
    EXPECT_NEAR(c.descent.x, -cp.k_v * risk.gradient.x / risk.phi, 1e-12);
    EXPECT_NEAR(c.command.v, std::clamp(D.x, -cp.v_max, cp.v_max), 1e-12);
    EXPECT_NEAR(c.command.omega, std::clamp(cp.k_omega * D.y / D.norm(), -cp.omega_max, cp.omega_max), 1e-12);
    // The turn is towards D whatever the target's bearing.
    if (std::abs(D.y) > 1e-9) {
      EXPECT_EQ(c.command.omega > 0, D.y > 0) << trial;
    }
  }
  // Heading along D: no turn, and full speed once |D| >= v_max.
  const ControlTerms ahead = risk_control({1.0, Vec2{-3, 0}}, Point(0, cp.preferred_distance), cp);
  EXPECT_NEAR(ahead.command.omega, 0, 1e-12);
  EXPECT_DOUBLE_EQ(ahead.command.v, cp.v_max);
}

TEST(RiskGradient, MatchesFiniteDifferencesAlongTheBoxRun) {
  // Every step of the box run against the adversarial target: phi-bar on the exact map at
  // the true positions, its closed-form gradient (recursive average of eq. (4) and its
  // perpendicular case) against central differences with V, the tree and the risks
  // rebuilt at the displaced observers, wherever the tree keeps its structure.
  const scene::Scene sc = scene::load_scene(example("box.json"));
  const TrackingScenario s = TrackingScenario::from_scene(sc);
  const geometry::VisibilityIndex index(*s.environment);
  SimulationParams p;
  p.policy = TargetPolicy::Adversarial;
  p.steps = 120;
  RiskParams rp;
  rp.delta = s.target.radius;
  int checked = 0;
  p.on_step = [&](const StepRecord& r) {
    if (!r.visible) return;
    for (Aggregation ag : {Aggregation::Recursive, Aggregation::Plain}) {
      RiskCheck c;
      try {
        c = check_risk_gradient(index, r.observer.position, r.target, rp, ag, 1e-6);
      } catch (const InputError&) {
        continue;  // the target on V's boundary
      }
      if (!c.stable) continue;
      const double scale = std::max(1e-6, c.risk.gradient.norm());
      EXPECT_NEAR(c.risk.gradient.x, c.difference.x, 1e-4 * scale) << "step " << r.step;
      EXPECT_NEAR(c.risk.gradient.y, c.difference.y, 1e-4 * scale) << "step " << r.step;
      ++checked;
    }
  };
  simulate(s, p);
  EXPECT_GT(checked, 60);
}

TEST(Detection, BeamsGrazingTheTargetAreTheTargets) {
  // Fixture box_grazing_rim_beam.json: the beam grazing the target's rim reads 9 cm beyond
  // its neighbour, the cluster's jump test split it off, and left in the scan it was a
  // spike in V with a free edge 0.25 m from the target. In a room at random poses: every
  // beam that hits the target is in the detection, and the map without the target keeps
  // no vertex on it.
  const auto sc = scene::load_scene(fixture("box_grazing_rim_beam.json"));
  {
    const Pose o{*sc.tracking->observer, sc.tracking->heading * M_PI / 180};
    const Scan scan = simulate_scan(sc.require_environment(), o, LaserSpec{}, Disc{*sc.tracking->target, 0.2});
    const Detection d = detect_target(scan, DetectParams{});
    ASSERT_TRUE(d.found);
    EXPECT_EQ(d.last, 199u) << "the grazing beam 199";
  }
  const auto room = geometry::Environment::make({{-5, -5}, {5, -5}, {5, 5}, {-5, 5}}, {});
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> U(-4.3, 4.3), H(-M_PI, M_PI);
  int runs = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Pose o{geometry::random_point(rng, U), H(rng)};
    const Point t = geometry::random_point(rng, U);
    if (dist(o.position, t) < 1.0 || dist(o.position, t) > 6.0) continue;  // (further, a 1-deg laser gets 3 readings)
    LaserSpec laser;
    laser.noise_sigma = 0.01;
    laser.max_range = 20;
    std::mt19937_64 noise(static_cast<std::uint64_t>(trial));
    const Scan with = simulate_scan(room, o, laser, Disc{t, 0.2}, &noise);
    const Scan without = simulate_scan(room, o, laser, std::nullopt);
    const Detection d = detect_target(with, DetectParams{}, to_sensor(o, t));
    ASSERT_TRUE(d.found) << "trial " << trial;
    for (std::size_t k = 0; k < with.ranges.size(); ++k) {
      if (without.ranges[k] - with.ranges[k] < 0.1) continue;  // the wall, not the target
      const bool in = d.first <= d.last ? k >= d.first && k <= d.last : k >= d.first || k <= d.last;  // (round the seam)
      EXPECT_TRUE(in) << "trial " << trial << " beam " << k;
    }
    const LocalMap map = local_map_without_target(with, d, MapParams{});
    const Point ts = to_sensor(o, t);
    for (const Point& v : map.vertices) EXPECT_GT(dist(v, ts), 0.3) << "trial " << trial << ": a vertex on the target";
    ++runs;
  }
  EXPECT_GT(runs, 150);
}

TEST(Detection, TargetPartlyHiddenByAnObstacleIsFound) {
  // Fixture box_target_partly_hidden.json: the box hides the target's left half; the
  // detector required both flanks to be further than the target, and dropped it.
  const auto sc = scene::load_scene(fixture("box_target_partly_hidden.json"));
  const auto& env = sc.require_environment();
  const Pose o{*sc.tracking->observer, sc.tracking->heading * M_PI / 180};
  const Point t = *sc.tracking->target;
  ASSERT_TRUE(geometry::visible(env, o.position, t));
  const Scan scan = simulate_scan(env, o, LaserSpec{}, Disc{t, 0.2});
  const Detection d = detect_target(scan, DetectParams{}, to_sensor(o, t));
  ASSERT_TRUE(d.found);
  EXPECT_LT(dist(to_world(o, d.center), t), 0.03);
}

TEST(Detection, TargetTouchingAnObstacleIsFoundNearItsEstimate) {
  // Fixture box_target_touching_the_box.json (step 43 of the box run): the target's
  // readings and the box face were one cluster, too wide to be the target, and TRACK lost
  // a target whose centre it could see. Sweep the target round the box corner at its
  // radius + 5 mm, with 1 cm range noise and an estimate 5 cm off.
  const auto sc = scene::load_scene(fixture("box_target_touching_the_box.json"));
  int found = 0;
  const int tried = around_the_box_corner(sc, [&](const Pose& o, const Point& t, const Scan& scan) {
    const Detection d = detect_target(scan, DetectParams{}, to_sensor(o, Point(t.x() + 0.05, t.y())));
    found += d.found && dist(to_world(o, d.center), t) < 0.03;
  });
  EXPECT_GT(tried, 10);
  EXPECT_EQ(found, tried);
}

TEST(Detection, ShadowFillKeepsTheEscapePastTheObstacleTheTargetTouches) {
  // Step 41 of the box run: the target beside the box corner, its shadow between the box
  // face (0.7 m away) and the far wall (5 m). Interpolating across drew a wall through the
  // shadow, the corner's free edge left V, and TRACK's SDE was 0.7-0.85 m where the true
  // one is 0.15-0.2 m: the risk of the very escape the target took vanished. Filled as the
  // paper assumes (no obstacle in the shadow: the nearer surface ends at its edge), TRACK's
  // map must not hide the escape: its SDE is at most the exact one plus 10 cm.
  const auto sc = scene::load_scene(fixture("box_target_touching_the_box.json"));
  const geometry::VisibilityIndex index(sc.require_environment());
  const int tried = around_the_box_corner(sc, [&](const Pose& o, const Point& t, const Scan& scan) {
    const TrackStep ts = track(scan, TrackerParams{}, to_sensor(o, t));
    ASSERT_TRUE(ts.tracked) << t;
    const double exact = escape_path_tree(exact_local_map(index, o.position), t).sde();
    EXPECT_LE(ts.tree.sde(), exact + 0.1) << t;
  });
  EXPECT_GT(tried, 10);
}

TEST(Adversary, DoesNotStallAtObstacleCorners) {
  // Fixture box_adversary_at_corner.json: the shortest-escape-path target stood at the box
  // corner for 25 s (its path ran through the corner; the step onto the boundary was
  // undone every time). Against an observer that does not move, from here and from random
  // starts in the lab, the adversary must escape within the time its shortest escape path
  // takes, lengthened by passing each corner at its radius.
  auto still = [](SimulationParams& p) {
    p.strategy = Strategy::Naive;
    p.tracker.control.k_distance = 0;
    p.tracker.control.k_bearing = 0;
    p.policy = TargetPolicy::Adversarial;
    p.steps = 600;
    p.stop_at_escape = true;
  };
  const auto box = scene::load_scene(fixture("box_adversary_at_corner.json"));
  TrackingScenario s = TrackingScenario::from_scene(box);
  SimulationParams p;
  still(p);
  const SimulationResult r = simulate(s, p);
  ASSERT_GE(r.escape_time, 0);
  EXPECT_LT(r.escape_time, 5.0);
  for (std::size_t i = 1; i < r.target.size(); ++i) EXPECT_GT(dist(r.target[i], r.target[i - 1]), 0.02) << i;

  const auto lab = scene::load_scene(example("lab.json"));
  s = TrackingScenario::from_scene(lab);
  const geometry::VisibilityIndex index(*s.environment);
  std::mt19937_64 rng(2);
  const auto bb = s.environment->bbox();
  std::uniform_real_distribution<double> X(bb.xmin(), bb.xmax()), Y(bb.ymin(), bb.ymax());
  int runs = 0, wrapped = 0;
  while (runs < 60) {
    const Point o = geometry::random_point(rng, X, Y), t = geometry::random_point(rng, X, Y);
    if (geometry::locate(*s.environment, o).kind != geometry::Location::Kind::Interior ||
        geometry::locate(*s.environment, t).kind != geometry::Location::Kind::Interior || dist(o, t) < 1 ||
        dist(o, t) > 7 || !geometry::visible(*s.environment, o, t))
      continue;
    std::optional<EscapePathTree> tree;
    try {
      tree = try_escape_path_tree(exact_local_map(index, o), t);
    } catch (const InputError&) {
      continue;
    }
    if (!tree || tree->shortest == kNone) continue;
    s.observer = Pose{o, 0};
    s.target.center = t;
    const SimulationResult run = simulate(s, p);
    const std::size_t pivots = tree->polyline(tree->shortest).size() - 2;
    const double speed = p.speed_ratio * p.tracker.control.v_max;
    // Each corner is passed on an arc of at most pi r plus 2 r to reach it and leave it.
    const double bound = (tree->sde() + (M_PI + 2) * s.target.radius * static_cast<double>(pivots + 1)) / speed + 0.5;
    ASSERT_GE(run.escape_time, 0) << "o " << o << " t " << t;
    EXPECT_LE(run.escape_time, bound) << "o " << o << " t " << t;
    // and it moves on every step on the way
    for (std::size_t i = 1; i < run.target.size(); ++i) EXPECT_GT(dist(run.target[i], run.target[i - 1]), 0.5 * speed * p.dt) << i;
    wrapped += pivots > 0;
    ++runs;
  }
  EXPECT_GE(wrapped, 3);
}

TEST(Detection, TheEstimateDoesNotJumpToAnotherBlob) {
  // Fixture lab_target_hugs_chair.json (issue 50, evaluate seed 88): the adversary, a
  // point, brushed the 0.3 m chair at (4, 4) with its disc inside it; the laser saw one
  // blob of chair and target, and with a fixed 1.5 m gate the estimate jumped 1.4 m to a
  // desk corner in one scan and stayed there while the target was in view (five of the
  // game strategy's seven lost winnable lab starts). The gate now grows from 0.25 m at the
  // target's top speed per scan since the last detection: while the target is in view the
  // estimate stays near it, for every strategy, here and from other lab starts.
  const auto lab = scene::load_scene(fixture("lab_target_hugs_chair.json"));
  const TrackingScenario s = TrackingScenario::from_scene(lab);
  SimulationParams base;
  base.policy = TargetPolicy::Adversarial;
  base.steps = 300;
  base.stop_at_escape = true;
  for (auto strategy : {Strategy::Risk, Strategy::Sde, Strategy::Naive}) {
    for (std::uint64_t seed : {88, 1, 2, 3}) {
      SimulationParams p = base;
      p.strategy = strategy;
      p.seed = seed;
      p.start_spread = seed == 88 ? 0 : 0.5;
      double err = 0;
      p.on_step = [&](const StepRecord& r) {
        if (r.visible) err = std::max(err, dist(r.estimate, r.target));
      };
      simulate(s, p);
      EXPECT_LT(err, 0.6) << to_string(strategy) << " seed " << seed;
    }
  }
}

TEST(Adversary, LookaheadTakesTheEscapeWithinReach) {
  // Put the target a step from leaving V in several directions at once: whichever way it
  // is, the look-ahead target leaves sight on its next step.
  const auto sc = scene::load_scene(example("box.json"));
  TrackingScenario s = TrackingScenario::from_scene(sc);
  SimulationParams p;
  p.policy = TargetPolicy::Lookahead;
  p.strategy = Strategy::Naive;
  p.tracker.control.k_distance = 0;
  p.tracker.control.k_bearing = 0;
  p.steps = 5;
  p.stop_at_escape = true;
  // The line of sight past the box corner (3.5, 3.25) from (1, 3) runs at slope 0.1: the
  // target 3 cm below it escapes with one 5 cm step up.
  s.observer = Pose{Point(1, 3), 0};
  s.target.center = Point(5.2, 3.42 - 0.03);
  const SimulationResult r = simulate(s, p);
  EXPECT_DOUBLE_EQ(r.escape_time, p.dt);
}

TEST(Dynamics, ExecutedVelocityChangesByAtMostTheBounds) {
  const auto sc = scene::load_scene(example("lab.json"));
  const TrackingScenario s = TrackingScenario::from_scene(sc);
  for (Strategy st : {Strategy::Risk, Strategy::Sde}) {
    SimulationParams p;
    p.strategy = st;
    p.policy = TargetPolicy::Random;
    p.steps = 150;
    p.accel = 0.5;
    p.alpha = 1.5;
    Command last;
    int limited = 0;
    p.on_step = [&](const StepRecord& r) {
      EXPECT_LE(std::abs(r.velocity.v - last.v), p.accel * p.dt + 1e-12) << r.step;
      EXPECT_LE(std::abs(r.velocity.omega - last.omega), p.alpha * p.dt + 1e-12) << r.step;
      limited += r.velocity.omega != r.command.omega;
      last = r.velocity;
    };
    simulate(s, p);
    EXPECT_GT(limited, 5) << to_string(st);
    // Without dynamics the command is the velocity.
    SimulationParams q = p;
    q.accel = q.alpha = 0;
    q.on_step = [&](const StepRecord& r) {
      if (r.velocity.v != 0) {
        EXPECT_EQ(r.velocity.v, r.command.v);  // (a blocked move stops it)
      }
      EXPECT_EQ(r.velocity.omega, r.command.omega);
    };
    simulate(s, q);
  }
}

TEST(Evaluation, IntervalsAreTheTextbookOnes) {
  CellResult c;
  c.horizon = 30;
  for (int i = 0; i < 100; ++i) c.escape_times.push_back(i < 20 ? 1.0 + i : 30.0);
  summarise(c);
  EXPECT_EQ(c.escaped, 20u);
  // Wilson score interval for 20/100: [0.1334, 0.2888].
  EXPECT_NEAR(c.escaped_fraction.low, 0.1334, 1e-4);
  EXPECT_NEAR(c.escaped_fraction.high, 0.2888, 1e-4);
  // Mean 0.2 * 10.5 + 0.8 * 30 = 26.1; sd from the two groups.
  EXPECT_NEAR(c.mean_escape.value, 26.1, 1e-12);
  double ss = 0;
  for (double t : c.escape_times) ss += (t - 26.1) * (t - 26.1);
  EXPECT_NEAR(c.mean_escape.high - c.mean_escape.value, 1.959964 * std::sqrt(ss / 99 / 100), 1e-5);
  // Median 30 (censored), its interval the 40th and 60th order statistics.
  EXPECT_DOUBLE_EQ(c.median_escape.value, 30);
  EXPECT_DOUBLE_EQ(c.median_escape.low, 30);
  CellResult d = c;
  for (auto& t : d.escape_times) t -= 0.5;
  const Interval diff = paired_difference(c, d);
  EXPECT_NEAR(diff.value, 0.5, 1e-12);
  EXPECT_NEAR(diff.low, 0.5, 1e-9);
}

TEST(Evaluation, ResultsDoNotDependOnTheNumberOfThreads) {
  const auto sc = scene::load_scene(example("box.json"));
  const std::vector<TrackingScenario> s{TrackingScenario::from_scene(sc)};
  EvaluationParams ep;
  ep.seeds = 3;
  ep.steps = 40;
  ep.fovs = {360};
  ep.dynamics = {false, true};
  ep.policies = {TargetPolicy::Random, TargetPolicy::Lookahead};
  ep.lookahead_headings = 4;
  ep.lookahead_steps = 2;
  ep.game_resolution = 0.5;  // the game is not what this tests (at 0.125 m it took 13 s)
  ep.jobs = 1;
  std::size_t calls = 0;
  const auto one = evaluate(s, ep, [&](std::size_t done, std::size_t total) {
    ++calls;
    EXPECT_EQ(done, calls);
    EXPECT_EQ(total, 2u * 2 * 3 * 3);
  });
  ep.jobs = 2;
  const auto two = evaluate(s, ep);
  ASSERT_EQ(one.size(), 12u);
  ASSERT_EQ(two.size(), one.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].escape_times, two[i].escape_times) << i;
    EXPECT_EQ(one[i].strategy, two[i].strategy);
    EXPECT_EQ(one[i].winnable, two[i].winnable) << i;
    EXPECT_EQ(one[i].grid_kept, two[i].grid_kept) << i;
  }
  EXPECT_EQ(calls, 36u);
}
