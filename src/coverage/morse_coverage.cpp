// SPDX-License-Identifier: Apache-2.0
// Coverage patterns of the variable-slice Morse decompositions (6.2.3): in each cell, laps
// along the slices at inter-lap distance at most w, joined by short moves; cells in the order
// of an exhaustive (depth-first) walk of the adjacency graph; shortest transits between them.
//
//   spiral      circles around c; in annular cells one spiral instead of circles and radial
//               steps (Fig. 6.12, right)
//   concentric  circles around c, a radial step between them
//   spike       rays from c, out and back, spaced so the far end is w apart (denser near c,
//               Fig. 6.13)
//   squarel     diamonds around c; in annular cells a diamond spiral (Fig. 6.14)
//
// Laps are computed in double on the cell's boundary (sampled within w/1000) and every
// segment is then certified exactly like the boustrophedon path (finish_path); a lap point
// outside the free space is dropped and a chord that a wall cuts is replaced by the
// shortest path between its ends, so a path never leaves the configuration space.
#include "coverage_internal.hpp"

#include <preimage/decompose/morse.hpp>
#include <preimage/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace preimage::coverage {

std::string_view to_string(Pattern p) {
  switch (p) {
    case Pattern::Boustrophedon: return "boustrophedon";
    case Pattern::Spiral: return "spiral";
    case Pattern::Concentric: return "concentric";
    case Pattern::Spike: return "spike";
    case Pattern::Squarel: return "squarel";
    case Pattern::Brushfire: return "brushfire";
    case Pattern::Wavefront: return "wavefront";
  }
  return "?";
}

std::optional<Pattern> parse_pattern(std::string_view s) {
  for (const Pattern p : {Pattern::Boustrophedon, Pattern::Spiral, Pattern::Concentric, Pattern::Spike, Pattern::Squarel, Pattern::Brushfire, Pattern::Wavefront})
    if (to_string(p) == s) return p;
  return std::nullopt;
}

namespace detail {

namespace {

constexpr double kPi = std::numbers::pi;

// The slice at level lam as a curve with parameter s: circles by angle, rays by distance from
// c, diamonds by perimeter position (corner k at s = k, corners (L,0), (0,L), (-L,0), (0,-L)).
struct Slices {
  SliceFamily f;
  Point c;
  double period(double) const { return f == SliceFamily::Circular ? 2 * kPi : f == SliceFamily::Squarel ? 4.0 : 0.0; }
  Point at(double lam, double s) const {
    switch (f) {
      case SliceFamily::Circular: return {c.x() + lam * std::cos(s), c.y() + lam * std::sin(s)};
      case SliceFamily::Spike: return {c.x() + s * std::cos(lam), c.y() + s * std::sin(lam)};
      case SliceFamily::Linear: return {lam, c.y() + s};  // not a pattern: boustrophedon has its own planner
      case SliceFamily::Squarel: {
        const double u = s - 4 * std::floor(s / 4);
        const int k = std::min(3, static_cast<int>(u));
        const double t = u - k;
        static constexpr double xs[] = {1, 0, -1, 0, 1}, ys[] = {0, 1, 0, -1, 0};
        return {c.x() + lam * (xs[k] + t * (xs[k + 1] - xs[k])), c.y() + lam * (ys[k] + t * (ys[k + 1] - ys[k]))};
      }
    }
    return c;
  }
  // Parameters where the slice at lam crosses segment ab.
  void crossings(double lam, const Point& a, const Point& b, std::vector<double>& out) const {
    const double ax = a.x() - c.x(), ay = a.y() - c.y(), dx = b.x() - a.x(), dy = b.y() - a.y();
    if (f == SliceFamily::Circular) {
      const double A = dx * dx + dy * dy, B = 2 * (ax * dx + ay * dy), C = ax * ax + ay * ay - lam * lam;
      const double D = B * B - 4 * A * C;
      if (A == 0 || D < 0) return;
      const double r = std::sqrt(D);
      for (const double t : {(-B - r) / (2 * A), (-B + r) / (2 * A)})
        if (t >= 0 && t < 1) out.push_back(std::atan2(ay + t * dy, ax + t * dx));
      return;
    }
    auto seg = [&](double px, double py, double qx, double qy, double s0, double s1, bool ray) {
      // p + u (q - p) = a' + t d  (coordinates relative to c)
      const double wx = qx - px, wy = qy - py, den = wx * dy - wy * dx;
      if (den == 0) return;
      const double u = ((ax - px) * dy - (ay - py) * dx) / den, t = ((ax - px) * wy - (ay - py) * wx) / den;
      if (t < 0 || t >= 1 || u < 0 || (!ray && u > 1)) return;
      out.push_back(s0 + u * (s1 - s0));
    };
    if (f == SliceFamily::Spike) {
      seg(0, 0, std::cos(lam), std::sin(lam), 0, 1, true);
      return;
    }
    static constexpr double xs[] = {1, 0, -1, 0, 1}, ys[] = {0, 1, 0, -1, 0};
    for (int k = 0; k < 4; ++k) seg(lam * xs[k], lam * ys[k], lam * xs[k + 1], lam * ys[k + 1], k, k + 1, false);
  }
};

bool inside_rings(const std::vector<std::vector<Point>>& rings, const Point& p) {
  bool in = false;
  for (const auto& r : rings)
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
      if ((r[i].y() > p.y()) != (r[j].y() > p.y()) && p.x() < (r[j].x() - r[i].x()) * (p.y() - r[i].y()) / (r[j].y() - r[i].y()) + r[i].x())
        in = !in;
  return in;
}

struct Interval {
  double a, b;  // parameters along the slice, a < b (b - a = period for a whole loop)
  bool loop = false;
};

// The slice at lam inside the cell (normally one interval: the Morse property).
std::vector<Interval> slice_in_cell(const Slices& S, double lam, const std::vector<std::vector<Point>>& rings, double far) {
  std::vector<double> xs;
  for (const auto& r : rings)
    for (std::size_t i = 0; i < r.size(); ++i) S.crossings(lam, r[i], r[(i + 1) % r.size()], xs);
  std::sort(xs.begin(), xs.end());
  std::vector<Interval> out;
  const double period = S.period(lam);
  if (period > 0) {
    if (xs.empty()) {
      if (inside_rings(rings, S.at(lam, 0))) out.push_back({0, period, true});
      return out;
    }
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const double a = xs[i], b = i + 1 < xs.size() ? xs[i + 1] : xs[0] + period;
      if (b - a <= 0) continue;
      if (inside_rings(rings, S.at(lam, (a + b) / 2))) out.push_back({a, b});
    }
    return out;
  }
  xs.insert(xs.begin(), 0.0);
  xs.push_back(far);
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    if (xs[i + 1] > xs[i] && inside_rings(rings, S.at(lam, (xs[i] + xs[i + 1]) / 2))) out.push_back({xs[i], xs[i + 1]});
  return out;
}

// Points along the slice from parameter a to b (either order), chords within `sag`.
void sample(const Slices& S, double lam, double a, double b, double sag, std::vector<Point>& out) {
  if (S.f == SliceFamily::Spike) {
    out.push_back(S.at(lam, a)), out.push_back(S.at(lam, b));
    return;
  }
  if (S.f == SliceFamily::Squarel) {
    out.push_back(S.at(lam, a));
    if (a < b) {
      for (double k = std::floor(a) + 1; k < b; ++k) out.push_back(S.at(lam, k));
    } else {
      for (double k = std::ceil(a) - 1; k > b; --k) out.push_back(S.at(lam, k));
    }
    out.push_back(S.at(lam, b));
    return;
  }
  const double step = lam > sag ? std::min(kPi / 8, 2 * std::acos(1 - sag / lam)) : kPi / 8;
  const auto n = static_cast<std::size_t>(std::ceil(std::abs(b - a) / step));
  for (std::size_t i = 0; i <= n; ++i) out.push_back(S.at(lam, a + (b - a) * static_cast<double>(i) / static_cast<double>(std::max<std::size_t>(n, 1))));
}

}  // namespace

void PathBuilder::go(const Point& z, Move move) {
  if (path.points.empty()) {
    path.append(z, move);
    return;
  }
  const Point a = path.points.back();
  if (a == z) return;
  if (certified(P, a, z)) {
    path.append(z, move);
    return;
  }
  const auto sp = P.graph.shortest_path(a, z);
  if (!sp.found) throw std::logic_error("coverage: no path between two points of one component");
  ++detours;
  for (std::size_t i = 1; i < sp.points.size(); ++i) path.append(sp.points[i], move == Move::Lap ? Move::Follow : move);
}

CoverageReport plan_pattern(const Planning& P) {
  const Pattern pattern = P.o.pattern;
  const SliceFamily family = pattern == Pattern::Spike ? SliceFamily::Spike : pattern == Pattern::Squarel ? SliceFamily::Squarel : SliceFamily::Circular;
  const auto box = P.env.bbox();
  const Point centre = P.o.centre.value_or(Point((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2));
  const MorseDecomposition m(P.E, family, centre);
  const Slices S{family, centre};
  const double w = P.w;
  const double scale = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  const double far = 4 * scale + std::hypot(centre.x() - box.xmin(), centre.y() - box.ymin()) + std::hypot(centre.x() - box.xmax(), centre.y() - box.ymax());
  const double sag = std::min(w / 20, 1e-3 * scale), eps = 1e-9 * scale;
  std::vector<double> node_level(m.num_nodes(), 0);
  for (const auto& k : m.critical_points()) node_level[k.node] = k.level;

  // The laps of every cell, in level order.
  struct Lap { std::vector<Point> pts; bool loop; };
  const std::size_t n = m.cells().size();
  std::vector<std::vector<Lap>> laps(n);
  std::vector<std::vector<std::vector<Point>>> cell_rings(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& cell = m.cells()[k];
    cell_rings[k] = m.cell_rings(k, std::min(sag, w / 1000));
    const auto& rings = cell_rings[k];
    double lo = 0, hi = 0, step = w;
    if (family == SliceFamily::Spike) {
      double rmax = 0;
      for (const auto& r : rings)
        for (const Point& p : r) rmax = std::max(rmax, std::hypot(p.x() - centre.x(), p.y() - centre.y()));
      if (cell.nodes.empty()) {
        lo = 0, hi = 2 * kPi;
      } else {
        lo = std::min(node_level[cell.nodes.front()], node_level[cell.nodes.back()]);
        hi = std::max(node_level[cell.nodes.front()], node_level[cell.nodes.back()]);
        if (cell.nodes.size() == 1) hi = lo + 2 * kPi;
        else if (slice_in_cell(S, (lo + hi) / 2, rings, far).empty()) std::swap(lo, hi), hi += 2 * kPi;  // the other way round
      }
      step = rmax > 0 ? w / rmax : 2 * kPi;
    } else {
      if (cell.nodes.size() != 2) throw std::logic_error("coverage: a Morse cell without two critical slices");
      lo = std::min(node_level[cell.nodes[0]], node_level[cell.nodes[1]]), hi = std::max(node_level[cell.nodes[0]], node_level[cell.nodes[1]]);
    }
    const auto count = static_cast<std::size_t>(std::max(1.0, std::ceil((hi - lo) / step)));
    const double gap = (hi - lo) / static_cast<double>(count);
    const bool spiral = (pattern == Pattern::Spiral || pattern == Pattern::Squarel) && count >= 2 &&
                        [&] { const auto iv = slice_in_cell(S, (lo + hi) / 2, rings, far); return iv.size() == 1 && iv[0].loop; }();
    if (spiral) {
      // One spiral from the first level to the last: the level grows by `gap` per turn.
      const double period = S.period(0), turns = static_cast<double>(count - 1);
      const double total = turns * period;
      const double ds = family == SliceFamily::Squarel ? 0.25 : std::min(kPi / 8, 2 * std::acos(std::max(-1.0, 1 - sag / std::max(lo + gap / 2, sag))));
      // A whole turn at the first level, the spiral, a whole turn at the last: without them a
      // crescent 1.5 gaps wide would stay uncovered along each side of the annulus.
      Lap lap{{}, false};
      const double first = lo + gap / 2, last = first + gap * turns;
      for (double s = 0;; s += ds) {
        const double t = std::min(s, total + 2 * period);
        const double lam = t < period ? first : t > total + period ? last : first + gap * (t - period) / period;
        lap.pts.push_back(S.at(lam, t));
        if (t >= total + 2 * period) break;
      }
      laps[k].push_back(std::move(lap));
      continue;
    }
    for (std::size_t i = 0; i < count; ++i) {
      const double lam = lo + gap * (static_cast<double>(i) + 0.5);
      for (const Interval& iv : slice_in_cell(S, lam, rings, far)) {
        Lap lap{{}, iv.loop};
        if (iv.loop) sample(S, lam, 0, S.period(lam), sag, lap.pts);
        else sample(S, lam, iv.a + eps / std::max(1.0, lam), iv.b - eps / std::max(1.0, lam), sag, lap.pts);
        laps[k].push_back(std::move(lap));
      }
    }
  }

  // Cell order: the exhaustive walk (depth-first) of the adjacency graph from the start's cell.
  const auto adj = m.adjacency();
  std::uint32_t first = 0;
  if (P.start)
    if (const auto c = m.cell_of(*P.start)) first = static_cast<std::uint32_t>(*c);
  const std::vector<std::uint32_t> order = depth_first_order(adj, first);

  // Assemble, keeping only points in the free space and joining consecutive points by a
  // straight move when it is certified, else by the shortest path.
  Polyline path;
  if (P.o.start) path.append(*P.o.start, Move::Transit);
  if (P.start && (path.points.empty() || *P.start != path.points.back())) path.append(*P.start, Move::Transit);
  std::size_t lap_count = 0;
  PathBuilder builder{P, std::move(path), 0};
  Polyline& built = builder.path;
  auto go = [&](const Point& z, Move move) { builder.go(z, move); };
  auto free_point = [&](const Point& p) { return P.index.in_free_space(p); };
  // From a to z along the cell's boundary (6.2.3: "motion along the boundary of the cell"),
  // the shorter way round the ring nearest to both: it sweeps the corners that the laps'
  // ends cut, where a straight step would leave them uncovered.
  auto along_boundary = [&](const std::vector<std::vector<Point>>& rings, const Point& a, const Point& z) {
    std::vector<Point> best;
    double best_cost = std::numeric_limits<double>::infinity();
    auto project = [](const std::vector<Point>& r, const Point& p, std::size_t& seg, double& dist) {
      dist = std::numeric_limits<double>::infinity();
      Point at = p;
      for (std::size_t i = 0; i < r.size(); ++i) {
        const Point &u = r[i], &v = r[(i + 1) % r.size()];
        const double ex = v.x() - u.x(), ey = v.y() - u.y(), L2 = ex * ex + ey * ey;
        const double t = L2 > 0 ? std::clamp(((p.x() - u.x()) * ex + (p.y() - u.y()) * ey) / L2, 0.0, 1.0) : 0.0;
        const Point q(u.x() + t * ex, u.y() + t * ey);
        const double d = std::hypot(q.x() - p.x(), q.y() - p.y());
        if (d < dist) dist = d, seg = i, at = q;
      }
      return at;
    };
    for (const auto& r : rings) {
      if (r.size() < 3) continue;
      std::size_t sa = 0, sz = 0;
      double da = 0, dz = 0;
      const Point pa = project(r, a, sa, da), pz = project(r, z, sz, dz);
      if (da + dz >= best_cost) continue;
      const std::size_t m2 = r.size();
      // forwards: pa, r[sa+1], ..., r[sz], pz; backwards: pa, r[sa], ..., r[sz+1], pz
      std::vector<Point> fw{pa}, bw{pa};
      for (std::size_t i = (sa + 1) % m2; sa != sz && fw.size() <= m2; i = (i + 1) % m2) {
        fw.push_back(r[i]);
        if (i == sz) break;
      }
      for (std::size_t i = sa; sa != sz && bw.size() <= m2; i = (i + m2 - 1) % m2) {
        bw.push_back(r[i]);
        if (i == (sz + 1) % m2) break;
      }
      fw.push_back(pz), bw.push_back(pz);
      auto len = [](const std::vector<Point>& v) {
        double l = 0;
        for (std::size_t i = 0; i + 1 < v.size(); ++i) l += std::hypot(v[i + 1].x() - v[i].x(), v[i + 1].y() - v[i].y());
        return l;
      };
      best = len(fw) <= len(bw) ? fw : bw;
      best_cost = da + dz;
    }
    return best;
  };
  for (const std::uint32_t k : order) {
    auto& cl = laps[k];
    if (cl.empty()) continue;
    // Run the levels upwards or downwards, whichever starts nearer.
    if (!built.points.empty()) {
      const Point& here = built.points.back();
      const auto d = [&](const Point& p) { return std::hypot(p.x() - here.x(), p.y() - here.y()); };
      if (d(cl.back().pts.back()) + 1e-12 < std::min(d(cl.front().pts.front()), d(cl.front().pts.back()))) std::reverse(cl.begin(), cl.end());
    }
    bool forward = true;
    if (!built.points.empty()) {
      const Point& here = built.points.back();
      const auto d = [&](const Point& p) { return std::hypot(p.x() - here.x(), p.y() - here.y()); };
      forward = d(cl.front().pts.front()) <= d(cl.front().pts.back());
    }
    bool entered = false;
    for (Lap& lap : cl) {
      if (!forward) std::reverse(lap.pts.begin(), lap.pts.end());
      bool first_point = true;
      for (const Point& p : lap.pts) {
        if (!free_point(p)) continue;
        if (first_point && entered && !lap.loop) {
          // Follow the cell's boundary to the next lap unless that wanders far (then step).
          const auto walk = along_boundary(cell_rings[k], built.points.back(), p);
          double l = 0;
          for (std::size_t i = 0; i + 1 < walk.size(); ++i) l += std::hypot(walk[i + 1].x() - walk[i].x(), walk[i + 1].y() - walk[i].y());
          if (l <= 20 * w + 4 * std::hypot(p.x() - built.points.back().x(), p.y() - built.points.back().y()))
            for (const Point& b : walk)
              if (free_point(b)) go(b, Move::Follow);
        }
        go(p, first_point ? (entered ? Move::Follow : Move::Transit) : Move::Lap);
        first_point = false;
      }
      if (!first_point) ++lap_count, entered = true;
      if (!lap.loop) forward = !forward;  // boustrophedon in the level; loops keep their sense
    }
  }
  if (built.points.empty()) throw InputError("coverage: no lap fits in the free space at this width");

  return pattern_report(P, std::move(built), builder.detours, lap_count, n, m.num_nodes(), order);
}

CoverageReport pattern_report(const Planning& P, Polyline path, std::size_t detours, std::size_t laps, std::size_t cells, std::size_t nodes,
                              std::vector<std::uint32_t> order) {
  CoverageReport rep;
  finish_path(P, std::move(path), rep);
  rep.rounding_detours = detours;
  rep.laps = laps;
  rep.cells = cells;
  rep.critical_points = nodes;
  rep.sweeps.assign(order.size(), 0);
  rep.cell_order = std::move(order);
  return rep;
}

}  // namespace detail
}  // namespace preimage::coverage
