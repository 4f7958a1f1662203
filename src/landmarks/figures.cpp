// SPDX-License-Identifier: Apache-2.0
#include <preimage/landmarks/figures.hpp>

#include <algorithm>

namespace preimage::landmarks {

render::SvgCanvas swap_cell_figure(const LandmarkSet& L, const SwapCellDecomposition& D, const LandmarkFigureOptions& o) {
  CGAL::Bbox_2 b = L.points.front().bbox();
  for (const auto& p : L.points) b += p.bbox();
  for (const auto& p : o.path) b += p.bbox();
  const double m = 0.35 * std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin());
  render::SvgCanvas svg(CGAL::Bbox_2(b.xmin() - m, b.ymin() - m, b.xmax() + m, b.ymax() + m));
  // Cells: the ones meeting the hull in blue, the others grey (shades alternate so that
  // neighbours differ).
  for (std::uint32_t c = 0; c < D.cells().size(); ++c) {
    std::vector<geometry::Point> poly;
    for (auto v : D.boundary(c)) poly.push_back(geometry::to_double(D.vertices()[v].p));
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
    svg.segment(geometry::to_double(D.vertices()[e.origin].p), geometry::to_double(D.vertices()[e.target].p), ray);
  }
  svg.legend("swap line", ray);
  svg.legend("cell meeting the hull", {"#b7d3ee", "none", 1, 1, ""});
  if (!o.highlight_cells.empty()) svg.legend(o.highlight_label, {"#f4a261", "none", 1, 1, ""});
  if (!o.route.empty()) {
    std::vector<geometry::Point> r;
    for (auto k : o.route) r.push_back(L.points[k]);
    r.push_back(r.front());
    render::Style s{"none", "#1d6fb8", 2.0, 1.0, "6 4"};
    svg.polyline(r, s);
    svg.legend(o.route_label, s);
  }
  if (!o.path.empty()) {
    render::Style s{"none", "#c0392b", 2.2, 1.0, ""};
    svg.polyline(o.path, s);
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
