// SPDX-License-Identifier: Apache-2.0
// Demo section of the geometry core: a floor plan, its triangulation, visibility polygons.
#include "common.hpp"
#include "demo.hpp"

#include <preimage/geometry/general_position.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/render/figures.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <random>

namespace preimage::cli {

void demo_geometry(DemoContext& ctx) {
  using namespace geometry;
  auto& R = ctx.report;
  R.section("Geometry core: exact environments, triangulation, visibility");

  scene::Scene office;
  office.name = "office";
  office.environment = generators::office(2, 3);
  const Environment& env = *office.environment;
  const VisibilityIndex index(env);
  const Triangulation& tri = index.triangulation();
  R.result("Office floor plan (2 x 3 rooms, walls as obstacles, doors): " + std::to_string(env.num_vertices()) +
           " vertices, " + count_of(env.num_holes(), "obstacle") + ", " + std::to_string(straight_vertices(env).size()) +
           " collinear (straight) vertices kept exactly.");
  R.result("Own constrained Delaunay triangulation: " + std::to_string(tri.size()) + " triangles (n + 2h - 2 = " +
           std::to_string(env.num_vertices() + 2 * env.num_holes() - 2) + "), " + std::to_string(tri.non_delaunay_edges()) +
           " edges not locally Delaunay.");
  {
    render::SvgCanvas c(render::scene_box(office));
    render::draw_scene(c, office);
    render::draw_triangulation(c, tri);
    ctx.figure("geometry-triangulation.svg", c.str(), "Constrained Delaunay triangulation of the office floor plan");
  }

  // Three viewpoints of every kind: interior, on a wall, at a door jamb (a reflex vertex).
  std::size_t jamb = 0;
  for (std::size_t v = 0; v < env.num_vertices(); ++v)
    if (env.ring_of(v) > 0 && env.is_reflex(v) && env.vertex(v).y() > 3 && env.vertex(v).x() > 3.5) { jamb = v; break; }
  struct View { Point q; const char* what; const char* colour; };
  const View views[] = {{Point(2.0, 2.7), "interior point", "#f4b400"},
                        {Point(10.0, 8.0), "point on the outer wall", "#34a853"},
                        {env.vertex(jamb), "wall corner (a vertex)", "#4285f4"}};
  // One panel per viewpoint: three translucent polygons overlaid mix into colours no
  // legend explains.
  std::vector<std::string> panels;
  for (const View& v : views) {
    render::SvgCanvas c(render::scene_box(office), 360);
    render::draw_scene(c, office);
    const VisibilityPolygon vp = index.compute(v.q);
    std::size_t free = 0;
    for (auto& e : vp.edges) free += e.kind == VisibilityEdge::Kind::Free;
    render::draw_visibility(c, vp, v.colour, std::string("V(q) from the ") + v.what);
    panels.push_back(c.str());
    R.result("Visibility from the " + std::string(v.what) + " " + format_point(v.q) + " [" + to_string(vp.location.kind) +
             "]: " + std::to_string(vp.vertices.size()) + " vertices, " + std::to_string(free) +
             " free edges (occlusion gaps), area " + format_number(vp.area()) + ".");
  }
  ctx.figure("geometry-visibility.svg", render::panel_grid(panels, 3),
             "Visibility polygons from an interior point, a wall point and a wall corner");

  // The same viewpoints with a sensor of range 3: V(q) within the disc, bounded by pieces of
  // V's edges and circle arcs (drawn as SVG arcs).
  std::vector<std::string> range_panels;
  std::string range_text;
  for (const View& v : views) {
    render::SvgCanvas c(render::scene_box(office), 360);
    render::draw_scene(c, office);
    const RangeVisibility rv = range_visibility(index, v.q, 3.0);
    render::draw_range_visibility(c, rv, v.colour, std::string("V(q) within range 3 from the ") + v.what);
    range_panels.push_back(c.str());
    std::size_t arcs = 0;
    for (const auto& p : rv.pieces) arcs += p.kind == RangePiece::Kind::Arc;
    if (!range_text.empty()) range_text.append("; ");
    range_text.append(v.what).append(": ").append(std::to_string(rv.pieces.size() - arcs)).append(" segments, ").append(count_of(arcs, "arc"));
    range_text.append(", area ").append(format_number(rv.area())).append(" of ").append(format_number(rv.polygon.area()));
  }
  R.result("Range-limited visibility (range 3, pieces decided exactly): " + range_text + ".");
  ctx.figure("geometry-range-visibility.svg", render::panel_grid(range_panels, 3),
             "Range-limited visibility (range 3) from the same three points: segments of V(q) and arcs of the range circle");

  // Cross-check on a random environment with holes: V(q) membership vs the O(n) two-point test.
  const Environment rnd = generators::random_environment(600, 8, 2026);
  const VisibilityIndex rindex(rnd);
  std::mt19937_64 rng(1);
  const auto box = rnd.bbox();
  std::uniform_real_distribution<double> X(box.xmin(), box.xmax()), Y(box.ymin(), box.ymax());
  // The most open of 20 random viewpoints, so the figure shows something.
  Point q(0, 0);
  double best = -1;
  for (int i = 0; i < 20;) {
    Point c = geometry::random_point(rng, X, Y);
    if (!rindex.in_free_space(c)) continue;
    ++i;
    const double a = rindex.compute(c).area();
    if (a > best) best = a, q = c;
  }
  const VisibilityPolygon vq = rindex.compute(q);
  const auto poly = canonical_cycle(vq.points());
  int agree = 0, total = 0;
  while (total < 300) {
    Point t = geometry::random_point(rng, X, Y);
    if (!rindex.in_free_space(t)) continue;
    ++total;
    const bool in_v = CGAL::bounded_side_2(poly.begin(), poly.end(), to_exact(t), ExactKernel()) != CGAL::ON_UNBOUNDED_SIDE;
    agree += in_v == visible(rnd, q, t);
  }
  R.result("Random environment (" + std::to_string(rnd.num_vertices()) + " vertices, " + std::to_string(rnd.num_holes()) +
           " obstacles): V(q) has " + std::to_string(vq.vertices.size()) + " vertices; membership in V(q) agrees with the "
           "two-point visibility test on " + std::to_string(agree) + " of " + std::to_string(total) + " random points.");
  scene::Scene rs;
  rs.environment = rnd;
  render::SvgCanvas rc(render::scene_box(rs));
  render::draw_scene(rc, rs);
  render::draw_visibility(rc, vq);
  ctx.figure("geometry-random-visibility.svg", rc.str(), "Visibility polygon in a random environment with obstacles");
}

}  // namespace preimage::cli
