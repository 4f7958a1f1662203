// Range-limited visibility V(q) ∩ D(q, R) against brute force: the region its pieces
// describe, evaluated exactly (CORE's square roots for circle crossings), contains a
// sample point p iff |p - q| <= R and the segment qp lies in free space (geometry::visible,
// the O(n) edge scan); every crossing lies exactly on the circle and on its edge; the area
// is V's area for a huge range and pi R^2 exactly when nothing is within range.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/range_visibility.hpp>

#include <CGAL/CORE_Expr.h>

#include <numbers>
#include <random>
#include <sstream>

#include "support/cgal_oracle.hpp"

using namespace preimage::geometry;

namespace {

using Real = CORE::Expr;
struct RPoint {
  Real x, y;
};

Real real_of(const ExactFT& v) {
  std::ostringstream s;
  s << CGAL::exact(v);
  return Real(CORE::BigRat(s.str()));
}
RPoint real_of(const ExactPoint& p) { return {real_of(p.x()), real_of(p.y())}; }
RPoint real_of(const Point& p) { return {Real(p.x()), Real(p.y())}; }

int orient(const RPoint& a, const RPoint& b, const RPoint& c) {
  return ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)).sign();
}
Real sqdist(const RPoint& a, const RPoint& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }

// A piece end, exactly: a vertex of V or the root of |a + t (b - a) - q|^2 = R^2 on its edge,
// computed here from scratch with square roots.
RPoint exact_end(const RangeVisibility& r, const RangePoint& p) {
  const auto& V = r.polygon;
  if (p.kind == RangePoint::Kind::PolygonVertex) return real_of(V.exact(p.vertex));
  const RPoint a = real_of(V.exact(p.edge)), b = real_of(V.exact((p.edge + 1) % V.vertices.size())), q = real_of(V.exact_query());
  const Real dx = b.x - a.x, dy = b.y - a.y, fx = a.x - q.x, fy = a.y - q.y, R = Real(r.range);
  const Real A = dx * dx + dy * dy, B = fx * dx + fy * dy, C = fx * fx + fy * fy - R * R;
  const Real s = sqrt(B * B - A * C);
  const Real t = p.entering ? (-B - s) / A : (-B + s) / A;
  return {a.x + t * dx, a.y + t * dy};
}

struct ExactPieces {
  RPoint q;
  Real r2;
  std::vector<int> kind;  // 0 segment, 1 arc
  std::vector<RPoint> from, to;
  bool full = false;
};

ExactPieces exact_pieces(const RangeVisibility& r) {
  ExactPieces e;
  e.q = real_of(r.polygon.exact_query());
  e.r2 = Real(r.range) * Real(r.range);
  e.full = r.full_disc;
  if (e.full) return e;
  for (const auto& p : r.pieces) {
    e.kind.push_back(p.kind == RangePiece::Kind::Arc);
    e.from.push_back(exact_end(r, p.from));
    e.to.push_back(exact_end(r, p.to));
  }
  return e;
}

// Membership of p in the star-shaped region bounded by the pieces: for every piece whose
// closed angular sector (seen from q) holds the direction of p, p is inside if it is on q's
// side of a segment piece or within the radius for an arc. At a direction shared by two
// pieces the region reaches the farther of them, hence "any".
bool in_pieces(const ExactPieces& e, const RPoint& p) {
  if (e.full) return sqdist(p, e.q) <= e.r2;
  if (p.x == e.q.x && p.y == e.q.y) return true;
  for (std::size_t k = 0; k < e.kind.size(); ++k) {
    const RPoint &s = e.from[k], &t = e.to[k], &q = e.q;
    if (e.kind[k] == 0) {
      if (orient(q, s, t) <= 0) continue;  // radial piece (or degenerate): no angular extent
      if (orient(q, s, p) < 0 || orient(q, p, t) < 0) continue;
      if (orient(s, t, p) >= 0) return true;
    } else {
      const int st = orient(q, s, t);
      bool in_sector;
      if (st > 0) in_sector = orient(q, s, p) >= 0 && orient(q, p, t) >= 0;          // less than a half-turn
      else if (st < 0) in_sector = !(orient(q, t, p) > 0 && orient(q, p, s) > 0);     // more than a half-turn
      else in_sector = (s.x - q.x) * (t.x - q.x) + (s.y - q.y) * (t.y - q.y) < 0 ? orient(q, s, p) >= 0 : true;  // half-turn or full
      if (in_sector && sqdist(p, q) <= e.r2) return true;
    }
  }
  return false;
}

struct Tally {
  std::size_t inside = 0, outside = 0, arcs = 0, crossings = 0, queries = 0;
};

// The whole check for one query and range.
void check_range(const Environment& env, const VisibilityIndex& index, const Point& q, double R, std::mt19937_64& rng, Tally& tally,
                 std::size_t samples) {
  const RangeVisibility r = range_visibility(index, q, R);
  const ExactPieces e = exact_pieces(r);
  const std::string where = "query " + format_point(q) + " range " + format_number(R);
  ++tally.queries;
  // Every piece end is where it says: crossings exactly on the circle and on their edge,
  // vertices in the closed disc; consecutive pieces meet.
  for (std::size_t k = 0; k < r.pieces.size() && !r.full_disc; ++k) {
    const auto& p = r.pieces[k];
    for (const RangePoint* end : {&p.from, &p.to}) {
      const RPoint x = exact_end(r, *end);
      if (end->kind == RangePoint::Kind::Crossing) {
        ++tally.crossings;
        ASSERT_TRUE(sqdist(x, e.q) == e.r2) << where;
        const RPoint a = real_of(r.polygon.exact(end->edge)), b = real_of(r.polygon.exact((end->edge + 1) % r.polygon.vertices.size()));
        EXPECT_EQ(orient(a, b, x), 0) << where;
        EXPECT_TRUE((x.x - a.x) * (x.x - b.x) + (x.y - a.y) * (x.y - b.y) <= 0) << where << ": crossing beyond its edge";
      } else {
        EXPECT_TRUE(sqdist(x, e.q) <= e.r2) << where << ": a vertex end outside the disc";
      }
    }
    if (p.kind == RangePiece::Kind::Arc) {
      ++tally.arcs;
      EXPECT_TRUE(sqdist(e.from[k], e.q) == e.r2 && sqdist(e.to[k], e.q) == e.r2) << where;
      EXPECT_GT(p.span, 0) << where;
    } else {
      EXPECT_TRUE(p.from.kind == RangePoint::Kind::Crossing ? p.from.edge == p.edge : p.from.vertex == p.edge) << where;
      EXPECT_GE(orient(e.q, e.from[k], e.to[k]), 0) << where << ": segment piece " << k << " runs clockwise";
      EXPECT_FALSE(e.from[k].x == e.to[k].x && e.from[k].y == e.to[k].y) << where << ": segment piece " << k << " has no length";
    }
    const std::size_t nk = (k + 1) % r.pieces.size();
    EXPECT_TRUE(e.to[k].x == e.from[nk].x && e.to[k].y == e.from[nk].y) << where << ": pieces " << k << " and " << nk << " do not meet";
  }
  // The pieces go once around q: their angles (arcs' spans, the angles segments subtend)
  // add up to V's angle at q (2 pi inside free space, pi on an edge, the free wedge at a
  // vertex).
  double turn = 0;
  for (std::size_t k = 0; k < r.pieces.size(); ++k) {
    const auto& p = r.pieces[k];
    if (p.kind == RangePiece::Kind::Arc) {
      turn += p.span;
    } else if (!r.full_disc && orient(e.q, e.from[k], e.to[k]) == 0) {
      // Radial, or through q (q inside a wall): no turn about q counted here.
    } else {
      const double ax = p.from.approx.x() - q.x(), ay = p.from.approx.y() - q.y(), bx = p.to.approx.x() - q.x(), by = p.to.approx.y() - q.y();
      if (ax * ax + ay * ay > 0 && bx * bx + by * by > 0) turn += std::max(0.0, std::atan2(ax * by - ay * bx, ax * bx + ay * by));
    }
  }
  double v_turn = 2 * std::numbers::pi;  // interior
  const Location& loc = r.polygon.location;
  if (loc.kind == Location::Kind::OnEdge) v_turn = std::numbers::pi;
  if (loc.kind == Location::Kind::AtVertex) {  // the free wedge: from the outgoing edge counter-clockwise to the incoming one
    const Point a = env.vertex(env.next(loc.index)), b = env.vertex(env.prev(loc.index));
    v_turn = std::atan2((a.x() - q.x()) * (b.y() - q.y()) - (a.y() - q.y()) * (b.x() - q.x()), (a.x() - q.x()) * (b.x() - q.x()) + (a.y() - q.y()) * (b.y() - q.y()));
    if (v_turn <= 0) v_turn += 2 * std::numbers::pi;
  }
  EXPECT_NEAR(turn, v_turn, 1e-9) << where << ": the pieces do not go once around q";
  // Sample points: random ones in the box and in the disc, V's vertices, and points on the
  // rays from q through V's vertices (the directions where pieces change).
  const auto box = env.bbox();
  std::uniform_real_distribution<double> X(box.xmin(), box.xmax()), Y(box.ymin(), box.ymax()), U(-1, 1), F(0.0, 1.6);
  std::vector<Point> pts;
  for (std::size_t s = 0; s < samples; ++s) {
    pts.push_back(random_point(rng, X, Y));
    pts.emplace_back(q.x() + R * U(rng), q.y() + R * U(rng));
  }
  for (std::size_t i = 0; i < r.polygon.vertices.size(); i += 1 + r.polygon.vertices.size() / 12) {
    const Point v = r.polygon.vertices[i].approx;
    pts.push_back(v);
    const double f = F(rng);
    pts.emplace_back(q.x() + f * (v.x() - q.x()), q.y() + f * (v.y() - q.y()));
  }
  for (const Point& p : pts) {
    const bool want = CGAL::compare(CGAL::squared_distance(to_exact(p), to_exact(q)), ExactFT(R) * ExactFT(R)) != CGAL::LARGER &&
                      visible(env, q, p);
    ASSERT_EQ(in_pieces(e, real_of(p)), want) << where << ", sample " << format_point(p);
    ASSERT_EQ(r.contains(p), want) << where << ", sample " << format_point(p);
    (want ? tally.inside : tally.outside)++;
  }
}

std::vector<Environment> test_environments() {
  std::vector<Environment> envs;
  for (std::uint64_t seed : {1u, 2u, 3u}) envs.push_back(preimage::testing::snapped_random_environment(60 + 20 * seed, seed, seed, 60.0));
  envs.push_back(generators::random_environment(120, 4, 7));
  envs.push_back(generators::office(2, 2));
  envs.push_back(generators::random_rectilinear(8, 7, true, 3));  // collinear runs of vertices
  envs.push_back(Environment::make(generators::comb(4), {}));
  return envs;
}

}  // namespace

TEST(RangeVisibility, AgreesWithBruteForceOnRandomAndDegenerateEnvironments) {
  std::mt19937_64 rng(29);
  Tally tally;
  const auto envs = test_environments();
  for (std::size_t k = 0; k < envs.size(); ++k) {
    const Environment& env = envs[k];
    VisibilityIndex index(env);
    const auto box = env.bbox();
    const double diam = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    for (const auto& q : preimage::testing::random_queries(env, 12, 5, 5, 100 + k))
      for (double f : {0.03, 0.1, 0.25, 0.6})
        check_range(env, index, q.p, f * diam, rng, tally, 12);
  }
  EXPECT_GT(tally.queries, 500u);
  EXPECT_GT(tally.inside, 5000u);
  EXPECT_GT(tally.outside, 5000u);
  EXPECT_GT(tally.arcs, 500u);
  EXPECT_GT(tally.crossings, 1000u);
}

// A range through vertices of V exactly (R = |q v| for a vertex v, integer-snapped points)
// and tangent to edges: the circle touches the boundary without crossing it.
TEST(RangeVisibility, RangeThroughVerticesAndTangentToEdges) {
  const Environment env = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}});
  VisibilityIndex index(env);
  std::mt19937_64 rng(3);
  Tally tally;
  // From (2, 5): the hole's near wall x = 4 is at distance 2 (tangent), its corners at sqrt 5.
  for (double R : {2.0, std::sqrt(5.0), 2.5, 3.0, 5.0, 100.0}) check_range(env, index, Point(2, 5), R, rng, tally, 200);
  // Exactly tangent: the wall x = 4 only touches the circle, so the whole disc is visible.
  EXPECT_TRUE(range_visibility(index, Point(2, 5), 2.0).full_disc);
  EXPECT_FALSE(range_visibility(index, Point(2, 5), 2.5).full_disc);
  // R = 5 from (5, 5): the circle passes through the outer corners' neighbourhood and the
  // walls at distance 5 are tangent; from a corner of the room (a vertex query).
  for (double R : {1.0, 5.0, std::sqrt(50.0), 20.0}) check_range(env, index, Point(0, 0), R, rng, tally, 200);
  for (double R : {1.0, 3.0, 8.0}) check_range(env, index, Point(5, 0), R, rng, tally, 200);  // on an edge
  EXPECT_GT(tally.arcs, 5u);
}

TEST(RangeVisibility, HugeRangeIsTheVisibilityPolygon) {
  for (std::uint64_t seed : {4u, 5u}) {
    const Environment env = preimage::testing::snapped_random_environment(150, 3, seed, 100.0);
    VisibilityIndex index(env);
    for (const auto& q : preimage::testing::random_queries(env, 10, 5, 5, seed)) {
      const auto r = range_visibility(index, q.p, 1e6);
      const auto& V = r.polygon;
      ASSERT_EQ(r.pieces.size(), V.vertices.size());
      for (std::size_t i = 0; i < r.pieces.size(); ++i) {
        EXPECT_EQ(r.pieces[i].kind, RangePiece::Kind::Segment);
        EXPECT_EQ(r.pieces[i].edge, i);
      }
      EXPECT_NEAR(r.area(), V.area(), 1e-9 * V.area());
    }
  }
}

// Nothing within range blocks the view exactly when the nearest boundary point is at least
// R away (decided here by exact squared distances to every edge): then the result is the
// whole disc, area pi R^2; just beyond that distance it is not.
TEST(RangeVisibility, WholeDiscIffNothingWithinRange) {
  const Environment env = preimage::testing::snapped_random_environment(120, 3, 11, 100.0);
  VisibilityIndex index(env);
  std::size_t whole = 0, cut = 0;
  for (const auto& q : preimage::testing::random_queries(env, 40, 0, 0, 12)) {
    ExactFT nearest = -1;
    for (std::size_t e = 0; e < env.num_vertices(); ++e) {
      const ExactFT d = CGAL::squared_distance(to_exact(q.p), ExactKernel::Segment_2(env.exact_vertex(e), env.exact_vertex(env.next(e))));
      if (nearest < 0 || d < nearest) nearest = d;
    }
    const double clearance = std::sqrt(CGAL::to_double(nearest));
    for (double R : {0.5 * clearance, std::nextafter(clearance, 0.0), clearance, std::nextafter(clearance, 1e300), 1.5 * clearance}) {
      const auto r = range_visibility(index, q.p, R);
      const bool want = CGAL::compare(ExactFT(R) * ExactFT(R), nearest) != CGAL::LARGER;
      ASSERT_EQ(r.full_disc, want) << format_point(q.p) << " range " << R;
      (want ? whole : cut)++;
      if (want) {
        EXPECT_NEAR(r.area(), std::numbers::pi * R * R, 1e-12 * R * R);
      } else if (R == 1.5 * clearance) {
        EXPECT_LT(r.area(), std::numbers::pi * R * R);
      }
    }
  }
  EXPECT_GT(whole, 40u);
  EXPECT_GT(cut, 40u);
}

TEST(RangeVisibility, AreaGrowsWithRangeUpToV) {
  const Environment env = generators::office(2, 3);
  VisibilityIndex index(env);
  for (const auto& q : preimage::testing::random_queries(env, 10, 3, 3, 5)) {
    const double area_v = index.compute(q.p).area();
    double last = 0;
    for (double R = 0.25; R < 40; R *= 1.5) {
      const auto r = range_visibility(index, q.p, R);
      const double a = r.area();
      EXPECT_GE(a, last * (1 - 1e-12));
      EXPECT_LE(a, std::numbers::pi * R * R * (1 + 1e-12));
      EXPECT_LE(a, area_v * (1 + 1e-12));
      // The drawing outline lies inside the region (chords of arcs): a smaller area.
      std::vector<Point> o = r.outline(0.01);
      double ao = 0;
      for (std::size_t i = 0; i < o.size(); ++i) ao += o[i].x() * o[(i + 1) % o.size()].y() - o[(i + 1) % o.size()].x() * o[i].y();
      EXPECT_LE(0.5 * ao, a * (1 + 1e-12));
      EXPECT_GE(0.5 * ao, a * (1 - 1e-3));
      last = a;
    }
  }
}

TEST(RangeVisibility, RejectsBadRangeAndPointsOutsideFreeSpace) {
  const Environment env = generators::office(1, 2);
  VisibilityIndex index(env);
  EXPECT_THROW(range_visibility(index, Point(1, 1), 0.0), std::invalid_argument);
  EXPECT_THROW(range_visibility(index, Point(1, 1), -1.0), std::invalid_argument);
  EXPECT_THROW(range_visibility(index, Point(1, 1), std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(range_visibility(index, Point(-5, -5), 1.0), preimage::InputError);
}
