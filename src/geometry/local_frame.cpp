// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/local_frame.hpp>

#include <preimage/geometry/clearance.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace preimage::geometry {

namespace {

// Unit in the last place of |x| (x normal or 0).
double ulp(double x) { return std::nextafter(std::fabs(x), std::numeric_limits<double>::infinity()) - std::fabs(x); }

// Is a - b exact in double? (Knuth's TwoSum: the rounding error of a + (-b), computed exactly.)
bool exact_difference(double a, double b) {
  const double s = a - b, bb = s - a;
  return (a - (s - bb)) + (-b - bb) == 0;
}

// The translation of one axis spanning [lo, hi] in an environment of extent `extent`: lo (or
// hi when negative) when every coordinate is more than 16 extents from 0, else 0. Then x and
// the shift lie within a factor 17/16 of each other, so x - shift is exact (Sterbenz).
double axis_shift(double lo, double hi, double extent) {
  if (lo > 16 * extent) return lo;
  if (hi < -16 * extent) return hi;
  return 0;
}

// Is x - lo exact for every coordinate of env along one axis?
bool exact_along(const Environment& env, bool x_axis, double lo) {
  for (std::size_t v = 0; v < env.num_vertices(); ++v)
    if (!exact_difference(x_axis ? env.vertex(v).x() : env.vertex(v).y(), lo)) return false;
  return true;
}

}  // namespace

LocalFrame LocalFrame::make(const Environment& env, bool canonical) {
  LocalFrame f;
  if (env.num_vertices() == 0) return f;
  const auto box = env.bbox();
  const double extent = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  if (!(extent > 0)) return f;
  f.dx_ = axis_shift(box.xmin(), box.xmax(), extent);
  f.dy_ = axis_shift(box.ymin(), box.ymax(), extent);
  // Canonical: along an axis the far rule left alone, the box's low end when every
  // difference from it is exact (x - lo and (x + S) - (lo + S) are one real number: both
  // exact or neither, so a plan and its exact translates get one local environment).
  if (canonical && f.dx_ == 0 && exact_along(env, true, box.xmin())) f.dx_ = box.xmin();
  if (canonical && f.dy_ == 0 && exact_along(env, false, box.ymin())) f.dy_ = box.ymin();
  if (f.identity()) return f;
  // Rounding back moves a point by at most half an ulp of the largest input coordinate per
  // axis (0.71 ulp in all); 4 ulps leave room for the segments between rounded points.
  const double M = std::max({std::fabs(box.xmin()), std::fabs(box.xmax()), std::fabs(box.ymin()), std::fabs(box.ymax())});
  f.margin_ = 4 * ulp(M) + std::ldexp(extent, -36);
  return f;
}

Environment LocalFrame::to_local(const Environment& env) const {
  if (identity()) return env;
  Environment out = env.translated(dx_, dy_);
  for (std::size_t v = 0; v < env.num_vertices(); ++v)
    if (!exact_difference(env.vertex(v).x(), dx_) || !exact_difference(env.vertex(v).y(), dy_))
      throw std::logic_error("local frame: a translation was not exact");
  return out;
}

std::size_t LocalFrame::to_input_certified(std::vector<Point>& path, const Clearance& clear) const {
  const std::vector<Point> local = path;
  for (Point& p : path) p = to_input(p);
  std::vector<std::size_t> failing;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (!clear.admits(path[i], path[i + 1])) failing.push_back(i);
  for (int pass = 0; pass < 4 && !failing.empty(); ++pass) {
    const double push = std::ldexp(margin(), pass);
    for (const std::size_t i : failing)
      for (const std::size_t k : {i, i + 1}) {
        // Away from the nearest obstacle, the direction taken in the frame: rounding may
        // have put the point on the obstacle itself (a path rounding a corner r = 1e-7 away,
        // 1e10 from the origin, lands on the corner).
        const Point p = to_input(local[k]), c = to_local(clear.nearest(p));
        const double dx = local[k].x() - c.x(), dy = local[k].y() - c.y(), d = std::hypot(dx, dy);
        if (d > 0) path[k] = Point(p.x() + push * dx / d, p.y() + push * dy / d);
      }
    // A moved point changes both its segments: check them all again.
    std::vector<std::size_t> again;
    for (const std::size_t i : failing)
      for (const std::size_t j : {i == 0 ? i : i - 1, i, i + 1})
        if (j + 1 < path.size() && (again.empty() || again.back() < j) && !clear.admits(path[j], path[j + 1])) again.push_back(j);
    failing = std::move(again);
  }
  return failing.empty() ? path.size() : failing.front();
}

}  // namespace preimage::geometry
