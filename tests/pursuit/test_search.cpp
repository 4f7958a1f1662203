// The information-graph search against the known answers of 6.3 and Guibas et al. 1999,
// every plan checked by the independent contamination checker, and the merged search
// against one that does not merge information states.
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/examples.hpp>
#include <preimage/pursuit/search.hpp>
#include <preimage/scene/scene.hpp>

#include <gtest/gtest.h>

using namespace preimage;
using geometry::Environment;
using geometry::Point;
using pursuit::ConservativeCells;
using pursuit::SearchResult;
namespace g = geometry::generators;

namespace {

void expect_checked(const Environment& env, const SearchResult& r, const std::string& what) {
  ASSERT_EQ(r.outcome, SearchResult::Outcome::Plan) << what;
  const auto& plan = *r.plan;
  ASSERT_EQ(plan.paths.size(), r.pursuers) << what;
  for (auto& p : plan.paths) {
    ASSERT_EQ(p.size(), plan.paths[0].size()) << what;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) EXPECT_TRUE(geometry::visible(env, p[i], p[i + 1])) << what;
  }
  const auto check = pursuit::check_paths(env, plan.paths);
  EXPECT_TRUE(check.cleared) << what << ": the checker finds " << check.contaminated_at_end.size()
                             << " contaminated regions at the end, area " << check.contaminated_area;
}

}  // namespace

TEST(PursuitSearch, StarShapedPolygonsNeedNoMotion) {
  for (std::size_t k : {3, 5, 8}) {
    const auto env = Environment::make(g::star(k), {});
    const auto C = ConservativeCells::build(env);
    const auto r = pursuit::search(C, 1, {Point(0, 0)});
    ASSERT_EQ(r.outcome, SearchResult::Outcome::Plan);
    EXPECT_TRUE(r.plan->moves.empty());
    EXPECT_EQ(r.plan->paths[0].size(), 1u);
    const auto anywhere = pursuit::search(C, 1);
    ASSERT_EQ(anywhere.outcome, SearchResult::Outcome::Plan);
    EXPECT_TRUE(anywhere.plan->moves.empty()) << "a cell of the kernel sees everything";
    expect_checked(env, r, "star");
  }
}

TEST(PursuitSearch, CorridorsWithSideRoomsNeedOnePursuer) {
  for (std::size_t rooms : {1, 2, 4}) {
    const auto env = pursuit::examples::corridor_with_rooms(rooms);
    const auto C = ConservativeCells::build(env);
    const auto r = pursuit::search(C, 1, {Point(0.5, 0.5)});
    expect_checked(env, r, std::to_string(rooms) + " rooms");
  }
  for (auto env : {Environment::make(g::comb(4), {}), Environment::make(g::spiral(2, 1.0, 16), {})}) {
    const auto C = ConservativeCells::build(env);
    expect_checked(env, pursuit::search(C, 1), "comb / spiral");
  }
}

TEST(PursuitSearch, EveryEnvironmentWithAHoleNeedsTwoPursuers) {
  std::vector<Environment> envs{pursuit::examples::room_with_pillar()};
  for (std::uint64_t s = 1; s <= 5; ++s) envs.push_back(g::random_environment(14 + 2 * s, 1 + s % 2, 100 + s));
  for (std::size_t i = 0; i < envs.size(); ++i) {
    const auto C = ConservativeCells::build(envs[i]);
    const auto one = pursuit::search(C, 1);
    EXPECT_EQ(one.outcome, SearchResult::Outcome::NoPlan) << "environment " << i;
    EXPECT_GE(one.states, C.size()) << "environment " << i;  // every cell is reachable
    if (i < 3) expect_checked(envs[i], pursuit::search(C, 2), "two pursuers, environment " + std::to_string(i));
  }
}

TEST(PursuitSearch, ThreeBentArmsAroundAHubNeedTwoPursuers) {
  const auto env = pursuit::examples::three_arms();
  const auto C = ConservativeCells::build(env);
  const auto one = pursuit::search(C, 1);
  EXPECT_EQ(one.outcome, SearchResult::Outcome::NoPlan);
  expect_checked(env, pursuit::search(C, 2, {Point(0, 0)}), "three arms, two pursuers");
}

TEST(PursuitSearch, RandomPolygonPlansPassTheChecker) {
  std::size_t plans = 0;
  for (std::uint64_t s = 1; s <= 12; ++s) {
    const auto env = Environment::make(g::random_simple_polygon(12 + s, 50 + s, 10.0), {});
    const auto C = ConservativeCells::build(env);
    const auto r = pursuit::search(C, 1);
    if (r.outcome != SearchResult::Outcome::Plan) continue;
    ++plans;
    expect_checked(env, r, "random polygon " + std::to_string(s));
  }
  EXPECT_GT(plans, 6u);
}

TEST(PursuitSearch, MergedSearchAgreesWithWalksThatDoNotMerge) {
  std::vector<Environment> envs{pursuit::examples::room_with_pillar(), pursuit::examples::corridor_with_rooms(2),
                                Environment::make(g::comb(3), {})};
  for (std::uint64_t s = 1; s <= 8; ++s) envs.push_back(Environment::make(g::random_simple_polygon(9 + s % 4, 200 + s, 10.0), {}));
  for (std::uint64_t s = 1; s <= 2; ++s) envs.push_back(g::random_environment(12, 1, 300 + s));
  std::size_t compared = 0, no_plan = 0;
  for (std::size_t i = 0; i < envs.size(); ++i) {
    const auto C = ConservativeCells::build(envs[i]);
    ASSERT_LE(C.reflex_vertices(), 12u);
    for (std::uint32_t start : {0u, static_cast<std::uint32_t>(C.size() / 2)}) {
      std::size_t reached = 0;
      const auto fewest = pursuit::fewest_crossings(C, start, &reached);
      std::size_t nodes = 0;
      bool complete = false;
      // With no plan, walks as long as there are information states: a shortest plan
      // visits each at most once, so none longer is needed.
      const std::size_t depth = fewest ? *fewest : reached;
      const auto brute = pursuit::search_without_merging(C, start, depth, 50'000'000, nodes, complete);
      if (!complete) continue;
      ++compared;
      if (!fewest) ++no_plan;
      EXPECT_EQ(brute, fewest) << "environment " << i << " from cell " << start;
      const auto r = pursuit::search(C, 1, {C.cell(start).sample});
      EXPECT_EQ(r.outcome == SearchResult::Outcome::Plan, fewest.has_value()) << "environment " << i;
    }
  }
  EXPECT_GT(compared, 12u);
  EXPECT_GE(no_plan, 3u) << "the environments with a hole";
}

TEST(PursuitSearch, AnyPlanOrderAgreesOnExistence) {
  std::vector<Environment> envs{pursuit::examples::room_with_pillar(), pursuit::examples::three_arms(),
                                pursuit::examples::corridor_with_rooms(3), g::random_environment(18, 1, 121)};
  for (std::uint64_t s = 1; s <= 6; ++s) envs.push_back(Environment::make(g::random_simple_polygon(16 + 2 * s, 700 + s, 10.0), {}));
  for (std::size_t i = 0; i < envs.size(); ++i) {
    const auto C = ConservativeCells::build(envs[i]);
    const auto shortest = pursuit::search(C, 1);
    pursuit::SearchOptions o;
    o.shortest = false;
    const auto any = pursuit::search(C, 1, o);
    EXPECT_EQ(any.outcome, shortest.outcome) << "environment " << i;
    if (any.plan) expect_checked(envs[i], any, "any plan, environment " + std::to_string(i));
  }
}

// Rings touching at vertices (contacts): every plan found (one or two pursuers, paths
// that avoid contact points) clears the environment by the independent checker, which
// joins shadow faces at a contact point only while nobody sees it. The pocket under the
// chevron is reached only through contact points: no plan avoids them, for any number of
// pursuers the search tries (docs/pursuit.md).
TEST(PursuitSearch, ContactMapPlansPassTheChecker) {
  std::vector<Environment> envs;
  for (const char* f : {"checkerboard", "corridor_closed_at_points", "hole_touches_boundary"})
    envs.push_back(*scene::load_scene(std::string(PREIMAGE_FIXTURES).append("/contacts/").append(f).append(".json")).environment);
  for (std::uint64_t s = 1; s <= 16; ++s) envs.push_back(g::touching_squares(3 + s % 4, 0.3 + 0.1 * (s % 6), s, s % 2 == 0));
  std::size_t plans = 0;
  for (std::size_t i = 0; i < envs.size(); ++i) {
    const auto C = ConservativeCells::build(envs[i]);
    for (std::size_t k : {1, 2}) {
      const auto r = pursuit::search(C, k);
      if (r.outcome != SearchResult::Outcome::Plan) continue;
      ++plans;
      expect_checked(envs[i], r, "contact map " + std::to_string(i) + ", " + std::to_string(k) + " pursuers");
      break;
    }
  }
  EXPECT_GE(plans, 6u);
  const auto pocket = *scene::load_scene(std::string(PREIMAGE_FIXTURES).append("/contacts/pocket_under_chevron.json")).environment;
  const auto C = ConservativeCells::build(pocket);
  for (std::size_t k : {1, 2, 3}) EXPECT_EQ(pursuit::search(C, k).outcome, SearchResult::Outcome::NoPlan) << k << " pursuers";
}
