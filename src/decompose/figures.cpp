// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/figures.hpp>

namespace preimage::decompose {

namespace {
const char* const kCellFills[] = {"#e8f0fe", "#fce8e6", "#e6f4ea", "#fef7e0", "#f3e8fd"};
}  // namespace

void draw_decomposition(render::SvgCanvas& c, const TrapezoidalDecomposition& d, const TrapezoidalPlanner* graph) {
  for (std::size_t i = 0; i < d.cells().size(); ++i) {
    std::vector<Point> pts;
    for (auto& p : d.polygon(i)) pts.push_back(geometry::to_double(p));
    c.polygon(pts, render::Style{kCellFills[i % 5], "#9aa0a6", 0.5, 0.7, ""}, "cell " + std::to_string(i));
  }
  const render::Style ext{"none", "#5f6368", 1.0, 1.0, "3 3"};
  for (std::size_t x = 0; x < d.extensions().size(); ++x) {
    auto [a, b] = d.segment(x);
    c.segment(geometry::to_double(a), geometry::to_double(b), ext);
  }
  c.legend("vertical extensions", ext);
  if (!graph) return;
  const render::Style edge{"none", "#1a73e8", 1.0, 0.8, ""};
  for (std::size_t x = 0; x < d.extensions().size(); ++x) {
    const auto& e = d.extensions()[x];
    c.polyline({graph->centroid(e.left_cell), graph->extension_midpoint(x), graph->centroid(e.right_cell)}, edge);
  }
  for (std::size_t i = 0; i < d.cells().size(); ++i) c.point(graph->centroid(i), 2, render::Style{"#1a73e8", "none", 0, 1, ""});
  c.legend("adjacency graph (centroids through extension midpoints)", edge);
}

void draw_boustrophedon(render::SvgCanvas& c, const BoustrophedonDecomposition& b) {
  std::vector<Point> centres;
  for (std::size_t i = 0; i < b.cells().size(); ++i) {
    const auto poly = b.polygon(i);
    c.polygon(poly, render::Style{kCellFills[i % 5], "#9aa0a6", 0.8, 0.75, ""}, "cell " + std::to_string(i));
    double sx = 0, sy = 0;
    for (auto& p : poly) sx += p.x(), sy += p.y();
    centres.emplace_back(sx / static_cast<double>(poly.size()), sy / static_cast<double>(poly.size()));
  }
  const render::Style slice{"none", "#5f6368", 1.4, 1.0, "4 3"}, node{"#202124", "#ffffff", 1.0, 1.0, ""},
      edge{"none", "#a142f4", 1.4, 0.9, ""};
  std::vector<Point> nodes;
  for (const auto& s : b.critical_slices()) {
    const Point a = b.to_input(Point(s.x, CGAL::to_double(s.y_low))), z = b.to_input(Point(s.x, CGAL::to_double(s.y_high)));
    if (a != z) c.segment(a, z, slice);
    nodes.emplace_back((a.x() + z.x()) / 2, (a.y() + z.y()) / 2);
  }
  for (std::size_t i = 0; i < b.cells().size(); ++i)
    c.polyline({nodes[b.cells()[i].left_slice], centres[i], nodes[b.cells()[i].right_slice]}, edge);
  for (const auto& n : nodes) c.point(n, 3.5, node);
  c.legend("critical slices", slice);
  c.legend("Reeb graph: critical points joined through their cells", edge);
}

}  // namespace preimage::decompose
