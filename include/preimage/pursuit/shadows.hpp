// SPDX-License-Identifier: Apache-2.0
// The shadow of a pursuer: what it cannot see, F \ V(q), in connected components. Each
// free edge of V(q) (a "gap", 6.3) is tagged by geometry with its occluding reflex
// vertex, which names the gap; a component is named by the gaps on its boundary (more
// than one when it wraps around an obstacle). Two gaps bound the same component when an
// invisible stretch of the boundary joins their ends.
#pragma once
#include <preimage/geometry/visibility.hpp>

#include <cstdint>
#include <vector>

namespace preimage::pursuit {

using geometry::kNone;

/// A free edge of V(q), from a to b in V's counter-clockwise order: V lies on its left,
/// the shadow on its right.
struct Gap {
  std::uint32_t reflex;  // occluding vertex
  geometry::VisibilityVertex a, b;
  std::uint32_t component;
};

struct Shadows {
  geometry::ExactPoint query;            // where they were computed
  std::vector<Gap> gaps;                 // sorted by reflex vertex
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
Shadows shadows_of(const geometry::VisibilityPolygon& V);

}  // namespace preimage::pursuit
