// SPDX-License-Identifier: Apache-2.0
// Test-only oracle for the generalized Voronoi diagram: CGAL's Segment_Delaunay_graph_2
// (GPL, never linked into the library), and a topology summary that compares two GVDs
// given as plain edge lists.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace preimage::testing {

/// One GVD edge as a straight piece between its end points, with its obstacle pair.
struct PlainGvdEdge {
  geometry::Point a, b;
  std::uint32_t obstacle[2];
};

/// CGAL's segment Delaunay graph of the environment's edges with vertices at `points`
/// (e.g. the GVD's snapped vertices; one per vertex id), filtered exact predicates; the
/// dual (Voronoi) edges between sites of different obstacles (`ring_obstacle[r]` for ring r),
/// end points in doubles. Throws std::logic_error on an infinite one.
std::vector<PlainGvdEdge> cgal_gvd_edges(const geometry::Environment& env, const std::vector<geometry::Point>& points,
                                         const std::vector<std::uint32_t>& ring_obstacle);

/// The same segment Delaunay graph, built and dropped: what the benchmark times.
std::size_t cgal_segment_delaunay_graph_size(const std::vector<geometry::Point>& points,
                                             const std::vector<std::pair<std::size_t, std::size_t>>& segments);

/// The topology of a GVD, insensitive to how a computation splits it: end points within
/// `merge` of each other are one node (zero-length edges vanish), and nodes of degree 2
/// are dissolved into chains, each between one obstacle pair.
struct GvdTopology {
  std::vector<geometry::Point> nodes;              // every node (cluster of end points)
  std::vector<std::uint32_t> degree;               // per node
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> chains;  // obstacle pair -> chains
  std::string problem;                              // non-empty if a degree-2 node joins different pairs
};
GvdTopology gvd_topology(const std::vector<PlainGvdEdge>& edges, double merge);

/// Matches nodes one to one within `tol` (each of a to a distinct one of b): "" or what failed.
std::string match_nodes(const GvdTopology& a, const GvdTopology& b, double tol, std::uint32_t min_degree);

}  // namespace preimage::testing
