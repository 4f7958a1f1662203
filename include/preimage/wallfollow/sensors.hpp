// SPDX-License-Identifier: Apache-2.0
// Ground truth for the sensors of section VI of the wall-following paper, computed from
// the environment by exact geometry; the simulator reads them out, strategies never see
// this header's types.
//
// - Shadow components of a simple polygon as arcs of its boundary: every component of
//   E \ V(q) is cut off by one free edge of V(q) and holds the open boundary arc between
//   that edge's ends (counter-clockwise from its start to its end, V being
//   counter-clockwise). The gap sensor follows them along a motion: V is computed exactly
//   at the motion's ends and once between every two crossings of a line through a reflex
//   vertex and a vertex it sees (between such crossings V only deforms), and two
//   components at consecutive samples correspond iff one holds a germ of the other — the
//   boundary just beyond a vertex at an end of its arc, i.e. next to its occluding reflex
//   vertex. A component keeps that germ until an event, so the rule follows components
//   through deformations, and across one event it is exactly appear / disappear / split /
//   merge (a slide keeps the old germ inside). Nothing here uses cuts, inflections or
//   bitangents: the gap sensor is independent of the paper's event theory.
// - Bitangents (VI.B): mutually visible reflex vertices whose line is tangent at both,
//   with the rays beyond each to the boundary.
#pragma once
#include <preimage/filter/shadow_labels.hpp>
#include <preimage/geometry/visibility.hpp>

#include <cstdint>
#include <utility>
#include <vector>

namespace preimage::wallfollow {

/// A point of the boundary of a simple polygon: on edge `edge` (from vertex `edge` to the
/// next; a vertex is the start of its edge), nudged infinitesimally along the boundary by
/// `nudge` (-1 before, +1 after): a germ.
struct BoundaryPoint {
  std::uint32_t edge = 0;
  geometry::ExactPoint point;
  int nudge = 0;
};
BoundaryPoint boundary_vertex(const geometry::Environment& env, std::uint32_t v, int nudge = 0);
/// The boundary point of p, which must lie on the boundary (InputError otherwise).
BoundaryPoint boundary_point(const geometry::Environment& env, const geometry::ExactPoint& p);
/// Linear order counter-clockwise from vertex 0.
bool boundary_less(const geometry::Environment& env, const BoundaryPoint& a, const BoundaryPoint& b);
/// Is x strictly inside the counter-clockwise arc from a to b?
bool in_open_arc(const geometry::Environment& env, const BoundaryPoint& x, const BoundaryPoint& a, const BoundaryPoint& b);

/// One shadow component: the open counter-clockwise arc (from, to) of the boundary it holds,
/// and the germs just inside the arc at its ends that are vertices.
struct ShadowArc {
  BoundaryPoint from, to;
  std::vector<BoundaryPoint> germs;
};
/// Components of the shadow of V(q), q in a simple polygon, ordered counter-clockwise from
/// q's boundary point when q is on the boundary.
std::vector<ShadowArc> shadow_arcs(const geometry::Environment& env, const geometry::VisibilityPolygon& V);
/// Do two components (at moments with no event strictly between them) share evaders?
bool corresponds(const geometry::Environment& env, const ShadowArc& a, const ShadowArc& b);

/// A line through a reflex vertex and a vertex it sees: where V changes combinatorially.
using VertexLine = std::pair<std::uint32_t, std::uint32_t>;
std::vector<VertexLine> vertex_lines(const geometry::VisibilityIndex& vis);
std::vector<VertexLine> vertex_lines(const geometry::Environment& env);

/// The gap sensor along a polyline path (the robot's motion in one action): components at
/// the end, and one correspondence per sample step where components changed.
struct GapReading {
  std::size_t gaps = 0;
  std::vector<filter::ShadowEvent> events;
};
GapReading gap_reading(const geometry::VisibilityIndex& vis, const std::vector<VertexLine>& lines,
                       const std::vector<geometry::ExactPoint>& path);
/// Components at one point (the count the gap sensor gives at stage 1).
std::size_t gap_count(const geometry::VisibilityIndex& vis, const geometry::ExactPoint& q);

/// A bitangent of E (VI.B): reflex vertices i < j, mutually visible, their line tangent at
/// both; b_ij the endpoint of the maximal segment beyond v_i, b_ji beyond v_j.
struct Bitangent {
  std::uint32_t i = 0, j = 0;
  BoundaryPoint b_ij, b_ji;
  /// The obstacles at v_i and v_j lie on opposite sides of the line.
  bool separating = false;
};
/// Every bitangent, by exact tangency and visibility tests and ray shooting. InputError
/// when a ray beyond a vertex meets another vertex (no general position).
std::vector<Bitangent> bitangents(const geometry::Environment& env);
/// The ray from v_i to b_ij (or from v_j to b_ji with `at_j`) cuts E in two; the robot at
/// boundary point x is on the side where the shadows behind v_i and v_j are one component
/// (VI.C): strictly inside the arc between the ray's ends that does not hold the other
/// vertex.
bool merged_side(const geometry::Environment& env, const Bitangent& b, bool at_j, const BoundaryPoint& x);

/// Does some point of the half-open segment (a, b] see p (meet the closed V(p))? With
/// a == b: does a see p.
bool sees_during(const geometry::VisibilityPolygon& Vp, const geometry::ExactPoint& a, const geometry::ExactPoint& b);

}  // namespace preimage::wallfollow
