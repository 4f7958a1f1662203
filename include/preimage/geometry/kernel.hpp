// SPDX-License-Identifier: Apache-2.0
// The exact-predicate core every module decides with.
//
// Input coordinates are doubles, so input points are represented exactly by
// `Point` (CGAL's Epick kernel) and every orientation / incidence test on them is
// an exact filtered predicate. Points that are *constructed* (ray hits, visibility
// vertices on an edge) are `ExactPoint` (Epeck, lazy exact) so later decisions on
// them stay exact. No decision anywhere uses an epsilon.
#pragma once
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace preimage::geometry {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;  // predicates exact
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;
using Vector = Kernel::Vector_2;
using Segment = Kernel::Segment_2;
using ExactPoint = ExactKernel::Point_2;
using ExactFT = ExactKernel::FT;

/// Sign of the turn a -> b -> c: +1 left (counter-clockwise), 0 collinear, -1 right.
inline int orientation(const Point& a, const Point& b, const Point& c) {
  return static_cast<int>(CGAL::orientation(a, b, c));
}
inline int orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
  return static_cast<int>(CGAL::orientation(a, b, c));
}

/// Sign of the dot product (b - a) . (d - c): +1 acute, 0 right angle, -1 obtuse — exactly
/// CGAL::angle(a, b, c, d). Epick filters Angle_2 only dynamically (an interval evaluation
/// with a rounding-mode switch per call, several times an orientation test); this puts in
/// front the semi-static filter of CGAL's own Angle_3 (same expression shape: differences
/// of doubles, products, a sum; same error bound and under/overflow guards) and falls back
/// to CGAL::angle whenever the double sign is not certain. Hot in the escape-path sweep.
inline int dot_sign(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y(), vx = d.x() - c.x(), vy = d.y() - c.y();
  const double mu = std::max(std::abs(ux), std::abs(uy)), mv = std::max(std::abs(vx), std::abs(vy));
  if (mu == 0 || mv == 0) return 0;  // a zero vector (a difference of doubles is 0 only for equal doubles)
  if (std::min(mu, mv) > 1e-146 && std::max(mu, mv) < 7e153) {  // thresholds of Static_filters/Angle_3.h
    const double s = ux * vx + uy * vy, eps = 1.6e-15 * mu * mv;
    if (s > eps) return 1;
    if (s < -eps) return -1;
  }
  return static_cast<int>(CGAL::angle(a, b, c, d));
}
/// Sign of (p - q) . (r - q), the angle at q: CGAL::angle(p, q, r), filtered as dot_sign.
inline int angle_sign(const Point& p, const Point& q, const Point& r) { return dot_sign(q, p, q, r); }

/// Which half-turn around c the direction c -> q lies in: 0 for angles [0, pi) from
/// east, 1 for [pi, 2 pi). Predicates only (p.x() of a lazy point builds a DAG node).
template <class P>
int half_turn(const P& c, const P& q) {
  return CGAL::compare_yx(q, c) == CGAL::LARGER ? 0 : 1;
}
/// Counter-clockwise order of the directions c -> a, c -> b, starting at east (exact).
template <class P>
bool ccw_less(const P& c, const P& a, const P& b) {
  const int ha = half_turn(c, a), hb = half_turn(c, b);
  if (ha != hb) return ha < hb;
  return CGAL::orientation(c, a, b) == CGAL::LEFT_TURN;
}

/// Lexicographic order (x, then y): the sweep order used by segment sweeps.
inline bool lex_less_xy(const Point& a, const Point& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

/// True if c lies on the closed segment [a, b] (exact).
inline bool on_segment(const Point& a, const Point& b, const Point& c) {
  return orientation(a, b, c) == 0 && CGAL::collinear_are_ordered_along_line(a, c, b);
}
/// True if c lies strictly inside the segment (a, b), not at an endpoint.
inline bool strictly_inside_segment(const Point& a, const Point& b, const Point& c) {
  return orientation(a, b, c) == 0 && CGAL::collinear_are_strictly_ordered_along_line(a, c, b);
}

/// For two non-crossing segments, each given left end first (lexicographic), whose
/// x-ranges overlap: is segment a below segment b on a vertical line crossing both?
/// One exact orientation test: the later-starting segment's left end against the other.
inline bool segment_below(const Point& La, const Point& Ra, const Point& Lb, const Point& Rb) {
  if (La == Lb) return orientation(La, Ra, Rb) > 0;
  if (lex_less_xy(Lb, La)) return orientation(Lb, Rb, La) < 0;
  return orientation(La, Ra, Lb) > 0;
}

inline ExactPoint to_exact(const Point& p) { return ExactPoint(p.x(), p.y()); }
inline Point to_double(const ExactPoint& p) {
  return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
}
/// Rounded from the exact value. to_double rounds a lazy number's current interval, which
/// tightens once anything needs the exact value, so its result depends on what was
/// computed before; this one does not (the pursuit checker's double samples: house 1451's
/// verdict changed with the order its moments were taken in). Costs the exact value.
inline Point to_double_canonical(const ExactPoint& p) {
  return Point(CGAL::to_double(CGAL::exact(p.x())), CGAL::to_double(CGAL::exact(p.y())));
}

/// "1.5" — shortest faithful-enough decimal for messages.
std::string format_number(double v);
/// "(1.5, 2)" — for error messages and reports.
std::string format_point(double x, double y);
inline std::string format_point(const Point& p) { return format_point(p.x(), p.y()); }
/// An exact point in messages: its nearest doubles.
inline std::string format_point(const ExactPoint& p) { return format_point(to_double(p)); }

/// An exact number as a rational string in lowest terms, without a decimal point ("7/2",
/// "-3"): what --json outputs give beside the rounded doubles.
std::string exact_string(const ExactFT& v);
/// The exact value of a rational string "p/q" (q not 0), an integer, or a decimal ("-12.5",
/// "1.5e-3"; the exponent at most 400 in magnitude), with no rounding: "0.1" is 1/10. An
/// optional sign leads; nothing else (no spaces). Nothing for any other text.
std::optional<ExactFT> parse_exact_number(std::string_view text);

}  // namespace preimage::geometry
