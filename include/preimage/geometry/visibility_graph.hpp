// SPDX-License-Identifier: Apache-2.0
// The (reduced) visibility graph of an environment and shortest paths in closed free space.
//
// A shortest path between two points of a polygonal domain is a polyline that bends only
// at reflex vertices, and at each bend the two segments wrap around the obstacle: the line
// of each segment is tangent to the boundary at its reflex ends (both neighbours of the
// vertex on one side of it). The graph keeps exactly those edges: pairs of mutually
// visible reflex vertices whose segment is tangent at both ends. Visibility comes from the
// triangular expansion (VisibilityIndex), so every edge is exact; lengths are doubles
// (they choose among exact paths, they decide nothing geometric).
//
// Used for coverage transits and planning with a footprint (on the configuration space);
// it is built once per environment. The full graphs
// (every visible pair, and graphs over points) are in visibility_graphs.hpp.
#pragma once
#include <preimage/geometry/visibility.hpp>

#include <memory>
#include <mutex>
#include <span>

namespace preimage::geometry {

class VisibilityGraph {
 public:
  /// Edges are computed on demand (a vertex's on first use, from its visibility polygon)
  /// and kept: a search touches only the vertices near its path. Thread-safe.
  explicit VisibilityGraph(const VisibilityIndex& index);
  VisibilityGraph(VisibilityIndex&&) = delete;  // keeps a pointer to the index
  /// Computes every vertex's edges now, on all cores.
  void build_all() const;

  const VisibilityIndex& index() const { return *index_; }
  const Environment& environment() const { return index_->environment(); }
  /// Reflex vertices (environment ids), ascending.
  const std::vector<std::uint32_t>& reflex_vertices() const { return reflex_; }
  /// Neighbours of reflex vertex v in the graph (environment ids); empty for others.
  std::span<const std::uint32_t> neighbours(std::uint32_t v) const;
  /// The reflex vertices w that reflex vertex v sees with segment vw tangent at v (not
  /// necessarily at w), ascending; neighbours(v) are those of them tangent at w too. A
  /// shortest path map's Dijkstra runs on these (a path may end at w in any direction), so
  /// it shares this graph's one visibility query per vertex instead of making its own.
  std::span<const std::uint32_t> tangent_out(std::uint32_t v) const;
  /// Number of edges (builds them all).
  std::size_t num_edges() const;

  struct Path {
    bool found = false;
    std::vector<Point> points;           // start, bends (reflex vertices), goal
    std::vector<std::uint32_t> bends;    // environment ids of the bends
    double length = 0;
  };
  /// Shortest path in closed free space from s to t (A* over the graph, joined to s and t
  /// through the reflex vertices they see). Not found when either point is outside free
  /// space or they lie in different components (never, for a valid Environment).
  Path shortest_path(const Point& s, const Point& t) const;

 private:
  // Reflex vertices visible from q whose segment to q is tangent at the vertex.
  std::vector<std::uint32_t> tangent_reflex_from(const Point& q) const;

  struct Lists {
    std::vector<std::uint32_t> tangent_out, neighbours;
  };
  const Lists& lists(std::uint32_t v) const;

  const VisibilityIndex* index_;
  std::vector<std::uint32_t> reflex_;
  // Per environment vertex: its lists once computed (they never change after).
  mutable std::vector<std::unique_ptr<const Lists>> adj_;
  mutable std::mutex mutex_;
};

/// Is the segment from reflex vertex v to point x tangent to the boundary at v (both
/// neighbours of v on one side of the line, or on it)? Only such segments can end at a
/// bend of a shortest path.
bool tangent_at(const Environment& env, std::uint32_t v, const Point& x);

}  // namespace preimage::geometry
