// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/local_frame.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace preimage::geometry {

namespace {

// Unit in the last place of |x| (x normal or 0).
double ulp(double x) { return std::nextafter(std::fabs(x), std::numeric_limits<double>::infinity()) - std::fabs(x); }

// The translation of one axis spanning [lo, hi] in an environment of extent `extent`: lo (or
// hi when negative) when every coordinate is more than 16 extents from 0, else 0. Then x and
// the shift lie within a factor 17/16 of each other, so x - shift is exact (Sterbenz).
// Is a - b exact in double? (Knuth's TwoSum: the rounding error of a + (-b), computed exactly.)
bool exact_difference(double a, double b) {
  const double s = a - b, bb = s - a;
  return (a - (s - bb)) + (-b - bb) == 0;
}

double axis_shift(double lo, double hi, double extent) {
  if (lo > 16 * extent) return lo;
  if (hi < -16 * extent) return hi;
  return 0;
}

}  // namespace

LocalFrame LocalFrame::of(const Environment& env) {
  LocalFrame f;
  if (env.num_vertices() == 0) return f;
  const auto box = env.bbox();
  const double extent = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  if (!(extent > 0)) return f;
  f.dx_ = axis_shift(box.xmin(), box.xmax(), extent);
  f.dy_ = axis_shift(box.ymin(), box.ymax(), extent);
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

}  // namespace preimage::geometry
