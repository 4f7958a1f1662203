// SPDX-License-Identifier: Apache-2.0
// Range-limited visibility: V(q) ∩ D(q, R), the part of the visibility polygon within
// distance R of the viewpoint (a sensor with a finite range).
//
// V(q) is star-shaped with respect to q and so is the disc, so the boundary of the
// intersection runs counter-clockwise around q through pieces of V's edges that lie in
// the disc and, where V's boundary leaves the disc, circle arcs to where it comes back.
// Every piece is described symbolically: a segment piece lies on one edge of V (an
// environment edge or a free edge) and ends at vertices of V or at crossings of that
// edge with the circle; an arc runs counter-clockwise from one such end to the next.
//
// Exactness. Along an edge a + t(b - a) of V the squared distance to q is the quadratic
// g(t) = A t^2 + 2 B t + C with A = |b-a|^2, B = (a-q).(b-a), C = |a-q|^2 - R^2: its
// coefficients are exact (lazy-exact rationals, R is a double so R^2 is exact too). Which
// part of the edge is in the closed disc is decided by signs of rationals only — g(0),
// g(1), the discriminant B^2 - A C, B, A + B — never by comparing square roots, so every
// piece and every crossing is decided exactly. A crossing's exact value is the root
// (-B ∓ sqrt(B^2 - A C)) / A of that quadratic (`RangePoint::crossing_parameter` gives
// it in doubles); coordinates, angles and the area are doubles for drawing and reports:
// the area of a circular sector is transcendental, so no finite number type holds it.
#pragma once
#include <preimage/geometry/visibility.hpp>

#include <cstdint>
#include <vector>

namespace preimage::geometry {

/// An end of a piece of the boundary of V(q) ∩ disc.
struct RangePoint {
  enum class Kind : std::uint8_t {
    PolygonVertex,  // vertex `vertex` of V(q) (inside the disc or on the circle)
    Crossing        // where edge `edge` of V(q) crosses the circle
  };
  Kind kind = Kind::PolygonVertex;
  std::uint32_t vertex = kNone;  // PolygonVertex: index into V(q).vertices
  std::uint32_t edge = kNone;    // Crossing: index of V's edge (vertex edge -> vertex edge+1)
  bool entering = false;         // Crossing: V's boundary enters the disc here (the smaller root), else leaves it
  Point approx;                  // double rounding, for drawing and reports
};

/// One piece of the boundary, counter-clockwise around q.
struct RangePiece {
  enum class Kind : std::uint8_t { Segment, Arc };
  Kind kind = Kind::Segment;
  RangePoint from, to;           // unset (kind PolygonVertex, vertex kNone) for a full circle
  std::uint32_t edge = kNone;    // Segment: the edge of V(q) it lies on (V.edges[edge]: solid or free)
  double from_angle = 0;         // Arc: direction of `from` seen from q, radians in (-pi, pi]
  double span = 0;               // Arc: counter-clockwise angle swept, in (0, 2 pi] (2 pi: full circle)
};

/// V(q) ∩ D(q, R).
struct RangeVisibility {
  VisibilityPolygon polygon;     // V(q) itself, unlimited
  double range = 0;
  std::vector<RangePiece> pieces;  // the boundary, counter-clockwise
  /// The whole disc is visible (V's boundary stays outside the open disc): `pieces` is one
  /// Arc with span 2 pi from angle 0, its ends unset.
  bool full_disc = false;

  const Point& query() const { return polygon.query; }
  /// Area (double): triangles from q over segment pieces plus circular sectors.
  double area() const;
  /// Does the closed region contain p? Exact: |p - q|^2 <= R^2 and p in the closed V(q).
  bool contains(const Point& p) const;
  /// The boundary as a polygon for drawing: arcs subdivided into steps of at most
  /// `max_step` radians (the chords lie inside the region: an inner approximation).
  std::vector<Point> outline(double max_step = 0.05) const;
};

/// The parameter t in [0, 1] of a circle crossing along its edge of V(q) (the exact root
/// of the quadratic above, rounded to double; 0 or 1 for a polygon vertex at that end).
double crossing_parameter(const RangeVisibility& r, const RangePoint& p);

/// V(q) ∩ D(q, R) from V(q) (any VisibilityPolygon, e.g. from VisibilityIndex::compute).
/// Throws std::invalid_argument unless R is finite and > 0.
RangeVisibility limit_range(VisibilityPolygon polygon, double range);
/// The same, computing V(q) with the index; throws InputError if q is not in free space.
RangeVisibility range_visibility(const VisibilityIndex& index, const Point& q, double range);

}  // namespace preimage::geometry
