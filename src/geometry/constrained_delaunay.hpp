// SPDX-License-Identifier: Apache-2.0
// Internal to geometry: the triangles of the constrained Delaunay triangulation of an
// environment's free space (see triangulation.hpp).
#pragma once
#include <preimage/geometry/environment.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace preimage::geometry {

/// Counter-clockwise vertex triples covering free space exactly, constrained Delaunay:
/// Delaunay triangulation of the vertices by randomised incremental insertion (a fixed
/// seed, so the result is deterministic), every environment edge then forced in, and the
/// triangles outside free space dropped. Exact predicates throughout.
std::vector<std::array<std::uint32_t, 3>> constrained_delaunay_triangles(const Environment& env);

}  // namespace preimage::geometry
