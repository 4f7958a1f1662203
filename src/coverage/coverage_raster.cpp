// SPDX-License-Identifier: Apache-2.0
#include "coverage_raster.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/kernel.hpp>

#include <algorithm>
#include <cmath>

namespace preimage::coverage::detail {

CoverageRaster::CoverageRaster(const Environment& E, const geometry::VisibilityIndex& index, double w, double cell_, bool offset_grid)
    : cell(cell_) {
  const auto box = E.bbox();
  const double phase = offset_grid ? 0.3819660112501051 : 0;  // 1/phi^2: no simple ratio to a binary grid
  // w/8 by default, but at least 256 samples across the box (a tool wider than the plan
  // would otherwise leave no sample in it: issue 47), and coarser where that would take more
  // than 4 million samples.
  const double extent = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  const bool automatic = !(cell > 0);
  if (automatic) cell = std::max(std::min(w / 8, extent / 256), std::sqrt((box.xmax() - box.xmin()) * (box.ymax() - box.ymin()) / 4e6));
  // A free space thinner than the automatic cell (a sliver of a component) may hold no
  // sample: the cell is refined, up to the cap, rather than the metrics refused.
  for (;;) {
    x0 = box.xmin() - phase * cell, y0 = box.ymin() - phase * cell;
    nx = static_cast<std::size_t>(std::ceil((box.xmax() - x0) / cell)) + 1;
    ny = static_cast<std::size_t>(std::ceil((box.ymax() - y0) / cell)) + 1;
    if (nx * ny > 50'000'000) throw InputError("coverage metrics: the raster would need more than 5e7 samples; give a coarser cell");
    target.assign(nx * ny, 0);
    bool any = false;
    for (std::size_t id = 0; id < target.size(); ++id) any |= (target[id] = index.in_free_space(centre(id))) != 0;
    if (any || !automatic || nx * ny * 16 > 50'000'000) break;
    cell /= 4;
  }
  // No sample in the free space even at the finest cell: a fraction of nothing is no
  // answer (refuse, never print 0).
  if (std::find(target.begin(), target.end(), 1) == target.end())
    throw InputError("coverage metrics: no raster sample (cell " + geometry::format_number(cell) + ") falls in the free space");
}

void capsule_row(const geometry::Point& a, const geometry::Point& b, double h, double y, double& lo, double& hi) {
  lo = INFINITY, hi = -INFINITY;
  for (const geometry::Point& c : {a, b}) {
    const double dy = y - c.y();
    if (dy * dy <= h * h) {
      const double dx = std::sqrt(h * h - dy * dy);
      lo = std::min(lo, c.x() - dx), hi = std::max(hi, c.x() + dx);
    }
  }
  const double vx = b.x() - a.x(), vy = b.y() - a.y(), L = std::hypot(vx, vy);
  if (L == 0) return;
  const double ux = vx / L, uy = vy / L, nx = -uy, ny = ux;
  // |n.(P - a)| <= h and 0 <= u.(P - a) <= L for P = (x, y): each linear in x.
  double blo = -INFINITY, bhi = INFINITY;
  auto clip = [&](double coef, double rest, double min_v, double max_v) {  // min_v <= coef x + rest <= max_v
    if (coef == 0) {
      if (rest < min_v || rest > max_v) blo = INFINITY, bhi = -INFINITY;
      return;
    }
    double x1 = (min_v - rest) / coef, x2 = (max_v - rest) / coef;
    if (x1 > x2) std::swap(x1, x2);
    blo = std::max(blo, x1), bhi = std::min(bhi, x2);
  };
  clip(nx, nx * -a.x() + ny * (y - a.y()), -h, h);
  clip(ux, ux * -a.x() + uy * (y - a.y()), 0, L);
  if (blo <= bhi) lo = std::min(lo, blo), hi = std::max(hi, bhi);
}

}  // namespace preimage::coverage::detail
