// SPDX-License-Identifier: Apache-2.0
// Private to coverage: a square raster of one configuration space component and the
// samples a path's tool covers (a measurement in floating point, never a decision on the
// geometry). measure_coverage reports from it; the touch-up pass finds what a pattern left.
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/geometry/visibility.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace preimage::coverage::detail {

struct CoverageRaster {
  double x0 = 0, y0 = 0, cell = 0;
  std::size_t nx = 0, ny = 0;
  std::vector<char> target;  // sample centre in the component

  /// Samples of E at `cell` (0: w/8, at least 256 across, at most about 4 million; refined
  /// when a sliver of a component holds none). `offset_grid` moves the samples by 0.382 of a
  /// cell from E's box: on a plan drawn on a binary grid, samples at (k + 1/2) cells from its
  /// walls lie exactly at w/2 or w/2 - cell/2 from the laps of a sweep or an offset ring, so
  /// a rounding of 1e-10 in the path changed 0.2 % of measure_coverage's overlap.
  CoverageRaster(const Environment& E, const geometry::VisibilityIndex& index, double w, double cell, bool offset_grid = false);
  geometry::Point centre(std::size_t id) const {
    return {x0 + (static_cast<double>(id % nx) + 0.5) * cell, y0 + (static_cast<double>(id / nx) + 0.5) * cell};
  }
  /// Calls f(id, inner) for every sample within h of segment ab (a = b: a disc), inner when
  /// it is within `inner` too. Row by row the samples form an interval of x: the capsule
  /// around a segment is convex.
  template <class F>
  void capsule(const geometry::Point& a, const geometry::Point& b, double h, double inner, F&& f) const;
};

// Samples of row y within h of segment ab: [lo, hi] in x (lo > hi when none).
void capsule_row(const geometry::Point& a, const geometry::Point& b, double h, double y, double& lo, double& hi);

template <class F>
void CoverageRaster::capsule(const geometry::Point& a, const geometry::Point& b, double h, double inner, F&& f) const {
  auto index_in = [](double v, std::size_t n) { return static_cast<long>(std::clamp(v, 0.0, static_cast<double>(n) - 1)); };
  const long j0 = index_in(std::floor((std::min(a.y(), b.y()) - h - y0) / cell), ny);
  const long j1 = index_in(std::ceil((std::max(a.y(), b.y()) + h - y0) / cell), ny);
  for (long j = j0; j <= j1; ++j) {
    const double y = y0 + (static_cast<double>(j) + 0.5) * cell;
    double lo, hi, ilo, ihi;
    capsule_row(a, b, h, y, lo, hi);
    if (!(lo <= hi)) continue;
    capsule_row(a, b, inner, y, ilo, ihi);
    const double fi0 = std::ceil((lo - x0) / cell - 0.5), fi1 = std::floor((hi - x0) / cell - 0.5);
    if (fi0 > static_cast<double>(nx) - 1 || fi1 < 0 || fi0 > fi1) continue;
    const long i0 = index_in(fi0, nx), i1 = index_in(fi1, nx);
    for (long i = i0; i <= i1; ++i) {
      const double x = x0 + (static_cast<double>(i) + 0.5) * cell;
      f(static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(i), x >= ilo && x <= ihi);
    }
  }
}

}  // namespace preimage::coverage::detail
