// SPDX-License-Identifier: Apache-2.0
#include <preimage/landmarks/figures.hpp>

#include <algorithm>
#include <optional>
#include <utility>

namespace preimage::landmarks {
namespace {

using geometry::ExactFT;
using geometry::ExactPoint;

// The frame [x0, x1] x [y0, y1] in exact numbers: cells and rays are clipped to it before
// rounding, since their far vertices can lie beyond the range of doubles (nearly
// parallel swap lines cross very far away).
struct Frame {
  ExactFT lo[2], hi[2];
  // Signed distance-like value of p against side s (>= 0 inside): x - x0, x1 - x, ...
  ExactFT inside(const ExactPoint& p, int s) const {
    const ExactFT c = s % 2 ? p.y() : p.x();
    return s < 2 ? c - lo[s % 2] : hi[s % 2] - c;
  }
};

// Sutherland-Hodgman against each side of the frame (exact; a non-convex cell may keep
// zero-width bridges along the frame, which draw as nothing).
std::vector<geometry::Point> clipped_polygon(std::vector<ExactPoint> poly, const Frame& f) {
  for (int s = 0; s < 4 && !poly.empty(); ++s) {
    std::vector<ExactPoint> out;
    for (std::size_t q = 0; q < poly.size(); ++q) {
      const ExactPoint &a = poly[q], &b = poly[(q + 1) % poly.size()];
      const ExactFT da = f.inside(a, s), db = f.inside(b, s);
      if (da >= 0) out.push_back(a);
      if ((da < 0) != (db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    poly = std::move(out);
  }
  std::vector<geometry::Point> r;
  for (const auto& p : poly) r.push_back(geometry::to_double(p));
  return r;
}

// The part of segment ab inside the frame, if any.
std::optional<std::pair<geometry::Point, geometry::Point>> clipped_segment(const ExactPoint& a, const ExactPoint& b, const Frame& f) {
  ExactFT t0 = 0, t1 = 1;
  for (int s = 0; s < 4; ++s) {
    const ExactFT da = f.inside(a, s), db = f.inside(b, s);
    if (da < 0 && db < 0) return std::nullopt;
    if (da < 0) t0 = CGAL::max(t0, da / (da - db));
    if (db < 0) t1 = CGAL::min(t1, da / (da - db));
  }
  if (t0 >= t1) return std::nullopt;
  return std::pair{geometry::to_double(a + (b - a) * t0), geometry::to_double(a + (b - a) * t1)};
}

}  // namespace

render::SvgCanvas swap_cell_figure(const LandmarkSet& L, const SwapCellDecomposition& D, const LandmarkFigureOptions& o) {
  CGAL::Bbox_2 b = L.points.front().bbox();
  for (const auto& p : L.points) b += p.bbox();
  for (const auto& p : o.path) b += p.bbox();
  const double m = 0.35 * std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin());
  const CGAL::Bbox_2 window(b.xmin() - m, b.ymin() - m, b.xmax() + m, b.ymax() + m);
  render::SvgCanvas svg(window);
  const Frame frame{{window.xmin(), window.ymin()}, {window.xmax(), window.ymax()}};
  // Cells: the ones meeting the hull in blue, the others grey (shades alternate so that
  // neighbours differ).
  for (std::uint32_t c = 0; c < D.cells().size(); ++c) {
    std::vector<ExactPoint> cell;
    for (auto v : D.boundary(c)) cell.push_back(D.vertices()[v].p);
    const auto poly = clipped_polygon(std::move(cell), frame);
    if (poly.size() < 3) continue;
    const bool hi = std::find(o.highlight_cells.begin(), o.highlight_cells.end(), c) != o.highlight_cells.end();
    render::Style s;
    s.stroke = "none";
    static const char* blue[3] = {"#cfe3f6", "#b7d3ee", "#a4c6e8"};
    static const char* grey[3] = {"#f0f0f0", "#e4e4e4", "#d8d8d8"};
    s.fill = hi ? "#f4a261" : D.cells()[c].meets_hull ? blue[c % 3] : grey[c % 3];
    svg.polygon(poly, s, "cell " + std::to_string(c) + ": " + format_reading(D.cells()[c].permutation, L.labels));
  }
  render::Style ray{"none", "#555", 0.8, 1.0, ""};
  for (std::uint32_t h = 0; h < D.half_edges().size(); h += 2) {
    const auto& e = D.half_edges()[h];
    if (e.ray == SwapCellDecomposition::kNone) continue;
    if (const auto piece = clipped_segment(D.vertices()[e.origin].p, D.vertices()[e.target].p, frame)) svg.segment(piece->first, piece->second, ray);
  }
  svg.legend("swap line", ray);
  svg.legend("cell meeting the hull", {"#b7d3ee", "none", 1, 1, ""});
  if (!o.highlight_cells.empty()) svg.legend(o.highlight_label, {"#f4a261", "none", 1, 1, ""});
  if (!o.route.empty()) {
    std::vector<geometry::Point> r;
    for (auto k : o.route) r.push_back(L.points[k]);
    r.push_back(r.front());
    render::Style s{"none", "#1d6fb8", 2.0, 1.0, "6 4"};
    svg.path(r, s, o.route_label);
    svg.legend(o.route_label, s);
  }
  if (!o.path.empty()) {
    render::Style s{"none", "#c0392b", 2.2, 1.0, ""};
    svg.path(o.path, s, o.path_label);
    svg.point(o.path.front(), 4, {"#c0392b", "#c0392b", 1, 1, ""}, "start");
    svg.legend(o.path_label, s);
  }
  for (std::size_t k = 0; k < L.size(); ++k) {
    svg.point(L.points[k], 4.5, {"#111", "#111", 1, 1, ""}, L.labels[k]);
    svg.label(L.points[k] + geometry::Vector(0.015 * (b.xmax() - b.xmin() + 1), 0.015 * (b.ymax() - b.ymin() + 1)), L.labels[k], 14);
  }
  return svg;
}

}  // namespace preimage::landmarks
