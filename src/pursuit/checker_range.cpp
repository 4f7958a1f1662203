// SPDX-License-Identifier: Apache-2.0
// The contamination checker's range sensor (CheckOptions::range; see checker.hpp and
// docs/pursuit.md): the polygon inscribed in the range's disc, its pieces in free space at
// one moment, and the events of a pursuer carrying it.
#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/pursuit/checker.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "checker_internal.hpp"

namespace preimage::pursuit {

using geometry::ExactFT;
using geometry::ExactKernel;
using geometry::Point;

std::vector<Point> range_sensor(double range, std::size_t sides) {
  if (!(range > 0) || !std::isfinite(range)) throw InputError("range: must be a finite number > 0, not " + geometry::format_number(range));
  if (sides < 8 || sides > 1024) throw InputError("range: the sensor polygon needs 8 to 1024 sides, not " + std::to_string(sides));
  const ExactFT r2 = ExactFT(range) * ExactFT(range);
  // The first corner a golden-section fraction of a side off the x axis: corners in line
  // with axis-parallel walls or guards would make needless degenerate contacts.
  const double step = 2 * std::numbers::pi / static_cast<double>(sides), first = 0.3819660112501051 * step;
  std::vector<Point> q;
  for (std::size_t i = 0; i < sides; ++i) {
    const double a = first + step * static_cast<double>(i);
    double s = range;
    for (int k = 0;; ++k) {
      const Point c(s * std::cos(a), s * std::sin(a));
      if (ExactFT(c.x()) * ExactFT(c.x()) + ExactFT(c.y()) * ExactFT(c.y()) <= r2) {
        q.push_back(c);
        break;
      }
      s = std::nextafter(s, 0.0);
      if (k > 64) throw std::logic_error("range sensor: a corner does not fit in the circle");
    }
  }
  for (std::size_t i = 0; i < sides; ++i)
    if (geometry::orientation(q[i], q[(i + 1) % sides], q[(i + 2) % sides]) <= 0)
      throw InputError("range " + geometry::format_number(range) + ": too small for a convex sensor polygon of " + std::to_string(sides) +
                       " sides in doubles");
  return q;
}


namespace detail {

// The sensor polygon's edges where they run through free space, into m.free: with V's free
// edges they bound what the pursuer sees, V ∩ (p + Q). Each edge is cut where it crosses a
// wall or touches a vertex; a piece is kept when it lies in the open free space (by parity
// from the first corner's location, or by locating its midpoint where an edge met the
// boundary other than by a proper crossing). Corners in free space end their pieces as
// isolated points (SegmentEnd::AtPoint, the index set when the overlay is built).
void add_sensor_pieces(const Environment& env, const std::vector<ExactPoint>& C, Moment& m) {
  using K = geometry::SegmentEnd::Kind;
  const std::size_t n = C.size();
  auto& points = m.sensor_points.back();
  auto end_at = [](const geometry::Location& loc) -> std::optional<geometry::SegmentEnd> {
    using L = geometry::Location::Kind;
    if (loc.kind == L::Interior) return geometry::SegmentEnd{K::AtPoint, 0};
    if (loc.kind == L::OnEdge) return geometry::SegmentEnd{K::OnEdge, static_cast<std::uint32_t>(loc.index)};
    if (loc.kind == L::AtVertex) return geometry::SegmentEnd{K::AtVertex, static_cast<std::uint32_t>(loc.index)};
    return std::nullopt;
  };
  geometry::Location corner = geometry::locate(env, C[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const ExactPoint &P0 = C[i], &P1 = C[(i + 1) % n];
    const auto d = P1 - P0;
    struct Cut {
      ExactFT t;
      geometry::SegmentEnd end;
      ExactPoint at;
    };
    std::vector<Cut> cuts;
    bool degenerate = false;
    const CGAL::Bbox_2 box = P0.bbox() + P1.bbox();
    for (std::uint32_t e = 0; e < env.num_vertices(); ++e) {
      const auto f = static_cast<std::uint32_t>(env.next(e));
      const Point &a = env.vertex(e), &b = env.vertex(f);
      if (std::max(a.x(), b.x()) < box.xmin() || std::min(a.x(), b.x()) > box.xmax() || std::max(a.y(), b.y()) < box.ymin() ||
          std::min(a.y(), b.y()) > box.ymax())
        continue;
      const ExactPoint &A = env.exact_vertex(e), &B = env.exact_vertex(f);
      const int o1 = geometry::orientation(P0, P1, A), o2 = geometry::orientation(P0, P1, B);
      if (o1 * o2 > 0) continue;
      const int o3 = geometry::orientation(A, B, P0), o4 = geometry::orientation(A, B, P1);
      if (o3 * o4 > 0) continue;
      if (o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0) {
        degenerate = true;
        for (const auto& [V, v] : {std::pair{A, e}, std::pair{B, f}})
          if (geometry::orientation(P0, P1, V) == 0 && CGAL::collinear_are_strictly_ordered_along_line(P0, V, P1))
            cuts.push_back({((V - P0) * d) / d.squared_length(), {K::AtVertex, v}, V});
        continue;
      }
      const auto ab = B - A;
      const ExactFT t = ((A - P0).x() * ab.y() - (A - P0).y() * ab.x()) / (d.x() * ab.y() - d.y() * ab.x());
      cuts.push_back({t, {K::OnEdge, e}, P0 + t * d});
    }
    std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.t < y.t; });
    // A vertex touched is reported by both its edges: once.
    cuts.erase(std::unique(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.t == y.t; }), cuts.end());
    const geometry::Location next_corner = degenerate ? geometry::locate(env, P1) : corner;
    bool inside = corner.kind == geometry::Location::Kind::Interior;
    std::optional<geometry::SegmentEnd> from_end = end_at(corner);
    ExactPoint from = P0;
    std::size_t proper = 0;
    auto piece = [&](const ExactPoint& to, std::optional<geometry::SegmentEnd> to_end) {
      const bool keep =
          degenerate ? geometry::locate(env, CGAL::midpoint(from, to)).kind == geometry::Location::Kind::Interior : inside;
      if (keep && from_end && to_end && from != to) {
        m.free.push_back({from, to, *from_end, *to_end, std::nullopt});
        points.push_back(from), points.push_back(to);
      }
    };
    for (const Cut& c : cuts) {
      piece(c.at, c.end);
      from = c.at, from_end = c.end;
      if (c.end.kind == K::OnEdge) ++proper, inside = !inside;
    }
    geometry::Location end_loc = next_corner;
    if (!degenerate) end_loc.kind = inside ? geometry::Location::Kind::Interior : geometry::Location::Kind::Outside;
    piece(P1, end_at(end_loc));
    corner = end_loc;
  }
}


static int range_sign_at(const std::array<ExactFT, 3>& g, const ExactFT& t) { return CGAL::sign(g[0] + t * (g[1] + t * g[2])); }
static int range_sign_at(const std::array<ExactFT, 3>& g, double t) { return range_sign_at(g, ExactFT(t)); }

void range_events(const Environment& env, const ExactPoint& a, const ExactPoint& b, const std::vector<Point>& Q, double R,
                  const std::vector<std::uint32_t>& reflex, const Moment* waiting, std::size_t mover, RangeEvents& out) {
  using V2 = ExactKernel::Vector_2;
  const std::size_t n = Q.size();
  CGAL::Bbox_2 reach = a.bbox() + b.bbox();
  reach = CGAL::Bbox_2(reach.xmin() - R, reach.ymin() - R, reach.xmax() + R, reach.ymax() + R);
  auto near = [&](const CGAL::Bbox_2& x) { return CGAL::do_overlap(reach, x); };
  // p(t) strictly crosses the line of L0 L1 inside the closed segment (crossing() decides
  // the strict crossing of the line): the t.
  auto through = [&](const ExactPoint& L0, const ExactPoint& L1) {
    if (geometry::orientation(a, b, L0) * geometry::orientation(a, b, L1) > 0) return;
    if (const auto t = crossing(a, b, L0, L1)) out.cuts.push_back(*t);
  };
  std::vector<std::pair<ExactPoint, ExactPoint>> lines;  // walls and waiting segments near
  for (std::uint32_t e = 0; e < env.num_vertices(); ++e) {
    const ExactPoint &A = env.exact_vertex(e), &B = env.exact_vertex(static_cast<std::uint32_t>(env.next(e)));
    if (near(A.bbox() + B.bbox())) lines.emplace_back(A, B);
  }
  std::vector<ExactPoint> ends;         // waiting pursuers' segment ends
  std::vector<ExactPoint> sensor_ends;  // those of their sensors' pieces (the critical rays above pass the others)
  if (waiting)
    for (std::size_t s = 0; s < waiting->at_exact.size(); ++s) {
      if (s == mover) continue;
      for (std::size_t f = waiting->free_begin[s]; f < waiting->free_begin[s + 1]; ++f) {
        const auto& g = waiting->free[f];
        if (!near(g.a.bbox() + g.b.bbox())) continue;
        lines.emplace_back(g.a, g.b);
        ends.push_back(g.a), ends.push_back(g.b);
      }
      if (!waiting->sensor.empty())
        for (const auto& z : waiting->sensor_points[s])
          if (near(z.bbox())) ends.push_back(z), sensor_ends.push_back(z);
    }
  std::vector<V2> q;
  for (const Point& c : Q) q.emplace_back(c.x(), c.y());
  const auto v = b - a;
  // (i), (v): corner i on a wall or a waiting segment.
  for (const auto& [L0, L1] : lines)
    for (std::size_t i = 0; i < n; ++i) through(L0 - q[i], L1 - q[i]);
  // (ii), (vi): a vertex or a waiting segment's end on edge j of Q.
  std::vector<ExactPoint> fixed;
  for (std::uint32_t w = 0; w < env.num_vertices(); ++w)
    if (near(env.exact_vertex(w).bbox())) fixed.push_back(env.exact_vertex(w));
  fixed.insert(fixed.end(), ends.begin(), ends.end());
  for (const ExactPoint& z : fixed)
    for (std::size_t j = 0; j < n; ++j) through(z - q[(j + 1) % n], z - q[j]);
  // (iii): corner i beyond reflex u on the ray from p through u.
  std::vector<std::uint32_t> reflex_near;
  for (std::uint32_t u : reflex)
    if (near(env.exact_vertex(u).bbox())) reflex_near.push_back(u);
  // Only while the corner is in the environment's box (a free edge lies in free space).
  const CGAL::Bbox_2 env_box = env.bbox();
  for (std::uint32_t u : reflex_near)
    for (std::size_t i = 0; i < n; ++i) {
      const auto before = out.cuts.size();
      through(env.exact_vertex(u) - q[i], env.exact_vertex(u));
      if (out.cuts.size() > before) {
        const ExactFT& t = out.cuts.back();
        const ExactPoint corner = a + t * v + q[i];
        if (!CGAL::do_overlap(corner.bbox(), env_box)) out.cuts.pop_back();
      }
    }
  // (vii): the mover's ray through u passes a waiting segment's end.
  for (const ExactPoint& z : sensor_ends)
    for (std::uint32_t u : reflex_near)
      if (tangent_at(env, u, z)) ray_crossings(a, b, env.exact_vertex(u), z, true, false, false, out.cuts);
  // (iv), (ix): X = p + mu d, d = u - p, on line L (n.x = c) and on the line of Q's edge j
  // (m.(x - p) = k): (n.p - c)(m.d) + k (n.d) = 0, a quadratic in t.
  const Point ad = geometry::to_double(a), vd(CGAL::to_double(v.x()), CGAL::to_double(v.y()));
  for (std::uint32_t u : reflex_near) {
    const ExactPoint& U = env.exact_vertex(u);
    const auto d0 = U - a;
    const Point Ud = env.vertex(u);
    for (std::size_t li = 0; li < lines.size(); ++li) {
      const auto& [L0, L1] = lines[li];
      const V2 nl(-(L1.y() - L0.y()), L1.x() - L0.x());
      const ExactFT c = nl * (L0 - CGAL::ORIGIN);
      const double nx = CGAL::to_double(nl.x()), ny = CGAL::to_double(nl.y()), cd = CGAL::to_double(c);
      const Point L0d = geometry::to_double(L0), L1d = geometry::to_double(L1);
      for (std::size_t j = 0; j < n; ++j) {
        const Point &qa = Q[j], &qb = Q[(j + 1) % n];
        const double mx = -(qb.y() - qa.y()), my = qb.x() - qa.x(), kd = mx * qa.x() + my * qa.y();
        // doubles first: the candidates
        const double a0 = nx * ad.x() + ny * ad.y() - cd, a1 = nx * vd.x() + ny * vd.y();
        const double d0x = Ud.x() - ad.x(), d0y = Ud.y() - ad.y();
        const double b0 = mx * d0x + my * d0y, b1 = -(mx * vd.x() + my * vd.y());
        const double c0 = nx * d0x + ny * d0y, c1 = -a1;
        const double g2 = a1 * b1, g1 = a0 * b1 + a1 * b0 + kd * c1, g0 = a0 * b0 + kd * c0;
        const double scale = std::abs(a0 * b0) + std::abs(a1 * b1) + std::abs(a0 * b1) + std::abs(a1 * b0) + std::abs(kd) * (std::abs(c0) + std::abs(c1));
        if (!(scale > 0)) continue;
        std::array<double, 2> roots{NAN, NAN};
        if (std::abs(g2) <= 1e-12 * scale) {
          if (std::abs(g1) > 1e-12 * scale) roots[0] = -g0 / g1;
        } else {
          const double disc = g1 * g1 - 4 * g2 * g0;
          if (disc < -1e-9 * scale * scale) continue;
          const double sq = std::sqrt(std::max(0.0, disc));
          const double r1 = (-g1 - std::copysign(sq, g1)) / (2 * g2);
          roots = {r1, r1 != 0 ? g0 / (g2 * r1) : -g1 / g2};
        }
        for (const double r : roots) {
          if (!(r > -1e-9 && r < 1 + 1e-9)) continue;
          // Relevance at r (generous margins: an extra cut only costs a sample): X beyond u,
          // within L and within Q's edge j.
          const Point p(ad.x() + r * vd.x(), ad.y() + r * vd.y());
          const double dx = Ud.x() - p.x(), dy = Ud.y() - p.y(), md = mx * dx + my * dy;
          if (md == 0) continue;
          const double mu = kd / md;
          if (mu < 1 - 1e-6) continue;
          const Point X(p.x() + mu * dx, p.y() + mu * dy);
          const double lx = L1d.x() - L0d.x(), ly = L1d.y() - L0d.y(), ll = lx * lx + ly * ly;
          const double along = ((X.x() - L0d.x()) * lx + (X.y() - L0d.y()) * ly) / ll;
          if (along < -1e-6 || along > 1 + 1e-6) continue;
          const double ex = qb.x() - qa.x(), ey = qb.y() - qa.y();
          const double on_q = ((X.x() - p.x() - qa.x()) * ex + (X.y() - p.y() - qa.y()) * ey) / (ex * ex + ey * ey);
          if (on_q < -1e-6 || on_q > 1 + 1e-6) continue;
          // Exact g and a bracket.
          const V2 m(-(qb.y() - qa.y()), qb.x() - qa.x());
          const ExactFT k = m * V2(qa.x(), qa.y());
          const ExactFT A0 = nl * (a - CGAL::ORIGIN) - c, A1 = nl * v, B0 = m * d0, B1 = -(m * v), C0 = nl * d0, C1 = -A1;
          const std::array<ExactFT, 3> g{A0 * B0 + k * C0, A0 * B1 + A1 * B0 + k * C1, A1 * B1};
          double lo = r, hi = r;
          bool found = false, exact_root = false;
          for (double delta = 1e-13 * std::max(1.0, std::abs(r)); delta < 1e-4 && !found; delta *= 8) {
            lo = std::max(0.0, r - delta), hi = std::min(1.0, r + delta);
            const int sl = range_sign_at(g, lo), sh = range_sign_at(g, hi);
            found = sl * sh < 0 || sl == 0 || sh == 0;
            // A root at a double (at a waypoint, t = 0 or 1, most often): an exact event.
            if (sl == 0 || sh == 0) {
              exact_root = true;
              for (const double t : {lo, hi})
                if (range_sign_at(g, t) == 0 && t > 0 && t < 1) out.cuts.push_back(ExactFT(t));
            }
          }
          if (exact_root) continue;
          if (!found) {
            // A double root: the point touches the line and turns back. Sampled at the
            // touch itself (its two sides are one shadow then).
            if (r > 0 && r < 1) out.cuts.push_back(ExactFT(r));
            continue;
          }
          out.brackets.push_back({ExactFT(lo), ExactFT(hi), g});
        }
      }
    }
  }
}


void separate_range_events(RangeEvents& re, std::vector<ExactFT>& events, std::size_t j) {
  auto& B = re.brackets;
  std::vector<char> dropped(B.size(), 0);
  // Halves x keeping its root: exact, so distinct events always come apart (the cap
  // only guards against a runaway).
  auto shrink = [](RangeEvents::Bracket& x) {
    const ExactFT mid = (x.lo + x.hi) / 2;
    const int sm = range_sign_at(x.g, mid);
    if (sm == 0) return x.lo = x.hi = mid, void();
    (range_sign_at(x.g, x.lo) * sm < 0 ? x.hi : x.lo) = mid;
  };
  // A quadratic of degree < 2 has its root exactly.
  for (std::size_t i = 0; i < B.size(); ++i)
    if (B[i].g[2] == 0) {
      dropped[i] = 1;
      if (B[i].g[1] != 0) {
        const ExactFT t = -B[i].g[0] / B[i].g[1];
        if (t > 0 && t < 1) events.push_back(t);
      }
    }
  for (int round = 0;; ++round) {
    if (round > 4000)
      throw InputError("pursuit check --range: events of the moving pursuer's sensor between waypoints " + std::to_string(j) + " and " +
                       std::to_string(j + 1) + " could not be told apart: not certified");
    bool conflict = false;
    std::sort(events.begin(), events.end());
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < B.size(); ++i)
      if (!dropped[i] && B[i].lo != B[i].hi) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return B[x].lo < B[y].lo; });
    for (std::size_t oi = 0; oi < order.size(); ++oi) {
      auto& x = B[order[oi]];
      if (dropped[order[oi]] || x.lo == x.hi) continue;
      const auto it = std::upper_bound(events.begin(), events.end(), x.lo);
      if (it != events.end() && *it < x.hi) {
        conflict = true;
        if (range_sign_at(x.g, *it) == 0) dropped[order[oi]] = 1;  // the same event
        else shrink(x);
        continue;
      }
      if (oi + 1 < order.size() && B[order[oi + 1]].lo < x.hi) {
        conflict = true;
        auto& y = B[order[oi + 1]];
        // y2 g - g2 y is linear: zero (proportional: the same roots) or its root is the
        // only one g and y can share.
        std::array<ExactFT, 3> l;
        for (int c = 0; c < 3; ++c) l[c] = y.g[2] * x.g[c] - x.g[2] * y.g[c];
        if (l[1] == 0 && l[0] == 0) {
          dropped[order[oi + 1]] = 1;
          continue;
        }
        if (l[1] != 0) {
          const ExactFT t = -l[0] / l[1];
          if (range_sign_at(x.g, t) == 0 && t > x.lo && t < x.hi && t > y.lo && t < y.hi) {
            dropped[order[oi]] = dropped[order[oi + 1]] = 1;
            events.push_back(t);
            continue;
          }
        }
        shrink(x), shrink(y);
      }
    }
    if (!conflict) break;
  }
  for (std::size_t i = 0; i < B.size(); ++i) {
    const auto& x = B[i];
    if (dropped[i]) continue;
    if (x.lo == x.hi) {
      if (x.lo > 0 && x.lo < 1) events.push_back(x.lo);
      continue;
    }
    // The sample between the ends must not be the root itself.
    const ExactFT mid = (x.lo + x.hi) / 2;
    if (range_sign_at(x.g, mid) == 0) {
      if (mid > 0 && mid < 1) events.push_back(mid);
      continue;
    }
    if (x.lo > 0) events.push_back(x.lo);
    if (x.hi < 1) events.push_back(x.hi);
  }
}

}  // namespace detail

}  // namespace preimage::pursuit
