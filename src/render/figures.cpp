// SPDX-License-Identifier: Apache-2.0
#include <preimage/render/figures.hpp>

namespace preimage::render {

CGAL::Bbox_2 scene_box(const scene::Scene& s) {
  CGAL::Bbox_2 b;
  bool any = false;
  auto add = [&](const Point& p) { b = any ? b + p.bbox() : p.bbox(), any = true; };
  if (s.environment)
    for (auto& p : s.environment->vertices()) add(p);
  for (auto& l : s.landmarks) add(l.at);
  for (auto& bm : s.beams) add(bm.from), add(bm.to);
  if (s.start) add(*s.start);
  if (s.goal) add(*s.goal);
  if (!any) return CGAL::Bbox_2(0, 0, 1, 1);
  const double pad = 0.03 * std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin()) + 1e-9;
  return CGAL::Bbox_2(b.xmin() - pad, b.ymin() - pad, b.xmax() + pad, b.ymax() + pad);
}

void draw_scene(SvgCanvas& c, const scene::Scene& s) {
  if (s.environment) c.environment(*s.environment);
  if (!s.beams.empty()) {
    Style beam{"none", "#d93025", 2.0, 1.0, ""};
    for (auto& b : s.beams) {
      c.segment(b.from, b.to, beam, "beam " + b.label);
      c.label(Point((b.from.x() + b.to.x()) / 2, (b.from.y() + b.to.y()) / 2), b.label, 13, "#d93025");
    }
    c.legend("beams", beam);
  }
  if (!s.landmarks.empty()) {
    Style lm{"#1a73e8", "#0b3d91", 1.0, 1.0, ""};
    for (auto& l : s.landmarks) {
      c.point(l.at, 4, lm, "landmark " + l.label);
      c.label(l.at, " " + l.label, 12, "#0b3d91");
    }
    c.legend("landmarks", lm);
  }
  if (s.start) {
    Style st{"#188038", "#0d652d", 1.0, 1.0, ""};
    c.point(*s.start, 6, st, "start");
    c.legend("start", st);
  }
  if (s.goal) {
    Style g{"#a142f4", "#681da8", 1.0, 1.0, ""};
    c.point(*s.goal, 6, g, "goal");
    c.legend("goal", g);
  }
}

void draw_triangulation(SvgCanvas& c, const geometry::Triangulation& t) {
  const auto& P = t.environment().vertices();
  Style tri{"none", "#9aa0a6", 0.6, 1.0, ""};
  for (const auto& T : t.triangles())
    for (int i = 0; i < 3; ++i)
      if (T.nbr[i] != geometry::kNone && T.nbr[i] > static_cast<std::uint32_t>(&T - t.triangles().data()))
        c.segment(P[T.v[i]], P[T.v[(i + 1) % 3]], tri);
  c.legend("constrained Delaunay triangulation", tri);
}

void draw_visibility(SvgCanvas& c, const geometry::VisibilityPolygon& v, const std::string& colour,
                     const std::string& label) {
  std::vector<Point> pts;
  for (auto& vv : v.vertices) pts.push_back(vv.approx);
  c.polygon(pts, Style{colour, "none", 0, 0.35, ""});
  const std::size_t n = v.vertices.size();
  Style solid{"none", colour, 2.5, 1.0, ""}, free{"none", "#d93025", 1.5, 1.0, "5 3"};
  for (std::size_t i = 0; i < n; ++i) {
    const auto& e = v.edges[i];
    const bool is_free = e.kind == geometry::VisibilityEdge::Kind::Free;
    c.segment(pts[i], pts[(i + 1) % n], is_free ? free : solid,
              is_free ? "free edge: occlusion at vertex " + std::to_string(e.reflex) : "on edge " + std::to_string(e.edge));
  }
  c.point(v.query, 4.5, Style{"#202124", "#ffffff", 1.5, 1.0, ""}, "query " + geometry::format_point(v.query));
  c.legend(label, Style{colour, colour, 2.5, 0.6, ""});
  c.legend("free edges (occlusion gaps)", free);
}

void draw_range_visibility(SvgCanvas& c, const geometry::RangeVisibility& r, const std::string& colour, const std::string& label) {
  using geometry::RangePiece;
  const Point& q = r.query();
  std::vector<RegionStep> steps;
  Point start;
  if (r.full_disc) {
    start = Point(q.x() + r.range, q.y());
    steps = {{Point(q.x() - r.range, q.y()), r.range, 3.141592653589793}, {start, r.range, 3.141592653589793}};
  } else {
    start = r.pieces.front().from.approx;
    for (const auto& p : r.pieces) steps.push_back({p.to.approx, p.kind == RangePiece::Kind::Arc ? r.range : 0.0, p.span});
  }
  c.region(start, steps, Style{colour, "none", 0, 0.35, ""});
  // The whole range circle, dotted.
  c.region(Point(q.x() + r.range, q.y()), {{Point(q.x() - r.range, q.y()), r.range, 3.141592653589793}, {Point(q.x() + r.range, q.y()), r.range, 3.141592653589793}},
           Style{"none", "#5f6368", 1.0, 0.8, "2 3"}, "range " + geometry::format_number(r.range));
  Style solid{"none", colour, 2.5, 1.0, ""}, free{"none", "#d93025", 1.5, 1.0, "5 3"}, arc{"none", "#1a73e8", 2.0, 1.0, ""};
  for (const auto& p : r.pieces) {
    if (p.kind == RangePiece::Kind::Arc) {
      if (r.full_disc) continue;
      c.region(p.from.approx, {{p.to.approx, r.range, p.span}}, arc, "range limit", false);
      continue;
    }
    const auto& e = r.polygon.edges[p.edge];
    const bool is_free = e.kind == geometry::VisibilityEdge::Kind::Free;
    c.segment(p.from.approx, p.to.approx, is_free ? free : solid,
              is_free ? "free edge: occlusion at vertex " + std::to_string(e.reflex) : "on edge " + std::to_string(e.edge));
  }
  c.point(q, 4.5, Style{"#202124", "#ffffff", 1.5, 1.0, ""}, "query " + geometry::format_point(q));
  c.legend(label, Style{colour, colour, 2.5, 0.6, ""});
  c.legend("free edges (occlusion gaps)", free);
  if (!r.full_disc) c.legend("range limit (circle arcs)", arc);
}

void draw_route(SvgCanvas& c, const std::vector<Point>& path, const std::string& label, const std::string& colour, double stroke,
                const std::string& dash) {
  if (path.empty()) return;
  const Style line{"none", colour, stroke, 0.95, dash};
  c.path(path, line, label);
  c.legend(label, line);
  const Style start{"#ffffff", colour, 2.5, 1.0, ""}, end{colour, "#202124", 1.5, 1.0, ""};
  c.point(path.front(), 6, start, label + ": start");
  c.point(path.back(), 5, end, label + ": end");
  c.legend(label + " start (ring) and end (dot)", start);
}

void draw_configuration_space(SvgCanvas& c, const geometry::ConfigurationSpace& cs) {
  const Style fill{"#e6f4ea", "#81c995", 1.0, 0.9, "3 2"};
  for (const auto& comp : cs.components()) {
    std::vector<std::vector<Point>> rings;
    for (std::size_t r = 0; r < comp.num_rings(); ++r) rings.push_back(comp.ring(r));
    c.rings(rings, fill, "configuration space of a robot of radius " + geometry::format_number(cs.radius()));
  }
  c.legend("where the robot's centre may go (radius " + geometry::format_number(cs.radius()) + ")", fill);
}

}  // namespace preimage::render
