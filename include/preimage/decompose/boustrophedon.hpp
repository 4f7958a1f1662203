// SPDX-License-Identifier: Apache-2.0
// Boustrophedon decomposition and its Reeb graph (Choset et al., 6.2.1, 6.2.2, 6.2.4).
//
// Built from the trapezoidal decomposition: two trapezoids that meet across an event line
// where the free slice keeps its connectivity (one cell closes, one opens, they share the
// extension) belong to the same boustrophedon cell. Everywhere else the event line holds
// a *critical slice*: a connected piece of the line where slice intervals appear,
// disappear, split or merge. In general position that piece contains one critical point
// (a vertex whose vertical extension goes both up and down, or an extreme vertex where a
// slice interval is born or dies); with vertical walls it is the whole wall, which is
// how degenerate critical points are handled without perturbation. Critical slices are
// the Reeb graph's nodes and cells its edges, so N_cells = N_critical + N_obstacles - 1.
#pragma once
#include <preimage/decompose/trapezoidal.hpp>

#include <memory>

namespace preimage::decompose {

/// A node of the Reeb graph: the piece of the event line x = x where connectivity changes.
struct CriticalSlice {
  double x;
  std::uint32_t cells_left, cells_right;  // boustrophedon cells ending / starting here
  ExactFT y_low, y_high;                  // extent on the line (equal for a single point)
};

/// A boustrophedon cell: x-monotone, a run of trapezoids left to right.
struct BoustrophedonCell {
  std::vector<std::uint32_t> trapezoids;
  std::uint32_t left_slice, right_slice;  // Reeb graph edge: critical slice at each end
};

/// The floor and ceiling of a cell, exact, in sweep coordinates, both left to right.
/// Abscissae never decrease along a chain; where an edge lies on a slice line (a vertical
/// wall in sweep coordinates) the chain has several points on that line, bottom to top or
/// top to bottom as the boundary runs, so every environment vertex on the floor or ceiling
/// is on its chain.
struct CellChains {
  std::vector<ExactPoint> floor, ceiling;
  /// Per point: the environment vertex it is, or kNoVertex for a point inside an edge.
  std::vector<std::uint32_t> floor_vertex, ceiling_vertex;
  /// Per point: the environment edge it lies on (for a vertex, the floor or ceiling edge
  /// of the trapezoid it was met from).
  std::vector<std::uint32_t> floor_edge, ceiling_edge;
  static constexpr std::uint32_t kNoVertex = UINT32_MAX;
};

class BoustrophedonDecomposition {
 public:
  /// Sweep along +x rotated by `angle_deg` (counter-clockwise). Angles that are multiples
  /// of 90 degrees rotate exactly; others rotate the input coordinates once, in double,
  /// and decompose that environment exactly (its validity is re-checked).
  explicit BoustrophedonDecomposition(const Environment& env, double angle_deg = 0);
  BoustrophedonDecomposition(Environment&&, double = 0) = delete;  // keeps a pointer to the input

  /// The environment actually swept (the input rotated by -angle into sweep coordinates).
  const Environment& sweep_environment() const { return *rotated_; }
  const TrapezoidalDecomposition& trapezoids() const { return *trap_; }
  const std::vector<BoustrophedonCell>& cells() const { return cells_; }
  const std::vector<CriticalSlice>& critical_slices() const { return slices_; }
  double angle() const { return angle_; }

  /// Floor and ceiling chains of a cell (sweep coordinates, exact).
  CellChains chains(std::size_t cell) const;
  /// The same for a run of trapezoids left to right, each meeting the next across an event
  /// line on a common piece of it: a cell, or cells merged across critical slices where
  /// the union stays x-monotone. Where two floors (or ceilings) do not meet on the line,
  /// the chain runs along it through every environment vertex between them.
  CellChains chains(const std::vector<std::uint32_t>& trapezoids) const;
  /// Cell outline, counter-clockwise, exact, in sweep coordinates: the floor chain, the
  /// right side, the ceiling chain backwards, the left side; every environment vertex on the
  /// cell's boundary is a vertex of it (points inside edges appear only at the corners).
  std::vector<ExactPoint> exact_polygon(std::size_t cell) const;
  /// exact_polygon mapped to the input's coordinates and rounded to doubles (exact for
  /// environment vertices at every angle, and for every point at quarter turns of an
  /// environment near the origin: far from it the sweep frame is the local one,
  /// geometry::LocalFrame, and mapping back rounds).
  std::vector<Point> polygon(std::size_t cell) const;
  /// Exact area in sweep coordinates: the sum of the cell's trapezoids, which equals the
  /// area of exact_polygon.
  ExactFT area(std::size_t cell) const;
  /// The input vertex a vertex of the swept environment came from, exact at every angle
  /// (edge e of the swept environment comes from the input edge that starts there).
  std::size_t input_vertex_id(std::size_t v) const { return input_->ring_begin(rotated_->ring_of(v)) + rotated_->input_index(v); }
  Point input_vertex(std::size_t v) const { return input_->vertex(input_vertex_id(v)); }
  /// Point of sweep coordinates mapped back to input coordinates, and the reverse. The sweep
  /// frame is the input's local frame (geometry::LocalFrame) rotated by -angle.
  Point to_input(const Point& p) const;
  Point to_sweep(const Point& p) const;
  /// Adjacent cells (sharing a critical slice with a common extension), per cell.
  std::vector<std::vector<std::uint32_t>> adjacency() const;

 private:
  // Environment vertices on the line x = c strictly between lo and hi, ordered from lo
  // towards hi (lo > hi walks downwards).
  void vertices_on_line(double c, const ExactFT& lo, const ExactFT& hi, std::vector<std::uint32_t>& out) const;
  // exact_polygon with, per point, its environment vertex or CellChains::kNoVertex.
  std::vector<ExactPoint> outline(std::size_t cell, std::vector<std::uint32_t>& ids) const;

  const Environment* input_;
  double angle_;
  double cos_ = 1, sin_ = 0;
  double dx_ = 0, dy_ = 0;  // the local frame's origin (geometry::LocalFrame), rotated about
  std::vector<std::uint32_t> by_xy_;  // swept vertices in lexicographic (x, y) order
  std::unique_ptr<Environment> rotated_;
  std::unique_ptr<TrapezoidalDecomposition> trap_;
  std::vector<BoustrophedonCell> cells_;
  std::vector<CriticalSlice> slices_;
  std::vector<std::uint32_t> cell_of_trapezoid_;
};

}  // namespace preimage::decompose
