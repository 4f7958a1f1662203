// SPDX-License-Identifier: Apache-2.0
#include <preimage/coverage/coverage.hpp>

#include <preimage/decompose/planner.hpp>
#include <preimage/coverage/sweep_order.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/clearance.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/local_frame.hpp>
#include <preimage/geometry/queries.hpp>

#include "cell_directions.hpp"
#include "cell_merging.hpp"
#include "cell_sweep.hpp"
#include "coverage_raster.hpp"
#include "coverage_internal.hpp"

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <set>
#include <tuple>

namespace preimage::coverage {

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

std::string_view to_string(Move m) {
  switch (m) {
    case Move::Lap: return "lap";
    case Move::Follow: return "follow";
    case Move::Transit: return "transit";
    case Move::Turn: return "turn";
  }
  return "?";
}

namespace {

using detail::Planning;
using detail::Polyline;
using geometry::ConfigurationSpace;
using geometry::VisibilityGraph;
using geometry::VisibilityIndex;

double dist(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

using detail::direction_score;

// A region of a boustrophedon decomposition to sweep (a cell, or cells merged into one
// monotone region), with its four sweeps.
struct SweptCell {
  const BoustrophedonDecomposition* dec;
  std::vector<std::uint32_t> trapezoids;
  std::array<Polyline, 4> sweeps;
  std::array<std::size_t, 4> laps;
};

// The four sweeps of a region in the input frame, certified (to_input_frame).
void sweep_four_ways(const Planning& P, SweptCell& s, const geometry::VisibilityIndex* sweep_index) {
  for (std::uint8_t v = 0; v < 4; ++v) {
    const auto pts = detail::sweep_cell(*s.dec, s.trapezoids, P.w, v & 1, v & 2, &s.laps[v]);
    s.sweeps[v] = detail::to_input_frame(*s.dec, P.E, pts, P.index, P.graph, sweep_index);
  }
}

CoverageReport plan_at(const Planning& P, const BoustrophedonDecomposition& b, double angle,
                       const detail::CellDirections* directions, bool merge) {
  const bool quarter = std::fmod(angle, 90.0) == 0;
  std::optional<VisibilityIndex> sweep_index;
  if (!quarter) sweep_index.emplace(b.sweep_environment());
  // The cells to sweep with their four sweeps, in the input frame, certified: b's cells,
  // and with a direction per cell (cell_directions.hpp) the own cells of those turned the
  // other way. A turned cell whose sweeps do not all map back certified (a slice end
  // rounded off a slanted wall) keeps b's direction.
  static const std::vector<detail::TurnedCell> kNoneTurned;
  const auto& turned_cells = directions ? directions->turned : kNoneTurned;
  std::vector<std::size_t> kept;
  if (directions) kept = directions->kept;
  else for (std::size_t c = 0; c < b.cells().size(); ++c) kept.push_back(c);
  std::vector<SweptCell> cells;
  std::size_t turned = 0;
  for (const auto& region : turned_cells) {
    const std::size_t first = cells.size();
    try {
      for (std::size_t k = 0; k < region.dec->cells().size(); ++k) {
        cells.push_back({region.dec.get(), region.dec->cells()[k].trapezoids, {}, {}});
        sweep_four_ways(P, cells.back(), nullptr);
      }
      ++turned;
    } catch (const std::logic_error&) {
      cells.resize(first);
      kept.push_back(region.base_cell);
    }
  }
  // The cells kept at b's direction, merged into monotone regions where that saves laps.
  const auto regions = merge ? detail::merge_monotone_cells(b, kept, P.w) : detail::single_cells(b, kept);
  std::size_t merged = 0;
  for (const auto& region : regions) {
    merged += region.cells.size() - 1;
    cells.push_back({&b, region.trapezoids, {}, {}});
    sweep_four_ways(P, cells.back(), sweep_index ? &*sweep_index : nullptr);
  }
  const std::size_t n = cells.size();
  std::vector<std::vector<Sweep>> options(n);
  std::size_t detours = 0;
  for (std::size_t c = 0; c < n; ++c)
    for (const Polyline& s : cells[c].sweeps) options[c].push_back({s.points.front(), s.points.back(), s.length()});

  // Transits: shortest paths in the component, or (the paper's planner) through the
  // trapezoids of its decomposition.
  std::optional<TrapezoidalDecomposition> trap;
  std::optional<TrapezoidalPlanner> trap_planner;
  if (P.o.transit == Transit::Decomposition) trap.emplace(P.E), trap_planner.emplace(*trap);
  auto transit_path = [&](const Point& a, const Point& z) -> std::vector<Point> {
    if (trap_planner) return trap_planner->plan(a, z, false).path;
    auto sp = P.graph.shortest_path(a, z);
    if (!sp.found) throw std::logic_error("coverage: no transit between two sweeps of one component");
    return sp.points;
  };

  CoverageReport rep;
  std::vector<std::uint32_t> order;
  std::vector<std::uint8_t> chosen;
  if (P.o.order == CellOrder::Optimised) {
    const auto cost = [&](const Point& a, const Point& z) {
      if (a == z) return 0.0;
      if (trap_planner) return trap_planner->plan(a, z, false).length;
      const auto sp = P.graph.shortest_path(a, z);
      return sp.found ? sp.length : std::numeric_limits<double>::infinity();
    };
    const SweepOrder so = order_sweeps(options, P.start, cost);
    order = so.cells, chosen = so.sweeps;
    rep.order_optimal = so.optimal, rep.order_lower_bound = so.lower_bound;
  } else {
    // 6.2.1: depth-first order of the adjacency graph from the start cell, every cell
    // swept left to right, first lap up.
    std::uint32_t first = 0;
    if (P.start) {
      const Point q = b.to_sweep(*P.start);
      double best = std::numeric_limits<double>::infinity();
      for (std::uint32_t c = 0; c < n; ++c) {
        const auto poly = b.polygon(c);
        if (CGAL::bounded_side_2(poly.begin(), poly.end(), *P.start, geometry::Kernel()) != CGAL::ON_UNBOUNDED_SIDE) {
          first = c;
          break;
        }
        const double d = dist(q, b.to_sweep(poly.front()));
        if (d < best) best = d, first = c;
      }
    }
    order = detail::depth_first_order(b.adjacency(), first);
    chosen.assign(order.size(), 0);
  }

  // Assemble: start, then per cell a transit to its sweep's entry and the sweep.
  Polyline path;
  if (P.o.start) path.append(*P.o.start, Move::Transit);
  if (P.start && *P.start != path.points.back()) path.append(*P.start, Move::Transit);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Polyline& s = cells[order[k]].sweeps[chosen[k]];
    if (!path.points.empty())
      for (const Point& p : transit_path(path.points.back(), s.points.front())) path.append(p, Move::Transit);
    path.append(s.points.front(), Move::Transit);
    for (std::size_t i = 1; i < s.points.size(); ++i) path.append(s.points[i], s.moves[i - 1]);
    detours += s.detours;
    rep.laps += cells[order[k]].laps[chosen[k]];
  }
  detail::finish_path(P, std::move(path), rep);
  rep.rounding_detours = detours;
  rep.angle = angle;
  rep.cell_order = order;
  rep.sweeps = chosen;
  rep.cells = n;
  rep.turned_cells = turned;
  rep.merged_cells = merged;
  rep.critical_points = b.critical_slices().size();
  return rep;
}

}  // namespace

// Boundary following, straightened (issue 49: a robot slows down at every turn, and most
// of the turns were the 1 cm jogs of walls): within a run of follow moves, a point is
// skipped when the straight segment past it is certified (inside the component, r from
// every obstacle: exact) and no skipped point lies more than w/8 from it, so corners of
// the room are still followed and only jogs go. Every segment it makes is certified by the
// same test as finish_path's.
void detail::straighten_follows(const Planning& P, Polyline& path) {
  const double tol = P.w / 8;
  auto near_segment = [&](const Point& a, const Point& z, std::size_t from, std::size_t to) {
    const double vx = z.x() - a.x(), vy = z.y() - a.y(), l2 = vx * vx + vy * vy;
    for (std::size_t k = from; k < to; ++k) {
      const Point& p = path.points[k];
      const double t = l2 > 0 ? std::clamp(((p.x() - a.x()) * vx + (p.y() - a.y()) * vy) / l2, 0.0, 1.0) : 0.0;
      if (std::hypot(p.x() - a.x() - t * vx, p.y() - a.y() - t * vy) > tol) return false;
    }
    return true;
  };
  detail::Polyline out;
  out.points.push_back(path.points.front());
  std::size_t i = 0;
  const std::size_t n = path.points.size();
  while (i + 1 < n) {
    if (path.moves[i] != Move::Follow) {
      out.append(path.points[i + 1], path.moves[i]);
      ++i;
      continue;
    }
    std::size_t end = i;  // the run of follow moves i .. end - 1 ends at point `end`
    while (end + 1 < n && path.moves[end] == Move::Follow) ++end;
    // Greedy string pulling from i: the farthest point of the run still reachable straight.
    std::vector<Point> pulled;
    std::size_t a = i;
    while (a < end) {
      std::size_t j = a + 1;
      while (j + 1 <= end && certified(P, path.points[a], path.points[j + 1]) && near_segment(path.points[a], path.points[j + 1], a + 1, j + 1)) ++j;
      pulled.push_back(path.points[j]);
      a = j;
    }
    // A run left with kinks between two laps (a wall drawn in steps: its jogs stick out
    // a few millimetres past the chord) goes straight once both laps stop a little short:
    // the lap ends pulled back along their laps by d (w/64 up to w/8, less than half of
    // either lap) where the chord and both shortened laps are certified and every point of
    // the run is within w/8 of the chord. The wall there stays within w/8 + d <= w/4 of the
    // path, so it is still covered.
    if (pulled.size() > 1 && i > 0 && out.moves.back() == Move::Lap && end + 1 < n && path.moves[end] == Move::Lap) {
      const Point a0 = out.points[out.points.size() - 2], A = path.points[i], B = path.points[end], b1 = path.points[end + 1];
      const double la = dist(a0, A), lb = dist(B, b1);
      for (double d = P.w / 64; d <= P.w / 8 && 2 * d < std::min(la, lb); d *= 2) {
        const Point A2(A.x() + (a0.x() - A.x()) * (d / la), A.y() + (a0.y() - A.y()) * (d / la));
        const Point B2(B.x() + (b1.x() - B.x()) * (d / lb), B.y() + (b1.y() - B.y()) * (d / lb));
        if (certified(P, a0, A2) && certified(P, A2, B2) && certified(P, B2, b1) && near_segment(A2, B2, i, end + 1)) {
          out.points.back() = A2;
          pulled = {B2};
          // the next lap starts at B2: point `end` is replaced
          path.points[end] = B2;
          break;
        }
      }
    }
    for (const Point& q : pulled) out.append(q, Move::Follow);
    i = end;
  }
  path = std::move(out);
}

// Bends merged (issue 49: most turns over 1 degree left were the chords of the
// configuration space's arcs, about 5 degrees each, that transits and follow moves round
// an obstacle's corner on). A run of small turns one way, outside laps, is replaced by the
// tangent polygon of some of its segments: consecutive kept segments' lines meet outside
// the run (away from the obstacle the run bends round), each new corner turning at most
// kBendTurn, so a quarter turn takes 7 turns instead of 18. A new corner is kept only when
// both segments to it are certified (inside the component, r from every obstacle: exact);
// else fewer segments are merged, down to none, and only when the path it adds is at most
// the turn cost (CoverageOptions::turn_cost, metres a turn is worth) per turn it saves:
// with a turn cost of 0 transits stay shortest paths.
constexpr double kBendTurn = 14 * std::numbers::pi / 180;

void detail::merge_bends(const Planning& P, Polyline& path) {
  const std::size_t n = path.points.size();
  if (n < 3 || !(P.o.turn_cost > 0)) return;
  const auto& q = path.points;
  std::vector<double> h(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) h[k] = std::atan2(q[k + 1].y() - q[k].y(), q[k + 1].x() - q[k].x());
  auto turn = [&](std::size_t a, std::size_t b) { return std::remainder(h[b] - h[a], 2 * std::numbers::pi); };
  // Vertex k joins segments k - 1 and k; it may go when both are not laps and it turns
  // less than kBendTurn, the same way as the run.
  auto bendable = [&](std::size_t k, double sign) {
    const double t = turn(k - 1, k);
    return path.moves[k - 1] != Move::Lap && path.moves[k] != Move::Lap && std::fabs(t) < kBendTurn && t * sign > 0 &&
           q[k] != q[k - 1] && q[k + 1] != q[k];
  };
  Polyline out;
  out.points.push_back(q[0]);
  std::size_t k = 1;
  while (k + 1 < n) {
    const double sign = turn(k - 1, k) >= 0 ? 1.0 : -1.0;
    if (!bendable(k, sign)) {
      out.append(q[k], path.moves[k - 1]);
      ++k;
      continue;
    }
    std::size_t j = k;  // the run: vertices k .. j, segments k - 1 .. j
    while (j + 2 < n && bendable(j + 1, sign)) ++j;
    // Greedy from segment c: the farthest segment e whose heading is within kBendTurn and
    // whose line meets c's where both new segments are certified.
    std::size_t c = k - 1;
    Point at = q[k - 1];
    while (c < j) {
      std::size_t e = c + 1;
      Point corner = q[c + 1];
      for (std::size_t f = j; f > c + 1; --f) {
        if (std::fabs(turn(c, f)) >= kBendTurn) continue;
        // Lines of segments c and f: at + s (q[c+1] - q[c]) = q[f] + u (q[f+1] - q[f]).
        const double dx = q[c + 1].x() - q[c].x(), dy = q[c + 1].y() - q[c].y();
        const double ex = q[f + 1].x() - q[f].x(), ey = q[f + 1].y() - q[f].y();
        const double den = dx * ey - dy * ex;
        if (den == 0) continue;
        const double s = ((q[f].x() - q[c].x()) * ey - (q[f].y() - q[c].y()) * ex) / den;
        const Point x(q[c].x() + s * dx, q[c].y() + s * dy);
        double before = dist(at, q[c + 1]);
        for (std::size_t g = c + 1; g <= f; ++g) before += dist(q[g], q[g + 1]);
        const double added = dist(at, x) + dist(x, q[f + 1]) - before;
        if (added > P.o.turn_cost * static_cast<double>(f - c - 1)) continue;
        if (certified(P, at, x) && certified(P, x, q[f + 1])) {
          e = f, corner = x;
          break;
        }
      }
      out.append(corner, path.moves[c]);
      at = corner, c = e;
    }
    k = j + 1;
  }
  out.append(q[n - 1], path.moves[n - 2]);
  path = std::move(out);
}

detail::Uncovered detail::uncovered(const CoverageRaster& R, const Polyline& path, double w) {
  const double half = w / 2;
  Uncovered u;
  u.open.assign(R.target.begin(), R.target.end());
  const std::size_t total = static_cast<std::size_t>(std::count(R.target.begin(), R.target.end(), 1));
  for (std::size_t seg = 0; seg + 1 < std::max<std::size_t>(path.points.size(), 2); ++seg)
    R.capsule(path.points[seg], path.points[std::min(seg + 1, path.points.size() - 1)], half, half, [&](std::size_t id, bool) { u.open[id] = 0; });
  u.left = static_cast<std::size_t>(std::count(u.open.begin(), u.open.end(), 1));
  u.allowed = static_cast<std::size_t>(kTouchUpLeft * static_cast<double>(total));
  return u;
}

std::vector<std::vector<std::size_t>> detail::patches_of(const CoverageRaster& R, const std::vector<char>& open) {
  // Patches: 4-connected uncovered samples, largest first.
  std::vector<std::vector<std::size_t>> patches;
  std::vector<char> seen(open.size(), 0);
  for (std::size_t id = 0; id < open.size(); ++id) {
    if (!open[id] || seen[id]) continue;
    std::vector<std::size_t> patch{id};
    seen[id] = 1;
    for (std::size_t k = 0; k < patch.size(); ++k) {
      const std::size_t c = patch[k], i = c % R.nx, j = c / R.nx;
      for (const std::size_t n : {i > 0 ? c - 1 : c, i + 1 < R.nx ? c + 1 : c, j > 0 ? c - R.nx : c, j + 1 < R.ny ? c + R.nx : c})
        if (open[n] && !seen[n]) seen[n] = 1, patch.push_back(n);
    }
    patches.push_back(std::move(patch));
  }
  std::stable_sort(patches.begin(), patches.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return patches;
}

namespace {

// Touch-ups, after every pattern: what its laps left on the raster of the component (a
// sliver between two offset rings, a corner no front reached) is visited point by point by
// shortest transits, the largest uncovered patches first, until at most kTouchUpLeft of the
// samples is left. A touch-up point is a sample centre in the component, so the robot's
// centre may stand there; it covers the samples within w/2 of it. The pattern's path
// (certified by finish_path), straightened, then touched up; only the touch-ups' transits
// are certified again.
// `raster`: the component's raster when the caller has it (it depends on the component
// and w only, so boustrophedon's candidates share one).
void touch_up(const Planning& P, CoverageReport& rep, const detail::CoverageRaster* raster = nullptr) {
  if (rep.path.empty()) return;
  detail::Polyline path;
  path.points = std::move(rep.path), path.moves = std::move(rep.moves);
  detail::straighten_follows(P, path);
  const std::size_t certified = path.points.size() - 1;
  const double half = P.w / 2;
  std::optional<detail::CoverageRaster> own;
  if (!raster) raster = &own.emplace(P.E, P.index, P.w, 0);
  const detail::CoverageRaster& R = *raster;
  detail::Uncovered u = detail::uncovered(R, path, P.w);
  auto& open = u.open;
  std::size_t& left = u.left;
  const std::size_t allowed = u.allowed;
  const auto patches = detail::patches_of(R, open);
  std::vector<Point> points;
  for (const auto& patch : patches) {
    if (left <= allowed) break;
    for (const std::size_t id : patch) {
      if (!open[id] || left <= allowed) continue;
      const Point q = R.centre(id);
      points.push_back(q);
      R.capsule(q, q, half, half, [&](std::size_t c, bool) {
        if (open[c]) open[c] = 0, --left;
      });
    }
  }
  // Nearest first from the path's end, each by the shortest transit in the component.
  std::vector<char> done(points.size(), 0);
  for (std::size_t n = 0; n < points.size(); ++n) {
    const Point from = path.points.back();
    std::size_t best = points.size();
    double best_d = INFINITY;
    for (std::size_t k = 0; k < points.size(); ++k)
      if (!done[k] && dist(from, points[k]) < best_d) best_d = dist(from, points[k]), best = k;
    done[best] = 1;
    const auto sp = P.graph.shortest_path(from, points[best]);
    if (!sp.found) throw std::logic_error("coverage: no transit to a touch-up point in the component");
    for (std::size_t k = 1; k < sp.points.size(); ++k) path.append(sp.points[k], Move::Transit);
  }
  rep.touch_ups = points.size();
  detail::finish_path(P, std::move(path), rep, certified);
  // Then bends merged; every segment it makes is certified there.
  path.points = std::move(rep.path), path.moves = std::move(rep.moves);
  detail::merge_bends(P, path);
  const std::size_t all = path.points.size();
  detail::finish_path(P, std::move(path), rep, all);
}

// 6.2.1's pattern: the sweep direction given, or the two most promising candidates planned
// and the cheaper path kept. A robot that turns in place gets each candidate touched up
// first (`touched`), so the choice is made on the paths it would drive: on office 848 at
// W = 0.5 the cheaper candidate before the touch-ups (and the bends merged) was the dearer
// after them.
CoverageReport plan_boustrophedon(const Planning& P, bool& touched) {
  // A direction planned: its decomposition and, with a direction per cell, each cell's. A
  // direction per cell where the direction is chosen (auto) and the cells are ordered by
  // the generalised TSP (6.2.1's depth-first walk runs over one decomposition's adjacency).
  struct Direction {
    double score, angle;
    std::unique_ptr<BoustrophedonDecomposition> b;
    std::optional<detail::CellDirections> cells;
  };
  std::vector<Direction> planned;
  const bool per_cell = !P.o.angle_deg && P.o.order == CellOrder::Optimised;
  if (P.o.angle_deg) {
    planned.push_back({0, *P.o.angle_deg, std::make_unique<BoustrophedonDecomposition>(P.E, *P.o.angle_deg), std::nullopt});
  } else {
    // Candidates: the axes and the directions of the longest edges (sweeping along an edge
    // avoids slivers along it); the two that need the fewest laps and cells are planned.
    std::vector<std::pair<double, double>> edges;  // length, angle
    for (std::size_t e = 0; e < P.env.num_vertices(); ++e) {
      const Point &a = P.env.vertex(e), &b = P.env.vertex(P.env.next(e));
      const double deg = std::fmod(std::atan2(b.y() - a.y(), b.x() - a.x()) * 180 / std::numbers::pi + 360.0, 180.0);
      edges.emplace_back(std::hypot(b.x() - a.x(), b.y() - a.y()), deg);
    }
    std::sort(edges.rbegin(), edges.rend());
    std::set<double> candidates{0.0, 90.0};
    for (std::size_t i = 0; i < edges.size() && candidates.size() < 10; ++i) candidates.insert(std::round(edges[i].second * 1e6) / 1e6);
    for (double a : candidates) {
      try {
        Direction d{0, a, std::make_unique<BoustrophedonDecomposition>(P.E, a), std::nullopt};
        if (per_cell) d.cells = detail::choose_directions(*d.b, P.w);
        d.score = d.cells ? d.cells->score : direction_score(*d.b, P.w);
        planned.push_back(std::move(d));
      } catch (const InputError&) {
        // this direction made the rotated environment invalid: skip it
      }
    }
    std::sort(planned.begin(), planned.end(),
              [](const Direction& x, const Direction& y) { return std::tie(x.score, x.angle) < std::tie(y.score, y.angle); });
    if (planned.size() > 2) planned.resize(2);
    if (planned.empty()) throw InputError("coverage: no sweep direction gave a valid decomposition");
  }
  // Each direction with its cells as they are and, with the order optimised, merged into
  // monotone regions where that saves laps (merging can cost order: a region enters and
  // leaves at its two ends only). A turned cell is swept on its own, so where cells were
  // turned the direction is also planned merged without them. Not for a robot with a
  // turning radius: its candidates are compared before the curves, which cut laps back at
  // the steps a merged region's ends make (house 0000, W = 0.5, R = 1: 99.48 % covered).
  const bool merge = P.o.merge_cells && P.o.order == CellOrder::Optimised && P.o.min_turn_radius == 0;
  struct Variant {
    const Direction* d;
    const detail::CellDirections* cells;
    bool merged;
  };
  // Beyond kMergedOnlyCells cells (floor plans have tens to hundreds) only the merged
  // regions are planned: each candidate is a GTSP over thousands of cells (the 10^4-vertex
  // benchmark field: 5,793 cells, 4.2 s with both, and the merged path was kept).
  constexpr std::size_t kMergedOnlyCells = 1000;
  std::vector<Variant> variants;
  for (const Direction& d : planned) {
    const detail::CellDirections* cells = d.cells ? &*d.cells : nullptr;
    if (!merge || d.b->cells().size() <= kMergedOnlyCells) variants.push_back({&d, cells, false});
    if (!merge) continue;
    variants.push_back({&d, cells, true});
    if (cells && !cells->turned.empty()) variants.push_back({&d, nullptr, true});
  }
  std::optional<CoverageReport> best;
  std::optional<detail::CoverageRaster> raster;
  for (const Variant& v : variants) {
    CoverageReport cand = plan_at(P, *v.d->b, v.d->angle, v.cells, v.merged);
    if (v.merged && cand.merged_cells == 0 && best) continue;  // the same regions: the same path
    // Two directions are compared on the paths a robot would drive (touched up: on office
    // 848 the touch-ups and merged bends turned the choice); one direction's merged and
    // unmerged paths before the touch-ups, so that only the one kept is touched up.
    if (planned.size() > 1 && P.o.min_turn_radius == 0) {
      if (!raster) raster.emplace(P.E, P.index, P.w, 0);
      touch_up(P, cand, &*raster), touched = true;
    }
    // The cheaper path (path_cost): a turn worth turn_cost metres (--turn-cost, as merged
    // bends), twice where the robot stops. Counting sharp turns once, house 0000 at
    // W = 0.3 took 0° (202.3 m, 187 turns, 121 over 15°) over 90° merged (205.9 m, 169
    // turns, 98 over 15°).
    if (!best || path_cost(cand, P.o.turn_cost) < path_cost(*best, P.o.turn_cost)) best = std::move(cand);
  }
  return std::move(*best);
}

}  // namespace

std::vector<std::uint32_t> detail::depth_first_order(const std::vector<std::vector<std::uint32_t>>& adj, std::uint32_t first) {
  std::vector<std::uint32_t> order;
  std::vector<char> seen(adj.size(), 0);
  std::vector<std::uint32_t> roots{first};
  for (std::uint32_t k = 0; k < adj.size(); ++k) roots.push_back(k);
  for (const std::uint32_t root : roots) {
    if (root >= adj.size() || seen[root]) continue;
    std::vector<std::uint32_t> stack{root};
    while (!stack.empty()) {
      const std::uint32_t k = stack.back();
      stack.pop_back();
      if (seen[k]) continue;
      seen[k] = 1;
      order.push_back(k);
      for (auto it = adj[k].rbegin(); it != adj[k].rend(); ++it)
        if (!seen[*it]) stack.push_back(*it);
    }
  }
  return order;
}

void detail::finish_path(const Planning& P, Polyline path, CoverageReport& rep, std::size_t certified_before) {
  // Certified output: every segment in the component (exact walk) and, with a footprint,
  // at distance >= r from every obstacle (exact arithmetic).
  for (std::size_t i = certified_before; i + 1 < path.points.size(); ++i) {
    const Point &a = path.points[i], &z = path.points[i + 1];
    const bool inside = (i == 0 && P.o.start && *P.o.start != *P.start) ? P.cs.admits(a, z) : P.index.visible(a, z);
    const bool clear = P.cs.radius() == 0 || P.cs.admits(a, z);
    if (!inside || !clear) {
      char where[160];
      std::snprintf(where, sizeof where, "(%.17g, %.17g) -> (%.17g, %.17g)", a.x(), a.y(), z.x(), z.y());
      throw std::logic_error("coverage: segment " + std::to_string(i) + " " + where + " failed certification (" +
                             (inside ? "closer than r to an obstacle" : "outside the configuration space polygon") + ")");
    }
  }
  rep.path = std::move(path.points);
  rep.moves = std::move(path.moves);
  rep.length = rep.transit_length = rep.rotation_deg = 0, rep.turns = rep.sharp_turns = 0;
  double heading_prev = NAN;
  for (std::size_t i = 0; i + 1 < rep.path.size(); ++i) {
    const double len = dist(rep.path[i], rep.path[i + 1]);
    rep.length += len;
    if (rep.moves[i] == Move::Transit) rep.transit_length += len;
    const double h = std::atan2(rep.path[i + 1].y() - rep.path[i].y(), rep.path[i + 1].x() - rep.path[i].x());
    if (!std::isnan(heading_prev)) {
      double d = std::fabs(h - heading_prev) * 180 / std::numbers::pi;
      if (d > 180) d = 360 - d;
      rep.rotation_deg += d;
      rep.turns += d > 1.0;  // heading changes over a degree, as coverage planners count them
      rep.sharp_turns += d > 15.0;
    }
    heading_prev = h;
  }
}

namespace {

// The tool width after checking the radius and width (w defaults to 2r).
double checked_width(const CoverageOptions& o) {
  const double r = o.robot_radius;
  if (!(r >= 0) || !std::isfinite(r)) throw InputError("robot radius: must be a finite number >= 0");
  if (!(o.width >= 0) || !std::isfinite(o.width)) throw InputError("--width: the tool width must be a positive number");
  const double w = o.width > 0 ? o.width : 2 * r;
  if (!(w > 0)) throw InputError("--width: the tool width must be a positive number (or give the robot a radius: it defaults to 2r)");
  return w;
}

CoverageReport plan_in_frame(const Environment& env, const CoverageOptions& o) {
  const double r = o.robot_radius;
  const double w = checked_width(o);
  if (!(o.min_turn_radius >= 0) || !std::isfinite(o.min_turn_radius))
    throw InputError("--min-turn-radius: must be a finite number >= 0");
  if (!(o.turn_cost >= 0) || !std::isfinite(o.turn_cost)) throw InputError("--turn-cost: must be a finite number >= 0");
  // A path of more than about kMaxLapsAcross laps across the environment is beyond reason
  // (memory grows with the laps): refuse it up front rather than run for hours.
  {
    const auto box = env.bbox();
    const double across = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    if (across / w > kMaxLapsAcross)
      throw InputError("--width " + geometry::format_number(w) + ": the environment is " + geometry::format_number(across) +
                       " across, which needs more than " + geometry::format_number(kMaxLapsAcross) +
                       " laps; the tool width must be at least 1e-5 of the environment's diameter");
    if (2 * o.min_turn_radius > across)
      throw InputError("--min-turn-radius " + geometry::format_number(o.min_turn_radius) + ": a U-turn needs " +
                       geometry::format_number(2 * o.min_turn_radius) + " across, and the whole environment is " + geometry::format_number(across) +
                       " across");
  }
  const ConfigurationSpace cs(env, r);
  if (cs.components().empty())
    throw InputError("a robot of radius " + geometry::format_number(r) + " fits nowhere in this environment");
  // The component covered: the start's, else the largest.
  std::size_t comp = 0;
  std::optional<Point> entry;
  if (o.start) {
    if (!geometry::locate(env, *o.start).in_free_space())
      throw InputError("start " + geometry::format_point(*o.start) + " is not in free space");
    if (!cs.admits(*o.start))
      throw InputError("start " + geometry::format_point(*o.start) + " is " + geometry::format_number(cs.clearance(*o.start)) +
                       " from an obstacle: a robot of radius " + geometry::format_number(r) + " does not fit there");
    const auto in = cs.entry(*o.start);
    if (!in)
      throw InputError("start " + geometry::format_point(*o.start) + " is within " + geometry::format_number(cs.approximation_error()) +
                       " of the configuration space's boundary and cannot be joined to it: move it inwards");
    comp = in->component, entry = in->at;
  }
  const Environment& E = cs.components()[comp];
  const VisibilityIndex index(E);
  const VisibilityGraph graph(index);
  const Planning P{env, cs, E, index, graph, o, w, entry};

  bool touched = false;  // touched up already (boustrophedon's candidates)
  CoverageReport rep = o.pattern == Pattern::Boustrophedon ? plan_boustrophedon(P, touched)
                       : o.pattern == Pattern::Brushfire   ? detail::plan_brushfire(P)
                       : o.pattern == Pattern::Wavefront   ? detail::plan_wavefront(P)
                                                           : detail::plan_pattern(P);
  if (o.min_turn_radius > 0)
    detail::make_drivable(P, rep, o.min_turn_radius);  // straightened, driven, touched up with curves
  else if (!touched)
    touch_up(P, rep);
  rep.width = w, rep.robot_radius = r;
  rep.target_area = E.area();
  for (std::size_t k = 0; k < cs.components().size(); ++k)
    if (k != comp) rep.unreachable_area += cs.components()[k].area();
  rep.cspace_error = cs.approximation_error();
  rep.diameter = min_disc_diameter(env.vertices());
  for (std::size_t e = 0; e < env.num_vertices(); ++e) rep.perimeter += dist(env.vertex(e), env.vertex(env.next(e)));
  const double D = rep.diameter, half = w / 2;
  rep.bound = D * D / (2 * half) + 4 * D * static_cast<double>(rep.critical_points + env.num_holes()) + 5 * rep.perimeter - 4 * D;
  return rep;
}

}  // namespace

double path_cost(const CoverageReport& r, double turn_cost) {
  return r.length + turn_cost * static_cast<double>(r.turns + r.sharp_turns);
}

CoverageReport plan_coverage(const Environment& env, const CoverageOptions& o) {
  const geometry::LocalFrame frame = geometry::LocalFrame::canonical(env);
  if (frame.identity()) return plan_in_frame(env, o);
  // In the plan's canonical frame (its box at 0, the same for every exact translate, so a
  // georeferenced plan gets the answer it gets at the origin, moved), where rasters, offsets
  // and GVD snapping keep the digits the plan needs, round the path back to input
  // coordinates and certify it again there (to_input_certified pushes the ends of a segment
  // that rounding took within r of a wall); should a segment still fail, plan again with the
  // robot frame.margin() wider, which rounding cannot undo.
  const double r = o.robot_radius, w = checked_width(o);
  const geometry::Clearance clear(env, r);
  // The start's errors in the user's coordinates (the local plan would name local ones).
  if (o.start && !geometry::locate(env, *o.start).in_free_space())
    throw InputError("start " + geometry::format_point(*o.start) + " is not in free space");
  if (o.start && !clear.admits(*o.start))
    throw InputError("start " + geometry::format_point(*o.start) + " is " + geometry::format_number(clear.distance(*o.start)) +
                     " from an obstacle: a robot of radius " + geometry::format_number(r) + " does not fit there");
  const Environment local = frame.to_local(env);
  CoverageOptions lo = o;
  lo.width = w;
  if (o.start) lo.start = frame.to_local(*o.start);
  if (o.centre) lo.centre = frame.to_local(*o.centre);
  CoverageReport rep;
  for (const double extra : {0.0, frame.margin()}) {
    lo.robot_radius = r + extra;
    try {
      rep = plan_in_frame(local, lo);
    } catch (const InputError&) {
      // The start fits at r but not at r + margin: say so in the user's coordinates.
      if (extra > 0 && o.start && clear.admits(*o.start))
        throw InputError("start " + geometry::format_point(*o.start) + " is within " + geometry::format_number(frame.margin()) +
                         " of where a robot of radius " + geometry::format_number(r) +
                         " fits: this far from the origin a path needs that much room to be rounded; move it inwards");
      throw;  // not about the start: the same error as at the origin
    }
    const std::size_t bad = frame.to_input_certified(rep.path, clear);
    // Arcs were certified in the local frame, whose environment is the input's translated
    // exactly (LocalFrame), so the same arcs moved back keep r; their centres are given in
    // input coordinates (rounded: a description, the chords are what was certified here).
    for (CoverageArc& a : rep.arcs) a.centre = frame.to_input(a.centre);
    if (bad == rep.path.size()) {
      rep.cspace_error += extra;
      break;
    }
    if (extra > 0) {
      char where[160];
      std::snprintf(where, sizeof where, "(%.17g, %.17g) -> (%.17g, %.17g)", rep.path[bad].x(), rep.path[bad].y(), rep.path[bad + 1].x(),
                    rep.path[bad + 1].y());
      throw std::logic_error("coverage: segment " + std::to_string(bad) + " " + where + " failed certification in input coordinates");
    }
  }
  rep.robot_radius = r;
  return rep;
}

namespace {

CoverageMetrics measure_in_frame(const Environment& env, const CoverageReport& rep, double cell) {
  CoverageMetrics m;
  if (rep.path.empty()) return m;
  const double w = rep.width, half = w / 2;
  const ConfigurationSpace cs(env, rep.robot_radius);
  const auto comp = cs.component_of(rep.path.front()) ? cs.component_of(rep.path.front())
                    : rep.path.size() > 1        ? cs.component_of(rep.path[1])
                                                 : std::nullopt;
  if (!comp) return m;
  const Environment& E = cs.components()[*comp];
  const VisibilityIndex index(E);
  const detail::CoverageRaster R(E, index, w, cell, true);
  std::vector<std::uint32_t> visits(R.target.size(), 0), last(R.target.size(), UINT32_MAX);
  std::vector<char> covered(R.target.size(), 0), counted(R.target.size(), 0);
  // Segment by segment: a sample within w/2 of segment s is covered. A pass over it is a run
  // of consecutive segments each within w/2 of it; the pass is a visit when one of them
  // comes within w/2 - cell/2 (the margin keeps samples exactly halfway between two laps,
  // covered by both to the last bit, from counting as overlap). Runs are cut at w/2, not at
  // w/2 - cell/2, so a sample near w/2 - cell/2 from a curve of short segments is not
  // visited anew at each one as one ulp takes it in or out: brushfire's overlap on office
  // 302 moved by 0.2 % between the plan and its shift by 5e5 when runs were cut there.
  const double inner = std::max(0.0, half - R.cell / 2);
  // A path of one point is the tool standing still: the disc of radius w/2 around it.
  for (std::size_t seg = 0; seg + 1 < std::max<std::size_t>(rep.path.size(), 2); ++seg) {
    const Point &a = rep.path[seg], &b = rep.path[std::min(seg + 1, rep.path.size() - 1)];
    const std::uint32_t stamp = static_cast<std::uint32_t>(seg);
    R.capsule(a, b, half, inner, [&](std::size_t id, bool in) {
      covered[id] = 1;
      if (last[id] == UINT32_MAX || (last[id] + 1 != stamp && last[id] != stamp)) counted[id] = 0;  // a new pass
      last[id] = stamp;
      if (in && !counted[id]) ++visits[id], counted[id] = 1;
    });
  }
  std::size_t total = 0, once = 0, twice = 0;
  for (std::size_t id = 0; id < R.target.size(); ++id) {
    if (!R.target[id]) continue;
    ++total, once += covered[id], twice += visits[id] > 1;
  }
  m.samples = total;
  m.covered_fraction = total ? static_cast<double>(once) / static_cast<double>(total) : 0;
  m.overlap = total ? static_cast<double>(twice) / static_cast<double>(total) : 0;
  const double area = E.area();
  m.efficiency = area > 0 ? rep.length / (area / w) : 0;
  return m;
}

}  // namespace

CoverageMetrics measure_coverage(const Environment& env, const CoverageReport& rep, double cell) {
  const geometry::LocalFrame frame = geometry::LocalFrame::canonical(env);
  if (frame.identity()) return measure_in_frame(env, rep, cell);
  // The raster in the local frame (a sample grid at 1e10 would have no digits left for w/8).
  CoverageReport local = rep;
  for (Point& p : local.path) p = frame.to_local(p);
  return measure_in_frame(frame.to_local(env), local, cell);
}

}  // namespace preimage::coverage
