// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/tracking/scan.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

namespace preimage::tracking {

bool Scan::full_circle() const {
  return ranges.size() >= 3 && std::abs(static_cast<double>(ranges.size()) * angle_increment - 2 * M_PI) < 0.5 * angle_increment;
}

void Scan::validate(const std::string& what) const {
  validate_layout(what);
  for (std::size_t i = 0; i < ranges.size(); ++i)
    if (!std::isfinite(ranges[i]) || ranges[i] < 0)
      throw InputError(what + ": reading " + std::to_string(i) + " is " + std::to_string(ranges[i]) +
                       " (ranges must be finite and non-negative)");
}

void Scan::validate_layout(const std::string& what) const {
  if (ranges.size() < 2) throw InputError(what + ": a scan needs at least 2 readings, got " + std::to_string(ranges.size()));
  if (!(angle_increment > 0) || !std::isfinite(angle_min))
    throw InputError(what + ": angle_increment must be positive and angle_min finite");
  if (!(max_range > 0) || !std::isfinite(max_range)) throw InputError(what + ": max_range must be positive and finite");
  // Beams must point different ways (a fuzzer's increment of 1.6e-47 made every beam one
  // direction in double, and the beams per quarter turn more than any integer). No laser
  // resolves a nanoradian; the check is O(1) because the tracking loop calls it per scan.
  const std::size_t n = ranges.size();
  if (angle_increment < 1e-9 || !(angle(1) > angle(0)) || !(angle(n - 1) > angle(n - 2)))
    throw InputError(what + ": angle_increment " + geometry::format_number(angle_increment) + " with angle_min " + geometry::format_number(angle_min) +
                     " does not give beams distinct directions (increments of at least 1e-9 rad are accepted)");
  const double span = static_cast<double>(ranges.size() - 1) * angle_increment;
  if (!full_circle() && span > M_PI * (1 + 1e-12))
    throw InputError(what + ": the beams span " + std::to_string(span * 180 / M_PI) +
                     " deg; only cones up to 180 deg or a full 360 deg are supported");
}

Scan simulate_scan(const geometry::Environment& env, const Pose& pose, const LaserSpec& spec,
                   const std::optional<Disc>& target, std::mt19937_64* rng) {
  Scan s;
  s.max_range = spec.max_range;
  const bool full = spec.fov >= 2 * M_PI - 1e-12;
  s.angle_increment = full ? 2 * M_PI / static_cast<double>(spec.beams) : spec.fov / static_cast<double>(spec.beams - 1);
  s.angle_min = full ? -M_PI : -spec.fov / 2;
  s.ranges.resize(spec.beams);
  std::normal_distribution<double> noise(0.0, spec.noise_sigma);
  const double ox = pose.position.x(), oy = pose.position.y();
  // All beams at once (the simulation's inner loop): the layout's cached directions turned
  // by the heading, and the walls as plain arrays relative to the sensor. Each beam keeps
  // the nearest wall it crosses, as geometry::ray_range does for one.
  const BeamDirections& dir = beam_directions(s);
  const double ch = std::cos(pose.heading), sh = std::sin(pose.heading);
  const std::size_t E = env.num_vertices();
  thread_local std::vector<double> wall;  // ax, ay, ex, ey per edge
  wall.resize(4 * E);
  for (std::size_t e = 0; e < E; ++e) {
    const Point& a = env.vertex(e);
    const Point& b = env.vertex(env.next(e));
    wall[4 * e] = a.x() - ox;
    wall[4 * e + 1] = a.y() - oy;
    wall[4 * e + 2] = b.x() - a.x();
    wall[4 * e + 3] = b.y() - a.y();
  }
  for (std::size_t i = 0; i < spec.beams; ++i) {
    const double dx = ch * dir.cos[i] - sh * dir.sin[i], dy = sh * dir.cos[i] + ch * dir.sin[i];
    double r = spec.max_range;
    for (std::size_t e = 0; e < E; ++e) {
      const double ax = wall[4 * e], ay = wall[4 * e + 1], ex = wall[4 * e + 2], ey = wall[4 * e + 3];
      const double den = dx * ey - dy * ex;
      if (den == 0) continue;  // parallel: a grazing beam returns from the next edge
      const double t = (ax * ey - ay * ex) / den;  // along the beam
      if (!(t > 0 && t < r)) continue;
      const double f = (ax * dy - ay * dx) / den;  // along the edge
      if (f >= 0 && f <= 1) r = t;
    }
    if (target) {  // first hit on the target's circle, if nearer
      const double cx = target->center.x() - ox, cy = target->center.y() - oy;
      const double b = cx * dx + cy * dy, c = cx * cx + cy * cy - target->radius * target->radius;
      const double disc = b * b - c;
      if (disc >= 0) {
        const double t = b - std::sqrt(disc);
        if (t > 0 && t < r) r = t;
      }
    }
    if (rng && spec.noise_sigma > 0 && r < spec.max_range) r = std::clamp(r + noise(*rng), 0.0, spec.max_range);
    s.ranges[i] = r;
  }
  return s;
}

const BeamDirections& beam_directions(const Scan& scan) {
  // Two layouts: a sensor's own, and the same beams indexed from half a turn on, which
  // detection uses when the target may lie across the seam of a 360-deg scan.
  struct Slot { BeamDirections dirs; double min = 0, inc = 0; };
  thread_local Slot slots[2];
  thread_local int last = 0;
  for (int k : {last, 1 - last}) {
    Slot& s = slots[k];
    if (s.dirs.cos.size() == scan.ranges.size() && s.min == scan.angle_min && s.inc == scan.angle_increment) {
      last = k;
      return s.dirs;
    }
  }
  last = 1 - last;  // the least recently used
  Slot& s = slots[last];
  s.min = scan.angle_min;
  s.inc = scan.angle_increment;
  s.dirs.cos.resize(scan.ranges.size());
  s.dirs.sin.resize(scan.ranges.size());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    s.dirs.cos[i] = std::cos(scan.angle(i));
    s.dirs.sin[i] = std::sin(scan.angle(i));
  }
  return s.dirs;
}

namespace {

// The scan's points as plain arrays in walk order, and its runs: maximal sequences of
// successive in-range readings with no occlusion gap between neighbours (the sub-lists of
// L_p in V.A). A full circle is walked from the first reading after a break, so the
// arrays hold up to 2n entries (beam k mod n at walk index k) and every run is contiguous.
struct ScanPoints {
  std::vector<double> x, y;
  struct Run { std::size_t first, last; };  // walk indices, inclusive
  std::vector<Run> runs;
};

// The point of (lo, hi) farthest from the line through lo and hi if it is further than
// tol, else lo. Distances are compared as cross products squared against tol^2 |chord|^2
// (same argmax, no square root). Long chords go four points at a time in two SSE2 lane
// pairs (GCC vector extensions), remembering the first block of four where the maximum
// grew; the point is then the first of that block attaining it — the lowest index, as
// the plain loop for short chords picks.
std::size_t farthest_from_chord(const double* xs, const double* ys, std::size_t lo, std::size_t hi, double tol) {
  const double ax = xs[lo], ay = ys[lo], dx = xs[hi] - ax, dy = ys[hi] - ay;
  const double floor = tol * tol * (dx * dx + dy * dy);
  const std::size_t m = hi - lo - 1;
  const double *X = xs + lo + 1, *Y = ys + lo + 1;
  auto sq = [&](std::size_t i) {
    const double c = dx * (Y[i] - ay) - dy * (X[i] - ax);
    return c * c;
  };
  double best = floor;
  std::size_t at = m;  // none
  std::size_t i = 0;
  if (m >= 8) {
    using v2d = double __attribute__((vector_size(16)));
    auto load = [](const double* p) {
      v2d v;
      std::memcpy(&v, p, sizeof v);
      return v;
    };
    auto block = [&](std::size_t b, v2d& c0, v2d& c1) {  // the squares at b .. b+3
      c0 = dx * (load(Y + b) - ay) - dy * (load(X + b) - ax);
      c1 = dx * (load(Y + b + 2) - ay) - dy * (load(X + b + 2) - ax);
      c0 *= c0;
      c1 *= c1;
    };
    std::size_t at_block = m;
    for (; i + 4 <= m; i += 4) {
      v2d c0, c1;
      block(i, c0, c1);
      const v2d h = c0 > c1 ? c0 : c1;
      const double top = h[0] > h[1] ? h[0] : h[1];
      if (top > best) {
        best = top;
        at_block = i;
      }
    }
    if (at_block != m)
      for (at = at_block; sq(at) != best; ++at) {
      }
  }
  for (; i < m; ++i)
    if (const double d = sq(i); d > best) {
      best = d;
      at = i;
    }
  return at == m ? lo : lo + 1 + at;
}

// Douglas-Peucker on the readings b..e (walk indices, inclusive), appending the kept
// indices after b. They are successive beams, so a chord from lo to hi spans (hi - lo)
// beam increments about the sensor; a chord of `max_span` beams or more is split too, so
// that every fitted edge stays well under a half turn and turns counter-clockwise about
// the observer (which LocalMap::validate then checks exactly).
void simplify(const ScanPoints& P, std::size_t b, std::size_t e, double tol, std::size_t max_span,
              std::vector<std::size_t>& out, std::vector<std::size_t>& stack) {
  stack.clear();
  stack.push_back(e);
  std::size_t lo = b;
  while (!stack.empty()) {
    const std::size_t hi = stack.back();
    std::size_t worst = lo;
    if (hi > lo + 1) {
      worst = farthest_from_chord(P.x.data(), P.y.data(), lo, hi, tol);
      if (worst == lo && hi - lo >= max_span) worst = (lo + hi) / 2;
    }
    if (worst == lo) {
      out.push_back(hi);
      lo = hi;
      stack.pop_back();
    } else {
      stack.push_back(worst);
    }
  }
}

struct Builder {
  LocalMap& m;
  void add(const Point& p, EdgeKind edge_from_previous, std::uint32_t corner_of_previous = kNone) {
    if (!m.vertices.empty()) {
      m.edges.push_back(edge_from_previous);
      m.corner.push_back(corner_of_previous);
    }
    m.vertices.push_back(p);
  }
  std::uint32_t last() const { return static_cast<std::uint32_t>(m.vertices.size() - 1); }
  std::uint32_t next_index() const { return static_cast<std::uint32_t>(m.vertices.size()); }
};

}  // namespace

LocalMap local_map_from_scan(const Scan& scan, const MapParams& mp) {
  scan.validate_layout();  // the readings are checked on the way (below)
  const std::size_t n = scan.ranges.size();
  const bool full = scan.full_circle();
  const double R = scan.max_range;
  const BeamDirections& dir = beam_directions(scan);

  // One pass over the beams: points, and runs split where a reading is out of range or
  // two neighbours are further apart than gap + 2 r dtheta (an occlusion gap).
  thread_local ScanPoints P;
  P.x.resize(2 * n);
  P.y.resize(2 * n);
  auto& runs = P.runs;
  runs.clear();
  const double* r = scan.ranges.data();
  const double lo_r = mp.min_range, hi_r = R - mp.range_margin, two_inc = 2 * scan.angle_increment;
  // Neighbours (range, point) further apart than gap + 2 r dtheta.
  auto gap_between = [&](double ra, double xa, double ya, double rb, double xb, double yb) {
    const double thr = mp.gap + two_inc * std::max(ra, rb);
    return (xa - xb) * (xa - xb) + (ya - yb) * (ya - yb) > thr * thr;
  };
  auto gap = [&](std::size_t a, std::size_t b) { return gap_between(r[a], P.x[a], P.y[a], r[b], P.x[b], P.y[b]); };
  {
    const double *cs = dir.cos.data(), *sn = dir.sin.data();
    double *x = P.x.data(), *y = P.y.data();  // (locals: the loop's stores cannot move them)
    bool bad = false, open = false;            // open: beam k-1 is in range, in a run from `first`
    std::size_t first = 0;
    double pr = 0, px = 0, py = 0;  // beam k-1
    for (std::size_t k = 0; k < n; ++k) {
      const double rk = r[k], xk = rk * cs[k], yk = rk * sn[k];
      bad |= !(rk >= 0) | !(rk <= std::numeric_limits<double>::max());  // NaN fails both
      x[k] = xk;
      y[k] = yk;
      const bool joins = open && !gap_between(pr, px, py, rk, xk, yk);
      pr = rk;
      px = xk;
      py = yk;
      if (!((rk > lo_r) & (rk < hi_r))) {
        if (open) runs.push_back({first, k - 1});
        open = false;
        continue;
      }
      if (joins) continue;  // the run goes on (the common case)
      if (open) runs.push_back({first, k - 1});
      first = k;
      open = true;
    }
    if (open) runs.push_back({first, n - 1});
    if (bad) scan.validate();  // throws, naming the reading
  }

  LocalMap m;
  m.observer = Point(0, 0);
  m.vertices.reserve(n / 2 + 16);  // one allocation per array in the common case
  m.edges.reserve(n / 2 + 16);
  m.corner.reserve(n / 2 + 16);
  Builder B{m};
  auto range_point = [&](double a) { return Point(R * std::cos(a), R * std::sin(a)); };
  auto angle_at = [&](std::size_t kw) { return scan.angle_min + static_cast<double>(kw) * scan.angle_increment; };
  auto point = [&](std::size_t kw) { return Point(P.x[kw], P.y[kw]); };
  // A radial occlusion edge between the reading at walk index kw and the range circle is
  // built turned away from the reading by turn(kw) = 1e-13 max(1, R / r) rad (1e-12 m at
  // R = 8 m): its orientation about the observer is then certified by CGAL's
  // floating-point filter instead of exact arithmetic, and it cannot come out turning
  // clockwise. Nothing a sensor with centimetre noise measured is changed by it.
  auto turn = [&](std::size_t kw) { return 1e-13 * std::max(1.0, R / r[kw < n ? kw : kw - n]); };
  // The range arc from angle a to b (a < b, unwrapped), after the point at a was added;
  // its last point is turned back by end_turn.
  auto arc = [&](double a, double b, double end_turn) {
    const int k = std::max(1, static_cast<int>(std::ceil((b - a) / mp.arc_step)));
    for (int j = 1; j <= k; ++j) B.add(range_point(j == k ? b - end_turn : a + (b - a) * j / k), EdgeKind::Range);
  };
  // Leaves the last emitted point (the reading at walk index kw) radially for the range
  // circle and follows the circle to angle b: the first two edges of
  // occlusion-range-occlusion.
  auto out_to_range = [&](std::size_t kw, double b, double end_turn) {
    const double a = angle_at(kw);
    B.add(range_point(a + turn(kw)), EdgeKind::Occlusion, B.last());
    arc(a, b, end_turn);
  };
  // Across an occlusion gap the corner is the endpoint nearer the observer.
  auto nearer_of = [&](const Point& p, std::uint32_t p_index, std::uint32_t other) {
    return CGAL::compare_distance_to_point(m.observer, p, m.vertices[other]) == CGAL::SMALLER ? p_index : other;
  };
  thread_local std::vector<std::size_t> fitted, stack;
  // beams per quarter turn, at most the walk's length (a cast of a larger double is undefined)
  const double beams_per_quarter = std::floor(M_PI / 2 / scan.angle_increment);
  const std::size_t quarter_turn = beams_per_quarter < static_cast<double>(2 * n + 2) ? static_cast<std::size_t>(std::max(2.0, beams_per_quarter)) : 2 * n + 2;
  // Emits the fitted polyline of a run (its first point is already emitted).
  auto flush = [&](const ScanPoints::Run& run) {
    if (run.last == run.first) return;
    fitted.clear();
    simplify(P, run.first, run.last, mp.simplify, quarter_turn, fitted, stack);
    for (auto kw : fitted) B.add(point(kw), EdgeKind::Solid);
  };

  // A full circle starts at the first run after a break. When the seam between the last
  // beam and the first is no break, the first run continues the last one: it moves to
  // walk indices n.. .
  std::size_t first_run = 0;
  bool closed_run = false;  // one run all round, no break anywhere
  if (full) {
    if (runs.empty()) {  // nothing in range all round: V is the range disc
      for (std::size_t i = 0; i < n; ++i) B.add(range_point(scan.angle(i)), EdgeKind::Range);
      m.edges.push_back(EdgeKind::Range);
      m.corner.push_back(kNone);
      m.validate("scan map");
      return m;
    }
    const bool seam_joins = runs.front().first == 0 && runs.back().last == n - 1 && !gap(n - 1, 0);
    if (seam_joins && runs.size() == 1) {
      closed_run = true;
    } else if (seam_joins) {
      const std::size_t k = runs.front().last + 1;
      std::copy_n(P.x.begin(), k, P.x.begin() + static_cast<std::ptrdiff_t>(n));
      std::copy_n(P.y.begin(), k, P.y.begin() + static_cast<std::ptrdiff_t>(n));
      runs.back().last = n + runs.front().last;
      first_run = 1;
    }
  } else {
    B.add(m.observer, EdgeKind::FieldOfView);
    m.observer_vertex = 0;
  }

  for (std::size_t j = first_run; j < runs.size(); ++j) {
    const auto& run = runs[j];
    const Point p = point(run.first);
    if (j == first_run) {
      if (!full && run.first > 0) {  // out-of-range readings before the first run
        B.add(range_point(angle_at(0)), EdgeKind::FieldOfView);
        arc(angle_at(0), angle_at(run.first), turn(run.first));
        B.add(p, EdgeKind::Occlusion, B.next_index());
      } else {
        B.add(p, EdgeKind::FieldOfView);  // (full circle: the first vertex; no edge yet)
      }
    } else if (run.first > runs[j - 1].last + 1) {  // an out-of-range gap
      out_to_range(runs[j - 1].last, angle_at(run.first), turn(run.first));
      B.add(p, EdgeKind::Occlusion, B.next_index());
    } else {  // an occlusion gap
      B.add(p, EdgeKind::Occlusion, nearer_of(p, B.next_index(), B.last()));
    }
    flush(run);
  }
  // Close the polygon.
  if (!full) {
    if (runs.empty()) {  // nothing in range
      B.add(range_point(angle_at(0)), EdgeKind::FieldOfView);
      arc(angle_at(0), angle_at(n - 1), 0);
    } else if (runs.back().last < n - 1) {
      out_to_range(runs.back().last, angle_at(n - 1), 0);
    }
    m.edges.push_back(EdgeKind::FieldOfView);
    m.corner.push_back(kNone);
  } else if (const std::size_t start = runs[first_run].first, last = runs.back().last; last + 1 < start + n) {
    out_to_range(last, angle_at(start + n), turn(start));
    m.edges.push_back(EdgeKind::Occlusion);
    m.corner.push_back(0);
  } else if (closed_run) {
    m.edges.push_back(EdgeKind::Solid);
    m.corner.push_back(kNone);
  } else {  // an occlusion gap between the last reading and the first
    m.edges.push_back(EdgeKind::Occlusion);
    m.corner.push_back(nearer_of(m.vertices[0], 0, B.last()));
  }
  // Every edge turns counter-clockwise about the observer by construction: solid and
  // occlusion-gap edges join readings of different beams, range points step round the
  // circle, and radial edges are built turned (see `turn`). So, unlike the exact map, a
  // scan map needs no straightening; validate() checks it exactly.
  m.validate("scan map");
  return m;
}

}  // namespace preimage::tracking
