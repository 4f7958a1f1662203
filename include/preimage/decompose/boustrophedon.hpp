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

class BoustrophedonDecomposition {
 public:
  /// Sweep along +x rotated by `angle_deg` (counter-clockwise). Angles that are multiples
  /// of 90 degrees rotate exactly; others rotate the input coordinates once, in double,
  /// and decompose that environment exactly (its validity is re-checked).
  explicit BoustrophedonDecomposition(const Environment& env, double angle_deg = 0);

  /// The environment actually swept (the input rotated by -angle into sweep coordinates).
  const Environment& sweep_environment() const { return *rotated_; }
  const TrapezoidalDecomposition& trapezoids() const { return *trap_; }
  const std::vector<BoustrophedonCell>& cells() const { return cells_; }
  const std::vector<CriticalSlice>& critical_slices() const { return slices_; }
  double angle() const { return angle_; }

  /// Cell outline, counter-clockwise, in the input's coordinates (double rounding).
  std::vector<Point> polygon(std::size_t cell) const;
  /// Exact area in sweep coordinates.
  ExactFT area(std::size_t cell) const;
  /// Point of sweep coordinates mapped back to input coordinates, and the reverse.
  Point to_input(const Point& p) const;
  Point to_sweep(const Point& p) const;
  /// Adjacent cells (sharing a critical slice with a common extension), per cell.
  std::vector<std::vector<std::uint32_t>> adjacency() const;

 private:
  double angle_;
  double cos_ = 1, sin_ = 0;
  std::unique_ptr<Environment> rotated_;
  std::unique_ptr<TrapezoidalDecomposition> trap_;
  std::vector<BoustrophedonCell> cells_;
  std::vector<CriticalSlice> slices_;
  std::vector<std::uint32_t> cell_of_trapezoid_;
};

}  // namespace preimage::decompose
