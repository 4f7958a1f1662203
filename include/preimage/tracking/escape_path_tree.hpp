// SPDX-License-Identifier: Apache-2.0
// Shortest escape paths and the escape-path tree (sections III, IV.A, IV.B).
//
// For a target q^t inside the local map V(q^o), SEP(q^t, e) is the shortest path from
// the target to free edge e inside V, and SDE its length. The ray sweep of IV.A visits the
// vertices left of the line l(q^o, q^t) counter-clockwise (L_l), then those right of it
// clockwise (L_r), keeping the pivot list: the shortest path to the vertex just visited
// (Theorem 1 — a vertex dropped from it never returns). A free edge is reached when the
// sweep crosses it; its escape point is then slid along the edge to the point nearest the
// pivot list (case 3 of IV.A). All paths together form the escape-path tree: the target
// is the root, pivots are nodes, and each free edge hangs from the last pivot of its SEP.
// O(n) for a map already in angular order.
#pragma once
#include <preimage/tracking/local_map.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace preimage::tracking {

/// A node of the tree: the target (node 0, vertex kNone) or a vertex of V at which an
/// escape path bends.
struct EscapeNode {
  std::uint32_t vertex = kNone;
  std::uint32_t parent = kNone;  // node index; kNone for the root
  Point at;
  double distance = 0;           // geodesic distance from the target
  int side = 0;                  // +1 left of l(q^o, q^t), -1 right, 0 root
};

/// SEP(q^t, e) for one escape edge e of V.
struct EscapePath {
  std::uint32_t edge = kNone;      // edge index in the local map
  EdgeKind kind = EdgeKind::Occlusion;
  std::uint32_t node = kNone;      // last pivot: the node the path leaves from in a straight line
  Point escape_point;              // where the path meets e (rounded)
  double length = 0;               // SDE(q^t, e)
  int side = 0;                    // which side of l(q^o, q^t) the path runs on (0: on it)
};

struct EscapePathTree {
  Point target;
  std::vector<EscapeNode> nodes;   // nodes[0] is the target; parents precede children
  std::vector<EscapePath> paths;   // one per escape edge of V, in edge order
  /// Index into `paths` of the overall shortest escape path SEP(q^t, q^o); kNone if V has
  /// no escape edge.
  std::uint32_t shortest = kNone;
  double sde() const;              // SDE(q^t, q^o); +inf without escape edges
  /// The polyline of SEP(q^t, e) for paths[i]: target, pivots, escape point.
  std::vector<Point> polyline(std::size_t i) const;
  /// Children lists (node -> child nodes, node -> escape paths hanging from it).
  std::vector<std::vector<std::uint32_t>> child_nodes() const;
  std::vector<std::vector<std::uint32_t>> child_paths() const;
};

/// The escape-path tree of `target` in `map` (validated). Throws InputError if the target
/// is not strictly inside V.
EscapePathTree escape_path_tree(const LocalMap& map, const Point& target);
/// The same, or nothing if the target is not strictly inside V (TRACK's case of a target
/// detected outside its own map), without an exception.
std::optional<EscapePathTree> try_escape_path_tree(const LocalMap& map, const Point& target);

}  // namespace preimage::tracking
