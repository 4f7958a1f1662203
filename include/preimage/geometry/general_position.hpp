// SPDX-License-Identifier: Apache-2.0
// General-position checks. Validation accepts degenerate but valid environments;
// each algorithm calls the checks it needs and rejects with these messages.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace preimage::geometry {

/// Three collinear points among `pts` (indices, ascending), or none. O(n^2 log n):
/// per point, the others sorted by exact direction (opposite directions identified).
std::optional<std::array<std::size_t, 3>> find_collinear_triple(const std::vector<Point>& pts);
/// Two points with equal x (indices), or none. O(n log n).
std::optional<std::array<std::size_t, 2>> find_equal_x(const std::vector<Point>& pts);
/// Vertices whose two neighbours are collinear with them (straight angles).
std::vector<std::size_t> straight_vertices(const Environment& env);

/// "boundary vertex 3" / "obstacles[1] vertex 0": a vertex in the caller's input terms.
std::string describe_vertex(const Environment& env, std::size_t v);

/// Throws InputError "<what> needs vertices in general position: boundary vertices 2, 5
/// and 9 are collinear" when the environment has three collinear vertices.
void require_no_collinear_vertices(const Environment& env, const std::string& what);
/// Throws InputError when two vertices share an x-coordinate.
void require_distinct_x(const Environment& env, const std::string& what);

}  // namespace preimage::geometry
