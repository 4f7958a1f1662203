// The configuration space of a disc robot against brute force: exact squared distances
// from sample points and segments to every obstacle edge (rational arithmetic), on random
// environments with holes, rectilinear plans and offices, for several radii.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>

#include <cmath>
#include <random>

using namespace preimage::geometry;

namespace {

using ExactSegment = ExactKernel::Segment_2;

// Exact: distance from segment pq to the boundary >= r, and p in free space.
bool brute_admits(const Environment& env, const Point& p, const Point& q, double r) {
  if (!locate(env, p).in_free_space()) return false;
  const ExactSegment s(to_exact(p), to_exact(q));
  for (std::size_t e = 0; e < env.num_vertices(); ++e)
    if (CGAL::squared_distance(s, ExactSegment(env.exact_vertex(e), env.exact_vertex(env.next(e)))) < ExactFT(r) * r) return false;
  return true;
}

double distance_to_boundary(const Environment& env, const Point& p) {
  double best = INFINITY;
  for (std::size_t e = 0; e < env.num_vertices(); ++e)
    best = std::min(best, std::sqrt(CGAL::to_double(CGAL::squared_distance(p, Kernel::Segment_2(env.vertex(e), env.vertex(env.next(e)))))));
  return best;
}

struct Case {
  Environment env;
  double r;
  std::string name;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (std::uint64_t s = 1; s <= 4; ++s) {
    auto env = generators::random_environment(80 + 10 * s, 1 + s % 4, s);
    const auto b = env.bbox();
    const double size = std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin());
    for (double f : {0.005, 0.02}) out.push_back({env, f * size, "random " + std::to_string(s) + " r " + std::to_string(f * size)});
  }
  for (std::uint64_t s = 1; s <= 3; ++s) out.push_back({generators::random_rectilinear(8, 7, true, s), 0.3, "rectilinear " + std::to_string(s)});
  out.push_back({generators::office(2, 2), 0.15, "office"});
  return out;
}

}  // namespace

TEST(ConfigurationSpace, ComponentsLieInsideTheExactErodedSetAndMissOnlyTheStatedBand) {
  std::mt19937_64 rng(5);
  std::size_t inside = 0, band = 0;
  for (const auto& c : cases()) {
    const ConfigurationSpace cs(c.env, c.r);
    ASSERT_FALSE(cs.components().empty()) << c.name;
    EXPECT_GT(cs.approximation_error(), 0) << c.name;
    EXPECT_LT(cs.approximation_error(), 0.01 * c.r) << c.name;
    // Every component vertex and edge is admitted (exact, brute force).
    for (const auto& comp : cs.components())
      for (std::size_t e = 0; e < comp.num_vertices(); ++e)
        ASSERT_TRUE(brute_admits(c.env, comp.vertex(e), comp.vertex(comp.next(e)), c.r)) << c.name << ": edge " << e;
    // Random points: inside a component => admitted; admitted and clear of the band =>
    // inside a component.
    const auto b = c.env.bbox();
    std::uniform_real_distribution<double> X(b.xmin(), b.xmax()), Y(b.ymin(), b.ymax());
    for (int k = 0; k < 400; ++k) {
      const Point p = random_point(rng, X, Y);
      const bool in_comp = cs.component_of(p).has_value();
      const bool admitted = brute_admits(c.env, p, p, c.r);
      ASSERT_EQ(cs.admits(p), admitted) << c.name << " at " << format_point(p);
      if (in_comp) {
        ASSERT_TRUE(admitted) << c.name << ": " << format_point(p) << " is in a component but closer than r to an obstacle";
        ++inside;
      } else if (admitted) {
        ASSERT_LE(distance_to_boundary(c.env, p), c.r + cs.approximation_error() * 1.01) << c.name << ": " << format_point(p)
                                                                                        << " is admitted but in no component";
        ++band;
      }
    }
  }
  EXPECT_GT(inside, 1000u);
}

TEST(ConfigurationSpace, SegmentsAgreeWithBruteForce) {
  std::mt19937_64 rng(7);
  std::size_t yes = 0, no = 0;
  for (const auto& c : cases()) {
    const ConfigurationSpace cs(c.env, c.r);
    const auto b = c.env.bbox();
    std::uniform_real_distribution<double> X(b.xmin(), b.xmax()), Y(b.ymin(), b.ymax());
    std::normal_distribution<double> step(0, 0.1 * (b.xmax() - b.xmin()));
    for (int k = 0; k < 200; ++k) {
      const Point p = random_point(rng, X, Y), q = p + (random_point(rng, step) - CGAL::ORIGIN);
      const bool want = brute_admits(c.env, p, q, c.r);
      ASSERT_EQ(cs.admits(p, q), want) << c.name << ": " << format_point(p) << " -> " << format_point(q);
      (want ? yes : no)++;
    }
  }
  EXPECT_GT(yes, 100u);
  EXPECT_GT(no, 100u);
}

TEST(ConfigurationSpace, CorridorExactlyTwoRadiiWideSeparatesTheRooms) {
  // Two rooms joined by a corridor of width 1: a robot of radius 0.5 touches both walls
  // along the whole corridor, so the exact configuration space pinches to a segment and
  // the rooms are separate components; at radius 0.45 they are one.
  const Ring outer{{0, 0}, {4, 0}, {4, 1.5}, {6, 1.5}, {6, 0}, {10, 0}, {10, 4}, {6, 4}, {6, 2.5}, {4, 2.5}, {4, 4}, {0, 4}};
  const auto env = Environment::make(outer, {});
  EXPECT_EQ(ConfigurationSpace(env, 0.5).components().size(), 2u);
  EXPECT_EQ(ConfigurationSpace(env, 0.45).components().size(), 1u);
  EXPECT_TRUE(ConfigurationSpace(env, 2.1).components().empty());  // fits nowhere
}

TEST(ConfigurationSpace, ZeroRadiusIsTheFreeSpaceAndBadRadiiAreRefused) {
  const auto env = generators::office(1, 2);
  const ConfigurationSpace cs(env, 0);
  ASSERT_EQ(cs.components().size(), 1u);
  EXPECT_EQ(cs.components()[0].num_vertices(), env.num_vertices());
  EXPECT_THROW(ConfigurationSpace(env, -1), preimage::InputError);
  EXPECT_THROW(ConfigurationSpace(env, NAN), preimage::InputError);
}
