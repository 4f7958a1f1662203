// SPDX-License-Identifier: Apache-2.0
// Coverage for a tethered robot (6.2.3, Fig. 6.18): the tether is fed out by the tool width
// and the robot sweeps each curve of constant tether length — a wave front h = λ of the
// geodesic distance from the anchor (geometry::ShortestPathMap on the configuration space).
//
// Fronts at λ = w/2 + k w are traced by marching squares over exact-root samples of h
// (spacing w/8; a drawing of where to drive, decided by nothing); the levels run outwards
// (the tether only lengthens), each level's arcs nearest first, and every segment is
// certified like every other pattern's (a straight move where it is free and r from the
// walls, else the shortest path there).
#include "coverage_internal.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/shortest_path_map.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

namespace preimage::coverage::detail {

namespace {

// The grid cells (j C + i, row-major) each level crosses, levels[k] ascending: a cell whose
// four samples are finite is crossed by every level in (min, max] of them, the levels
// marching squares would find there. Scanning the whole grid per level (266 levels of 2 M
// cells on office 848 at w 0.3) was a quarter of the pattern's time.
std::vector<std::vector<std::size_t>> crossed_cells(const geometry::ShortestPathMap::Samples& S, const std::vector<double>& levels) {
  const std::size_t C = S.columns, R = S.rows;
  std::vector<std::vector<std::size_t>> out(levels.size());
  for (std::size_t j = 0; j + 1 < R; ++j)
    for (std::size_t i = 0; i + 1 < C; ++i) {
      const double v[4] = {S.at(i, j).distance, S.at(i + 1, j).distance, S.at(i + 1, j + 1).distance, S.at(i, j + 1).distance};
      if (!(std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) && std::isfinite(v[3]))) continue;
      const double lo = std::min({v[0], v[1], v[2], v[3]}), hi = std::max({v[0], v[1], v[2], v[3]});
      const auto first = std::upper_bound(levels.begin(), levels.end(), lo), last = std::upper_bound(levels.begin(), levels.end(), hi);
      for (auto k = first; k < last; ++k) out[static_cast<std::size_t>(k - levels.begin())].push_back(j * C + i);
    }
  return out;
}

// Contours of h = lam on the sample grid through `cells` (those it crosses, row-major), as
// polylines (marching squares; the ambiguous saddle cells split by the cell's mean).
std::vector<std::vector<Point>> front_polylines(const geometry::ShortestPathMap::Samples& S, double lam,
                                                const std::vector<std::size_t>& cells) {
  const std::size_t C = S.columns;
  auto value = [&](std::size_t i, std::size_t j) { return S.at(i, j).distance; };
  // crossing ids: horizontal edge (i, j)-(i+1, j) -> 2 (j C + i), vertical (i, j)-(i, j+1) -> 2 (j C + i) + 1
  std::map<std::size_t, Point> at;
  std::map<std::size_t, std::vector<std::size_t>> links;
  auto crossing = [&](std::size_t i0, std::size_t j0, std::size_t i1, std::size_t j1) {
    const std::size_t id = 2 * (j0 * C + i0) + (j1 != j0 ? 1 : 0);
    if (!at.count(id)) {
      const double a = value(i0, j0), b = value(i1, j1), t = std::clamp((lam - a) / (b - a), 0.0, 1.0);
      const Point p = S.point(i0, j0), q = S.point(i1, j1);
      at.emplace(id, Point(p.x() + t * (q.x() - p.x()), p.y() + t * (q.y() - p.y())));
    }
    return id;
  };
  for (const std::size_t cell : cells) {
    const std::size_t i = cell % C, j = cell / C;
    const double v[4] = {value(i, j), value(i + 1, j), value(i + 1, j + 1), value(i, j + 1)};  // finite: crossed_cells
    // corners counter-clockwise from (i, j); edges 0: bottom, 1: right, 2: top, 3: left
    const int mask = (v[0] >= lam) | (v[1] >= lam) << 1 | (v[2] >= lam) << 2 | (v[3] >= lam) << 3;
    if (mask == 0 || mask == 15) continue;
    auto edge = [&](int e) {
      switch (e) {
        case 0: return crossing(i, j, i + 1, j);
        case 1: return crossing(i + 1, j, i + 1, j + 1);
        case 2: return crossing(i, j + 1, i + 1, j + 1);
        default: return crossing(i, j, i, j + 1);
      }
    };
    auto link = [&](int e0, int e1) {
      const std::size_t a = edge(e0), b = edge(e1);
      links[a].push_back(b), links[b].push_back(a);
    };
    // edges crossed: between corners k and k+1 (edge k) where the sides differ
    std::vector<int> crossed;
    for (int k = 0; k < 4; ++k)
      if (((mask >> k) & 1) != ((mask >> ((k + 1) % 4)) & 1)) crossed.push_back(k);
    if (crossed.size() == 2) {
      link(crossed[0], crossed[1]);
    } else {
      // a saddle cell: pair each high corner with its neighbours unless the mean is high
      const bool high_centre = (v[0] + v[1] + v[2] + v[3]) / 4 >= lam;
      const bool c0_high = mask & 1;
      if (c0_high != high_centre) link(3, 0), link(1, 2);
      else link(0, 1), link(2, 3);
    }
  }
  std::vector<std::vector<Point>> out;
  std::map<std::size_t, char> used;
  auto walk = [&](std::size_t start) {
    std::vector<Point> line{at.at(start)};
    used[start] = 1;
    std::size_t cur = start;
    for (;;) {
      std::size_t next = SIZE_MAX;
      for (const std::size_t n : links[cur])
        if (!used[n]) next = n;
      if (next == SIZE_MAX) break;
      used[next] = 1;
      line.push_back(at.at(next));
      cur = next;
    }
    return line;
  };
  for (const auto& [id, nb] : links)  // open lines first, from an end
    if (nb.size() == 1 && !used[id]) out.push_back(walk(id));
  for (const auto& [id, nb] : links)  // then loops
    if (!used[id]) {
      auto line = walk(id);
      line.push_back(line.front());
      out.push_back(std::move(line));
    }
  return out;
}

}  // namespace

CoverageReport plan_wavefront(const Planning& P) {
  if (!P.start) throw InputError("coverage: the wavefront pattern needs a start (the tether's anchor): --start X,Y");
  const geometry::ShortestPathMap spm(P.graph, *P.start);
  const double w = P.w;
  const auto box = P.E.bbox();
  const auto columns = static_cast<std::size_t>(std::ceil((box.xmax() - box.xmin()) / (w / 8))) + 1;
  if (columns > 4000) throw InputError("coverage: the wavefront pattern samples h every w/8; this width needs more than 4000 columns");
  const auto S = spm.sample(columns);
  double top = 0;
  for (const auto& q : S.values)
    if (std::isfinite(q.distance)) top = std::max(top, q.distance);
  std::vector<double> levels;
  for (double lam = w / 2; lam < top; lam += w) levels.push_back(lam);
  const auto crossed = crossed_cells(S, levels);

  Polyline start_path;
  if (P.o.start) start_path.append(*P.o.start, Move::Transit);
  if (start_path.points.empty() || *P.start != start_path.points.back()) start_path.append(*P.start, Move::Transit);
  PathBuilder builder{P, std::move(start_path), 0};
  Polyline& path = builder.path;
  std::size_t laps = 0;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    auto arcs = front_polylines(S, levels[k], crossed[k]);
    while (!arcs.empty()) {
      const Point here = path.points.back();
      std::size_t best = 0;
      double bd = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < arcs.size(); ++i)
        for (const Point* q : {&arcs[i].front(), &arcs[i].back()})
          if (const double d = planar_distance(*q, here); d < bd) bd = d, best = i;
      auto arc = std::move(arcs[best]);
      arcs.erase(arcs.begin() + static_cast<std::ptrdiff_t>(best));
      if (planar_distance(arc.back(), here) < planar_distance(arc.front(), here)) std::reverse(arc.begin(), arc.end());
      // An open front ends within a sample step of the boundary: carry it on to the wall
      // (at most w/4), or the strip along the wall between fronts stays uncovered.
      if (arc.size() >= 2 && arc.front() != arc.back()) {
        auto extend = [&](const Point& a, const Point& b) -> std::optional<Point> {
          if (!P.index.in_free_space(b) || a == b) return std::nullopt;
          const auto hit = geometry::shoot_ray(P.E, b, Point(2 * b.x() - a.x(), 2 * b.y() - a.y()));
          if (!hit) return std::nullopt;
          const Point h = geometry::to_double(hit->point);
          const double d = planar_distance(b, h), t = std::min(0.999 * d, w / 4);
          if (!(t > 0)) return std::nullopt;
          return Point(b.x() + (h.x() - b.x()) * t / d, b.y() + (h.y() - b.y()) * t / d);
        };
        if (const auto e = extend(arc[1], arc[0])) arc.insert(arc.begin(), *e);
        if (const auto e = extend(arc[arc.size() - 2], arc.back())) arc.push_back(*e);
      }
      bool first = true;
      for (const Point& p : arc) {
        if (!P.index.in_free_space(p)) continue;
        builder.go(p, first ? Move::Transit : Move::Lap);
        first = false;
      }
      laps += !first;
    }
  }
  // No front fits: the tool standing at the anchor is the whole path when its disc holds
  // every vertex of the free space, hence (a disc is convex) all of it; decided exactly.
  if (laps == 0) {
    const geometry::ExactFT r2 = geometry::ExactFT(w / 2) * geometry::ExactFT(w / 2);
    const auto anchor = geometry::to_exact(*P.start);
    for (std::size_t v = 0; v < P.E.num_vertices(); ++v)
      if (CGAL::compare_squared_distance(anchor, geometry::to_exact(P.E.vertex(v)), r2) == CGAL::LARGER)
        throw InputError("coverage: no wave front fits in the free space at this width");
  }

  CoverageReport rep;
  finish_path(P, std::move(path), rep);
  rep.rounding_detours = builder.detours;
  rep.laps = laps;
  rep.cells = spm.num_reached() + 1;  // the regions of the shortest path map (roots)
  // A count for the report: the bends' extensions without locating their collisions (the
  // bisection's point queries were most of this pattern's time on a 1,000-vertex plan).
  rep.critical_points = spm.num_extensions() + spm.collisions().size();
  return rep;
}

}  // namespace preimage::coverage::detail
