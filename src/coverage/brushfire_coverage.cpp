// SPDX-License-Identifier: Apache-2.0
// The brushfire coverage pattern (6.2.3, Fig. 6.17): the robot keeps a fixed distance from
// the obstacle boundary (a slice of D, an offset curve) and steps inwards by the tool width,
// then follows the generalized Voronoi diagram where the fronts meet.
//
// On the configuration space E: laps are the slices D = w/2 + k w of E's distance
// function, so that every flow line of D (from the boundary to the medial axis) is crossed
// by a lap every w below its top; the part of a flow line above its last lap is shorter
// than w, and within w/2 of the axis where it is longer than w/2 — there the robot follows
// the axis. Cells (the brushfire decomposition of E) are visited in 6.2.1's depth-first
// order over their adjacency graph; inside a cell the laps run outwards-in (ascending D),
// then the axis pieces, nearest first.
#include "coverage_internal.hpp"

#include <preimage/decompose/brushfire.hpp>
#include <preimage/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace preimage::coverage::detail {

CoverageReport plan_brushfire(const Planning& P) {
  const BrushfireDecomposition bd(P.E);
  const double w = P.w;
  const auto box = P.E.bbox();
  const double scale = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  const double sag = std::min(w / 20, 1e-3 * scale);
  double top = 0;
  for (const auto& v : bd.gvd().medial_vertices()) top = std::max(top, v.clearance);

  struct Lap {
    std::vector<Point> pts;
    bool loop;
  };
  const std::size_t n = bd.cells().size();
  std::vector<std::vector<Lap>> laps(n);
  for (double lam = w / 2; lam < top; lam += w)
    for (auto& c : bd.level_curves(lam, sag)) laps[c.cell].push_back({std::move(c.points), true});
  // The axis where the flow line's part above its last lap is longer than w/2 (or no lap
  // crosses it): followed as whole runs of the axis with D >= w/4 (a run's gaps, where the
  // laps alone would do, cost less to drive along than to transit around), so that a cell's
  // axis is a few chains rather than many fragments.
  auto needs_axis = [&](double d) {
    if (d <= w / 2) return true;
    // height of the flow line above its last lap; a lap exactly at D(m) does not exist (the
    // slice at the axis' own level is the axis), so a remainder of 0 is a whole w. The
    // margins keep rasterised coverage from missing the laps' outer edges.
    const double rem = std::fmod(d - w / 2, w);
    return rem < w / 20 || rem > 0.4 * w;
  };
  std::vector<std::vector<Lap>> axis(n);
  for (const auto& piece : bd.axis_pieces()) {
    bool wanted = false;
    for (const double d : piece.clearance) wanted = wanted || (d >= w / 4 && needs_axis(d));
    if (!wanted) continue;
    Lap run{{}, false};
    for (std::size_t k = 0; k < piece.points.size(); ++k) {
      if (piece.clearance[k] >= w / 4) {
        run.pts.push_back(piece.points[k]);
      } else if (!run.pts.empty()) {
        if (run.pts.size() >= 2) axis[piece.cell].push_back(std::move(run));
        run = {{}, false};
      }
    }
    if (run.pts.size() >= 2) axis[piece.cell].push_back(std::move(run));
  }
  // Runs that meet end to end (at an axis vertex) become one chain: greedy, from each run
  // on through any unused run starting or ending where it ends.
  for (auto& runs : axis) {
    if (runs.size() < 2) continue;
    std::map<std::pair<double, double>, std::vector<std::size_t>> at_end;
    auto key = [](const Point& p) { return std::make_pair(p.x(), p.y()); };
    for (std::size_t i = 0; i < runs.size(); ++i) at_end[key(runs[i].pts.front())].push_back(i), at_end[key(runs[i].pts.back())].push_back(i);
    std::vector<char> used(runs.size(), 0);
    std::vector<Lap> chains;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (used[i]) continue;
      used[i] = 1;
      std::vector<Point> chain = runs[i].pts;
      for (int side = 0; side < 2; ++side) {
        for (bool grown = true; grown;) {
          grown = false;
          for (const std::size_t j : at_end[key(chain.back())]) {
            if (used[j]) continue;
            auto pts = runs[j].pts;
            if (pts.front() != chain.back()) std::reverse(pts.begin(), pts.end());
            chain.insert(chain.end(), pts.begin() + 1, pts.end());
            used[j] = 1, grown = true;
            break;
          }
        }
        std::reverse(chain.begin(), chain.end());
      }
      // a stub shorter than w/4 (into a corner the first lap cuts) is within the laps' reach
      double len = 0;
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) len += planar_distance(chain[k], chain[k + 1]);
      if (len >= w / 4) chains.push_back({std::move(chain), false});
    }
    runs = std::move(chains);
  }

  // Cell order: the exhaustive walk of the adjacency graph from the cell of the lap nearest
  // the start (the first cell with laps otherwise).
  std::uint32_t first = 0;
  {
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t k = 0; k < n; ++k)
      for (const Lap& l : laps[k])
        for (const Point& p : l.pts) {
          const double d = P.start ? planar_distance(p, *P.start) : 0;
          if (d < best) best = d, first = k;
          if (!P.start) break;
        }
  }
  const std::vector<std::uint32_t> order = depth_first_order(bd.adjacency(), first);

  Polyline start_path;
  if (P.o.start) start_path.append(*P.o.start, Move::Transit);
  if (P.start && (start_path.points.empty() || *P.start != start_path.points.back())) start_path.append(*P.start, Move::Transit);
  PathBuilder builder{P, std::move(start_path), 0};
  Polyline& path = builder.path;
  auto free_point = [&](const Point& p) { return P.index.in_free_space(p); };
  std::size_t lap_count = 0;
  auto run_lap = [&](std::vector<Point> pts, bool loop) {
    // Closed laps start at the point nearest the robot; open ones at their nearer end.
    if (!path.points.empty() && !pts.empty()) {
      const Point here = path.points.back();
      if (loop) {
        std::size_t best = 0;
        double bd2 = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < pts.size(); ++i)
          if (const double d = planar_distance(pts[i], here); d < bd2) bd2 = d, best = i;
        std::rotate(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(best), pts.end());
      } else if (planar_distance(pts.back(), here) < planar_distance(pts.front(), here)) {
        std::reverse(pts.begin(), pts.end());
      }
    }
    if (loop && !pts.empty()) pts.push_back(pts.front());
    bool first_point = true;
    for (const Point& p : pts) {
      if (!free_point(p)) continue;
      builder.go(p, first_point ? Move::Transit : Move::Lap);
      first_point = false;
    }
    if (!first_point) ++lap_count;
  };
  for (const std::uint32_t k : order) {
    for (Lap& lap : laps[k]) run_lap(std::move(lap.pts), true);
    // axis pieces, nearest first
    auto& rest = axis[k];
    while (!rest.empty()) {
      std::size_t best = 0;
      double bd2 = std::numeric_limits<double>::infinity();
      const Point here = path.points.empty() ? rest.front().pts.front() : path.points.back();
      for (std::size_t i = 0; i < rest.size(); ++i)
        for (const Point* q : {&rest[i].pts.front(), &rest[i].pts.back()})
          if (const double d = planar_distance(*q, here); d < bd2) bd2 = d, best = i;
      run_lap(std::move(rest[best].pts), false);
      rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(best));
    }
  }
  if (path.points.empty()) throw InputError("coverage: no lap fits in the free space at this width");

  return pattern_report(P, std::move(path), builder.detours, lap_count, n, bd.num_nodes(), order);
}

}  // namespace preimage::coverage::detail
