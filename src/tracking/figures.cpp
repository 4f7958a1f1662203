// SPDX-License-Identifier: Apache-2.0
#include <preimage/render/svg.hpp>
#include <preimage/tracking/figures.hpp>

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

std::string escape_path_tree_figure(const geometry::Environment* env, const LocalMap& map, const EscapePathTree& tree,
                                    const Vec2* descent, const Vec2* plain_descent) {
  CGAL::Bbox_2 box = env ? env->bbox() : box_of(map.vertices);
  render::SvgCanvas c(box, 720);
  if (env) c.environment(*env);
  c.polygon(map.vertices, render::Style{"#fff3c4", "none", 0, 0.8, ""}, "V(q^o)");
  const render::Style solid{"none", "#222", 2.5, 1.0, ""}, occl{"none", "#d62728", 2.0, 1.0, "6 4"},
      range{"none", "#ff7f0e", 2.0, 1.0, "2 3"}, fov{"none", "#999", 1.0, 1.0, "1 3"};
  for (std::size_t e = 0; e < map.size(); ++e) {
    const auto k = map.edges[e];
    c.segment(map.vertices[e], map.vertices[map.next(e)],
              k == EdgeKind::Solid ? solid : k == EdgeKind::Occlusion ? occl : k == EdgeKind::Range ? range : fov,
              std::string(to_string(k)) + " edge " + std::to_string(e));
  }
  const render::Style branch{"none", "#1f77b4", 1.6, 1.0, "3 2"};
  for (std::size_t i = 0; i < tree.paths.size(); ++i)
    c.polyline(tree.polyline(i), branch, "SEP through edge " + std::to_string(tree.paths[i].edge) + ", length " +
                                             std::to_string(tree.paths[i].length));
  if (tree.shortest != kNone) c.polyline(tree.polyline(tree.shortest), render::Style{"none", "#1f77b4", 3.5, 1.0, ""}, "shortest escape path");
  for (std::size_t v = 1; v < tree.nodes.size(); ++v) c.point(tree.nodes[v].at, 4, render::Style{"#1f77b4", "#fff", 1, 1.0, ""}, "tree node");
  c.point(tree.target, 7, render::Style{"#2ca02c", "#222", 1.5, 1.0, ""}, "target (root)");
  c.point(map.observer, 7, render::Style{"#9467bd", "#222", 1.5, 1.0, ""}, "observer");
  const double len = 0.15 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  if (descent) arrow(c, map.observer, *descent, len, render::Style{"none", "#9467bd", 3, 1.0, ""}, "-grad phi (recursive average)");
  if (plain_descent) arrow(c, map.observer, *plain_descent, len, render::Style{"none", "#8c564b", 2, 1.0, "5 3"}, "-grad phi (plain average)");
  c.legend("solid edge", solid);
  c.legend("occlusion edge (free)", occl);
  if (map.count(EdgeKind::Range)) c.legend("range edge (free)", range);
  c.legend("escape-path tree", branch);
  c.legend("shortest escape path", render::Style{"none", "#1f77b4", 3.5, 1.0, ""});
  if (descent) c.legend("-grad phi, recursive average", render::Style{"none", "#9467bd", 3, 1.0, ""});
  if (plain_descent) c.legend("-grad phi, plain average", render::Style{"none", "#8c564b", 2, 1.0, "5 3"});
  return c.str();
}

std::string tracking_run_figure(const geometry::Environment& env, const SimulationResult& run, const std::string& title) {
  render::SvgCanvas c(env.bbox(), 720);
  c.environment(env);
  std::vector<Point> obs;
  for (auto& p : run.observer) obs.push_back(p.position);
  const render::Style os{"none", "#d62728", 2.5, 1.0, ""}, ts{"none", "#1f77b4", 2.5, 1.0, "6 3"};
  c.polyline(obs, os, "observer path");
  c.polyline(run.target, ts, "target path");
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

}  // namespace preimage::tracking
