// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/range_visibility.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace preimage::geometry {

namespace range_detail {

// g(t) = A t^2 + 2 B t + C: squared distance from q minus R^2 along a + t (b - a), exact.
struct EdgeQuadratic {
  ExactFT A, B, C;
};

EdgeQuadratic edge_quadratic(const ExactPoint& a, const ExactPoint& b, const ExactPoint& q, const ExactFT& r2) {
  const ExactFT dx = b.x() - a.x(), dy = b.y() - a.y(), fx = a.x() - q.x(), fy = a.y() - q.y();
  return {dx * dx + dy * dy, fx * dx + fy * dy, fx * fx + fy * fy - r2};
}

// The roots of g in doubles, smaller first, by the cancellation-free formulas (the exact
// discriminant is rounded once).
std::pair<double, double> quadratic_roots(const EdgeQuadratic& g) {
  const double A = CGAL::to_double(g.A), B = CGAL::to_double(g.B), C = CGAL::to_double(g.C);
  const double s = std::sqrt(std::max(0.0, CGAL::to_double(g.B * g.B - g.A * g.C)));
  if (B <= 0) {
    const double big = -B + s;  // >= 0
    return {big == 0 ? 0.0 : C / big, big / A};
  }
  const double neg = -B - s;  // < 0
  return {neg / A, C / neg};
}

// Which part [t0, t1] of the edge lies in the closed disc, when that part has positive
// length (a single touching point is no piece: the circle passes there anyway).
struct InsidePart {
  bool some = false;
  bool from_start = false, to_end = false;  // t0 == 0 / t1 == 1, else crossings
};

InsidePart inside_part(const EdgeQuadratic& g) {
  const int g0 = CGAL::sign(g.C);
  const int g1 = CGAL::sign(g.A + 2 * g.B + g.C);
  InsidePart p;
  if (g0 <= 0 && g1 <= 0) return {true, true, true};  // g convex: the whole edge
  if (g0 <= 0) {                                       // starts inside, ends outside
    // On the circle at t = 0: the edge enters the disc only if g decreases there.
    if (g0 == 0 && CGAL::sign(g.B) >= 0) return p;
    return {true, true, false};
  }
  if (g1 <= 0) {  // starts outside, ends inside
    if (g1 == 0 && CGAL::sign(g.A + g.B) <= 0) return p;
    return {true, false, true};
  }
  // Both ends outside: a chord iff the discriminant is positive and the minimum of g lies
  // strictly inside (0, 1), i.e. B < 0 and -B < A.
  if (CGAL::sign(g.B * g.B - g.A * g.C) > 0 && CGAL::sign(g.B) < 0 && CGAL::sign(g.A + g.B) > 0) return {true, false, false};
  return p;
}

double angle_from(const Point& q, const Point& p) { return std::atan2(p.y() - q.y(), p.x() - q.x()); }

// Counter-clockwise angle from direction q->a to q->b, for consecutive points of a
// star-shaped boundary (so it is in [0, pi)); rounding can only make it a hair negative.
double ccw_step(const Point& q, const Point& a, const Point& b) {
  const double ax = a.x() - q.x(), ay = a.y() - q.y(), bx = b.x() - q.x(), by = b.y() - q.y();
  return std::max(0.0, std::atan2(ax * by - ay * bx, ax * bx + ay * by));
}

}  // namespace range_detail

RangeVisibility limit_range(VisibilityPolygon polygon, double range) {
  using namespace range_detail;
  if (!std::isfinite(range) || !(range > 0)) throw std::invalid_argument("range-limited visibility: the range must be finite and > 0");
  RangeVisibility out;
  out.polygon = std::move(polygon);
  out.range = range;
  const VisibilityPolygon& V = out.polygon;
  const std::size_t n = V.vertices.size();
  const ExactPoint q = V.exact_query();
  const ExactFT r2 = ExactFT(range) * ExactFT(range);
  const Point qd = V.query;

  std::vector<ExactPoint> P = V.points();
  std::vector<Point> Pd(n);
  for (std::size_t i = 0; i < n; ++i) Pd[i] = to_double(P[i]);

  // Segment pieces in boundary order.
  struct Span {
    RangePiece piece;
    std::uint32_t edge;
    bool from_start, to_end;
  };
  std::vector<Span> spans;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const EdgeQuadratic g = edge_quadratic(P[i], P[j], q, r2);
    const InsidePart part = inside_part(g);
    if (!part.some) continue;
    const auto [t_in, t_out] = (part.from_start && part.to_end) ? std::pair{0.0, 1.0} : quadratic_roots(g);
    auto at = [&](double t) {
      t = std::clamp(t, 0.0, 1.0);
      return Point(Pd[i].x() + t * (Pd[j].x() - Pd[i].x()), Pd[i].y() + t * (Pd[j].y() - Pd[i].y()));
    };
    RangePiece s;
    s.kind = RangePiece::Kind::Segment;
    s.edge = static_cast<std::uint32_t>(i);
    if (part.from_start) s.from = {RangePoint::Kind::PolygonVertex, static_cast<std::uint32_t>(i), kNone, false, Pd[i]};
    else s.from = {RangePoint::Kind::Crossing, kNone, static_cast<std::uint32_t>(i), true, at(t_in)};
    if (part.to_end) s.to = {RangePoint::Kind::PolygonVertex, static_cast<std::uint32_t>(j), kNone, false, Pd[j]};
    else s.to = {RangePoint::Kind::Crossing, kNone, static_cast<std::uint32_t>(i), false, at(t_out)};
    spans.push_back({s, static_cast<std::uint32_t>(i), part.from_start, part.to_end});
  }

  if (spans.empty()) {  // V's boundary never enters the open disc: the whole disc is visible
    RangePiece arc;
    arc.kind = RangePiece::Kind::Arc;
    arc.from_angle = 0;
    arc.span = 2 * std::numbers::pi;
    out.pieces.push_back(arc);
    out.full_disc = true;
    return out;
  }

  // Between consecutive segment pieces, V's boundary is outside the disc unless the two
  // pieces meet at a vertex of V: an arc then joins them, sweeping what that stretch of
  // boundary sweeps (its angle is summed vertex by vertex, so a tiny arc stays tiny).
  for (std::size_t k = 0; k < spans.size(); ++k) {
    const Span& cur = spans[k];
    const Span& nxt = spans[(k + 1) % spans.size()];
    out.pieces.push_back(cur.piece);
    const bool contiguous = spans.size() > 1 && cur.to_end && nxt.from_start && nxt.edge == (cur.edge + 1) % n;
    if (contiguous) continue;
    RangePiece arc;
    arc.kind = RangePiece::Kind::Arc;
    arc.from = cur.piece.to;
    arc.to = nxt.piece.from;
    arc.from_angle = angle_from(qd, arc.from.approx);
    // Vertices of V strictly after the exit and up to the entry's edge start.
    std::size_t count = (nxt.edge + n - cur.edge) % n;
    if (count == 0) count = n;  // one piece: all the way round
    Point prev = arc.from.approx;
    double span = 0;
    for (std::size_t s = 1; s <= count; ++s) {
      const Point& v = Pd[(cur.edge + s) % n];
      span += ccw_step(qd, prev, v);
      prev = v;
    }
    span += ccw_step(qd, prev, arc.to.approx);
    arc.span = span;
    out.pieces.push_back(arc);
  }
  return out;
}

RangeVisibility range_visibility(const VisibilityIndex& index, const Point& q, double range) {
  if (!std::isfinite(range) || !(range > 0)) throw std::invalid_argument("range-limited visibility: the range must be finite and > 0");
  return limit_range(index.compute(q), range);
}

double crossing_parameter(const RangeVisibility& r, const RangePoint& p) {
  using namespace range_detail;
  if (p.kind != RangePoint::Kind::Crossing) throw std::invalid_argument("crossing_parameter: not a circle crossing");
  const auto& V = r.polygon;
  const std::size_t n = V.vertices.size();
  const EdgeQuadratic g = edge_quadratic(V.exact(p.edge), V.exact((p.edge + 1) % n), V.exact_query(), ExactFT(r.range) * ExactFT(r.range));
  const auto [lo, hi] = quadratic_roots(g);
  return std::clamp(p.entering ? lo : hi, 0.0, 1.0);
}

double RangeVisibility::area() const {
  const Point& q = polygon.query;
  double a = 0;
  for (const auto& p : pieces) {
    if (p.kind == RangePiece::Kind::Arc) {
      a += 0.5 * range * range * p.span;
    } else {
      const double ax = p.from.approx.x() - q.x(), ay = p.from.approx.y() - q.y();
      const double bx = p.to.approx.x() - q.x(), by = p.to.approx.y() - q.y();
      a += 0.5 * (ax * by - ay * bx);
    }
  }
  return a;
}

bool RangeVisibility::contains(const Point& p) const {
  const ExactPoint e = to_exact(p);
  if (CGAL::compare(CGAL::squared_distance(e, polygon.exact_query()), ExactFT(range) * ExactFT(range)) == CGAL::LARGER) return false;
  const auto pts = polygon.points();
  return CGAL::bounded_side_2(pts.begin(), pts.end(), e, ExactKernel()) != CGAL::ON_UNBOUNDED_SIDE;
}

std::vector<Point> RangeVisibility::outline(double max_step) const {
  if (!(max_step > 0)) max_step = 0.05;
  const Point& q = polygon.query;
  std::vector<Point> out;
  for (const auto& p : pieces) {
    if (p.kind == RangePiece::Kind::Segment) {
      out.push_back(p.from.approx);
      continue;
    }
    const std::size_t steps = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(p.span / max_step)));
    out.push_back(full_disc ? Point(q.x() + range, q.y()) : p.from.approx);
    for (std::size_t s = 1; s < steps; ++s) {
      const double t = p.from_angle + p.span * static_cast<double>(s) / static_cast<double>(steps);
      out.emplace_back(q.x() + range * std::cos(t), q.y() + range * std::sin(t));
    }
  }
  return out;
}

}  // namespace preimage::geometry
