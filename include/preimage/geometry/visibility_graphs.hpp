// SPDX-License-Identifier: Apache-2.0
// Full visibility graphs, as TřiVis users know them: vertex–vertex (every pair of
// environment vertices whose segment lies in closed free space, boundary edges included —
// not only the reduced graph over tangent reflex vertices of visibility_graph.hpp),
// point–point (a set of points, an edge between each mutually visible pair) and
// point–vertex (each point to the environment vertices it sees).
//
// Every edge is decided exactly by VisibilityIndex (`visible_vertices`, the triangular
// expansion, for vertices; `visible`, a triangle walk, for pairs of points): the closed
// segment lies in closed free space, so segments grazing the boundary, running along an
// edge or through a vertex count as visible. The work is split over threads by rows.
#pragma once
#include <preimage/geometry/visibility.hpp>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace preimage::geometry {

/// Edges as index pairs, sorted lexicographically.
using GraphEdges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/// Pairs (u, v), u < v, of environment vertices that see each other (every boundary edge
/// is one). `threads` 0: all cores.
GraphEdges vertex_visibility_graph(const VisibilityIndex& index, unsigned threads = 0);

/// Pairs (i, j), i < j, of points that see each other (equal points do). Throws
/// InputError naming the first point outside free space. `threads` 0: all cores.
GraphEdges point_visibility_graph(const VisibilityIndex& index, std::span<const Point> points, unsigned threads = 0);

/// Pairs (i, v): point i sees environment vertex v. Throws InputError naming the first
/// point outside free space. `threads` 0: all cores.
GraphEdges point_vertex_visibility_graph(const VisibilityIndex& index, std::span<const Point> points, unsigned threads = 0);

}  // namespace preimage::geometry
