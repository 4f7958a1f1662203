// SPDX-License-Identifier: Apache-2.0
#include <preimage/tracking/tracker.hpp>

#include <algorithm>
#include <cmath>

namespace preimage::tracking {

const char* to_string(Aggregation a) { return a == Aggregation::Recursive ? "recursive" : "plain"; }

namespace {

// Gauss-Newton fit of a circle of known radius to pts: minimises sum (|p - c| - r)^2,
// starting behind the cluster's centroid as seen from the sensor.
bool fit_circle(const std::vector<Vec2>& pts, double r, Vec2& c, double& rms) {
  Vec2 m;
  for (auto& p : pts) m = m + p;
  m = m * (1.0 / static_cast<double>(pts.size()));
  const double mn = m.norm();
  if (mn == 0) return false;
  c = m + m * (r / mn);
  for (int it = 0; it < 8; ++it) {
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    for (auto& p : pts) {
      const Vec2 d = c - p;
      const double n = d.norm();
      if (n == 0) return false;
      const Vec2 J = d * (1.0 / n);  // d(|c - p| - r)/dc
      const double res = n - r;
      a11 += J.x * J.x; a12 += J.x * J.y; a22 += J.y * J.y;
      b1 -= J.x * res; b2 -= J.y * res;
    }
    const double det = a11 * a22 - a12 * a12;
    if (std::abs(det) < 1e-18) break;
    const Vec2 step{(a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det};
    c = c + step;
    if (step.dot(step) < 1e-12) break;  // converged to a micrometre (readings are noisy to ~1 cm)
  }
  double ss = 0;
  for (auto& p : pts) ss += ((c - p).norm() - r) * ((c - p).norm() - r);
  rms = std::sqrt(ss / static_cast<double>(pts.size()));
  return std::isfinite(rms);
}

}  // namespace

namespace {

// The best-fitting cluster (nearest the prior, with one), before widening to its rim.
Detection best_cluster(const Scan& scan, const DetectParams& dp, const std::optional<Point>& prior) {
  Detection best;
  const std::size_t n = scan.ranges.size();
  const double margin = 0.05;
  auto valid = [&](std::size_t i) { return scan.ranges[i] > 0.01 && scan.ranges[i] < scan.max_range - margin; };
  const BeamDirections& dir = beam_directions(scan);
  auto point = [&](std::size_t i) { return Vec2{scan.ranges[i] * dir.cos[i], scan.ranges[i] * dir.sin[i]}; };
  thread_local std::vector<Vec2> cluster;
  double best_score = 1e300;
  const double jump2 = dp.jump * dp.jump;
  auto joins = [&](std::size_t i, std::size_t j) {  // beams i, j in one cluster (i, j valid)
    const Vec2 d = point(j) - point(i);
    return d.dot(d) <= jump2;
  };
  // The clusters that start in beams [from, to) (and may run on past `to`).
  auto scan_beams = [&](std::size_t from, std::size_t to) {
    std::size_t i = from;
    // A cluster running into `from` started before it: not ours.
    if (from > 0 && valid(from - 1))
      while (i < n && valid(i) && joins(i - 1, i)) ++i;
    while (i < to) {
      if (!valid(i)) { ++i; continue; }
      std::size_t j = i;
      Vec2 pj = point(j);
      while (j + 1 < n && valid(j + 1)) {
        const Vec2 q = point(j + 1), d = q - pj;
        if (d.dot(d) > jump2) break;
        pj = q;
        ++j;
      }
      const std::size_t a = i, b = j;
      i = j + 1;
      if (b - a + 1 < dp.min_points) continue;
      if ((point(b) - point(a)).norm() > 2.2 * dp.radius) continue;  // wider than the target
      // The cluster is an object of its own, not a piece of a longer surface: each flank
      // is empty, further (the target stands in front of what is behind it) or nearer than
      // all of it (an obstacle hides part of the target).
      double near = 1e300;
      for (std::size_t k = a; k <= b; ++k) near = std::min(near, scan.ranges[k]);
      auto flank_ok = [&](std::size_t k) { return !valid(k) || scan.ranges[k] > near + 0.5 * dp.radius || scan.ranges[k] < near; };
      const bool left_ok = a == 0 || flank_ok(a - 1);
      const bool right_ok = b + 1 == n || flank_ok(b + 1);
      if (!left_ok || !right_ok) continue;
      // With a prior, skip clusters whose fit could not pass the gate: a fit with rms <=
      // max_rms has every point within r + sqrt(N) max_rms of its centre.
      const double reach = dp.radius + std::sqrt(static_cast<double>(b - a + 1)) * dp.max_rms;
      if (prior && (point(a) - vec(*prior)).norm() > dp.gate + reach) continue;
      cluster.clear();
      for (std::size_t k = a; k <= b; ++k) cluster.push_back(point(k));
      Vec2 c;
      double rms;
      if (!fit_circle(cluster, dp.radius, c, rms) || rms > dp.max_rms) continue;
      double score = rms;
      if (prior) {
        const double d = (c - vec(*prior)).norm();
        if (d > dp.gate) continue;
        score = d;
      }
      ++best.candidates;
      if (score < best_score) {
        best_score = score;
        best.found = true;
        best.center = Point(c.x, c.y);
        best.rms = rms;
        best.first = a;
        best.last = b;
      }
    }
  };
  // With a prior, a cluster is fitted only if its first point lies within D = gate + reach
  // (at most r + sqrt(n) max_rms) of it, so only beams whose bearing is within
  // asin(D / |prior|) of the prior's (plus a beam either side) can start one.
  const double D = dp.gate + dp.radius + std::sqrt(static_cast<double>(n)) * dp.max_rms;
  const double dist = prior ? vec(*prior).norm() : 0;
  if (!prior || !(dist > D)) {
    scan_beams(0, n);
    return best;
  }
  const double half = std::asin(D / dist), inc = scan.angle_increment, nn = static_cast<double>(n);
  double bearing = std::atan2(prior->y(), prior->x());
  while (bearing < scan.angle_min) bearing += 2 * M_PI;  // into [angle_min, angle_min + 2 pi)
  while (bearing >= scan.angle_min + 2 * M_PI) bearing -= 2 * M_PI;
  // The window in beam indices, inclusive: k0 >= -n/4 - 2, k1 < 5n/4 + 2 for a full circle.
  const double k0 = std::floor((bearing - half - scan.angle_min) / inc) - 1;
  const double k1 = std::ceil((bearing + half - scan.angle_min) / inc) + 1;
  if (scan.full_circle()) {
    if (k1 - k0 + 1 >= nn) {
      scan_beams(0, n);
    } else {  // one range, or two across the seam
      const auto from = static_cast<std::size_t>(k0 < 0 ? k0 + nn : k0), len = static_cast<std::size_t>(k1 - k0 + 1);
      scan_beams(from, std::min(n, from + len));
      if (from + len > n) scan_beams(0, from + len - n);
    }
    return best;
  }
  // A cone: the window, and its copy a turn earlier (a prior just clockwise of the first
  // beam has its bearing near angle_min + 2 pi), clipped to the beams; the two merged
  // when they meet.
  const double turn = 2 * M_PI / inc;
  const double lo1 = std::max(0.0, k0), hi1 = std::min(nn - 1, k1);
  const double lo2 = std::max(0.0, k0 - turn), hi2 = std::min(nn - 1, k1 - turn);
  auto scan_window = [&](double lo, double hi) {
    scan_beams(static_cast<std::size_t>(lo), static_cast<std::size_t>(hi) + 1);
  };
  if (lo2 <= hi2 && lo1 <= hi1 && hi2 + 1 >= lo1) {
    scan_window(lo2, std::max(hi1, hi2));
  } else {
    if (lo2 <= hi2) scan_window(lo2, hi2);
    if (lo1 <= hi1) scan_window(lo1, hi1);
  }
  return best;
}

// A target touching an obstacle is one cluster with it, too wide to be the target. With
// an estimate, the readings near it (within the radius and one step's motion of it,
// contiguous about the beam that points at it) are fitted, dropping the points off the
// circle once (the obstacle's), and kept if the circle fits.
Detection beside_obstacle(const Scan& scan, const DetectParams& dp, const Point& prior) {
  Detection d;
  const std::size_t n = scan.ranges.size();
  const BeamDirections& dir = beam_directions(scan);
  const Vec2 e = vec(prior);
  auto near_prior = [&](std::size_t k) {
    const double r = scan.ranges[k];
    return r > 0.01 && r < scan.max_range - 0.05 && (Vec2{r * dir.cos[k], r * dir.sin[k]} - e).norm() <= dp.radius + dp.jump;
  };
  const double m = std::round((std::atan2(prior.y(), prior.x()) - scan.angle_min) / scan.angle_increment);
  const double nn = static_cast<double>(n);
  std::size_t mid = n;
  for (double k : {m, m - 1, m + 1, m - 2, m + 2}) {
    const double kk = scan.full_circle() ? std::fmod(k + 2 * nn, nn) : k;
    if (kk >= 0 && kk < nn && near_prior(static_cast<std::size_t>(kk))) { mid = static_cast<std::size_t>(kk); break; }
  }
  if (mid == n) return d;
  std::size_t a = mid, b = mid;
  while (a > 0 && near_prior(a - 1)) --a;
  while (b + 1 < n && near_prior(b + 1)) ++b;
  thread_local std::vector<Vec2> pts;
  auto fit = [&](Vec2& c, double& rms) {
    pts.clear();
    for (std::size_t k = a; k <= b; ++k) pts.push_back(Vec2{scan.ranges[k] * dir.cos[k], scan.ranges[k] * dir.sin[k]});
    return pts.size() >= dp.min_points && fit_circle(pts, dp.radius, c, rms);
  };
  Vec2 c;
  double rms;
  // Drop the obstacle's readings, those off the fitted circle at either end, and refit
  // (a few times: the first fit is pulled towards the obstacle).
  auto off = [&](std::size_t k) {
    const double r = scan.ranges[k];
    return std::abs((Vec2{r * dir.cos[k], r * dir.sin[k]} - c).norm() - dp.radius) > 2 * dp.max_rms;
  };
  for (int round = 0; round < 4; ++round) {
    if (!fit(c, rms)) return d;
    const std::size_t a0 = a, b0 = b;
    while (a < b && off(a)) ++a;
    while (b > a && off(b)) --b;
    if (a == a0 && b == b0) break;
  }
  if (!fit(c, rms) || rms > dp.max_rms || (c - e).norm() > dp.gate) return d;
  // A short piece of wall also fits a circle of the radius within max_rms; the target's
  // arc bulges towards the sensor (by the sagitta of its chord, less where the window
  // still ends on the obstacle), a wall's by its noise only.
  const Vec2 pa = pts.front(), pb = pts.back(), ab = pb - pa;
  const double chord = ab.norm();
  if (chord == 0) return d;
  double bulge = 0;
  const double towards = ab.cross(pa * -1.0) > 0 ? 1.0 : -1.0;  // the sensor's side of the chord
  for (const Vec2& q : pts) bulge = std::max(bulge, towards * ab.cross(q - pa) / chord);
  const double sagitta = dp.radius - std::sqrt(std::max(0.0, dp.radius * dp.radius - chord * chord / 4));
  if (bulge < 0.25 * sagitta || bulge < dp.max_rms) return d;
  d.found = true;
  d.center = Point(c.x, c.y);
  d.rms = rms;
  d.first = a;
  d.last = b;
  d.candidates = 1;
  return d;
}

}  // namespace

namespace {

// Detection within one indexing of the beams: the best cluster (or, with an estimate,
// the target beside an obstacle), widened to the readings on its rim.
Detection detect_in(const Scan& scan, const DetectParams& dp, const std::optional<Point>& prior) {
  Detection d = best_cluster(scan, dp, prior);
  if (!d.found && prior) d = beside_obstacle(scan, dp, *prior);
  if (!d.found) return d;
  const BeamDirections& dir = beam_directions(scan);
  const Vec2 c = vec(d.center);
  // A reading on the fitted circle, and not nearer than the disc's nearest point (which
  // an obstacle hiding part of the target is).
  auto on_rim = [&](std::size_t k) {
    const double r = scan.ranges[k];
    if (!(r > 0.01 && r < scan.max_range - 0.05) || r < c.norm() - dp.radius - dp.rim) return false;
    return (Vec2{r * dir.cos[k], r * dir.sin[k]} - c).norm() <= dp.radius + dp.rim;
  };
  while (d.first > 0 && on_rim(d.first - 1)) --d.first;
  while (d.last + 1 < scan.ranges.size() && on_rim(d.last + 1)) ++d.last;
  return d;
}

}  // namespace

Detection detect_target(const Scan& scan, const DetectParams& dp, const std::optional<Point>& prior) {
  Detection d = detect_in(scan, dp, prior);
  const std::size_t n = scan.ranges.size();
  // Clusters stop at the seam of a 360-deg scan (straight behind). If the target may lie
  // across it, look again with the beams indexed from half a turn on, and say where its
  // beams are in the scan's own indices (first > last: round through the seam).
  if (!scan.full_circle() || (d.found && d.first > 0 && d.last + 1 < n)) return d;
  thread_local Scan turned;
  const std::size_t h = n / 2;
  turned.timestamp = scan.timestamp;
  turned.max_range = scan.max_range;
  turned.angle_increment = scan.angle_increment;
  turned.angle_min = scan.angle_min + static_cast<double>(h) * scan.angle_increment;
  turned.ranges.resize(n);
  for (std::size_t i = 0; i < n; ++i) turned.ranges[i] = scan.ranges[(i + h) % n];
  Detection t = detect_in(turned, dp, prior);
  if (!t.found || t.first == 0 || t.last + 1 == n) return d;
  t.first = (t.first + h) % n;
  t.last = (t.last + h) % n;
  return t;
}

namespace {
// Replaces the target's readings in s (a copy of the scan) by the background (see
// without_target). Its beams run from d.first to d.last, round through the seam of a full
// circle if first > last.
void fill_shadow(Scan& s, const Detection& d, const MapParams& mp) {
  const std::size_t n = s.ranges.size(), m = (d.last + n - d.first) % n + 1;
  const bool round = s.full_circle() && m < n;
  const bool has_l = round || d.first > 0, has_r = round || d.last + 1 < n;
  const double left = s.ranges[(d.first + n - 1) % n], right = s.ranges[(d.last + 1) % n];
  const double rl = has_l ? left : (has_r ? right : s.max_range);
  const double rr = has_r ? right : rl;
  auto no_return = [&](double r) { return r <= mp.min_range || r >= s.max_range - mp.range_margin; };
  const bool open = no_return(rl) || no_return(rr), one_surface = std::abs(rl - rr) <= mp.gap;
  for (std::size_t j = 0; j < m; ++j) {
    double& r = s.ranges[(d.first + j) % n];
    if (open) {
      r = s.max_range;
    } else if (one_surface) {
      const double f = static_cast<double>(j + 1) / static_cast<double>(m + 1);
      r = rl + f * (rr - rl);
    } else {
      r = std::max(rl, rr);
    }
  }
}
}  // namespace

Scan without_target(const Scan& scan, const Detection& d, const MapParams& mp) {
  Scan s = scan;
  if (d.found) fill_shadow(s, d, mp);
  return s;
}

LocalMap local_map_without_target(const Scan& scan, const Detection& d, const MapParams& mp) {
  if (!d.found) return local_map_from_scan(scan, mp);
  thread_local Scan filled;  // (assignment reuses its buffer: one scan per TRACK iteration)
  filled = scan;
  fill_shadow(filled, d, mp);
  return local_map_from_scan(filled, mp);
}

namespace {
Command clamp(Command c, const ControlParams& p) {
  c.v = std::clamp(c.v, p.reverse ? -p.v_max : 0.0, p.v_max);
  c.omega = std::clamp(c.omega, -p.omega_max, p.omega_max);
  return c;
}
Command regulator(const Point& t, const ControlParams& p) {
  const double dist = std::hypot(t.x(), t.y()), bearing = std::atan2(t.y(), t.x());
  return {p.k_distance * (dist - p.preferred_distance) * std::max(0.0, std::cos(bearing)), p.k_bearing * bearing};
}
}  // namespace

ControlTerms risk_control(const RiskAverage& risk, const Point& target, const ControlParams& p) {
  ControlTerms out;
  const double dist = std::hypot(target.x(), target.y()), bearing = std::atan2(target.y(), target.x());
  if (dist > 0) out.pull = Vec2{target.x(), target.y()} * (p.k_distance * (dist - p.preferred_distance) / dist);
  if (risk.phi > 0) out.descent = risk.gradient * (-p.k_v / risk.phi);
  const Vec2 D = out.descent + out.pull;
  const double len = D.norm();
  Command c{D.x, len > 0 ? p.k_omega * D.y / len : 0.0};  // n = (1, 0): n . D and n x D
  if (p.centre_target) c.omega += p.k_bearing * bearing;
  out.command = clamp(c, p);
  return out;
}

Command naive_command(const Point& target, const ControlParams& p) { return clamp(regulator(target, p), p); }

TrackStep track(const Scan& scan, const TrackerParams& tp, const std::optional<Point>& prior) {
  TrackStep out;
  out.detection = detect_target(scan, tp.detect, prior);
  out.map = local_map_without_target(scan, out.detection, tp.map);
  if (!out.detection.found) return out;
  auto tree = try_escape_path_tree(out.map, out.detection.center);
  if (!tree) return out;  // the target is not inside V
  out.tracked = true;
  out.tree = std::move(*tree);
  out.risks = escape_risks(out.map, out.tree, tp.risk);
  out.risk = tp.aggregation == Aggregation::Recursive ? recursive_average(out.tree, out.risks) : plain_average(out.risks);
  out.control = risk_control(out.risk, out.detection.center, tp.control);
  return out;
}

}  // namespace preimage::tracking
