// SPDX-License-Identifier: Apache-2.0
// Constrained Delaunay triangulation of an Environment (outer boundary with holes),
// built without CGAL's GPL triangulation packages (src/geometry/constrained_delaunay.cpp):
//   1. Delaunay triangulation of the vertices by randomised incremental insertion with
//      Lawson flips, exact in-circle and orientation predicates;
//   2. every environment edge forced in, the pseudo-polygons on its sides re-triangulated
//      by their Delaunay vertices (Anglada);
//   3. the triangles outside free space dropped.
// O(n log n) expected, collinear runs and cocircular vertices included.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace preimage::geometry {

inline constexpr std::uint32_t kNone = UINT32_MAX;

/// At a contact point (Environment::same_point_next) a corner's id is the vertex whose
/// out-edge starts the free wedge the triangle lies in, so the triangles around one id
/// form one wedge's fan and a boundary edge (v[i], v[i+1]) is environment edge v[i].
struct Triangle {
  std::array<std::uint32_t, 3> v;    // environment vertex ids, counter-clockwise
  std::array<std::uint32_t, 3> nbr;  // nbr[i]: triangle across edge (v[i], v[i+1]); kNone on the boundary
  std::array<std::uint32_t, 3> edge; // edge[i]: environment edge id when edge i is a boundary edge, else kNone
};

class Triangulation {
 public:
  explicit Triangulation(const Environment& env);
  Triangulation(Environment&&) = delete;  // keeps a pointer to the environment

  const Environment& environment() const { return *env_; }
  const std::vector<Triangle>& triangles() const { return tris_; }
  std::size_t size() const { return tris_.size(); }
  /// Triangle and slot holding boundary edge e (environment edge id).
  std::pair<std::uint32_t, std::uint8_t> boundary_slot(std::size_t e) const { return edge_slot_[e]; }

  /// Pieces of free space: the connected components of free space minus its contact
  /// points (triangles joined across shared edges, never at a point alone). Per environment
  /// edge e, the piece on its free side, numbered from 0 in edge order. Without contacts
  /// every entry is 0. O(n).
  std::vector<std::uint32_t> edge_pieces() const;

  /// Throws std::logic_error if any structural invariant fails (tests use this):
  /// positive orientation, symmetric adjacency, boundary edges exactly the
  /// environment's, triangle count n - 2c + 2h - 2 (c vertices merged at contacts), exact
  /// area equal to the free area.
  void check() const;
  /// Number of interior edges that are not locally Delaunay (0 after construction).
  std::size_t non_delaunay_edges() const;

 private:
  void link();
  void label_wedges();

  const Environment* env_;
  std::vector<Triangle> tris_;
  std::vector<std::pair<std::uint32_t, std::uint8_t>> edge_slot_;
};

}  // namespace preimage::geometry
