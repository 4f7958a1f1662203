// SPDX-License-Identifier: Apache-2.0
// Dubins' six words (LaValle, Planning Algorithms 15.3.1) and the exact certificate of the
// arcs a curvature-limited robot drives.
#include <preimage/coverage/turn_model.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace preimage::coverage {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// An angle in [0, 2 pi); within 1e-12 of a full turn it is none (rounding of an angle
// that is 0 must not make the robot drive a whole circle).
double mod2pi(double a) {
  a = std::fmod(a, kTwoPi);
  if (a < 0) a += kTwoPi;
  return a > kTwoPi - 1e-12 ? 0.0 : a;
}

// The three normalised lengths (t, p, q) of a word, in units of the radius, for the
// canonical problem: start at the origin heading alpha, goal at (d, 0) heading beta.
std::optional<std::array<double, 3>> word_lengths(DubinsWord w, double d, double alpha, double beta) {
  const double sa = std::sin(alpha), sb = std::sin(beta), ca = std::cos(alpha), cb = std::cos(beta);
  const double cab = std::cos(alpha - beta);
  switch (w) {
    case DubinsWord::LSL: {
      const double p2 = 2 + d * d - 2 * cab + 2 * d * (sa - sb);
      // p2 is a squared length: negative only by rounding (the circles coincide; then the
      // tangent's direction is noise, and dubins_curves adds the single arc).
      const double th = std::atan2(cb - ca, d + sa - sb);
      return std::array<double, 3>{mod2pi(th - alpha), std::sqrt(std::max(p2, 0.0)), mod2pi(beta - th)};
    }
    case DubinsWord::RSR: {
      const double p2 = 2 + d * d - 2 * cab + 2 * d * (sb - sa);
      const double th = std::atan2(ca - cb, d - sa + sb);
      return std::array<double, 3>{mod2pi(alpha - th), std::sqrt(std::max(p2, 0.0)), mod2pi(th - beta)};
    }
    case DubinsWord::LSR: {
      const double p2 = -2 + d * d + 2 * cab + 2 * d * (sa + sb);
      if (p2 < 0) return std::nullopt;
      const double p = std::sqrt(p2);
      const double th = std::atan2(-ca - cb, d + sa + sb) - std::atan2(-2.0, p);
      return std::array<double, 3>{mod2pi(th - alpha), p, mod2pi(th - beta)};
    }
    case DubinsWord::RSL: {
      const double p2 = d * d - 2 + 2 * cab - 2 * d * (sa + sb);
      if (p2 < 0) return std::nullopt;
      const double p = std::sqrt(p2);
      const double th = std::atan2(ca + cb, d - sa - sb) - std::atan2(2.0, p);
      return std::array<double, 3>{mod2pi(alpha - th), p, mod2pi(beta - th)};
    }
    case DubinsWord::RLR: {
      const double c = (6 - d * d + 2 * cab + 2 * d * (sa - sb)) / 8;
      if (std::fabs(c) > 1) return std::nullopt;
      const double p = mod2pi(kTwoPi - std::acos(c));
      const double t = mod2pi(alpha - std::atan2(ca - cb, d - sa + sb) + p / 2);
      return std::array<double, 3>{t, p, mod2pi(alpha - beta - t + p)};
    }
    case DubinsWord::LRL: {
      const double c = (6 - d * d + 2 * cab + 2 * d * (sb - sa)) / 8;
      if (std::fabs(c) > 1) return std::nullopt;
      const double p = mod2pi(kTwoPi - std::acos(c));
      const double t = mod2pi(-alpha - std::atan2(ca - cb, d + sa - sb) + p / 2);
      return std::array<double, 3>{t, p, mod2pi(beta - alpha - t + p)};
    }
  }
  return std::nullopt;
}

// Turn direction of each piece of a word: +1 left, -1 right, 0 straight.
std::array<int, 3> turns_of(DubinsWord w) {
  switch (w) {
    case DubinsWord::LSL: return {1, 0, 1};
    case DubinsWord::RSR: return {-1, 0, -1};
    case DubinsWord::LSR: return {1, 0, -1};
    case DubinsWord::RSL: return {-1, 0, 1};
    case DubinsWord::RLR: return {-1, 1, -1};
    case DubinsWord::LRL: return {1, -1, 1};
  }
  return {0, 0, 0};
}

}  // namespace

std::string_view to_string(DubinsWord w) {
  static constexpr std::array<std::string_view, 6> names{"LSL", "RSR", "LSR", "RSL", "RLR", "LRL"};
  return names[static_cast<std::size_t>(w)];
}

Pose drive(const Pose& p, const DrivePiece& piece, double radius) {
  const double x = p.at.x(), y = p.at.y(), h = p.heading;
  if (piece.turn == 0) return {Point(x + piece.length * std::cos(h), y + piece.length * std::sin(h)), h};
  // Left: the centre is r to the left of the heading; right: to the right.
  const double side = piece.turn > 0 ? 1.0 : -1.0;
  const double cx = x - side * radius * std::sin(h), cy = y + side * radius * std::cos(h);
  const double h2 = h + piece.turn;
  return {Point(cx + side * radius * std::sin(h2), cy - side * radius * std::cos(h2)), h2};
}

Pose DubinsCurve::at(double s) const {
  Pose p = from;
  for (const DrivePiece& piece : pieces) {
    if (s <= 0) break;
    const double part = std::min(s, piece.length);
    DrivePiece q = piece;
    if (piece.length > 0) q.turn = piece.turn * (part / piece.length);
    q.length = part;
    p = drive(p, q, radius);
    s -= part;
  }
  return p;
}

std::vector<DubinsCurve> dubins_curves(const Pose& a, const Pose& b, double radius) {
  std::vector<DubinsCurve> out;
  if (!(radius > 0)) return out;
  const double dx = b.at.x() - a.at.x(), dy = b.at.y() - a.at.y();
  const double d = std::hypot(dx, dy) / radius, phi = std::atan2(dy, dx);
  const double alpha = mod2pi(a.heading - phi), beta = mod2pi(b.heading - phi);
  // Every curve returned ends at b (to rounding); a word whose formula lost its digits does not.
  const double tol = 1e-9 * (radius + std::hypot(dx, dy));
  auto ends_at = [&](const DubinsCurve& c) {
    const Pose e = c.at(c.length());
    return std::hypot(e.at.x() - b.at.x(), e.at.y() - b.at.y()) <= tol && std::fabs(std::remainder(e.heading - b.heading, kTwoPi)) <= 1e-9;
  };
  for (const DubinsWord w : {DubinsWord::LSL, DubinsWord::RSR, DubinsWord::LSR, DubinsWord::RSL, DubinsWord::RLR, DubinsWord::LRL}) {
    const auto len = word_lengths(w, d, alpha, beta);
    if (!len) continue;
    DubinsCurve c{a, radius, w, {}};
    const auto turn = turns_of(w);
    for (std::size_t k = 0; k < 3; ++k) {
      const double l = (*len)[k] < 1e-12 ? 0.0 : (*len)[k];  // rounding of a piece that is not there
      c.pieces[k] = turn[k] == 0 ? DrivePiece{0, l * radius} : DrivePiece{turn[k] * l, l * radius};
    }
    if (ends_at(c)) out.push_back(c);
  }
  // A single arc (the circles of LSL or RSR coincide, where their formulas divide by ~0).
  for (const int side : {1, -1}) {
    const double turn = mod2pi(side * (b.heading - a.heading));
    DubinsCurve c{a, radius, side > 0 ? DubinsWord::LSL : DubinsWord::RSR, {}};
    c.pieces[0] = {side * turn, turn * radius};
    if (turn > 0 && ends_at(c)) out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](const DubinsCurve& x, const DubinsCurve& y) { return x.length() < y.length(); });
  return out;
}

ArcCertifier::ArcCertifier(const geometry::Environment& workspace, double robot_radius)
    : r_(robot_radius), clearance_(workspace, robot_radius) {}

bool ArcCertifier::segment(const Point& p, const Point& q) const {
  // p is in free space (see the header), so a segment r > 0 from every edge stays there.
  return r_ > 0 ? clearance_.clear(p, q, r_) : clearance_.admits(p, q);
}

std::vector<Point> ArcCertifier::sample_arc(const Pose& p, double radius, double turn) {
  const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(std::fabs(turn) / kChordTurn)));
  std::vector<Point> out;
  out.reserve(n);
  for (std::size_t k = 1; k <= n; ++k) {
    const double part = turn * static_cast<double>(k) / static_cast<double>(n);
    out.push_back(drive(p, {part, std::fabs(part) * radius}, radius).at);
  }
  return out;
}

bool ArcCertifier::arc(const Point& p, const std::vector<Point>& samples, double radius, double turn) const {
  if (samples.empty()) return true;
  // An arc turning by theta <= pi/2 lies within R (1 - cos(theta / 2)) of its chord (its
  // points project onto the chord); the slack covers the rounding of the chord ends (each
  // within a few ulps of the circle). One capsule around the chord of a run of samples is
  // tried first; where it touches an obstacle the run is halved, down to single chords.
  const double step = std::fabs(turn) / static_cast<double>(samples.size());
  const double scale = std::fabs(p.x()) + std::fabs(p.y()) + 2 * radius;
  const double slack = 64 * std::numeric_limits<double>::epsilon() * scale + 1e-9 * radius;
  auto point = [&](std::size_t k) -> const Point& { return k == 0 ? p : samples[k - 1]; };
  auto clear = [&](auto&& self, std::size_t i, std::size_t j) -> bool {
    const double theta = step * static_cast<double>(j - i);
    const double bulge = radius * (1 - std::cos(theta / 2)) * (1 + 1e-6) + slack;
    if (theta <= std::numbers::pi / 2 && clearance_.clear(point(i), point(j), std::nextafter(r_ + bulge, INFINITY))) return true;
    if (j == i + 1) return false;
    const std::size_t m = (i + j) / 2;
    return self(self, i, m) && self(self, m, j);
  };
  return clear(clear, 0, samples.size());
}

}  // namespace preimage::coverage
