// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/coverage.hpp>

#include <preimage/decompose/planner.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

namespace preimage::decompose {

double min_disc_diameter(std::vector<Point> pts) {
  if (pts.empty()) return 0;
  std::shuffle(pts.begin(), pts.end(), std::mt19937_64(1));
  struct Disc { double x, y, r2; };
  auto contains = [](const Disc& d, const Point& p) {
    const double dx = p.x() - d.x, dy = p.y() - d.y;
    return dx * dx + dy * dy <= d.r2 * (1 + 1e-12) + 1e-300;
  };
  auto two = [](const Point& a, const Point& b) {
    const double x = (a.x() + b.x()) / 2, y = (a.y() + b.y()) / 2;
    return Disc{x, y, (a.x() - x) * (a.x() - x) + (a.y() - y) * (a.y() - y)};
  };
  auto three = [&](const Point& a, const Point& b, const Point& c) {
    const double bx = b.x() - a.x(), by = b.y() - a.y(), cx = c.x() - a.x(), cy = c.y() - a.y();
    const double d = 2 * (bx * cy - by * cx);
    if (d == 0) {  // collinear: the widest pair
      Disc best = two(a, b);
      for (const Disc& o : {two(a, c), two(b, c)})
        if (o.r2 > best.r2) best = o;
      return best;
    }
    const double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
    const double uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
    return Disc{a.x() + ux, a.y() + uy, ux * ux + uy * uy};
  };
  Disc d{pts[0].x(), pts[0].y(), 0};
  for (std::size_t i = 1; i < pts.size(); ++i) {
    if (contains(d, pts[i])) continue;
    d = Disc{pts[i].x(), pts[i].y(), 0};
    for (std::size_t j = 0; j < i; ++j) {
      if (contains(d, pts[j])) continue;
      d = two(pts[i], pts[j]);
      for (std::size_t k = 0; k < j; ++k)
        if (!contains(d, pts[k])) d = three(pts[i], pts[j], pts[k]);
    }
  }
  return 2 * std::sqrt(d.r2);
}

namespace {

// y of a floor (rounded up) or ceiling (rounded down) at x: the rounded point stays in
// the closed cell, so the path can be checked exactly.
double inward(const TrapezoidalDecomposition& t, std::uint32_t edge, double x, bool floor) {
  const auto iv = CGAL::to_interval(t.edge_y(edge, x));
  return floor ? iv.second : iv.first;
}

struct Builder {
  const BoustrophedonDecomposition& b;
  const TrapezoidalPlanner& planner;  // in sweep coordinates
  double r;
  std::vector<Point> path;            // sweep coordinates
  std::size_t laps = 0;

  // Boundary-following from x0 to x1 (x0 < x1 or x0 > x1) along the floor or ceiling of
  // the cell, through the environment vertices it passes.
  void follow(const BoustrophedonCell& cell, double x0, double x1, bool floor) {
    const auto& T = b.trapezoids().cells();
    std::vector<Point> pts;
    for (auto t : cell.trapezoids) {
      const double xs = T[t].x_left;
      if (xs > std::min(x0, x1) && xs < std::max(x0, x1)) {
        const std::uint32_t e = floor ? T[t].floor : T[t].ceiling;
        pts.emplace_back(xs, inward(b.trapezoids(), e, xs, floor));
      }
    }
    if (x1 < x0) std::reverse(pts.begin(), pts.end());
    for (auto& p : pts) add(p);
  }
  void add(const Point& p) {
    if (path.empty() || path.back() != p) path.push_back(p);
  }
  // Trapezoid of the cell spanning abscissa x.
  std::uint32_t at(const BoustrophedonCell& cell, double x) const {
    const auto& T = b.trapezoids().cells();
    for (auto t : cell.trapezoids)
      if (T[t].x_left <= x && x <= T[t].x_right) return t;
    return cell.trapezoids.back();
  }
  std::vector<double> lap_positions(const BoustrophedonCell& cell) const {
    const auto& T = b.trapezoids().cells();
    const double xl = T[cell.trapezoids.front()].x_left, xr = T[cell.trapezoids.back()].x_right;
    std::vector<double> xs;
    if (xr - xl <= 2 * r) {
      xs.push_back(xl + (xr - xl) / 2);
    } else {
      for (double x = xl + r; x < xr - r; x += 2 * r) xs.push_back(x);
      if (xs.empty() || xs.back() < xr - r) xs.push_back(xr - r);
    }
    return xs;
  }
  void cover(const BoustrophedonCell& cell) {
    const auto& T = b.trapezoids().cells();
    const auto xs = lap_positions(cell);
    // Enter at the first lap's floor (after a transit from wherever we are).
    bool up = true;
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const std::uint32_t t = at(cell, xs[k]);
      const Point lo(xs[k], inward(b.trapezoids(), T[t].floor, xs[k], true));
      const Point hi(xs[k], inward(b.trapezoids(), T[t].ceiling, xs[k], false));
      if (k == 0) {
        transit(up ? lo : hi);
      } else {
        // The previous lap ended on the ceiling if it went up (then this one goes down):
        // follow that same boundary to this lap's start.
        follow(cell, xs[k - 1], xs[k], /*floor=*/up);
        add(up ? lo : hi);
      }
      add(up ? hi : lo);
      ++laps;
      up = !up;
    }
  }
  void transit(const Point& to) {
    if (path.empty()) {
      path.push_back(to);
      return;
    }
    if (path.back() == to) return;
    // Midpoints and centroids are collision-free as they are; shortening would cost O(n)
    // exact visibility tests per point, on every transit.
    const Plan p = planner.plan(path.back(), to, false);
    for (std::size_t i = 1; i < p.path.size(); ++i) add(p.path[i]);
  }
};

CoverageReport cover_at(const Environment& env, const CoverageOptions& o, double angle) {
  const BoustrophedonDecomposition b(env, angle);
  const TrapezoidalPlanner planner(b.trapezoids());
  // Start cell: the one holding the start point (in sweep coordinates), else cell 0.
  std::uint32_t first = 0;
  std::optional<Point> start_sweep;
  if (o.start) {
    const Point q = b.to_sweep(*o.start);
    auto t = planner.locator().locate(q);
    if (!t) throw InputError("start " + geometry::format_point(*o.start) + " is not in free space");
    for (std::uint32_t k = 0; k < b.cells().size(); ++k)
      for (auto tt : b.cells()[k].trapezoids)
        if (tt == *t) first = k;
    start_sweep = q;
  }
  // Depth-first order over the adjacency graph (6.2.1), neighbours left to right.
  const auto adj = b.adjacency();
  std::vector<std::uint32_t> order;
  std::vector<char> seen(b.cells().size(), 0);
  std::vector<std::uint32_t> stack{first};
  while (!stack.empty()) {
    const std::uint32_t k = stack.back();
    stack.pop_back();
    if (seen[k]) continue;
    seen[k] = 1;
    order.push_back(k);
    for (auto it = adj[k].rbegin(); it != adj[k].rend(); ++it)
      if (!seen[*it]) stack.push_back(*it);
  }
  Builder bl{b, planner, o.radius, {}, 0};
  if (start_sweep) bl.path.push_back(*start_sweep);
  for (auto k : order) bl.cover(b.cells()[k]);

  CoverageReport rep;
  rep.angle = angle;
  rep.cell_order = order;
  rep.cells = b.cells().size();
  rep.critical_points = b.critical_slices().size();
  rep.laps = bl.laps;
  for (auto& p : bl.path) rep.path.push_back(b.to_input(p));
  for (std::size_t i = 0; i + 1 < rep.path.size(); ++i)
    rep.length += std::sqrt(CGAL::to_double(CGAL::squared_distance(rep.path[i], rep.path[i + 1])));
  for (std::size_t i = 1; i + 1 < bl.path.size(); ++i)
    rep.turns += geometry::orientation(bl.path[i - 1], bl.path[i], bl.path[i + 1]) != 0;
  rep.diameter = min_disc_diameter(env.vertices());
  for (std::size_t e = 0; e < env.num_vertices(); ++e)
    rep.perimeter += std::sqrt(CGAL::to_double(CGAL::squared_distance(env.vertex(e), env.vertex(env.next(e)))));
  const double D = rep.diameter, r = o.radius;
  rep.bound = D * D / (2 * r) + 4 * D * static_cast<double>(rep.critical_points + env.num_holes()) + 5 * rep.perimeter - 4 * D;
  return rep;
}

}  // namespace

CoverageReport plan_coverage(const Environment& env, const CoverageOptions& o) {
  if (!(o.radius > 0) || !std::isfinite(o.radius)) throw InputError("--width: the tool width must be a positive number");
  if (o.start && !geometry::locate(env, *o.start).in_free_space())
    throw InputError("start " + geometry::format_point(*o.start) + " is not in free space");
  if (o.angle_deg) return cover_at(env, o, *o.angle_deg);
  // Candidates: the axes and the directions of the longest edges (sweeping along an edge
  // direction avoids slivers along it); keep the shortest path.
  std::vector<std::pair<double, double>> edges;  // length, angle
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    const Point &a = env.vertex(e), &b = env.vertex(env.next(e));
    const double deg = std::fmod(std::atan2(b.y() - a.y(), b.x() - a.x()) * 180 / std::numbers::pi + 360.0, 180.0);
    edges.emplace_back(std::hypot(b.x() - a.x(), b.y() - a.y()), deg);
  }
  std::sort(edges.rbegin(), edges.rend());
  std::set<double> candidates{0.0, 90.0};
  for (std::size_t i = 0; i < edges.size() && candidates.size() < 10; ++i) candidates.insert(std::round(edges[i].second * 1e6) / 1e6);
  std::optional<CoverageReport> best;
  for (double a : candidates) {
    try {
      CoverageReport r = cover_at(env, o, a);
      if (!best || r.length < best->length) best = std::move(r);
    } catch (const InputError&) {
      // this direction made the rotated environment invalid: skip it
    }
  }
  if (!best) throw InputError("coverage: no sweep direction gave a valid decomposition");
  return *best;
}

}  // namespace preimage::decompose
