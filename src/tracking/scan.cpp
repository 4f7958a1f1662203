// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/tracking/scan.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace preimage::tracking {

bool Scan::full_circle() const {
  return ranges.size() >= 3 && std::abs(static_cast<double>(ranges.size()) * angle_increment - 2 * M_PI) < 0.5 * angle_increment;
}

void Scan::validate(const std::string& what) const {
  if (ranges.size() < 2) throw InputError(what + ": a scan needs at least 2 readings, got " + std::to_string(ranges.size()));
  if (!(angle_increment > 0) || !std::isfinite(angle_min))
    throw InputError(what + ": angle_increment must be positive and angle_min finite");
  if (!(max_range > 0) || !std::isfinite(max_range)) throw InputError(what + ": max_range must be positive and finite");
  const double span = static_cast<double>(ranges.size() - 1) * angle_increment;
  if (!full_circle() && span > M_PI * (1 + 1e-12))
    throw InputError(what + ": the beams span " + std::to_string(span * 180 / M_PI) +
                     " deg; only cones up to 180 deg or a full 360 deg are supported");
  for (std::size_t i = 0; i < ranges.size(); ++i)
    if (!std::isfinite(ranges[i]) || ranges[i] < 0)
      throw InputError(what + ": reading " + std::to_string(i) + " is " + std::to_string(ranges[i]) +
                       " (ranges must be finite and non-negative)");
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
  for (std::size_t i = 0; i < spec.beams; ++i) {
    const double a = pose.heading + s.angle(i);
    double r = geometry::ray_range(env, pose.position, a, spec.max_range);
    if (target) {  // first hit on the target's circle, if nearer
      const double dx = std::cos(a), dy = std::sin(a);
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
  thread_local BeamDirections dirs;
  thread_local double min = 0, inc = 0;
  if (dirs.cos.size() != scan.ranges.size() || min != scan.angle_min || inc != scan.angle_increment) {
    min = scan.angle_min;
    inc = scan.angle_increment;
    dirs.cos.resize(scan.ranges.size());
    dirs.sin.resize(scan.ranges.size());
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
      dirs.cos[i] = std::cos(scan.angle(i));
      dirs.sin[i] = std::sin(scan.angle(i));
    }
  }
  return dirs;
}

namespace {

// The beams of one scan as plain arrays, indexed in walk order: a full circle is walked
// from `start` for n beams, so the arrays hold 2n entries (beam k mod n at k) and every
// run of successive readings is contiguous.
struct ScanPoints {
  std::vector<double> x, y;
  std::vector<char> valid;
  std::vector<char> brk;  // brk[k]: the readings k-1 and k are not neighbours on one polyline
};

// The point of (lo, hi) farthest from the line through lo and hi if its distance, times
// the chord length, exceeds `above`; else lo. Squared distances (same argmax), four at a
// time in two SSE2 lane pairs (GCC vector extensions) so that no single max chain limits
// the loop; ties go to the lower index, as a plain scalar loop would.
std::size_t farthest_from_chord(const double* xs, const double* ys, std::size_t lo, std::size_t hi, double above) {
  const double ax = xs[lo], ay = ys[lo], dx = xs[hi] - ax, dy = ys[hi] - ay;
  double best = above * above;
  std::size_t worst = lo, i = lo + 1;
  using v2d = double __attribute__((vector_size(16)));
  using v2i = std::int64_t __attribute__((vector_size(16)));
  if (hi - i >= 8) {
    v2d w0 = {best, best}, w1 = w0;
    v2i at0 = {0, 0}, at1 = at0;
    const v2i step = {4, 4};
    v2i idx0 = {static_cast<std::int64_t>(i), static_cast<std::int64_t>(i + 1)}, idx1 = idx0 + 2;
    auto sq = [&](std::size_t j) {
      v2d px, py;
      std::memcpy(&px, xs + j, sizeof px);
      std::memcpy(&py, ys + j, sizeof py);
      const v2d c = dx * (py - ay) - dy * (px - ax);
      return c * c;
    };
    for (; i + 4 <= hi; i += 4) {
      const v2d d0 = sq(i), d1 = sq(i + 2);
      const v2i g0 = d0 > w0, g1 = d1 > w1;  // strictly greater: a lane keeps its earliest maximum
      w0 = g0 ? d0 : w0;
      w1 = g1 ? d1 : w1;
      at0 = g0 ? idx0 : at0;
      at1 = g1 ? idx1 : at1;
      idx0 += step;
      idx1 += step;
    }
    const double lane_w[4] = {w0[0], w0[1], w1[0], w1[1]};
    const std::int64_t lane_at[4] = {at0[0], at0[1], at1[0], at1[1]};
    const double floor = best;
    for (int l = 0; l < 4; ++l) {
      const auto j = static_cast<std::size_t>(lane_at[l]);
      if (lane_w[l] > best || (lane_w[l] == best && lane_w[l] > floor && j < worst)) {
        best = lane_w[l];
        worst = j;
      }
    }
  }
  for (; i < hi; ++i) {
    const double c = dx * (ys[i] - ay) - dy * (xs[i] - ax), d = c * c;
    if (d > best) { best = d; worst = i; }
  }
  return worst;
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
      const double dx = P.x[hi] - P.x[lo], dy = P.y[hi] - P.y[lo];
      worst = farthest_from_chord(P.x.data(), P.y.data(), lo, hi, tol * std::sqrt(dx * dx + dy * dy));
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
  scan.validate();
  const std::size_t n = scan.ranges.size();
  const bool full = scan.full_circle();
  const double R = scan.max_range;
  const double lo_r = mp.min_range, hi_r = R - mp.range_margin;
  const double two_inc = 2 * scan.angle_increment;
  const BeamDirections& dir = beam_directions(scan);

  // Points, validity and breaks in beam order. A break between beams k-1 and k: either is
  // out of range, or an occlusion gap (further apart than gap + 2 r dtheta).
  thread_local ScanPoints P;
  P.x.resize(2 * n);
  P.y.resize(2 * n);
  P.valid.resize(2 * n);
  P.brk.resize(2 * n + 1);
  {  // raw pointers: stores through char would otherwise make the compiler reload every
     // vector's data pointer on each beam
    const double *r = scan.ranges.data(), *cs = dir.cos.data(), *sn = dir.sin.data();
    double *x = P.x.data(), *y = P.y.data();
    char *valid = P.valid.data(), *brk = P.brk.data();
    for (std::size_t k = 0; k < n; ++k) {
      valid[k] = r[k] > lo_r && r[k] < hi_r;
      x[k] = r[k] * cs[k];
      y[k] = r[k] * sn[k];
    }
    auto gap = [&](std::size_t a, std::size_t b) {  // beams a, b both valid
      const double thr = mp.gap + two_inc * std::max(r[a], r[b]);
      const double dx = x[a] - x[b], dy = y[a] - y[b];
      return dx * dx + dy * dy > thr * thr;
    };
    brk[0] = 1;
    for (std::size_t k = 1; k < n; ++k) brk[k] = !valid[k - 1] || !valid[k] || gap(k - 1, k);
    brk[n] = !full || !valid[n - 1] || !valid[0] || gap(n - 1, 0);  // across the seam
  }

  LocalMap m;
  m.observer = Point(0, 0);
  m.vertices.reserve(n / 2 + 16);  // one allocation per array in the common case
  m.edges.reserve(n / 2 + 16);
  m.corner.reserve(n / 2 + 16);
  Builder B{m};
  auto range_point = [&](double a) { return Point(R * std::cos(a), R * std::sin(a)); };
  // The range arc from angle a to b (a < b, unwrapped), after range_point(a) was added.
  auto arc = [&](double a, double b) {
    const int k = std::max(1, static_cast<int>(std::ceil((b - a) / mp.arc_step)));
    for (int j = 1; j <= k; ++j) B.add(range_point(a + (b - a) * j / k), EdgeKind::Range);
  };

  // Where to start walking: a cone at its first beam; a full circle at the first valid
  // beam that follows a break, so that no run wraps past the end of the walk.
  std::size_t start = 0;
  if (full) {
    start = n;
    for (std::size_t k = 0; k < n && start == n; ++k)
      if (P.valid[k] && P.brk[k == 0 ? n : k]) start = k;
    if (start == n) {
      bool any = false;
      for (std::size_t k = 0; k < n; ++k) any = any || P.valid[k];
      if (!any) {  // nothing in range all round: V is the range disc
        for (std::size_t i = 0; i < n; ++i) B.add(range_point(scan.angle(i)), EdgeKind::Range);
        m.edges.push_back(EdgeKind::Range);
        m.corner.push_back(kNone);
        straighten_occlusion_edges(m);
        m.validate("scan map");
        return m;
      }
      start = 0;  // one closed run all round
    }
    // Walk indices n .. start+n-1 are beams 0 .. start-1 again.
    std::copy_n(P.x.begin(), start, P.x.begin() + static_cast<std::ptrdiff_t>(n));
    std::copy_n(P.y.begin(), start, P.y.begin() + static_cast<std::ptrdiff_t>(n));
    std::copy_n(P.valid.begin(), start, P.valid.begin() + static_cast<std::ptrdiff_t>(n));
    std::copy_n(P.brk.begin() + 1, start, P.brk.begin() + static_cast<std::ptrdiff_t>(n + 1));
  } else {
    B.add(m.observer, EdgeKind::FieldOfView);
    m.observer_vertex = 0;
  }

  thread_local std::vector<std::size_t> fitted, stack;
  const auto quarter_turn = static_cast<std::size_t>(std::max(2.0, std::floor(M_PI / 2 / scan.angle_increment)));
  auto angle_at = [&](std::size_t kw) { return scan.angle_min + static_cast<double>(kw) * scan.angle_increment; };
  auto point = [&](std::size_t kw) { return Point(P.x[kw], P.y[kw]); };
  // Emits the fitted polyline of the run b..e (its first point is already emitted).
  auto flush = [&](std::size_t b, std::size_t e) {
    if (e == b) return;
    fitted.clear();
    simplify(P, b, e, mp.simplify, quarter_turn, fitted, stack);
    for (auto kw : fitted) B.add(point(kw), EdgeKind::Solid);
  };
  // Leaves the last emitted point radially for the range circle at angle a and follows
  // the circle to angle b: the first two edges of occlusion-range-occlusion.
  auto out_to_range = [&](double a, double b) {
    B.add(range_point(a), EdgeKind::Occlusion, B.last());
    arc(a, b);
  };
  // Across an occlusion gap the corner is the endpoint nearer the observer.
  auto nearer_of = [&](const Point& p, std::uint32_t p_index, std::uint32_t other) {
    return CGAL::compare_distance_to_point(m.observer, p, m.vertices[other]) == CGAL::SMALLER ? p_index : other;
  };

  constexpr std::size_t kNoReading = static_cast<std::size_t>(-1);
  std::size_t last = kNoReading, run = 0;  // walk index of the last valid reading; its run's first
  bool saw_invalid = false;
  const char *valid = P.valid.data(), *brk = P.brk.data();
  for (std::size_t kw = start; kw < start + n; ++kw) {
    if (!valid[kw]) { saw_invalid = true; continue; }
    if (last != kNoReading && !brk[kw]) { last = kw; continue; }  // the run goes on (the common case)
    const Point p = point(kw);
    if (last == kNoReading) {  // first valid reading
      if (!full && saw_invalid) {
        B.add(range_point(angle_at(0)), EdgeKind::FieldOfView);
        arc(angle_at(0), angle_at(kw));
        B.add(p, EdgeKind::Occlusion, B.next_index());
      } else {
        B.add(p, EdgeKind::FieldOfView);  // (full circle: the first vertex; no edge yet)
      }
    } else {
      flush(run, last);
      if (saw_invalid) {
        out_to_range(angle_at(last), angle_at(kw));
        B.add(p, EdgeKind::Occlusion, B.next_index());
      } else {
        B.add(p, EdgeKind::Occlusion, nearer_of(p, B.next_index(), B.last()));
      }
    }
    run = last = kw;
    saw_invalid = false;
  }
  if (last != kNoReading) flush(run, last);
  // Close the polygon.
  if (!full) {
    if (last == kNoReading) {  // nothing in range
      B.add(range_point(angle_at(0)), EdgeKind::FieldOfView);
      arc(angle_at(0), angle_at(n - 1));
    } else if (saw_invalid) {
      out_to_range(angle_at(last), angle_at(n - 1));
    }
    m.edges.push_back(EdgeKind::FieldOfView);
    m.corner.push_back(kNone);
  } else if (saw_invalid) {
    out_to_range(angle_at(last), angle_at(start + n));
    m.edges.push_back(EdgeKind::Occlusion);
    m.corner.push_back(0);
  } else if (P.brk[start == 0 ? n : start]) {  // the seam between the last reading and the first
    m.edges.push_back(EdgeKind::Occlusion);
    m.corner.push_back(nearer_of(m.vertices[0], 0, B.last()));
  } else {
    m.edges.push_back(EdgeKind::Solid);
    m.corner.push_back(kNone);
  }
  straighten_occlusion_edges(m);
  m.validate("scan map");
  return m;
}

}  // namespace preimage::tracking
