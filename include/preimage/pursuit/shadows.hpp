// SPDX-License-Identifier: Apache-2.0
// The shadow of a pursuer: what it cannot see, F \ V(q), in connected components. Each
// free edge of V(q) (a "gap", 6.3) is tagged by geometry with its occluding reflex
// vertex, which names the gap; a component is named by the gaps on its boundary (more
// than one when it wraps around an obstacle). Two gaps bound the same component when an
// invisible stretch of the boundary joins their ends.
//
// Where rings touch (contacts), a vertex id names the free wedge starting at its out-edge.
// V(q) is regularised, so q sees into one wedge at a contact point c at most. The other
// wedges' parts near c are hidden: while c itself is seen they are regions of their own,
// "pinched" at c (the evader cannot pass c unseen), named by a pinch entry per wedge; while
// c is hidden the evader passes through it and every wedge there belongs to one component
// (pinch entries too, all in that component). A component may have pinch entries only (a
// pocket closed at contact points).
#pragma once
#include <preimage/geometry/visibility.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace preimage::pursuit {

using geometry::kNone;

/// A free edge of V(q), from a to b in V's counter-clockwise order: V lies on its left,
/// the shadow on its right.
struct Gap {
  std::uint32_t reflex;  // occluding vertex (its wedge, at a contact); for a pinch: the hidden wedge
  geometry::VisibilityVertex a, b;  // a pinch: both the wedge's vertex
  std::uint32_t component;
  bool pinch = false;  // not a free edge: the hidden part of wedge `reflex` at a contact point
};

struct Shadows {
  geometry::ExactPoint query;            // where they were computed
  std::vector<Gap> gaps;                 // sorted by reflex vertex (pinch entries included)
  std::uint32_t num_components = 0;      // components numbered by their smallest gap vertex
  /// Component whose boundary holds the gap of vertex v, kNone if v is not a gap vertex.
  std::uint32_t component_of(std::uint32_t v) const;
  /// Gap vertices of component c, ascending.
  std::vector<std::uint32_t> gap_vertices(std::uint32_t c) const;
  bool operator==(const Shadows& o) const;  // same gaps in the same components (wherever computed)
  /// Exact position of a gap's end (constructed on demand).
  geometry::ExactPoint end(const geometry::Environment& env, const geometry::VisibilityVertex& v) const {
    return geometry::exact_point(env, query, v);
  }
};

/// Shadow components of V(q). Throws std::logic_error if V has two consecutive free
/// edges or two gaps at one vertex (q on a critical line: not a point of an open cell).
/// With contacts, `edge_pieces` (Triangulation::edge_pieces) is required: a piece of free
/// space q does not see into is one hidden region, however its rings lie.
Shadows shadows_of(const geometry::VisibilityPolygon& V, std::span<const std::uint32_t> edge_pieces = {});

}  // namespace preimage::pursuit
