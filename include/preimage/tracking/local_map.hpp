// SPDX-License-Identifier: Apache-2.0
// The observer's local map (section V.A): its visibility polygon V(q^o), star-shaped
// about the observer, with every edge tagged solid (seen obstacle) or free (occlusion,
// range) — free edges are where a target can leave the view (section III). Built from a
// laser scan (scan.hpp) or from the exact visibility polygon of the geometry core, so the
// two can be compared.
#pragma once
#include <preimage/geometry/kernel.hpp>
#include <preimage/geometry/visibility.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace preimage::tracking {

using geometry::Point;
inline constexpr std::uint32_t kNone = 0xffffffffu;

enum class EdgeKind : std::uint8_t {
  Solid,        // part of an obstacle the sensor saw
  Occlusion,    // free: the line of sight past an occluding corner
  Range,        // free: the edge of the sensor's range across an out-of-range gap
  FieldOfView,  // bound of a sensor cone narrower than 360 deg (through the observer)
};
const char* to_string(EdgeKind k);
/// Edges a target escapes through. Field-of-view bounds are not: as in the paper (V.A)
/// the centring regulator, not the escape risk, keeps the target inside the cone.
inline bool is_escape(EdgeKind k) { return k == EdgeKind::Occlusion || k == EdgeKind::Range; }

/// V(q^o) as a counter-clockwise polygon whose vertices are in angular order about the
/// observer. Edge i runs from vertex i to vertex i+1 (cyclically). With a cone of at most
/// 180 deg the observer itself is a vertex (`observer_vertex`) between the two
/// field-of-view edges; with 360 deg it is inside.
struct LocalMap {
  Point observer;
  std::vector<Point> vertices;
  std::vector<EdgeKind> edges;
  /// For an occlusion edge: the vertex index of its occluding corner (the endpoint nearer
  /// the observer), whose distance is r_o of equation (3). kNone otherwise.
  std::vector<std::uint32_t> corner;
  std::uint32_t observer_vertex = kNone;

  std::size_t size() const { return vertices.size(); }
  std::size_t next(std::size_t i) const { return i + 1 == vertices.size() ? 0 : i + 1; }
  std::size_t prev(std::size_t i) const { return i == 0 ? vertices.size() - 1 : i - 1; }
  std::size_t count(EdgeKind k) const;
  double area() const;
  /// Is p in the closed polygon (exact)?
  bool contains(const Point& p) const;
  /// Is p strictly inside (exact)?
  bool strictly_contains(const Point& p) const;
  /// Every precondition of the sweep: at least 3 vertices, counter-clockwise angular
  /// order about the observer (no edge turning back), corners set. Throws InputError naming
  /// the offending vertex; `what` prefixes the message.
  void validate(const std::string& what = "local map") const;
};

/// Occlusion edges (and solid edges seen edge-on) are radial: their ends are on one ray
/// from the observer. Rounded to doubles, the far end may fall a hair clockwise of it, and
/// V would no longer be star-shaped. This turns such far ends about the observer by the least amount (from
/// 1e-15 rad up) that exact orientation accepts.
void straighten_occlusion_edges(LocalMap& map);

/// The local map from the exact visibility polygon of the geometry core (unlimited range,
/// 360 deg): solid edges on environment edges, occlusion edges from the reflex vertex
/// outwards. Vertex coordinates are rounded to doubles, as sensor data would be; the
/// decisions made on them afterwards are exact. Throws InputError if the observer is on
/// the boundary (V is then not star-shaped about an interior point).
LocalMap local_map_from_visibility(const geometry::VisibilityPolygon& vis);

}  // namespace preimage::tracking
