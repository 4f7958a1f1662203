// Wall-following pursuit-evasion (section VI): the strategies against each other, every
// plan executed by the simulator and its path checked by the independent contamination
// checker of module pursuit.
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/wallfollow/environment.hpp>
#include <preimage/wallfollow/pursuit.hpp>
#include <preimage/wallfollow/sensors.hpp>

#include <gtest/gtest.h>

#include <iostream>
#include <random>

using namespace preimage;
using namespace preimage::wallfollow;
using geometry::Environment;
using geometry::Point;

namespace {

Sensors sensors_for(PursuitSensor s) {
  Sensors out;
  out.gap = s == PursuitSensor::Gap;
  out.bitangent = s == PursuitSensor::Bitangent;
  out.pebble_visibility = s == PursuitSensor::Pebble;
  return out;
}

struct Outcome {
  PursuitReport rep;
  std::vector<geometry::ExactPoint> path;  // the executed plan
  std::optional<bool> cleared;             // the independent checker on it
};

// The strategy through the simulator, its plan executed and checked.
Outcome run(const Environment& env, PursuitSensor s, const Point& start) {
  Simulator sim(env, start, geometry::Vector(1, 0.3));
  sim.enable(sensors_for(s));
  PursuitOptions o;
  o.sensor = s;
  Outcome r{pursue(sim, o), {}, std::nullopt};
  if (r.rep.outcome == PursuitReport::Outcome::Plan) {
    const std::size_t from = sim.path().size() - 1;
    EXPECT_FALSE(execute(sim, r.rep.plan).has_value());  // no evader: never detected
    r.path.assign(sim.path().begin() + static_cast<long>(from), sim.path().end());
    r.cleared = pursuit::check_exact_paths(env, pursuit::ExactPaths{r.path}).cleared;
  }
  return r;
}

std::optional<Environment> random_polygon(std::size_t n, std::uint64_t seed) {
  auto env = Environment::make(geometry::generators::random_simple_polygon(n, seed, 100.0), {});
  try {
    require_general_position(env);
  } catch (const InputError&) {
    return std::nullopt;
  }
  return env;
}

// A point strictly inside the polygon, by rejection.
Point random_interior(const Environment& env, std::mt19937_64& rng) {
  const auto box = env.bbox();
  std::uniform_real_distribution<double> x(box.xmin(), box.xmax()), y(box.ymin(), box.ymax());
  for (;;) {
    const Point p(x(rng), y(rng));
    if (geometry::locate(env, p).kind == geometry::Location::Kind::Interior) return p;
  }
}

}  // namespace

namespace {
// The true bitangents as keys of an OrderingMap over the true cut ordering.
std::vector<KnownBitangent> true_bitangents(const Environment& env, const OrderingMap& m) {
  const auto cuts = true_cut_ordering(env);
  auto key_of = [&](const BoundaryPoint& b) {
    std::uint32_t before = 0;
    for (const Cut& c : cuts.cuts)
      if (c.edge == b.edge && CGAL::has_smaller_distance_to_point(env.exact_vertex(b.edge), c.end, b.point)) ++before;
    return m.key(m.vertex(b.edge) + before, 2);
  };
  std::vector<KnownBitangent> out;
  for (const Bitangent& b : bitangents(env)) out.push_back({b.i, b.j, key_of(b.b_ij), key_of(b.b_ji)});
  return out;
}
}  // namespace

TEST(WallFollowBitangents, CandidatesHoldEveryBitangentAndBoundsHoldItsRays) {
  std::size_t checked = 0, separating = 0;
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    const std::size_t n = 6 + seed % 35;
    auto env = Environment::make(geometry::generators::random_simple_polygon(n, 5000 + seed, 100.0), {});
    try {
      require_general_position(env);
    } catch (const InputError&) {
      continue;
    }
    const OrderingMap m(true_cut_ordering(env).ordering);
    const auto truth = true_bitangents(env, m);
    const auto approx = approximate_bitangents(m);
    const auto geo = bitangents(env);
    for (std::size_t k = 0; k < truth.size(); ++k) {
      const KnownBitangent& t = truth[k];
      EXPECT_TRUE(bitangent_candidate(m, t.i, t.j)) << "Proposition 11, seed " << seed;
      const auto a = std::find_if(approx.begin(), approx.end(), [&](auto& x) { return x.i == t.i && x.j == t.j; });
      ASSERT_NE(a, approx.end());
      for (bool at_j : {false, true}) {
        const std::uint32_t v = at_j ? t.j : t.i, w = at_j ? t.i : t.j;
        const std::uint64_t kv = m.key(m.vertex(v)), end = at_j ? t.b_ji : t.b_ij, bound = at_j ? a->b_ji : a->b_ij;
        // The true end lies strictly between the bound and v (Propositions 13-15).
        if (m.on_right_side(v, w)) EXPECT_TRUE(m.in_arc(end, bound, kv)) << "seed " << seed << " v" << v + 1;
        else EXPECT_TRUE(m.in_arc(end, kv, bound)) << "seed " << seed << " v" << v + 1;
      }
      ++checked;
      separating += geo[k].separating;
      EXPECT_EQ(geo[k].separating, m.on_right_side(t.i, t.j) == m.on_right_side(t.j, t.i)) << "seed " << seed;
    }
  }
  EXPECT_GT(checked, 500u);
  EXPECT_GT(separating, 100u);
}

namespace {
// The true partition of the active primitives at point k (true ordering): which shadow
// component of V holds each primitive's germ. Also checks that every component holds one.
std::vector<std::uint16_t> true_partition(const Environment& env, const geometry::VisibilityIndex& vis, const OrderingMap& m,
                                          const TrueCuts& cuts, std::uint32_t k, std::string& problem) {
  geometry::ExactPoint q;
  const CutPoint& c = m.ordering().points[k];
  if (c.kind == CutPoint::Kind::Vertex) q = env.exact_vertex(c.vertex);
  else
    for (const Cut& x : cuts.cuts)
      if (x.vertex == c.vertex && x.left == (c.kind == CutPoint::Kind::Left)) q = x.end;
  const auto arcs = shadow_arcs(env, vis.compute(q));
  std::vector<int> arc_of;
  std::vector<char> used(arcs.size(), 0);
  for (PrimitiveId p : m.active(k)) {
    const BoundaryPoint g = boundary_vertex(env, p / 2, p % 2 ? -1 : +1);
    int found = -1;
    for (std::size_t a = 0; a < arcs.size(); ++a)
      if (in_open_arc(env, g, arcs[a].from, arcs[a].to)) found = static_cast<int>(a);
    if (found < 0) problem = "active primitive " + std::string(p % 2 ? "R" : "L") + std::to_string(p / 2 + 1) + " is not in the shadow at " + m.name(k);
    else used[static_cast<std::size_t>(found)] = 1;
    arc_of.push_back(found);
  }
  for (std::size_t a = 0; a < arcs.size(); ++a)
    if (!used[a]) problem = "a shadow component at " + m.name(k) + " holds no active primitive";
  std::vector<std::uint16_t> out;
  std::vector<int> seen;
  for (int a : arc_of) {
    auto it = std::find(seen.begin(), seen.end(), a);
    if (it == seen.end()) seen.push_back(a), it = seen.end() - 1;
    out.push_back(static_cast<std::uint16_t>(it - seen.begin()));
  }
  return out;
}
}  // namespace

TEST(WallFollowPursuit, CompoundsOfStrategy3FollowTheTrueShadowComponents) {
  std::size_t steps = 0, merges = 0, splits = 0, separating_events = 0;
  std::mt19937_64 rng(7);
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const std::size_t n = 6 + seed % 30;
    auto env = Environment::make(geometry::generators::random_simple_polygon(n, 9000 + seed, 100.0), {});
    try {
      require_general_position(env);
    } catch (const InputError&) {
      continue;
    }
    const auto cuts = true_cut_ordering(env);
    const OrderingMap m(cuts.ordering);
    const geometry::VisibilityIndex vis(env);
    const auto truth = true_bitangents(env, m);
    std::string problem;
    Position p{m.vertex(0), 0};
    CompoundState s{true_partition(env, vis, m, cuts, p.at, problem), {}};
    s.labels = filter::ShadowLabels(s.compound.empty() ? 0 : *std::max_element(s.compound.begin(), s.compound.end()) + 1u, true);
    for (int step = 0; step < 60; ++step) {
      const Action u = std::array{Action::RFollow, Action::LFollow, Action::Jump}[rng() % 3];
      const auto q = m.move(p, u);
      if (!q) continue;
      const auto x = crossings_of(m, truth, p.at, q->at);
      for (auto& c : x) (c.merge ? merges : splits)++, separating_events += m.on_right_side(c.i, c.j) == m.on_right_side(c.j, c.i);
      s = compound_transition(m, p.at, s, q->at, x);
      p = *q;
      const auto want = true_partition(env, vis, m, cuts, p.at, problem);
      ASSERT_EQ(problem, "") << "seed " << seed;
      ASSERT_EQ(s.compound, want) << "seed " << seed << " step " << step << " at " << m.name(p.at);
      ++steps;
    }
  }
  EXPECT_GT(steps, 2000u);
  EXPECT_GT(merges, 50u);
  EXPECT_GT(splits, 50u);
  EXPECT_GT(separating_events, 20u);
}

TEST(WallFollowPursuit, StrategiesAgreeAndEveryPlanClears) {
  // Strategies 2, 3 and 5 are complete (Propositions 8, 10): they agree on solvability.
  // Strategy 6 never returns a plan that does not clear (Proposition 17), so it solves a
  // subset. Every plan runs on the simulator and passes the independent checker; the
  // free-moving pursuer of module pursuit solves whatever the wall-follower solves.
  std::mt19937_64 rng(11);
  std::size_t polygons = 0, solved = 0, by_none = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto env = random_polygon(6 + seed % 21, 100 + seed);
    if (!env) continue;
    ++polygons;
    const Point start = random_interior(*env, rng);
    bool plan[4];
    int k = 0;
    for (PursuitSensor s : {PursuitSensor::Gap, PursuitSensor::Bitangent, PursuitSensor::Pebble, PursuitSensor::None}) {
      const Outcome r = run(*env, s, start);
      ASSERT_NE(r.rep.outcome, PursuitReport::Outcome::Budget);
      plan[k++] = r.rep.outcome == PursuitReport::Outcome::Plan;
      if (r.cleared) {
        EXPECT_TRUE(*r.cleared) << to_string(s) << " plan, seed " << seed;
      }
      EXPECT_EQ(r.rep.labels_along.size(), plan[k - 1] ? r.rep.plan.size() + 1 : 0u);
    }
    EXPECT_EQ(plan[1], plan[0]) << "Strategies 2 and 3, seed " << seed;
    EXPECT_EQ(plan[2], plan[0]) << "Strategies 2 and 5, seed " << seed;
    EXPECT_TRUE(!plan[3] || plan[0]) << "Strategy 6 solves what Strategy 2 does not, seed " << seed;
    solved += plan[0];
    by_none += plan[3];
    if (plan[0]) {
      const auto free = pursuit::search(pursuit::ConservativeCells::build(*env), 1);
      EXPECT_EQ(free.outcome, pursuit::SearchResult::Outcome::Plan) << "seed " << seed;
    }
  }
  EXPECT_GT(polygons, 30u);
  EXPECT_GT(solved, polygons * 3 / 4);
  EXPECT_GT(by_none, polygons / 2);
}

TEST(WallFollowPursuit, EveryStaticEvaderIsDetected) {
  // A plan clears E, so an evader standing anywhere is seen on the way (h_d); and the
  // sensor agrees with exact two-point visibility at the waypoints.
  std::mt19937_64 rng(5);
  std::size_t evaders = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto env = random_polygon(10 + 2 * seed, 300 + seed);
    if (!env) continue;
    PursuitOptions o;
    o.sensor = PursuitSensor::None;
    for (int e = 0; e < 8; ++e) {
      Simulator sim(*env, env->vertex(0), geometry::Vector(1, 0));
      const auto rep = pursue(sim, o);
      if (rep.outcome != PursuitReport::Outcome::Plan) break;
      const std::size_t from = sim.path().size() - 1;
      const auto evader = geometry::to_exact(random_interior(*env, rng));
      Sensors d;
      d.detection = true;
      sim.set_evader(evader);
      sim.enable(d);
      const auto when = execute(sim, rep.plan);
      ASSERT_TRUE(when.has_value()) << "an evader at " << geometry::to_double(evader) << " is never seen, seed " << seed;
      // Seen at the start iff visible from there; not seen before the action that sees it.
      const auto& P = sim.path();
      EXPECT_EQ(*when == 0, geometry::visible(*env, P[from], evader));
      if (*when > 0) {
        EXPECT_FALSE(geometry::visible(*env, P[from + *when - 1], evader));
      }
      ++evaders;
    }
  }
  EXPECT_GT(evaders, 30u);
}
