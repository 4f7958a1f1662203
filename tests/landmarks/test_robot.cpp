// The landmark robot's strategies against the ground truth from coordinates: they see
// only RobotInterface (readings and track), the checks read the OrderType.
#include <preimage/error.hpp>
#include <preimage/landmarks/robot.hpp>
#include <preimage/scene/scene.hpp>

#include <gtest/gtest.h>
#include <support/landmark_robot.hpp>

#include <algorithm>
#include <random>

using namespace preimage;
using geometry::Point;
using landmarks::OrderType;

using preimage::testing::generic_start;

TEST(LandmarkRobot, Strategy1LearnsTheWholeOrderType) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const std::size_t n = 3 + seed;
    const auto P = landmarks::random_landmarks(n, seed, 1000);
    const OrderType T = OrderType::of(P);
    landmarks::Simulator robot(P, generic_start(P, seed));
    const auto lambda = landmarks::learn_order_type(robot);
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = 0; j < n; ++j)
        if (i != j) {
          EXPECT_EQ(lambda[i * n + j], T.lambda(i, j)) << "seed " << seed;
        }
    EXPECT_LE(robot.primitives(), n * (n - 1));
    // Lemma 1's sets themselves, for one pair.
    const auto [l01, l10] = landmarks::learn_lambda(robot, 0, 1);
    EXPECT_EQ(l01, T.Lambda(0, 1));
    EXPECT_EQ(l10, T.Lambda(1, 0));
  }
}

TEST(LandmarkRobot, Strategies4And5FindTheHullWithLinearlyManyTracks) {
  for (std::size_t n : {3u, 4u, 7u, 20u, 50u, 100u, 200u})
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const auto P = landmarks::random_landmarks(n, seed * 31 + n, 1 << 20);
      const OrderType T = OrderType::of(P);
      landmarks::Simulator robot(P, generic_start(P, seed));
      const auto pair = landmarks::find_hull_pair(robot);
      EXPECT_EQ(T.lambda(pair.second, pair.first), 0u) << "n " << n;
      const std::size_t pair_tracks = robot.primitives();
      EXPECT_LE(pair_tracks, 2 * n + 2) << "n " << n;  // Theorem 2: O(n)
      landmarks::Simulator fresh(P, generic_start(P, seed + 7));
      auto hull = landmarks::learn_hull(fresh);
      auto truth = T.hull();
      std::rotate(truth.begin(), std::find(truth.begin(), truth.end(), hull.front()), truth.end());
      EXPECT_EQ(hull, truth) << "n " << n << " seed " << seed;
      EXPECT_LE(fresh.primitives(), 3 * n + 4) << "n " << n;
    }
}

TEST(LandmarkRobot, StartOnALineThroughTwoLandmarksIsRejected) {
  const std::vector<Point> P{{0, 0}, {10, 0}, {3, 7}};
  EXPECT_THROW(landmarks::Simulator(P, Point(5, 0)), InputError);
  EXPECT_THROW(landmarks::Simulator(P, Point(20, 0)), InputError);
  EXPECT_NO_THROW(landmarks::Simulator(P, Point(4, 2)));
}

TEST(LandmarkRobot, StartAtALaterLandmarkIsAccepted) {
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/landmarks_start_at_third.json");
  const auto L = landmarks::landmark_set(s);
  ASSERT_TRUE(s.start.has_value());
  landmarks::Simulator robot(L.points, *s.start);
  EXPECT_EQ(robot.at(), std::optional<std::uint32_t>(2));
  EXPECT_EQ(robot.lcd().size(), 3u);  // at a landmark: the other three
  for (std::uint32_t k = 0; k < 4; ++k) EXPECT_NO_THROW(landmarks::Simulator(L.points, k));
}
