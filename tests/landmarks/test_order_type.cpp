// Order types from coordinates against brute force (every triple's orientation), the
// axioms of section 3.1 on realizable and corrupted chirotopes, and canonical forms
// under relabelling, affine maps and reflection.
#include <preimage/error.hpp>
#include <preimage/landmarks/order_type.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace preimage;
using geometry::Point;
using landmarks::OrderType;

namespace {

std::vector<Point> random_points(std::size_t n, std::uint64_t seed, int range = 1000) {
  return landmarks::random_landmarks(n, seed, range);
}

landmarks::Chirotope chi_of(const OrderType& T) {
  return [&T](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return T.chi(i, j, k); };
}

}  // namespace

TEST(OrderType, MatchesEveryTripleOrientation) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const std::size_t n = 3 + seed % 14;
    const auto P = random_points(n, seed, seed % 2 ? 20 : 1000);  // small grids: many equal x and y
    const OrderType T = OrderType::of(P);
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = 0; j < n; ++j) {
        if (i == j) continue;
        std::vector<std::uint32_t> left;
        for (std::uint32_t k = 0; k < n; ++k) {
          if (k == i || k == j) continue;
          const int o = geometry::orientation(P[i], P[j], P[k]);
          ASSERT_EQ(T.chi(i, j, k), o) << "seed " << seed;
          if (o > 0) left.push_back(k);
        }
        EXPECT_EQ(T.lambda(i, j), left.size());
        EXPECT_EQ(T.Lambda(i, j), left);
      }
    // Hull: landmarks with every other on one side of some edge, counter-clockwise.
    const auto h = T.hull();
    for (std::size_t t = 0; t < h.size(); ++t)
      for (std::uint32_t k = 0; k < n; ++k)
        if (k != h[t] && k != h[(t + 1) % h.size()]) {
          EXPECT_GT(geometry::orientation(P[h[t]], P[h[(t + 1) % h.size()]], P[k]), 0);
        }
  }
}

TEST(OrderType, GeneralPositionErrorsNameTheLandmarks) {
  scene::Scene s;
  s.landmarks = {{"a", {0, 0}}, {"b", {5, 1}}, {"c", {2, 2}}, {"d", {1, 7}}, {"e", {4, 4}}};
  try {
    (void)landmarks::landmark_set(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "$.landmarks[0] ('a'), $.landmarks[2] ('c') and $.landmarks[4] ('e') are collinear (landmarks must be in general position)");
  }
  // OrderType::of meets both kinds of collinear triple in its sweep: a landmark straight
  // behind another, and two in the same direction.
  EXPECT_THROW((void)OrderType::of(std::vector<Point>{{0, 0}, {2, 1}, {-4, -2}, {0, 5}}), InputError);
  EXPECT_THROW((void)OrderType::of(std::vector<Point>{{0, 0}, {2, 1}, {4, 2}, {0, 5}}), InputError);
  EXPECT_THROW((void)OrderType::of(std::vector<Point>{{0, 0}, {2, 1}, {0, 0}}), InputError);
  s.landmarks[4].at = {5, 1};
  EXPECT_THROW((void)landmarks::landmark_set(s), InputError);
  s.landmarks.resize(2);
  EXPECT_THROW((void)landmarks::landmark_set(s), InputError);
}

TEST(OrderType, AxiomsHoldForPointsAndCatchAFlippedTriangle) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const OrderType T = OrderType::of(random_points(6, seed));
    EXPECT_EQ(landmarks::knuth_violation(6, chi_of(T)), std::nullopt);
    EXPECT_EQ(landmarks::chirotope_violation(6, chi_of(T)), std::nullopt);
    // Through Lambda, as a robot would record it.
    const auto chi = landmarks::chirotope_of(6, [&](std::uint32_t i, std::uint32_t j) { return T.Lambda(i, j); });
    EXPECT_EQ(landmarks::knuth_violation(6, chi), std::nullopt);
  }
  // Landmark 4 inside triangle 1 2 3; flipping that triangle contradicts interiority.
  const std::vector<Point> P{{0, 0}, {10, 0}, {0, 10}, {1, 1}, {20, 3}};
  const OrderType T = OrderType::of(P);
  const landmarks::Chirotope flipped = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t t[3] = {a, b, c};
    std::sort(t, t + 3);
    const bool tri = t[0] == 0 && t[1] == 1 && t[2] == 2;
    return tri ? -T.chi(a, b, c) : T.chi(a, b, c);
  };
  const auto k = landmarks::knuth_violation(5, flipped);
  ASSERT_TRUE(k.has_value());
  EXPECT_NE(k->find("axiom 4"), std::string::npos) << *k;
  EXPECT_TRUE(landmarks::chirotope_violation(5, flipped).has_value());
  // Breaking the alternation is caught too.
  const landmarks::Chirotope lopsided = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return a == 0 && b == 1 && c == 2 ? -T.chi(a, b, c) : T.chi(a, b, c);
  };
  EXPECT_NE(landmarks::chirotope_violation(5, lopsided)->find("alternating"), std::string::npos);
}

TEST(CanonicalForm, InvariantUnderRelabellingAndAffineMaps) {
  std::mt19937_64 rng(3);
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const std::size_t n = 3 + seed % 9;
    const auto P = random_points(n, seed);
    const OrderType T = OrderType::of(P);
    const auto C = landmarks::canonical_form(T);
    // Relabel and map by an integer affine map of positive determinant.
    std::vector<std::uint32_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0u);
    std::shuffle(perm.begin(), perm.end(), rng);
    std::uniform_int_distribution<int> u(-3, 3);
    int a, b, c, d;
    do a = u(rng), b = u(rng), c = u(rng), d = u(rng);
    while (a * d - b * c <= 0);
    std::vector<Point> Q(n), R(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Point& p = P[perm[i]];
      Q[i] = Point(a * p.x() + b * p.y() + 7, c * p.x() + d * p.y() - 5);
      R[i] = Point(-p.x(), p.y());  // a reflection
    }
    const OrderType TQ = OrderType::of(Q), TR = OrderType::of(R);
    const auto CQ = landmarks::canonical_form(TQ);
    EXPECT_EQ(C, CQ) << "seed " << seed;
    // Equal forms mean the canonical labellings are an isomorphism of chirotopes.
    for (std::uint32_t x = 0; x < n; ++x)
      for (std::uint32_t y = 0; y < n; ++y)
        for (std::uint32_t z = 0; z < n; ++z)
          ASSERT_EQ(T.chi(C.labelling[x], C.labelling[y], C.labelling[z]), TQ.chi(CQ.labelling[x], CQ.labelling[y], CQ.labelling[z]));
    // A reflection is the same order type only up to reflection.
    EXPECT_EQ(landmarks::canonical_form(T, true), landmarks::canonical_form(TR, true)) << "seed " << seed;
  }
  // A triangle with a point inside is its own mirror image; a convex position too.
  const auto inner = OrderType::of(std::vector<Point>{{0, 0}, {10, 0}, {0, 10}, {1, 1}});
  const auto convex = OrderType::of(std::vector<Point>{{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  EXPECT_FALSE(landmarks::canonical_form(inner) == landmarks::canonical_form(convex));
}

TEST(CanonicalForm, CountsTheKnownOrderTypesOfSmallSets) {
  // Up to relabelling and reflection there are 1, 2 and 3 order types of 3, 4 and 5 points
  // in general position, and 16 of 6.
  EXPECT_EQ(landmarks::count_order_types(3, 200, 1, true).distinct, 1u);
  EXPECT_EQ(landmarks::count_order_types(4, 500, 2, true).distinct, 2u);
  EXPECT_EQ(landmarks::count_order_types(5, 2000, 3, true).distinct, 3u);
  const auto six = landmarks::count_order_types(6, 5000, 4, true);
  EXPECT_EQ(six.distinct, 16u);
  // Mirror images told apart: the chiral types count twice.
  EXPECT_GT(landmarks::count_order_types(6, 5000, 4, false).distinct, six.distinct);
}
