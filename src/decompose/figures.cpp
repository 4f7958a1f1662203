// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/figures.hpp>

namespace preimage::decompose {

void draw_decomposition(render::SvgCanvas& c, const TrapezoidalDecomposition& d, const TrapezoidalPlanner* graph) {
  static const char* fills[] = {"#e8f0fe", "#fce8e6", "#e6f4ea", "#fef7e0", "#f3e8fd"};
  for (std::size_t i = 0; i < d.cells().size(); ++i) {
    std::vector<Point> pts;
    for (auto& p : d.polygon(i)) pts.push_back(geometry::to_double(p));
    c.polygon(pts, render::Style{fills[i % 5], "#9aa0a6", 0.5, 0.7, ""}, "cell " + std::to_string(i));
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

}  // namespace preimage::decompose
