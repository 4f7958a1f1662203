// The constructive strategy of 6.3 (static guards, holes included) and the interval of
// pursuers needed. The strategy: every plan passes the independent checker,
// its pursuer count stays within the logarithmic bound, and it is never below the exact
// minimum found by exhaustive search.
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/pursuit/bounds.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/pursuit/examples.hpp>
#include <preimage/pursuit/split.hpp>
#include <preimage/scene/import.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace preimage;
using geometry::Environment;
using geometry::Point;
namespace g = geometry::generators;

namespace {
void expect_cleared(const Environment& env, const pursuit::SplitResult& r, const std::string& what) {
  ASSERT_EQ(r.plan.paths.size(), r.pursuers) << what;
  const auto c = pursuit::check_paths(env, r.plan.paths);
  EXPECT_TRUE(c.cleared) << what << ": " << c.contaminated_at_end.size() << " regions left";
  // Depth of balanced splits: each part keeps at least a third of the triangles.
  const double n = static_cast<double>(env.num_vertices());
  EXPECT_LE(static_cast<double>(r.pursuers), 1 + std::ceil(std::log(n) / std::log(1.5))) << what;
}
}  // namespace

TEST(PursuitSplit, StarShapedNeedsOneAndNoGuard) {
  const auto env = Environment::make(g::star(7), {});
  const auto r = pursuit::split_strategy(env);
  EXPECT_EQ(r.pursuers, 1u);
  EXPECT_EQ(r.guards, 0u);
  expect_cleared(env, r, "star");
}

TEST(PursuitSplit, ClearsSimplyConnectedEnvironments) {
  std::vector<std::pair<std::string, Environment>> envs{
      {"three arms", pursuit::examples::three_arms()},
      {"corridor with rooms", pursuit::examples::corridor_with_rooms(4)},
      {"comb", Environment::make(g::comb(6), {})},
      {"spiral", Environment::make(g::spiral(2.5, 1.0, 16), {})}};
  for (std::uint64_t s = 1; s <= 4; ++s) envs.push_back({"random " + std::to_string(s), Environment::make(g::random_simple_polygon(15 + 10 * s, 600 + s, 10.0), {})});
  for (auto& [name, env] : envs)
    for (bool search : {false, true}) {
      const auto r = pursuit::split_strategy(env, std::nullopt, search);
      expect_cleared(env, r, name + (search ? " (regions by search)" : " (star-shaped regions)"));
      if (name == "three arms") {
        EXPECT_GE(r.pursuers, 2u) << "one pursuer cannot clear three bent arms";
        if (search) {
          EXPECT_EQ(r.pursuers, 2u) << "the exact minimum";
        }
      }
    }
}

TEST(PursuitSplit, HouseExpoFloorPlan) {
  const auto s = scene::import_houseexpo(
      scene::read_file(std::string(PREIMAGE_FLOORPLANS) + "/house_expo_room_0000.json"), "house 0000");
  const auto r = pursuit::split_strategy(*s.environment);
  expect_cleared(*s.environment, r, "house 0000");
}

// House 1451 draws a diagonal wall as a staircase of 1 cm steps; the guard's split left
// one part of one triangle per step, 70 of its 86 parts, and the pursuer walked to each in
// triangle order: 307 m of plan, 293,860 checker moments, 196 s to certify. Standing
// where many parts are seen at once, and touring the stops, makes it 74 m (the CLI test
// cli.pursuit_plan_house_1451 certifies it end to end).
TEST(PursuitSplit, StaircaseWallPartsAreClearedFromFewStops) {
  const auto s = scene::import_houseexpo(
      scene::read_file(std::string(PREIMAGE_FLOORPLANS) + "/house_expo_room_1451.json"), "house 1451");
  const auto r = pursuit::split_strategy(*s.environment);
  EXPECT_EQ(r.pursuers, 2u);
  EXPECT_EQ(r.guards, 1u);
  EXPECT_EQ(r.regions, 86u);
  EXPECT_LE(r.stops, 20u) << "one stop per part walks to every step of the staircase";
  EXPECT_LT(r.plan.length, 100.0);
}

// 6.3 with holes: a static guard in a triangle cuts free space where it sees whole
// triangulation edges; the parts are cleared one at a time while it stands.
TEST(PursuitSplit, StaticGuardsClearEnvironmentsWithHoles) {
  std::vector<std::pair<std::string, Environment>> envs{{"room with pillar", pursuit::examples::room_with_pillar()},
                                                        {"office 2 x 2", g::office(2, 2)}};
  for (std::uint64_t s = 1; s <= 3; ++s) envs.push_back({"random, " + std::to_string(s) + " holes", g::random_environment(14 + 2 * s, s, 700 + s)});
  for (std::uint64_t s = 0; s < 4; ++s)
    envs.push_back({"rectilinear " + std::to_string(s), g::random_rectilinear(4 + s % 2, 4 + s % 3, true, 900 + s)});
  for (auto& [name, env] : envs) {
    ASSERT_GT(env.num_holes(), 0u) << name;
    const auto r = pursuit::split_strategy(env);
    EXPECT_GE(r.pursuers, 2u) << name << ": one pursuer never clears a hole";
    EXPECT_GE(r.guards, 1u) << name;
    EXPECT_EQ(r.guard_points.size(), r.guards) << name;
    expect_cleared(env, r, name);
  }
}

// The book: "if all of the trichromatic triangles were removed, then W_free would be
// divided into simply-connected regions". Not with one hole: its triangles touch two
// rings, none is trichromatic, and the annulus stays. (The strategy takes every triangle
// as a candidate post, so it cuts the annulus anyway.)
TEST(PursuitSplit, TrichromaticTrianglesDoNotCutEveryHole) {
  const auto r = pursuit::split_strategy(pursuit::examples::room_with_pillar());
  EXPECT_EQ(r.trichromatic, 0u);
  EXPECT_EQ(r.pursuers, 2u);
  const auto office = pursuit::split_strategy(g::office(2, 2));
  EXPECT_GT(office.trichromatic, 0u);
}

// Fig. 6.40's family: level L needs L pursuers; the strategy stays within the issue's
// bounds (2, 4, 6) and one pursuer is never enough from level 2 on.
TEST(PursuitSplit, NestedUFamily) {
  const std::size_t bound[] = {0, 1, 2, 4, 6};
  for (std::size_t level = 1; level <= 4; ++level) {
    const auto env = pursuit::examples::nested_u(level);
    ASSERT_EQ(env.num_holes(), 0u);
    const auto r = pursuit::split_strategy(env);
    EXPECT_GE(r.pursuers, std::min<std::size_t>(level, 2)) << "level " << level;
    EXPECT_LE(r.pursuers, bound[level]) << "level " << level;
    expect_cleared(env, r, "nested U level " + std::to_string(level));  // every plan in the suite is checked (level 4: 3 s)
    const auto C = pursuit::ConservativeCells::build(env);
    const auto one = pursuit::search(C, 1, {std::nullopt, 1'000'000, false});
    EXPECT_EQ(one.outcome, level == 1 ? pursuit::SearchResult::Outcome::Plan : pursuit::SearchResult::Outcome::NoPlan)
        << "level " << level;
  }
  EXPECT_EQ(pursuit::split_strategy(pursuit::examples::nested_u(2)).pursuers, 2u);
  EXPECT_THROW(pursuit::examples::nested_u(0), std::invalid_argument);
}

// The interval: both ends with their reasons, the plan checked.
TEST(PursuitBounds, IntervalsWithReasons) {
  {
    const auto b = pursuit::pursuer_bounds(pursuit::examples::corridor_with_rooms(3));
    EXPECT_EQ(b.lower, 1u);
    EXPECT_EQ(b.upper, 1u);
    EXPECT_EQ(b.plan_source, "search");
    ASSERT_TRUE(b.check);
    EXPECT_TRUE(b.check->cleared);
  }
  {
    const auto b = pursuit::pursuer_bounds(pursuit::examples::room_with_pillar());
    EXPECT_EQ(b.lower, 2u);
    EXPECT_EQ(b.upper, 2u);
    EXPECT_NE(b.lower_reason.find("1 hole"), std::string::npos) << b.lower_reason;
    EXPECT_TRUE(b.searches.empty()) << "a hole settles the lower end without searching";
  }
  {
    const auto b = pursuit::pursuer_bounds(pursuit::examples::three_arms());
    EXPECT_EQ(b.lower, 2u) << "the complete one-pursuer search fails";
    EXPECT_EQ(b.upper, 2u);
    EXPECT_NE(b.lower_reason.find("complete one-pursuer search"), std::string::npos) << b.lower_reason;
  }
  {
    // Level 3 needs 3; the interval holds it although no search proves more than 2.
    pursuit::BoundsOptions o;
    o.time_limit = 10;
    const auto b = pursuit::pursuer_bounds(pursuit::examples::nested_u(3), o);
    EXPECT_EQ(b.lower, 2u);
    EXPECT_GE(b.upper, 3u);
    EXPECT_LE(b.upper, 4u);
    ASSERT_TRUE(b.check);
    EXPECT_TRUE(b.check->cleared);
  }
}

TEST(PursuitBounds, BudgetsStopTheSearchNotTheAnswer) {
  pursuit::BoundsOptions o;
  o.max_states = 5;
  const auto b = pursuit::pursuer_bounds(pursuit::examples::three_arms(), o);
  ASSERT_FALSE(b.searches.empty());
  EXPECT_EQ(b.searches[0].outcome, pursuit::SearchResult::Outcome::Budget);
  EXPECT_EQ(b.searches[0].budget, "states");
  EXPECT_EQ(b.lower, 1u) << "an unfinished search proves nothing";
  EXPECT_GE(b.upper, 2u);
  ASSERT_TRUE(b.check);
  EXPECT_TRUE(b.check->cleared);
  // A search stopped by its memory budget says so.
  const auto C = pursuit::ConservativeCells::build(pursuit::examples::nested_u(3));
  pursuit::SearchOptions so;
  so.max_mb = 1;
  so.shortest = false;
  const auto r = pursuit::search(C, 2, so);
  EXPECT_EQ(r.outcome, pursuit::SearchResult::Outcome::Budget);
  EXPECT_EQ(r.budget, "memory");
  EXPECT_LE(r.bytes, std::size_t{1} << 20);
}
