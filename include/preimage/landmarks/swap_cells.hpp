// SPDX-License-Identifier: Apache-2.0
// The swap cell decomposition (landmark paper, 6.1) from coordinates: the exact
// arrangement of the n(n-1) swap rays, every 2-cell (swap cell) with the cyclic
// permutation the detector reads inside it, whether it meets the convex hull, and the
// swap graph, its dual (section 7).
//
// The swap ray (i, j) is the paper's swap line p_i p_j: it starts at p_i and points away
// from p_j. Two rays of four distinct landmarks cross iff each starts nearer the other's
// line than its second landmark (exact predicates on the input points); rays sharing a
// landmark meet only at it. The rays are clipped by a box that strictly contains every
// crossing, which changes no cell, and half-edges are linked around each vertex by an
// exact angular sort. Permutations propagate across the dual from one cell read by an
// exact angular sort: crossing a ray of (i, j) transposes i and j.
#pragma once
#include <preimage/geometry/kernel.hpp>
#include <preimage/landmarks/robot.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace preimage::landmarks {

class SwapCellDecomposition {
 public:
  static constexpr std::uint32_t kNone = UINT32_MAX;
  struct Ray {
    std::uint32_t from, away;  // starts at p_from, points away from p_away
  };
  struct Vertex {
    geometry::ExactPoint p;
    enum class Kind { Landmark, Crossing, Box } kind;
    std::uint32_t landmark = kNone;
  };
  struct HalfEdge {
    std::uint32_t origin, target;
    std::uint32_t next = kNone;  // next half-edge around the cell on the left
    std::uint32_t cell = kNone;
    std::uint32_t ray = kNone;   // kNone: a piece of the clipping box
    bool meets_hull = false;     // the open piece meets the interior of hull(L)
  };
  struct Cell {
    Reading permutation;     // normalized (least label first)
    bool meets_hull = false;  // intersects hull(L): Theorem 7's cells
    bool unbounded = false;
    std::uint32_t half_edge = kNone;  // one half-edge of its boundary
  };
  /// Neighbouring cells across a swap ray of landmarks (i, j) (one per pair of cells).
  struct SwapEdge {
    std::uint32_t a, b;
    std::uint32_t i, j;
    bool meets_hull = false;  // some shared piece meets the hull's interior
  };

  /// From landmarks in general position (checked: InputError otherwise). Theta(n^4)
  /// cells, time and memory (about 0.05 n^4 cells for random sets); `progress` is told
  /// the fraction done now and then.
  static SwapCellDecomposition of(std::span<const geometry::Point> landmarks, const std::function<void(double)>& progress = {});

  std::size_t num_landmarks() const { return P_.size(); }
  const std::vector<Ray>& rays() const { return rays_; }
  const std::vector<Vertex>& vertices() const { return vertices_; }
  const std::vector<HalfEdge>& half_edges() const { return half_edges_; }
  static std::uint32_t twin(std::uint32_t h) { return h ^ 1U; }
  /// The swap cells (the box's outside is not one).
  const std::vector<Cell>& cells() const { return cells_; }
  /// The swap graph: one edge per pair of neighbouring cells.
  const std::vector<SwapEdge>& swap_graph() const { return graph_; }
  /// The boundary cycle of a cell, as vertex indices (counter-clockwise, clipped).
  std::vector<std::uint32_t> boundary(std::uint32_t cell) const;
  /// Identities of the arrangement vertices on a cell's boundary, as the robot can name
  /// them: landmark i as n*n + i, a crossing by the sorted lines (i * n + j, i < j) of
  /// its rays; box vertices are left out. Sorted.
  std::vector<std::vector<std::uint32_t>> vertex_keys(std::uint32_t cell) const;
  std::vector<std::uint32_t> vertex_key(std::uint32_t vertex) const;
  /// The hull boundary, counter-clockwise.
  const std::vector<std::uint32_t>& hull() const { return hull_; }

 private:
  std::vector<geometry::ExactPoint> P_;
  std::vector<Ray> rays_;
  std::vector<Vertex> vertices_;
  std::vector<HalfEdge> half_edges_;
  std::vector<std::vector<std::uint32_t>> vertex_rays_;  // rays through each crossing vertex
  std::vector<Cell> cells_;
  std::vector<SwapEdge> graph_;
  std::vector<std::uint32_t> hull_;
};

}  // namespace preimage::landmarks
