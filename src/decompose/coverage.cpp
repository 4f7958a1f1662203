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

// A cell's floor or ceiling as a polyline of doubles in sweep coordinates. Environment
// vertices are exact; points inside an edge are rounded into the cell (a floor up, a
// ceiling down), so every point lies in the closed cell and the path can be certified
// exactly.
struct Chain {
  std::vector<Point> pts;
  std::vector<std::uint32_t> vertex;  // environment vertex per point, or CellChains::kNoVertex
  std::vector<std::uint32_t> edge;    // environment edge it lies on
};

// Where a lap at abscissa x meets a chain: after point k (the last with x_k <= x); on k
// itself when x_k == x (at a wall on the slice line, the last of its points), else inside
// segment k -> k+1.
struct Foot {
  std::size_t k;
  bool at_point;
  Point p;
  std::uint32_t edge;  // environment edge it lies on
};

struct PathPoint {
  Point p;                                        // sweep coordinates
  std::uint32_t vertex = CellChains::kNoVertex;   // environment vertex it is, if any
  std::uint32_t edge = CellChains::kNoVertex;     // else the environment edge it lies on, if any
};

struct Builder {
  const BoustrophedonDecomposition& b;
  const TrapezoidalPlanner& planner;  // in sweep coordinates
  double r;
  std::vector<PathPoint> path;
  std::size_t laps = 0;

  void add(const Point& p, std::uint32_t vertex = CellChains::kNoVertex, std::uint32_t edge = CellChains::kNoVertex) {
    if (path.empty() || path.back().p != p) path.push_back({p, vertex, edge});
  }
  void add(const Chain& c, std::size_t i) { add(c.pts[i], c.vertex[i], c.edge[i]); }
  void add(const Chain& c, const Foot& f) {
    if (f.at_point) add(c, f.k);
    else add(f.p, CellChains::kNoVertex, f.edge);
  }

  Chain chain(const std::vector<ExactPoint>& pts, const std::vector<std::uint32_t>& ids, const std::vector<std::uint32_t>& edges,
              bool floor) const {
    Chain c;
    c.edge = edges;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (ids[i] != CellChains::kNoVertex) {
        c.pts.push_back(b.sweep_environment().vertex(ids[i]));
      } else {
        const auto iy = CGAL::to_interval(pts[i].y());
        c.pts.emplace_back(CGAL::to_double(pts[i].x()), floor ? iy.second : iy.first);
      }
      c.vertex.push_back(ids[i]);
    }
    return c;
  }

  // Trapezoid of the cell whose x-range holds x strictly inside (x is not an event there).
  std::uint32_t at(const BoustrophedonCell& cell, double x) const {
    const auto& T = b.trapezoids().cells();
    for (auto t : cell.trapezoids)
      if (T[t].x_left <= x && x <= T[t].x_right) return t;
    return cell.trapezoids.back();
  }

  Foot foot(const BoustrophedonCell& cell, const Chain& c, double x, bool floor) const {
    auto it = std::upper_bound(c.pts.begin(), c.pts.end(), x, [](double v, const Point& p) { return v < p.x(); });
    const std::size_t k = static_cast<std::size_t>(it - c.pts.begin()) - 1;  // x >= the chain's first abscissa
    if (c.pts[k].x() == x) return {k, true, c.pts[k], c.edge[k]};
    const auto& T = b.trapezoids().cells()[at(cell, x)];
    const std::uint32_t e = floor ? T.floor : T.ceiling;
    const auto iy = CGAL::to_interval(b.trapezoids().edge_y(e, x));
    return {k, false, Point(x, floor ? iy.second : iy.first), e};
  }

  // Boundary following along a chain from one foot to another, through every chain point
  // between them (walls on slice lines included).
  void walk(const Chain& c, const Foot& from, const Foot& to) {
    if (to.k > from.k) {
      for (std::size_t i = from.k + 1; i <= to.k; ++i) add(c, i);
    } else if (to.k < from.k) {
      for (std::size_t i = from.at_point ? from.k - 1 : from.k; i > to.k; --i) add(c, i);
    }
    add(c, to);
  }

  std::vector<double> lap_positions(double xl, double xr) const {
    std::vector<double> xs;
    if (xr - xl <= 2 * r) {
      xs.push_back(xl + (xr - xl) / 2);
    } else {
      for (double x = xl + r; x < xr - r; x += 2 * r) xs.push_back(x);
      if (xs.empty() || xs.back() < xr - r) xs.push_back(xr - r);
    }
    return xs;
  }

  void cover(std::size_t index) {
    const BoustrophedonCell& cell = b.cells()[index];
    const CellChains ch = b.chains(index);
    const Chain floor = chain(ch.floor, ch.floor_vertex, ch.floor_edge, true);
    const Chain ceiling = chain(ch.ceiling, ch.ceiling_vertex, ch.ceiling_edge, false);
    const auto xs = lap_positions(floor.pts.front().x(), floor.pts.back().x());
    bool up = true;
    Foot prev_lo{}, prev_hi{};
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const Foot lo = foot(cell, floor, xs[k], true), hi = foot(cell, ceiling, xs[k], false);
      if (k == 0) {
        transit(up ? lo.p : hi.p);
        if (up) add(floor, lo);
        else add(ceiling, hi);
      } else if (up) {
        walk(floor, prev_lo, lo);  // the previous lap went down: follow the floor
      } else {
        walk(ceiling, prev_hi, hi);
      }
      if (up) add(ceiling, hi);
      else add(floor, lo);
      ++laps;
      up = !up;
      prev_lo = lo, prev_hi = hi;
    }
  }

  // Travel to `to` through the trapezoids (waypoints only: the caller adds `to` itself,
  // with what it knows about it).
  void transit(const Point& to) {
    if (path.empty() || path.back().p == to) return;
    // Midpoints and centroids are collision-free as they are; shortening would cost O(n)
    // exact visibility tests per point, on every transit.
    const Plan p = planner.plan(path.back().p, to, false);
    for (std::size_t i = 1; i + 1 < p.path.size(); ++i) add(p.path[i]);
  }
};

// Nearest point of input edge e to p, exactly, rounded to a corner of its ulp box that lies
// in closed free space (one does unless free space is thinner than an ulp there).
std::optional<Point> onto_edge(const Environment& env, std::size_t e, const Point& p) {
  const ExactPoint& a = env.exact_vertex(e);
  const ExactPoint& c = env.exact_vertex(env.next(e));
  const auto d = c - a;
  ExactFT t = ((geometry::to_exact(p) - a) * d) / d.squared_length();
  t = CGAL::max(ExactFT(0), CGAL::min(ExactFT(1), t));
  const ExactPoint on = a + t * d;
  const auto ix = CGAL::to_interval(on.x()), iy = CGAL::to_interval(on.y());
  for (double x : {ix.first, ix.second})
    for (double y : {iy.first, iy.second})
      if (geometry::locate(env, Point(x, y)).in_free_space()) return Point(x, y);
  return std::nullopt;
}

// Input-frame point for a sweep-frame path point: environment vertices exactly; a point on
// an environment edge becomes the exact nearest point of the same input edge, rounded into
// free space; other points (transit waypoints) are rotated back and, if rounding left free
// space (a waypoint in a sliver trapezoid that hugs a wall), moved onto the nearest edge
// the same way. Quarter turns map back exactly.
Point to_input_point(const BoustrophedonDecomposition& b, const Environment& env, const PathPoint& q) {
  if (q.vertex != CellChains::kNoVertex) return b.input_vertex(q.vertex);
  const Point p = b.to_input(q.p);
  if (std::fmod(b.angle(), 90.0) == 0) return p;
  std::optional<Point> out;
  if (q.edge != CellChains::kNoVertex) {
    out = onto_edge(env, b.input_vertex_id(q.edge), p);
  } else if (geometry::locate(env, p).in_free_space()) {
    out = p;
  } else {
    std::size_t nearest = 0;
    double best = INFINITY;
    for (std::size_t e = 0; e < env.num_vertices(); ++e) {
      const double d = CGAL::to_double(CGAL::squared_distance(p, geometry::Kernel::Segment_2(env.vertex(e), env.vertex(env.next(e)))));
      if (d < best) best = d, nearest = e;
    }
    out = onto_edge(env, nearest, p);
  }
  if (out) return *out;
  throw std::logic_error("coverage: path point " + geometry::format_point(p) + " rotated back from the sweep frame is outside free space");
}

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
  if (start_sweep) bl.add(*start_sweep);
  for (auto k : order) bl.cover(k);

  // Certified output (every segment in closed free space, exactly) — first in the sweep
  // frame, where the path was built: a failure there is a bug.
  const Environment& swept = b.sweep_environment();
  for (std::size_t i = 0; i + 1 < bl.path.size(); ++i)
    if (!geometry::visible(swept, bl.path[i].p, bl.path[i + 1].p))
      throw std::logic_error("coverage: segment " + std::to_string(i) + " " + geometry::format_point(bl.path[i].p) + " -> " +
                             geometry::format_point(bl.path[i + 1].p) + " leaves free space in the sweep frame");
  // Then in the input frame. Quarter turns map back exactly; at other angles rounding can
  // move a point hugging a wall by an ulp, and such a segment is replaced by a shortest
  // path between its ends, which must itself pass.
  std::vector<Point> input;
  input.reserve(bl.path.size());
  for (const auto& q : bl.path) input.push_back(to_input_point(b, env, q));
  if (o.start) input.front() = *o.start;  // exactly where the robot stands
  std::vector<Point> certified;
  std::optional<TrapezoidalDecomposition> input_trap;
  std::optional<TrapezoidalPlanner> input_planner;
  std::size_t repaired = 0;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (i > 0 && !geometry::visible(env, certified.back(), input[i])) {
      if (std::fmod(angle, 90.0) == 0)
        throw std::logic_error("coverage: segment " + geometry::format_point(certified.back()) + " -> " + geometry::format_point(input[i]) +
                               " leaves free space at a quarter-turn sweep");
      if (!input_planner) input_trap.emplace(env), input_planner.emplace(*input_trap);
      const Plan detour = input_planner->plan(certified.back(), input[i], true);
      for (std::size_t j = 1; j + 1 < detour.path.size(); ++j) {
        if (!geometry::visible(env, certified.back(), detour.path[j]))
          throw std::logic_error("coverage: detour around a rounded segment leaves free space");
        certified.push_back(detour.path[j]);
      }
      if (!geometry::visible(env, certified.back(), input[i]))
        throw std::logic_error("coverage: detour around a rounded segment leaves free space");
      ++repaired;
    }
    if (certified.empty() || certified.back() != input[i]) certified.push_back(input[i]);
  }

  CoverageReport rep;
  rep.angle = angle;
  rep.cell_order = order;
  rep.cells = b.cells().size();
  rep.critical_points = b.critical_slices().size();
  rep.laps = bl.laps;
  rep.rounding_detours = repaired;
  rep.path = std::move(certified);
  for (std::size_t i = 0; i + 1 < rep.path.size(); ++i)
    rep.length += std::sqrt(CGAL::to_double(CGAL::squared_distance(rep.path[i], rep.path[i + 1])));
  for (std::size_t i = 1; i + 1 < rep.path.size(); ++i)
    rep.turns += geometry::orientation(rep.path[i - 1], rep.path[i], rep.path[i + 1]) != 0;
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
