// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/clearance.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <cmath>

namespace preimage::geometry {

// Uniform grid of the workspace's edges, for "which edges may be within r of this segment".
struct Clearance::EdgeGrid {
  double x0 = 0, y0 = 0, cell = 1;
  std::uint32_t nx = 1, ny = 1;
  std::vector<std::uint32_t> offset, edges;
  mutable std::vector<std::uint32_t> stamp;
  mutable std::uint32_t now = 0;

  explicit EdgeGrid(const Environment& env) {
    const auto box = env.bbox();
    const std::size_t n = env.num_vertices();
    x0 = box.xmin(), y0 = box.ymin();
    const double w = std::max(box.xmax() - box.xmin(), 1e-300), h = std::max(box.ymax() - box.ymin(), 1e-300);
    cell = std::max(std::sqrt(w * h / static_cast<double>(std::max<std::size_t>(n, 1))), std::max(w, h) / 2048);
    nx = static_cast<std::uint32_t>(std::clamp(std::ceil(w / cell), 1.0, 2048.0));
    ny = static_cast<std::uint32_t>(std::clamp(std::ceil(h / cell), 1.0, 2048.0));
    offset.assign(std::size_t(nx) * ny + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::uint32_t> fill;
      if (pass == 1) {
        for (std::size_t i = 1; i < offset.size(); ++i) offset[i] += offset[i - 1];
        edges.resize(offset.back());
        fill.assign(offset.begin(), offset.end() - 1);
      }
      for (std::uint32_t e = 0; e < n; ++e) {
        const CGAL::Bbox_2 b = env.vertex(e).bbox() + env.vertex(env.next(e)).bbox();
        visit(b.xmin(), b.ymin(), b.xmax(), b.ymax(), [&](std::size_t c) {
          if (pass == 0) ++offset[c + 1];
          else edges[fill[c]++] = e;
        });
      }
    }
    stamp.assign(n, 0);
  }
  // Cells overlapping the box, widened by one so rounding in the index never loses one.
  template <class F>
  void visit(double xa, double ya, double xb, double yb, F&& f) const {
    auto ix = [&](double x) { return static_cast<long>(std::floor((x - x0) / cell)); };
    auto iy = [&](double y) { return static_cast<long>(std::floor((y - y0) / cell)); };
    const long i0 = std::max<long>(0, ix(xa) - 1), i1 = std::min<long>(nx - 1, ix(xb) + 1);
    const long j0 = std::max<long>(0, iy(ya) - 1), j1 = std::min<long>(ny - 1, iy(yb) + 1);
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i) f(std::size_t(j) * nx + std::size_t(i));
  }
  // Calls f(e) once for every edge filed in a cell within `reach` of segment pq's box.
  template <class F>
  void near(const Point& p, const Point& q, double reach, F&& f) const {
    if (++now == 0) std::fill(stamp.begin(), stamp.end(), 0), now = 1;
    visit(std::min(p.x(), q.x()) - reach, std::min(p.y(), q.y()) - reach, std::max(p.x(), q.x()) + reach,
          std::max(p.y(), q.y()) + reach, [&](std::size_t c) {
            for (auto k = offset[c]; k < offset[c + 1]; ++k) {
              const std::uint32_t e = edges[k];
              if (stamp[e] != now) stamp[e] = now, f(e);
            }
          });
  }
};

namespace {

using ExactSegment = ExactKernel::Segment_2;

// Squared distance from p to segment ab in double (a clamped projection: well-conditioned
// even for a segment of zero length).
double point_segment2(const Point& p, const Point& a, const Point& b) {
  const double vx = b.x() - a.x(), vy = b.y() - a.y(), wx = p.x() - a.x(), wy = p.y() - a.y();
  const double l2 = vx * vx + vy * vy;
  const double t = l2 > 0 ? std::clamp((wx * vx + wy * vy) / l2, 0.0, 1.0) : 0.0;
  const double dx = wx - t * vx, dy = wy - t * vy;
  return dx * dx + dy * dy;
}

// Is segment pq at distance >= r from workspace edge e? Crossing segments are at distance
// 0 (exact orientations); otherwise the distance is the least of the four endpoint-to-
// segment distances, filtered in double (squared: no square roots in the hot loop; the
// slack dwarfs their rounding), decided in exact (rational) arithmetic when the filter
// cannot tell.
bool clear_of(const Environment& env, std::uint32_t e, const Point& p, const Point& q, double r, double slack) {
  const Point &a = env.vertex(e), &b = env.vertex(env.next(e));
  if (CGAL::do_intersect(Kernel::Segment_2(p, q), Kernel::Segment_2(a, b))) return false;
  const double d2 = std::min({point_segment2(p, a, b), point_segment2(q, a, b), point_segment2(a, p, q), point_segment2(b, p, q)});
  const double hi = r + slack, lo = r - slack;
  if (d2 >= hi * hi) return true;
  if (lo > 0 && d2 < lo * lo) return false;
  const ExactFT exact = CGAL::squared_distance(ExactSegment(to_exact(p), to_exact(q)), ExactSegment(env.exact_vertex(e), env.exact_vertex(env.next(e))));
  return exact >= ExactFT(r) * ExactFT(r);
}

}  // namespace

Clearance::Clearance(const Environment& workspace, double radius)
    : workspace_(&workspace), radius_(radius), grid_(std::make_unique<EdgeGrid>(workspace)) {
  if (!(radius >= 0) || !std::isfinite(radius)) throw InputError("robot radius must be a finite number >= 0");
}
Clearance::~Clearance() = default;
Clearance::Clearance(Clearance&&) noexcept = default;
Clearance& Clearance::operator=(Clearance&&) noexcept = default;

bool Clearance::admits(const Point& p) const { return admits(p, p); }

bool Clearance::admits(const Point& p, const Point& q) const {
  if (!locate(*workspace_, p).in_free_space()) return false;
  if (radius_ == 0) return visible(*workspace_, p, q);
  return clear(p, q, radius_);
}

bool Clearance::clear(const Point& p, const Point& q, double r) const {
  const double slack = 1e-9 * (std::max({std::fabs(p.x()), std::fabs(p.y()), std::fabs(q.x()), std::fabs(q.y())}) + r);
  bool ok = true;
  grid_->near(p, q, r + slack, [&](std::uint32_t e) { ok = ok && clear_of(*workspace_, e, p, q, r, slack); });
  return ok;
}

double Clearance::distance(const Point& p) const {
  double best = INFINITY;
  for (std::size_t e = 0; e < workspace_->num_vertices(); ++e)
    best = std::min(best, std::sqrt(CGAL::to_double(CGAL::squared_distance(
                              p, Kernel::Segment_2(workspace_->vertex(e), workspace_->vertex(workspace_->next(e)))))));
  return best;
}

Point Clearance::nearest(const Point& p) const {
  double best = INFINITY;
  Point at = p;
  for (std::size_t e = 0; e < workspace_->num_vertices(); ++e) {
    const Kernel::Segment_2 s(workspace_->vertex(e), workspace_->vertex(workspace_->next(e)));
    const double d = CGAL::to_double(CGAL::squared_distance(p, s));
    if (d < best) {
      best = d;
      const Point foot = s.supporting_line().projection(p);
      at = s.has_on(foot) ? foot : (CGAL::squared_distance(p, s.source()) < CGAL::squared_distance(p, s.target()) ? s.source() : s.target());
    }
  }
  return at;
}

}  // namespace preimage::geometry
