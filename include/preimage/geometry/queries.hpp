// SPDX-License-Identifier: Apache-2.0
// Exact one-shot queries on an Environment: point location, ray shooting, two-point
// visibility. Each is O(n) and needs no preprocessing; VisibilityIndex answers many
// visibility queries on one environment faster.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <optional>
#include <span>
#include <vector>

namespace preimage::geometry {

struct Location {
  enum class Kind { Interior, OnEdge, AtVertex, InHole, Outside };
  Kind kind;
  std::size_t index = 0;  // edge id (OnEdge), vertex id (AtVertex), hole number 0.. (InHole)
  bool in_free_space() const { return kind == Kind::Interior || kind == Kind::OnEdge || kind == Kind::AtVertex; }
};
const char* to_string(Location::Kind k);

/// Where q lies: in the open free space, on the relative interior of edge e, at vertex v,
/// strictly inside hole h, or outside the outer boundary.
Location locate(const Environment& env, const Point& q);
/// The same for a constructed point (e.g. a ray hit on an edge), decided exactly.
Location locate(const Environment& env, const ExactPoint& q);

struct RayHit {
  ExactPoint point;         // exact first contact
  std::size_t edge;         // edge containing it (for a vertex: the edge starting there)
  std::optional<std::size_t> vertex;  // set when the contact is a vertex
  bool along_edge = false;  // the ray runs along `edge` from its origin
};

/// First boundary point met by the ray from `origin` in direction `dir`, strictly
/// beyond the origin. The origin is meant to lie in closed free space.
std::optional<RayHit> shoot_ray(const Environment& env, const ExactPoint& origin,
                                const ExactKernel::Vector_2& dir);
inline std::optional<RayHit> shoot_ray(const Environment& env, const Point& origin, const Point& toward) {
  return shoot_ray(env, to_exact(origin), to_exact(toward) - to_exact(origin));
}

/// Distance from `origin` along direction `angle` (radians) to the boundary, or
/// `max_range` if nothing is nearer: a floating-point *measurement* for simulated range
/// sensors (a laser's reading), not a decision — nothing is decided on it exactly.
double ray_range(const Environment& env, const Point& origin, double angle, double max_range);

/// Does the closed segment pq lie in closed free space (grazing the boundary allowed)?
/// p and q may be interior points, on edges or at vertices.
bool visible(const Environment& env, const Point& p, const Point& q);
/// The same for constructed points (e.g. cut endpoints on edges).
bool visible(const Environment& env, const ExactPoint& p, const ExactPoint& q);

/// Is direction towards t, from boundary vertex v, inside the closed free-space wedge at v?
bool in_free_wedge(const Environment& env, std::size_t v, const Point& t);  // at a contact: outside every ring there
/// At boundary vertex v's point (t elsewhere): the vertex id w there whose free wedge (from
/// w's out-edge counter-clockwise to the in-edge of wedge_end(w), both edges included)
/// holds the direction towards t; SIZE_MAX when that direction points into material.
/// Without contacts: v or SIZE_MAX.
std::size_t wedge_toward(const Environment& env, std::size_t v, const Point& t);
std::size_t wedge_toward(const Environment& env, std::size_t v, const ExactPoint& t);

/// Winding number of the closed polyline `loop` (last point joined to the first) about
/// c, counter-clockwise positive. Exact (crossings of the ray from c to +x, decided by
/// orientation predicates); c must not lie on the polyline.
long winding_number(std::span<const ExactPoint> loop, const ExactPoint& c);

/// A crossing of a polyline with a segment ab.
struct PolylineCrossing {
  std::size_t segment;  // polyline segment path[segment] -> path[segment + 1]
  ExactPoint at;
  int sign;             // +1: from the right of a->b to its left; -1: the other way
};
/// Where the polyline crosses the open segment ab (or, if `ray`, the open ray from a
/// through b), in order along the polyline. A polyline vertex on ab's line counts as
/// lying just left of it (a symbolic perturbation), so touching ab or running along it
/// is not a crossing and every crossing is counted consistently. Throws
/// std::invalid_argument if the polyline passes through a (or b, for a segment).
std::vector<PolylineCrossing> polyline_crossings(std::span<const ExactPoint> path, const ExactPoint& a,
                                                 const ExactPoint& b, bool ray = false);

}  // namespace preimage::geometry
