// The constructive O(log n) strategy of 6.3: every plan passes the independent checker,
// its pursuer count stays within the logarithmic bound, and it is never below the exact
// minimum found by exhaustive search.
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
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

TEST(PursuitSplit, RejectsHoles) {
  EXPECT_THROW(pursuit::split_strategy(pursuit::examples::room_with_pillar()), InputError);
}
