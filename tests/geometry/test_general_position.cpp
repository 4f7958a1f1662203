#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/geometry/generators.hpp>

#include <random>

using namespace preimage::geometry;

TEST(GeneralPosition, CollinearTripleAgreesWithBruteForce) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> c(0, 9);
  int found = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Point> pts;
    const int n = 3 + trial % 6;
    while (static_cast<int>(pts.size()) < n) {
      Point p = random_point(rng, c);
      if (std::find(pts.begin(), pts.end(), p) == pts.end()) pts.push_back(p);
    }
    bool brute = false;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        for (int k = j + 1; k < n; ++k) brute |= orientation(pts[i], pts[j], pts[k]) == 0;
    auto t = find_collinear_triple(pts);
    ASSERT_EQ(t.has_value(), brute) << "trial " << trial;
    if (t) {
      ++found;
      EXPECT_EQ(orientation(pts[(*t)[0]], pts[(*t)[1]], pts[(*t)[2]]), 0);
    }
  }
  EXPECT_GT(found, 30);
}

TEST(GeneralPosition, ErrorsNameTheVertices) {
  auto env = Environment::make({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, {});
  try {
    require_no_collinear_vertices(env, "wall-following");
    FAIL() << "expected an error";
  } catch (const preimage::InputError& e) {
    EXPECT_STREQ(e.what(), "wall-following needs vertices in general position: boundary vertex 0, boundary vertex 1 and boundary vertex 2 are collinear");
  }
  try {
    require_distinct_x(env, "sweep");
    FAIL() << "expected an error";
  } catch (const preimage::InputError& e) {
    EXPECT_STREQ(e.what(), "sweep needs distinct x-coordinates: boundary vertex 0 and boundary vertex 4 share x = 0");
  }
  EXPECT_EQ(straight_vertices(env), std::vector<std::size_t>{1});
  EXPECT_NO_THROW(require_distinct_x(Environment::make({{0, 0}, {3, 1}, {1, 2}}, {}), "sweep"));
}
