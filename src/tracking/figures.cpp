// SPDX-License-Identifier: Apache-2.0
#include <preimage/render/svg.hpp>
#include <preimage/tracking/figures.hpp>
#include <preimage/tracking/replay.hpp>

#include <cmath>

namespace preimage::tracking {

namespace {
CGAL::Bbox_2 box_of(const std::vector<Point>& pts) {
  CGAL::Bbox_2 b;
  for (auto& p : pts) b += p.bbox();
  return b;
}
void arrow(render::SvgCanvas& c, const Point& from, const Vec2& v, double len, const render::Style& s, const std::string& title) {
  const double n = v.norm();
  if (n == 0) return;
  const Vec2 d = v * (len / n);
  const Point to(from.x() + d.x, from.y() + d.y);
  c.segment(from, to, s, title);
  const Vec2 back = d * -0.25, side{-d.y * 0.12, d.x * 0.12};
  c.segment(to, Point(to.x() + back.x + side.x, to.y() + back.y + side.y), s);
  c.segment(to, Point(to.x() + back.x - side.x, to.y() + back.y - side.y), s);
}
}  // namespace

namespace {
// V with its edges by kind, the escape-path tree, the observer and the target: the part
// every tracking figure shares (the paper's Figs. 2-3).
void draw_escape_path_tree(render::SvgCanvas& c, const LocalMap& map, const EscapePathTree* tree) {
  c.polygon(map.vertices, render::Style{"#fff3c4", "none", 0, 0.8, ""}, "V(q^o)");
  const render::Style solid{"none", "#222", 2.5, 1.0, ""}, occl{"none", "#d62728", 2.0, 1.0, "6 4"},
      range{"none", "#ff7f0e", 2.0, 1.0, "2 3"}, fov{"none", "#999", 1.0, 1.0, "1 3"};
  for (std::size_t e = 0; e < map.size(); ++e) {
    const auto k = map.edges[e];
    c.segment(map.vertices[e], map.vertices[map.next(e)],
              k == EdgeKind::Solid ? solid : k == EdgeKind::Occlusion ? occl : k == EdgeKind::Range ? range : fov,
              std::string(to_string(k)) + " edge " + std::to_string(e));
  }
  c.legend("V(q^o)", render::Style{"#fff3c4", "#e0c060", 1, 1.0, ""});
  c.legend("solid edge", solid);
  if (map.count(EdgeKind::Occlusion)) c.legend("occlusion edge (free)", occl);
  if (map.count(EdgeKind::Range)) c.legend("range edge (free)", range);
  if (map.count(EdgeKind::FieldOfView)) c.legend("field-of-view edge", fov);
  const render::Style observer{"#9467bd", "#222", 1.5, 1.0, ""};
  if (tree) {
    const render::Style branch{"none", "#1f77b4", 1.6, 1.0, "3 2"}, shortest{"none", "#1f77b4", 3.5, 1.0, ""};
    for (std::size_t i = 0; i < tree->paths.size(); ++i) {
      c.polyline(tree->polyline(i), branch, "SEP through edge " + std::to_string(tree->paths[i].edge) + ", length " +
                                                std::to_string(tree->paths[i].length));
      c.arrows(tree->polyline(i), "#1f77b4", 60, 3.5);  // escape paths run from the target outwards
    }
    if (tree->shortest != kNone) c.polyline(tree->polyline(tree->shortest), shortest, "shortest escape path");
    for (std::size_t v = 1; v < tree->nodes.size(); ++v) c.point(tree->nodes[v].at, 4, render::Style{"#1f77b4", "#fff", 1, 1.0, ""}, "tree node");
    const render::Style target{"#2ca02c", "#222", 1.5, 1.0, ""};
    c.point(tree->target, 7, target, "target (root)");
    c.legend("escape-path tree (target to each free edge)", branch);
    if (tree->shortest != kNone) c.legend("shortest escape path", shortest);
    c.legend("target (the tree's root)", target);
  }
  c.point(map.observer, 7, observer, "observer");
  c.legend("observer", observer);
}
}  // namespace

std::string escape_path_tree_figure(const geometry::Environment* env, const LocalMap& map, const EscapePathTree& tree,
                                    const Vec2* descent, const Vec2* plain_descent) {
  CGAL::Bbox_2 box = env ? env->bbox() : box_of(map.vertices);
  render::SvgCanvas c(box, 720);
  if (env) c.environment(*env);
  draw_escape_path_tree(c, map, &tree);
  const double len = 0.15 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  if (descent) arrow(c, map.observer, *descent, len, render::Style{"none", "#9467bd", 3, 1.0, ""}, "-grad phi (recursive average)");
  if (plain_descent) arrow(c, map.observer, *plain_descent, len, render::Style{"none", "#8c564b", 2, 1.0, "5 3"}, "-grad phi (plain average)");
  if (descent) c.legend("-grad phi, recursive average", render::Style{"none", "#9467bd", 3, 1.0, ""});
  if (plain_descent) c.legend("-grad phi, plain average", render::Style{"none", "#8c564b", 2, 1.0, "5 3"});
  return c.str();
}

std::string replay_scan_figure(const ReplayScan& r, const std::string& title, double width_px, bool legend) {
  CGAL::Bbox_2 box = box_of(r.map.vertices);
  for (auto& p : r.points) box += p.bbox();
  render::SvgCanvas c(box, width_px);
  draw_escape_path_tree(c, r.map, r.tree ? &*r.tree : nullptr);
  const render::Style hit{"#444", "none", 0, 1.0, ""};
  for (auto& p : r.points) c.point(p, 1.3, hit);
  c.legend("scan returns (short of max range)", hit);
  if (r.detected) {
    std::vector<Point> circle;
    for (int k = 0; k < 32; ++k)
      circle.emplace_back(r.detected->x() + r.detected_radius * std::cos(k * M_PI / 16), r.detected->y() + r.detected_radius * std::sin(k * M_PI / 16));
    const render::Style det{"none", "#2ca02c", 2, 1.0, ""};
    c.polygon(circle, det, "detected target circle");
    c.legend("detected target (fitted circle)", det);
  }
  c.label(Point(box.xmin(), box.ymax()), title, 12);
  if (r.gradient.norm() > 0) {
    const double len = 0.12 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    arrow(c, r.map.observer, r.gradient * -1.0, len, render::Style{"none", "#9467bd", 2.5, 1.0, ""}, "-grad phi-bar");
    c.legend("-grad phi-bar (the observer's move)", render::Style{"none", "#9467bd", 2.5, 1.0, ""});
  }
  if (!legend) c.clear_legend();
  return c.str();
}

std::string tracking_run_figure(const geometry::Environment& env, const SimulationResult& run, const std::string& title) {
  render::SvgCanvas c(env.bbox(), 720);
  c.environment(env);
  std::vector<Point> obs;
  for (auto& p : run.observer) obs.push_back(p.position);
  const render::Style os{"none", "#d62728", 2.5, 1.0, ""}, ts{"none", "#1f77b4", 2.5, 1.0, "6 3"};
  c.path(obs, os, "observer path");
  c.path(run.target, ts, "target path");
  for (std::size_t i = 0; i < run.target.size(); i += 10) {
    c.point(obs[i], 2.5, render::Style{"#d62728", "none", 0, 1.0, ""});
    c.point(run.target[i], 2.5, render::Style{run.visible[i] ? "#1f77b4" : "#bbb", "none", 0, 1.0, ""});
  }
  c.point(obs.front(), 6, render::Style{"#d62728", "#222", 1, 1.0, ""}, "observer start");
  c.point(run.target.front(), 6, render::Style{"#1f77b4", "#222", 1, 1.0, ""}, "target start");
  if (run.escape_time >= 0) {
    const std::size_t k = static_cast<std::size_t>(std::lround(run.escape_time / run.dt));
    c.point(run.target[k], 8, render::Style{"none", "#000", 2, 1.0, ""}, "first loss of sight");
    c.legend("first loss of sight", render::Style{"none", "#000", 2, 1.0, ""});
  }
  c.legend("observer (" + title + ")", os);
  c.legend("target", ts);
  return c.str();
}

std::string game_region_figure(const geometry::Environment& env, const VisibilityGame& g, std::uint32_t target,
                               const Point* observer, const std::string& title) {
  render::SvgCanvas c(env.bbox(), 720);
  const double h = g.params().resolution / 2;
  std::uint32_t longest = 1;
  for (std::uint32_t o = 0; o < g.num_points(); ++o)
    if (!g.keeps(o, target)) longest = std::max(longest, g.escape_steps(o, target));
  const render::Style keep{"#2ca02c", "none", 0, 0.75, ""};
  for (std::uint32_t o = 0; o < g.num_points(); ++o) {
    const Point& p = g.point(o);
    const std::vector<Point> sq{Point(p.x() - h, p.y() - h), Point(p.x() + h, p.y() - h), Point(p.x() + h, p.y() + h),
                                Point(p.x() - h, p.y() + h)};
    const std::uint32_t v = g.escape_steps(o, target);
    if (v == VisibilityGame::kForever) {
      c.polygon(sq, keep);
    } else if (v > 0) {
      // Orange, darker the longer the target needs to escape.
      const double f = static_cast<double>(v) / static_cast<double>(longest);
      c.polygon(sq, render::Style{"#ff7f0e", "none", 0, 0.15 + 0.6 * f, ""});
    }
  }
  c.environment(env);
  c.legend("observer keeps the target forever", keep);
  c.legend("target escapes (darker: later; white: at once)", render::Style{"#ff7f0e", "none", 0, 0.6, ""});
  c.point(g.point(target), 6, render::Style{"#1f77b4", "#222", 1, 1.0, ""}, "target");
  c.legend("target", render::Style{"#1f77b4", "#222", 1, 1.0, ""});
  if (observer) {
    c.point(*observer, 6, render::Style{"#d62728", "#222", 1, 1.0, ""}, "observer");
    c.legend("observer", render::Style{"#d62728", "#222", 1, 1.0, ""});
  }
  c.label(Point(env.bbox().xmin(), env.bbox().ymax() + 0.004 * (env.bbox().ymax() - env.bbox().ymin())), title, 12);
  return c.str();
}

}  // namespace preimage::tracking
