// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/figures.hpp>

#include <numbers>

#include <cmath>

namespace preimage::decompose {

namespace {
const char* const kCellFills[] = {"#e8f0fe", "#fce8e6", "#e6f4ea", "#fef7e0", "#f3e8fd"};
}  // namespace

void draw_morse(render::SvgCanvas& c, const MorseDecomposition& m) {
  const auto box = m.environment().bbox();
  const double err = 1e-4 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  for (std::size_t i = 0; i < m.cells().size(); ++i)
    c.rings(m.cell_rings(i, err), render::Style{kCellFills[i % 5], "none", 0, 0.8, ""},
            "cell " + std::to_string(i) + " (area " + geometry::format_number(m.cells()[i].area) + ")");
  const render::Style slice{"none", "#5f6368", 1.2, 1.0, "4 3"};
  for (const MorseArc& a : m.arcs()) {
    std::vector<render::RegionStep> steps;
    if (a.family == SliceFamily::Circular) {
      const double rho = std::sqrt(CGAL::to_double(a.level));
      // SVG cannot draw an arc between equal ends: halve every arc (a loop is two half-turns).
      const double a0 = std::atan2(a.a.y() - a.centre.y(), a.a.x() - a.centre.x()) + a.span / 2;
      steps.push_back({Point(a.centre.x() + rho * std::cos(a0), a.centre.y() + rho * std::sin(a0)), rho, a.span / 2});
      steps.push_back({a.b, rho, a.span / 2});
    } else {
      for (const Point& p : a.corners) steps.push_back({p});
      steps.push_back({a.b});
    }
    c.region(a.a, steps, slice, "critical slice (node " + std::to_string(a.node) + ")", false);
  }
  c.legend("critical slice intervals", slice);
  const render::Style split{"#d93025", "#d93025", 1, 1, ""}, birth{"white", "#d93025", 1.5, 1, ""};
  for (const MorseCritical& k : m.critical_points())
    c.point(m.points()[k.point].approx, 3, k.kind == CriticalKind::BirthDeath ? birth : split,
            "critical point, node " + std::to_string(k.node) + ", h = " + geometry::format_number(k.level));
  c.legend("critical points (split/merge or minimum)", split);
  c.legend("critical points (birth/death)", birth);
  const render::Style centre{"#1a73e8", "#1a73e8", 1, 1, ""};
  c.point(m.centre(), 4, centre, "centre");
  c.legend(std::string("centre of the ") + std::string(to_string(m.family())) + " slices", centre);
}

void draw_brushfire(render::SvgCanvas& c, const BrushfireDecomposition& b) {
  const auto box = b.environment().bbox();
  const double sag = 1e-3 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  for (std::uint32_t k = 0; k < b.num_bands(); ++k) {
    const std::uint32_t cell = b.band_cell(k);
    c.polygon(b.band_polygon(k, sag), render::Style{kCellFills[cell % 5], kCellFills[cell % 5], 0.3, 0.85, ""},
              "cell " + std::to_string(cell) + " (D from " + geometry::format_number(b.cells()[cell].lo) + " to " +
                  geometry::format_number(b.cells()[cell].hi) + ")");
  }
  const render::Style axis{"none", "#9aa0a6", 0.6, 1.0, ""}, gvd{"none", "#1a73e8", 1.4, 0.9, ""};
  for (const auto& e : b.gvd().medial_edges()) c.polyline(e.polyline, axis, "medial axis");
  for (const auto& e : b.gvd().edges()) c.polyline(e.polyline, gvd, "GVD");
  c.legend("medial axis (fronts of one obstacle meet)", axis);
  c.legend("generalized Voronoi diagram (fronts of two obstacles meet)", gvd);
  const render::Style saddle{"#d93025", "#d93025", 1, 1, ""}, maximum{"white", "#d93025", 1.5, 1, ""};
  for (const auto& k : b.critical_points())
    c.point(k.p, 3, k.kind == BrushfireCriticalPoint::Kind::Saddle ? saddle : maximum,
            std::string(k.kind == BrushfireCriticalPoint::Kind::Saddle ? "saddle" : "maximum") + " of D = " + geometry::format_number(k.level) +
                ", node " + std::to_string(k.node));
  c.legend("saddles of D (fronts collide)", saddle);
  c.legend("maxima of D (a front vanishes)", maximum);
}

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
  for (std::size_t i = 0; i < b.cells().size(); ++i)
    c.polygon(b.polygon(i), render::Style{kCellFills[i % 5], "#9aa0a6", 0.8, 0.75, ""}, "cell " + std::to_string(i));
  const render::Style slice{"none", "#5f6368", 1.4, 1.0, "4 3"}, node{"#202124", "#ffffff", 1.0, 1.0, ""},
      edge{"none", "#a142f4", 1.4, 0.9, ""};
  std::vector<Point> nodes;  // sweep frame
  for (const auto& s : b.critical_slices()) {
    const Point a(s.x, CGAL::to_double(s.y_low)), z(s.x, CGAL::to_double(s.y_high));
    if (a != z) c.segment(b.to_input(a), b.to_input(z), slice);
    nodes.emplace_back(s.x, (a.y() + z.y()) / 2);
  }
  // Each Reeb edge inside its cell: from its left node along the slice to the middle of the
  // cell's left side, through the middles of the cell at every event between its
  // trapezoids, to the right side and along that slice to the right node.
  const auto& T = b.trapezoids().cells();
  auto mid = [&](std::uint32_t t, double x) {
    return Point(x, (CGAL::to_double(b.trapezoids().edge_y(T[t].floor, x)) + CGAL::to_double(b.trapezoids().edge_y(T[t].ceiling, x))) / 2);
  };
  for (std::size_t i = 0; i < b.cells().size(); ++i) {
    const auto& ts = b.cells()[i].trapezoids;
    std::vector<Point> route{nodes[b.cells()[i].left_slice]};
    for (auto t : ts) route.push_back(mid(t, T[t].x_left));
    route.push_back(mid(ts.back(), T[ts.back()].x_right));
    route.push_back(nodes[b.cells()[i].right_slice]);
    for (auto& p : route) p = b.to_input(p);
    c.polyline(route, edge, "Reeb graph edge: cell " + std::to_string(i));
  }
  for (const auto& n : nodes) c.point(b.to_input(n), 3.5, node);
  c.legend("critical slices", slice);
  c.legend("Reeb graph: critical points joined through their cells", edge);
}

void draw_wavefront(render::SvgCanvas& c, const WavefrontDecomposition& w, int levels) {
  const auto box = w.shortest_path_map().environment().bbox();
  const double sag = 1e-3 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  double top = 0;
  for (const auto& n : w.nodes()) top = std::max(top, n.level);
  for (int k = 1; k <= levels; ++k) {
    const double level = top * k / (levels + 1);
    for (const auto& f : w.fronts(level)) {
      const bool known = f.cell != WavefrontCell::kNone;
      const render::Style s{"none", known ? std::string("hsl(").append(std::to_string((f.cell * 137u) % 360u)).append(",70%,38%)") : std::string("#555"), 1.1, 1, ""};
      std::vector<Point> pts;
      for (const auto& arc : f.arcs) {
        const auto a = w.arc_points(arc, sag);
        pts.insert(pts.end(), a.begin(), a.end());
      }
      if (f.closed && !pts.empty()) pts.push_back(pts.front());
      c.polyline(pts, s, known ? "front of cell " + std::to_string(f.cell) : "front on a critical slice");
    }
  }
  const render::Style node{"#111", "#fff", 1, 1, ""};
  for (std::size_t i = 0; i < w.nodes().size(); ++i)
    c.point(w.nodes()[i].point, 2.8, node, "critical slice " + std::to_string(i) + " at h = " + geometry::format_number(w.nodes()[i].level));
  const render::Style start{"#1e8449", "#fff", 1, 1, ""};
  c.point(w.shortest_path_map().source(), 4, start, "start");
  c.legend("wave fronts h = const, one colour per cell", {"none", "hsl(200,70%,38%)", 1.1, 1, ""});
  c.legend("critical slice (a point on it)", node);
  c.legend("start (minimum of h)", start);
}

}  // namespace preimage::decompose
