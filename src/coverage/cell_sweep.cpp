// SPDX-License-Identifier: Apache-2.0
#include "cell_sweep.hpp"

#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace preimage::coverage::detail {

namespace {

// A cell's floor or ceiling as a polyline of doubles in sweep coordinates. Environment
// vertices are exact; points inside an edge are rounded into the cell (a floor up, a
// ceiling down), so every point lies in the closed cell and the path can be certified.
struct Chain {
  std::vector<Point> pts;
  std::vector<std::uint32_t> vertex, edge;
};

// Where a lap at abscissa x meets a chain: after point k (the last with x_k <= x); on k
// itself when x_k == x (at a wall on the slice line: the last of its points), else inside
// segment k -> k+1, on environment edge `edge`.
struct Foot {
  std::size_t k;
  bool at_point;
  Point p;
  std::uint32_t edge;
};

Chain make_chain(const BoustrophedonDecomposition& b, const std::vector<ExactPoint>& pts, const std::vector<std::uint32_t>& ids,
                 const std::vector<std::uint32_t>& edges, bool floor) {
  Chain c;
  c.edge = edges, c.vertex = ids;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (ids[i] != CellChains::kNoVertex) {
      c.pts.push_back(b.sweep_environment().vertex(ids[i]));
    } else {
      const auto iy = CGAL::to_interval(pts[i].y());
      c.pts.emplace_back(CGAL::to_double(pts[i].x()), floor ? iy.second : iy.first);
    }
  }
  return c;
}

struct Sweeper {
  const BoustrophedonDecomposition& b;
  const std::vector<std::uint32_t>& trapezoids;  // the region's, left to right
  std::vector<SweepPoint> out;

  void add(const Point& p, Move m, std::uint32_t vertex = CellChains::kNoVertex, std::uint32_t edge = CellChains::kNoVertex) {
    if (out.empty() || out.back().p != p) out.push_back({p, vertex, edge, m});
  }
  void add(const Chain& c, std::size_t i, Move m) { add(c.pts[i], m, c.vertex[i], c.edge[i]); }
  void add(const Chain& c, const Foot& f, Move m) {
    if (f.at_point) add(c, f.k, m);
    else add(f.p, m, CellChains::kNoVertex, f.edge);
  }
  // Trapezoid of the region whose x-range holds x (x is not an event there).
  std::uint32_t at(double x) const {
    const auto& T = b.trapezoids().cells();
    for (auto t : trapezoids)
      if (T[t].x_left <= x && x <= T[t].x_right) return t;
    return trapezoids.back();
  }
  Foot foot(const Chain& c, double x, bool floor) const {
    auto it = std::upper_bound(c.pts.begin(), c.pts.end(), x, [](double v, const Point& p) { return v < p.x(); });
    const std::size_t k = static_cast<std::size_t>(it - c.pts.begin()) - 1;  // x >= the chain's first abscissa
    if (c.pts[k].x() == x) return {k, true, c.pts[k], c.edge[k]};
    const auto& T = b.trapezoids().cells()[at(x)];
    const std::uint32_t e = floor ? T.floor : T.ceiling;
    const auto iy = CGAL::to_interval(b.trapezoids().edge_y(e, x));
    return {k, false, Point(x, floor ? iy.second : iy.first), e};
  }
  // Boundary following along a chain from one foot to another, through every chain point
  // between them (walls on slice lines included).
  void walk(const Chain& c, const Foot& from, const Foot& to) {
    if (to.k > from.k) {
      for (std::size_t i = from.k + 1; i <= to.k; ++i) add(c, i, Move::Follow);
    } else if (to.k < from.k) {
      for (std::size_t i = from.at_point ? from.k - 1 : from.k; i > to.k; --i) add(c, i, Move::Follow);
    }
    add(c, to, Move::Follow);
  }
};

// Where the laps go. At most w apart (so every point farther than w/2 from the boundary is
// within w/2 of a lap), and placed so that the boundary itself is covered too: where a wall
// lies on a slice line inside the cell, or the floor or ceiling climbs steeply between two
// laps, the region next to it is within w/2 of no lap unless one is put there. Greedy from
// the left: the leftmost boundary sample not yet within w/2 of a lap gets the rightmost lap
// position (no farther than w from the previous one) that covers it. The samples are the
// chains' points, points every w/4 along them, and the cell's two sides. Floating point:
// this is where coverage is measured, not where safety is decided.
// y of a chain at x, interpolated in double (at a wall on the slice line: its last point).
double chain_y(const Chain& c, double x) {
  auto it = std::upper_bound(c.pts.begin(), c.pts.end(), x, [](double v, const Point& p) { return v < p.x(); });
  if (it == c.pts.begin()) return c.pts.front().y();
  const std::size_t k = static_cast<std::size_t>(it - c.pts.begin()) - 1;
  if (c.pts[k].x() == x || k + 1 == c.pts.size()) return c.pts[k].y();
  const Point &a = c.pts[k], &b = c.pts[k + 1];
  return a.y() + (x - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
}

std::vector<double> lap_positions(const Chain& floor, const Chain& ceiling, double w, std::size_t* left_out = nullptr) {
  const double xl = floor.pts.front().x(), xr = floor.pts.back().x(), half = w / 2;
  std::vector<Point> samples;
  for (const Chain* c : {&floor, &ceiling})
    for (std::size_t i = 0; i < c->pts.size(); ++i) {
      samples.push_back(c->pts[i]);
      if (i + 1 == c->pts.size()) break;
      const Point &a = c->pts[i], &z = c->pts[i + 1];
      const std::size_t k = static_cast<std::size_t>(std::hypot(z.x() - a.x(), z.y() - a.y()) / (w / 4));
      for (std::size_t j = 1; j <= k; ++j) {
        const double t = static_cast<double>(j) / static_cast<double>(k + 1);
        samples.emplace_back(a.x() + t * (z.x() - a.x()), a.y() + t * (z.y() - a.y()));
      }
    }
  for (const auto& [x, lo, hi] : {std::tuple{xl, floor.pts.front().y(), ceiling.pts.front().y()},
                                  std::tuple{xr, floor.pts.back().y(), ceiling.pts.back().y()}}) {
    const std::size_t k = static_cast<std::size_t>((hi - lo) / (w / 4));
    for (std::size_t j = 1; j <= k; ++j) samples.emplace_back(x, lo + (hi - lo) * static_cast<double>(j) / static_cast<double>(k + 1));
  }
  std::sort(samples.begin(), samples.end(), [](const Point& a, const Point& b) { return a.x() < b.x(); });
  const double tol = 1e-9 * (half + std::fabs(xl) + std::fabs(xr));
  auto covers = [&](double x, const Point& v) {
    const double lo = chain_y(floor, x), hi = chain_y(ceiling, x);
    const double dy = std::max({0.0, lo - v.y(), v.y() - hi});
    return std::hypot(x - v.x(), dy) <= half + tol;
  };
  // Laps stay at least w/2 inside the cell's ends (at its middle when it is narrower than
  // w): a lap at an end where floor and ceiling meet would be a point.
  const double inset = std::min(half, (xr - xl) / 2), first_x = xl + inset, last_x = xr - inset;
  // Interval stabbing: each sample is covered by laps in some range of abscissae; taken in
  // order of the right end of their range, an uncovered sample gets a lap at that right end
  // (the greedy that stabs intervals with the fewest points).
  std::vector<std::pair<double, std::size_t>> by_right;
  if (left_out) *left_out = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Point& v = samples[i];
    const double hi = std::min(v.x() + half, last_x), lo = std::max(v.x() - half, first_x);
    for (int step = 0; step <= 32 && hi >= lo; ++step) {
      const double x = hi - (hi - lo) * step / 32;
      if (covers(x, v)) {
        by_right.emplace_back(x, i);
        break;
      }
    }  // a sample no lap covers (met by the slice only at an end of the cell) is left out
    if (left_out && (by_right.empty() || by_right.back().second != i)) ++*left_out;
  }
  std::sort(by_right.begin(), by_right.end());
  // Left to right: the next lap goes at the earliest right end among the samples still
  // uncovered, or w after the previous lap if that comes first (so laps are at most w
  // apart and every point farther than w/2 from the boundary is covered too).
  std::vector<double> xs;
  std::vector<char> done(samples.size(), 0);
  double last = xl - half;  // a virtual lap: the first real one is at most w/2 inside
  std::size_t next = 0;
  while (true) {
    while (next < by_right.size() && (done[by_right[next].second] || by_right[next].first <= last)) ++next;
    if (next == by_right.size()) break;
    const double x = std::max(std::min(by_right[next].first, last + w), std::nextafter(last, INFINITY));
    xs.push_back(x);
    last = x;
    // A sample this lap covers is within w/2 of it, so its range ends by x + w: stop there
    // (scanning to the end made many laps quadratic).
    for (std::size_t k = next; k < by_right.size() && by_right[k].first <= x + w + tol; ++k) {
      const std::size_t i = by_right[k].second;
      if (!done[i] && std::fabs(samples[i].x() - x) <= half + tol && covers(x, samples[i])) done[i] = 1;
    }
  }
  if (xs.empty()) xs.push_back(first_x);
  return xs;
}

}  // namespace

std::vector<SweepPoint> sweep_cell(const BoustrophedonDecomposition& b, const std::vector<std::uint32_t>& trapezoids, double w,
                                   bool from_right, bool first_down, std::size_t* laps) {
  const CellChains ch = b.chains(trapezoids);
  const Chain floor = make_chain(b, ch.floor, ch.floor_vertex, ch.floor_edge, true);
  const Chain ceiling = make_chain(b, ch.ceiling, ch.ceiling_vertex, ch.ceiling_edge, false);
  Sweeper s{b, trapezoids, {}};
  std::vector<double> xs = lap_positions(floor, ceiling, w);
  if (from_right) std::reverse(xs.begin(), xs.end());
  bool up = !first_down;
  Foot prev_lo{}, prev_hi{};
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const Foot lo = s.foot(floor, xs[k], true), hi = s.foot(ceiling, xs[k], false);
    if (k == 0) {
      if (up) s.add(floor, lo, Move::Transit);
      else s.add(ceiling, hi, Move::Transit);
    } else if (up) {
      s.walk(floor, prev_lo, lo);  // the previous lap went down: follow the floor
    } else {
      s.walk(ceiling, prev_hi, hi);
    }
    if (up) s.add(ceiling, hi, Move::Lap);
    else s.add(floor, lo, Move::Lap);
    up = !up;
    prev_lo = lo, prev_hi = hi;
  }
  if (laps) *laps = xs.size();
  return std::move(s.out);
}

std::vector<double> lap_positions(const BoustrophedonDecomposition& b, const std::vector<std::uint32_t>& trapezoids, double w,
                                  std::size_t* left_out) {
  const CellChains ch = b.chains(trapezoids);
  return lap_positions(make_chain(b, ch.floor, ch.floor_vertex, ch.floor_edge, true),
                       make_chain(b, ch.ceiling, ch.ceiling_vertex, ch.ceiling_edge, false), w, left_out);
}

double Polyline::length() const {
  double l = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) l += std::hypot(points[i + 1].x() - points[i].x(), points[i + 1].y() - points[i].y());
  return l;
}

void Polyline::append(const Point& p, Move m) {
  if (!points.empty() && points.back() == p) return;
  if (!points.empty()) moves.push_back(m);
  points.push_back(p);
}

namespace {

// Nearest point of edge e of env to p, exactly, rounded to a corner of its ulp box that
// lies in closed free space (one does unless free space is thinner than an ulp there).
std::optional<Point> onto_edge(const Environment& env, const geometry::VisibilityIndex& index, std::size_t e, const Point& p) {
  const ExactPoint& a = env.exact_vertex(e);
  const ExactPoint& c = env.exact_vertex(env.next(e));
  const auto d = c - a;
  ExactFT t = ((geometry::to_exact(p) - a) * d) / d.squared_length();
  t = CGAL::max(ExactFT(0), CGAL::min(ExactFT(1), t));
  const ExactPoint on = a + t * d;
  const auto ix = CGAL::to_interval(on.x()), iy = CGAL::to_interval(on.y());
  for (double x : {ix.first, ix.second})
    for (double y : {iy.first, iy.second})
      if (index.in_free_space(Point(x, y))) return Point(x, y);
  return std::nullopt;
}

// Input-frame point for a sweep-frame point: environment vertices exactly; a point on an
// environment edge becomes the exact nearest point of the same input edge, rounded into
// free space; other points are rotated back and, if rounding left free space (a point in a
// sliver hugging a wall), moved onto the nearest edge the same way.
Point to_input_point(const BoustrophedonDecomposition& b, const Environment& env, const geometry::VisibilityIndex& index,
                     const SweepPoint& q) {
  if (q.vertex != CellChains::kNoVertex) return b.input_vertex(q.vertex);
  const Point p = b.to_input(q.p);
  if (std::fmod(b.angle(), 90.0) == 0) return p;
  std::optional<Point> out;
  if (q.edge != CellChains::kNoVertex) {
    out = onto_edge(env, index, b.input_vertex_id(q.edge), p);
  } else if (index.in_free_space(p)) {
    out = p;
  } else {
    std::size_t nearest = 0;
    double best = INFINITY;
    for (std::size_t e = 0; e < env.num_vertices(); ++e) {
      const double d = CGAL::to_double(CGAL::squared_distance(p, geometry::Kernel::Segment_2(env.vertex(e), env.vertex(env.next(e)))));
      if (d < best) best = d, nearest = e;
    }
    out = onto_edge(env, index, nearest, p);
  }
  if (out) return *out;
  throw std::logic_error("coverage: path point " + geometry::format_point(p) + " rotated back from the sweep frame is outside free space");
}

}  // namespace

Polyline to_input_frame(const BoustrophedonDecomposition& b, const Environment& env, const std::vector<SweepPoint>& pts,
                        const geometry::VisibilityIndex& index, const geometry::VisibilityGraph& graph,
                        const geometry::VisibilityIndex* sweep_index) {
  const bool quarter = std::fmod(b.angle(), 90.0) == 0;
  if (!quarter && sweep_index)
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
      if (!sweep_index->visible(pts[i].p, pts[i + 1].p))
        throw std::logic_error("coverage: segment " + geometry::format_point(pts[i].p) + " -> " + geometry::format_point(pts[i + 1].p) +
                               " leaves free space in the sweep frame");
  Polyline out;
  for (const auto& q : pts) {
    const Point p = to_input_point(b, env, index, q);
    if (!out.points.empty() && !index.visible(out.points.back(), p)) {
      if (quarter)
        throw std::logic_error("coverage: segment " + geometry::format_point(out.points.back()) + " -> " + geometry::format_point(p) +
                               " leaves free space at a quarter-turn sweep");
      const auto detour = graph.shortest_path(out.points.back(), p);
      if (!detour.found) throw std::logic_error("coverage: no detour around a rounded segment");
      for (std::size_t j = 1; j + 1 < detour.points.size(); ++j) out.append(detour.points[j], q.move);
      ++out.detours;
    }
    out.append(p, q.move);
  }
  return out;
}

}  // namespace preimage::coverage::detail
