// Visibility polygons against CGAL's Triangular_expansion_visibility_2 (exact
// constructions): identical regions on >= 1,000 queries of every kind.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/visibility.hpp>

#include "support/cgal_oracle.hpp"

using namespace preimage::geometry;
using preimage::testing::CgalVisibility;

namespace {
int compare_with_cgal(const Environment& env, std::size_t interior, std::size_t edges, std::size_t vertices, std::uint64_t seed) {
  VisibilityIndex ours(env);
  CgalVisibility cgal(env);
  int compared = 0;
  for (auto& q : preimage::testing::random_queries(env, interior, edges, vertices, seed)) {
    EXPECT_EQ(ours.locate(q.p).kind, q.loc.kind);
    auto mine = ours.compute(q.p);
    auto a = canonical_cycle(mine.points());
    auto b = canonical_cycle(cgal.compute(q.p, q.loc));
    EXPECT_EQ(a, b) << "query " << format_point(q.p) << " (" << to_string(q.loc.kind) << ") seed " << seed
                    << ": " << a.size() << " vs " << b.size() << " vertices";
    // Every edge tag says something true.
    const std::size_t n = mine.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto p = mine.exact(i), r = mine.exact((i + 1) % n);
      const auto& e = mine.edges[i];
      if (e.kind == VisibilityEdge::Kind::Solid) {
        const auto s = to_exact(env.vertex(e.edge)), t = to_exact(env.vertex(env.next(e.edge)));
        EXPECT_EQ(CGAL::orientation(s, t, p), CGAL::COLLINEAR);
        EXPECT_EQ(CGAL::orientation(s, t, r), CGAL::COLLINEAR);
      } else {
        const auto c = to_exact(env.vertex(e.reflex));
        EXPECT_EQ(CGAL::orientation(to_exact(q.p), c, p), CGAL::COLLINEAR);
        EXPECT_EQ(CGAL::orientation(to_exact(q.p), c, r), CGAL::COLLINEAR);
        EXPECT_TRUE(p == c || r == c) << "a free edge starts or ends at its occluding vertex";
      }
    }
    ++compared;
  }
  return compared;
}
}  // namespace

TEST(Visibility, MatchesCgalWithoutHoles) {
  int n = 0;
  for (std::uint64_t s = 1; s <= 6; ++s)
    n += compare_with_cgal(preimage::testing::snapped_random_environment(150 * s, 0, s), 60, 15, 15, s);
  EXPECT_GE(n, 500);
}

TEST(Visibility, MatchesCgalWithHoles) {
  int n = 0;
  for (std::uint64_t s = 1; s <= 6; ++s)
    n += compare_with_cgal(preimage::testing::snapped_random_environment(200 * s, s * 2, 100 + s), 60, 15, 15, s);
  EXPECT_GE(n, 500);
}

TEST(Visibility, MatchesCgalOnDegenerateFloorPlans) {
  int n = compare_with_cgal(generators::office(3, 4), 100, 0, 60, 77);
  n += compare_with_cgal(Environment::make(generators::comb(12), {}), 60, 0, 40, 78);
  EXPECT_GE(n, 200);
}

TEST(Visibility, RejectsQueriesOutsideFreeSpace) {
  auto env = generators::office(2, 2);
  VisibilityIndex index(env);
  EXPECT_THROW(index.compute(Point(-1, -1)), preimage::InputError);
  EXPECT_THROW(index.compute(Point(4, 1)), preimage::InputError);  // inside a wall
}
