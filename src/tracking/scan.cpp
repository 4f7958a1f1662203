// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/tracking/scan.hpp>

#include <cmath>
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

// Douglas-Peucker on pts[b..e] (inclusive), appending the kept points after pts[b]. A chord
// is also split when it spans a quarter turn or more about the sensor, so every fitted
// edge turns counter-clockwise about the observer.
void simplify(const std::vector<Point>& pts, std::size_t b, std::size_t e, double tol, std::vector<Point>& out,
              std::vector<std::size_t>& stack) {
  stack.clear();
  stack.push_back(e);
  std::size_t lo = b;
  const Point origin(0, 0);
  while (!stack.empty()) {
    const std::size_t hi = stack.back();
    std::size_t worst = lo;
    if (hi > lo + 1) {
      const double ax = pts[lo].x(), ay = pts[lo].y();
      const double dx = pts[hi].x() - ax, dy = pts[hi].y() - ay, len = std::hypot(dx, dy);
      double wd = tol * len;
      for (std::size_t i = lo + 1; i < hi; ++i) {
        const double d = std::abs(dx * (pts[i].y() - ay) - dy * (pts[i].x() - ax));
        if (d > wd) { wd = d; worst = i; }
      }
      if (worst == lo && (CGAL::angle(origin, pts[lo], origin, pts[hi]) != CGAL::ACUTE)) worst = (lo + hi) / 2;
    }
    if (worst == lo) {
      out.push_back(pts[hi]);
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
  thread_local std::vector<char> valid;
  thread_local std::vector<Point> pts;
  valid.assign(n, 0);
  pts.assign(n, Point(0, 0));
  const BeamDirections& dir = beam_directions(scan);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = scan.ranges[i];
    valid[i] = r > mp.min_range && r < R - mp.range_margin;
    if (valid[i]) pts[i] = Point(r * dir.cos[i], r * dir.sin[i]);
  }
  // A break between beam i-1 and i: an out-of-range reading, or an occlusion gap.
  auto gap_between = [&](std::size_t a, std::size_t b) {
    const double r = std::max(scan.ranges[a], scan.ranges[b]);
    const double thr = mp.gap + 2 * r * scan.angle_increment;
    return CGAL::squared_distance(pts[a], pts[b]) > thr * thr;
  };

  LocalMap m;
  m.observer = Point(0, 0);
  Builder B{m};
  auto range_point = [&](double a) { return Point(R * std::cos(a), R * std::sin(a)); };
  // The range arc from angle a to b (a < b, unwrapped), after range_point(a) was added.
  auto arc = [&](double a, double b) {
    const int k = std::max(1, static_cast<int>(std::ceil((b - a) / mp.arc_step)));
    for (int j = 1; j <= k; ++j) B.add(range_point(a + (b - a) * j / k), EdgeKind::Range);
  };

  // Beam order to walk: a cone from its first beam; a full circle from the first beam
  // that starts a run (after an out-of-range reading or a gap), so runs do not wrap.
  std::size_t start = 0;
  if (full) {
    start = n;
    for (std::size_t i = 0; i < n && start == n; ++i) {
      const std::size_t p = (i + n - 1) % n;
      if (valid[i] && (!valid[p] || gap_between(p, i))) start = i;
    }
    if (start == n) {
      bool any = false;
      for (auto v : valid) any = any || v;
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
  } else {
    B.add(m.observer, EdgeKind::FieldOfView);
    m.observer_vertex = 0;
  }

  std::vector<Point> run, fitted;
  std::vector<std::size_t> stack;
  auto angle_at = [&](std::size_t kw) { return scan.angle_min + static_cast<double>(kw) * scan.angle_increment; };
  // Emits the fitted polyline of the current run (its first point is already emitted).
  auto flush = [&]() {
    if (run.size() < 2) return;
    fitted.clear();
    simplify(run, 0, run.size() - 1, mp.simplify, fitted, stack);
    for (auto& q : fitted) B.add(q, EdgeKind::Solid);
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
  std::size_t last_kw = kNoReading;  // walk index of the last valid reading
  bool saw_invalid = false;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (start + k) % n;
    const std::size_t kw = start + k;  // unwrapped: angles keep increasing
    if (!valid[i]) { saw_invalid = true; continue; }
    const Point& p = pts[i];
    if (last_kw == kNoReading) {  // first valid reading
      if (!full && saw_invalid) {
        B.add(range_point(angle_at(0)), EdgeKind::FieldOfView);
        arc(angle_at(0), angle_at(kw));
        B.add(p, EdgeKind::Occlusion, B.next_index());
      } else {
        B.add(p, EdgeKind::FieldOfView);  // (full circle: the first vertex; no edge yet)
      }
      run.assign(1, p);
    } else if (!saw_invalid && !gap_between(last_kw % n, i)) {
      run.push_back(p);
    } else {
      flush();
      if (saw_invalid) {
        out_to_range(angle_at(last_kw), angle_at(kw));
        B.add(p, EdgeKind::Occlusion, B.next_index());
      } else {
        B.add(p, EdgeKind::Occlusion, nearer_of(p, B.next_index(), B.last()));
      }
      run.assign(1, p);
    }
    last_kw = kw;
    saw_invalid = false;
  }
  flush();
  // Close the polygon.
  if (!full) {
    if (last_kw == kNoReading) {  // nothing in range
      B.add(range_point(angle_at(0)), EdgeKind::FieldOfView);
      arc(angle_at(0), angle_at(n - 1));
    } else if (saw_invalid) {
      out_to_range(angle_at(last_kw), angle_at(n - 1));
    }
    m.edges.push_back(EdgeKind::FieldOfView);
    m.corner.push_back(kNone);
  } else {
    const std::size_t first_i = start % n;
    if (saw_invalid) {
      out_to_range(angle_at(last_kw), angle_at(start + n));
      m.edges.push_back(EdgeKind::Occlusion);
      m.corner.push_back(0);
    } else if (gap_between(last_kw % n, first_i)) {
      m.edges.push_back(EdgeKind::Occlusion);
      m.corner.push_back(nearer_of(m.vertices[0], 0, B.last()));
    } else {
      m.edges.push_back(EdgeKind::Solid);
      m.corner.push_back(kNone);
    }
  }
  straighten_occlusion_edges(m);
  m.validate("scan map");
  return m;
}

}  // namespace preimage::tracking
