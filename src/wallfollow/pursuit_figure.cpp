// SPDX-License-Identifier: Apache-2.0
#include <preimage/wallfollow/pursuit_figure.hpp>

#include <algorithm>

namespace preimage::wallfollow {

using geometry::Point;

render::SvgCanvas pursuit_map(const geometry::Environment& env, const TrueCuts& T, const std::vector<Bitangent>& bitangents,
                              const std::vector<geometry::ExactPoint>& path, double width_px, const std::string& title) {
  const auto b = env.bbox();
  const double m = std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin());
  const CGAL::Bbox_2 box(b.xmin() - 0.03 * m, b.ymin() - 0.03 * m, b.xmax() + 0.03 * m, b.ymax() + 0.1 * m);
  render::SvgCanvas c(box, width_px, 8);
  c.environment(env);
  const std::size_t n = env.num_vertices();
  const render::Style inflection{"none", "#1a73e8", 1.2, 0.9, "5 3"}, other{"none", "#1a73e8", 0.7, 0.35, "2 3"},
      ray{"none", "#d93025", 1.0, 0.8, "2 2"};
  for (const Cut& k : T.cuts) {
    // Left cut of v: an inflection when v + 1 is convex; right cut when v - 1 is.
    const std::size_t nb = k.left ? (k.vertex + 1) % n : (k.vertex + n - 1) % n;
    c.segment(env.vertex(k.vertex), geometry::to_double(k.end), env.is_reflex(nb) ? other : inflection);
  }
  for (const Bitangent& t : bitangents) {
    c.segment(env.vertex(t.i), geometry::to_double(t.b_ij.point), ray);
    c.segment(env.vertex(t.j), geometry::to_double(t.b_ji.point), ray);
  }
  std::vector<Point> pts;
  for (auto& p : path) pts.push_back(geometry::to_double(p));
  const render::Style walk{"none", "#188038", 2.2, 0.95, ""};
  if (pts.size() > 1) {
    c.path(pts, walk, "the executed plan", 40, 5);
  }
  if (!pts.empty()) c.point(pts.front(), 4, {"#188038", "#000", 0.8, 1.0, ""}, "start");
  for (std::size_t k = 1; k < pts.size() && pts.size() <= 30; ++k) c.label(pts[k], std::to_string(k), 10, "#0b5e22");
  c.legend("inflection (a primitive appears or disappears)", inflection);
  c.legend("other cut", other);
  c.legend("bitangent ray (compounds split or merge)", ray);
  c.legend("plan (waypoints numbered)", walk);
  c.label(Point(box.xmin(), b.ymax() + 0.035 * (box.xmax() - box.xmin())), title, 11);
  return c;
}

}  // namespace preimage::wallfollow
