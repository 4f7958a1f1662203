// SPDX-License-Identifier: Apache-2.0
// Internal to the contamination checker (checker.cpp) and its range sensor
// (checker_range.cpp): the moment the checker samples, and the event helpers both use.
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/geometry/segment_arrangement.hpp>

#include <array>
#include <optional>
#include <vector>

namespace preimage::pursuit::detail {

using geometry::Environment;
using geometry::ExactFT;
using geometry::ExactPoint;
using geometry::Point;

// A free edge of some V, split at environment vertices it grazes.
struct FreeSeg {
  ExactPoint a, b;
  geometry::SegmentEnd ea, eb;
  std::optional<std::pair<Point, Point>> carrier;  // input doubles on its line, when the pursuer is one
};

struct Moment {
  std::size_t waypoint;
  double fraction;
  std::vector<ExactPoint> at_exact;
  std::vector<Point> at;  // rounded
  std::vector<std::vector<ExactPoint>> loops;  // V of each pursuer, exact
  std::vector<CGAL::Bbox_2> boxes;  // per pursuer, V's box (a point outside it is not in V)
  std::vector<std::vector<ExactPoint>> ray_hits;  // per pursuer, V's constructed vertices (ends of free edges on walls)
  std::vector<FreeSeg> free;
  std::vector<std::size_t> free_begin;  // pursuer l's free edges: free[free_begin[l] .. free_begin[l + 1])
  std::vector<char> contact_seen;  // per vertex id at a contact: some pursuer sees the point
  // With a limited range (CheckOptions::range), per pursuer: the sensor polygon's corners
  // around it, their box, and the constructed points where its pieces end (corners in free
  // space, crossings with walls), which a moving pursuer's critical rays may pass.
  std::vector<std::vector<ExactPoint>> sensor;
  std::vector<CGAL::Bbox_2> sensor_boxes;
  std::vector<std::vector<ExactPoint>> sensor_points;
};

/// Is x in the closed convex polygon C (counter-clockwise corners; `box` holds them)?
inline bool in_convex(const std::vector<ExactPoint>& C, const CGAL::Bbox_2& box, const ExactPoint& x) {
  if (!CGAL::do_overlap(box, x.bbox())) return false;
  for (std::size_t i = 0; i < C.size(); ++i)
    if (geometry::orientation(C[i], C[(i + 1) % C.size()], x) < 0) return false;
  return true;
}

/// Is the line through reflex vertex u and point z tangent to the obstacle at u (u's
/// neighbours not strictly on opposite sides of it)? Only then can a ray graze u along it.
bool tangent_at(const Environment& env, std::uint32_t u, const ExactPoint& z);
/// The parameter in (0, 1) where segment a -> b crosses the line through p and q, if it does.
std::optional<ExactFT> crossing(const ExactPoint& ea, const ExactPoint& eb, const ExactPoint& p, const ExactPoint& q);
/// The events of a pursuer moving on a -> b on the critical rays of the line through p and
/// q (see checker.cpp), appended to `out`.
void ray_crossings(const ExactPoint& ea, const ExactPoint& eb, const ExactPoint& p, const ExactPoint& q, bool from_p, bool from_q,
                   bool whole_line, std::vector<ExactFT>& out);

/// The range sensor's pieces in free space for the pursuer whose corners are C, appended to
/// m.free (and their ends to m.sensor_points.back()).
void add_sensor_pieces(const Environment& env, const std::vector<ExactPoint>& C, Moment& m);

// The events of a range sensor's polygon Q carried by a pursuer moving on a -> b (its V's
// events are the critical rays above), where V ∩ (p + Q) or its meeting with a waiting
// pursuer's changes structure:
//   (i)   a corner of Q crosses a wall, (ii) a wall vertex crosses an edge of Q,
//   (iii) a corner of Q crosses the free edge beyond a reflex vertex,
//   (v)   a corner crosses a waiting pursuer's segment, (vi) a waiting pursuer's segment end
//         crosses an edge of Q, (vii) the mover's ray through a reflex vertex passes such an
//         end — all where p(t) crosses a fixed segment, so at rational t;
//   (iv)  the end of a free edge on a wall, or (ix) its crossing with an edge of Q, crosses
//         a wall or a waiting pursuer's segment — a quadratic in t. Its roots are bracketed
//         by exact signs, both ends of the bracket become cuts (one sample falls inside), and
//         a bracket that cannot be separated from another event is refused.
// Only walls, vertices and segments within the range of the path count.
struct RangeEvents {
  std::vector<ExactFT> cuts;
  struct Bracket {
    ExactFT lo, hi;            // exact ends: shrunk by exact bisection as far as needed
    std::array<ExactFT, 3> g;  // g(t) = g0 + g1 t + g2 t^2, exact
  };
  std::vector<Bracket> brackets;
};

void range_events(const Environment& env, const ExactPoint& a, const ExactPoint& b, const std::vector<Point>& Q, double R,
                  const std::vector<std::uint32_t>& reflex, const Moment* waiting, std::size_t mover, RangeEvents& out);

/// Adds the events of `re` to `events` (sorted): its exact cuts, and a cut at each end of
/// every bracket once each holds one root and no other event — shrunk by exact bisection
/// until it is apart from the others, or found to be the same event as another (an exact
/// event the quadratic vanishes at; two quadratics with their common root, rational, in
/// both). On axis-parallel plans one wall end is the end of two walls, and a hit there is
/// an event of both. Throws InputError (naming waypoint j) when they cannot be told apart.
void separate_range_events(RangeEvents& re, std::vector<ExactFT>& events, std::size_t j);

}  // namespace preimage::pursuit::detail
