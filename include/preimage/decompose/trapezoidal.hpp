// SPDX-License-Identifier: Apache-2.0
// Trapezoidal (vertical) decomposition of an environment with holes — Choset et al.,
// Principles of Robot Motion, section 6.1 — by a sweep over the vertices in x order
// with a balanced tree of the edges crossing the sweep line.
//
// Degenerate input is decomposed exactly as the geometry says, without perturbation:
// all vertices sharing an x-coordinate form one event, so vertical edges, vertices
// stacked on one vertical line and collinear vertices need no special case. Every
// vertex emits its vertical extensions (up and/or down, where free space is); a cell is
// bounded by a floor edge, a ceiling edge and two vertical sides at event abscissae.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace preimage::decompose {

using geometry::Environment;
using geometry::ExactFT;
using geometry::ExactPoint;
using geometry::Point;

/// A trapezoid (a triangle when floor and ceiling meet at one side). Its sides are
/// x = x_left and x = x_right; floor and ceiling are environment edge ids.
struct Trapezoid {
  std::uint32_t floor, ceiling;
  double x_left, x_right;  // event abscissae: input coordinates, exact
};

/// A vertical extension segment on x = x, shared by the cell to its left and the cell to
/// its right. Each end is an environment vertex or a point on an edge.
struct Extension {
  std::uint32_t left_cell, right_cell;
  double x;
  bool bottom_is_vertex, top_is_vertex;
  std::uint32_t bottom, top;  // vertex id or edge id, per the flags
};

class TrapezoidalDecomposition {
 public:
  explicit TrapezoidalDecomposition(const Environment& env);
  TrapezoidalDecomposition(Environment&&) = delete;  // keeps a pointer to the environment

  const Environment& environment() const { return *env_; }
  const std::vector<Trapezoid>& cells() const { return cells_; }
  const std::vector<Extension>& extensions() const { return extensions_; }
  /// Extension ids touching cell c (its adjacency in the graph of cells).
  std::span<const std::uint32_t> extensions_of(std::size_t c) const {
    return {cell_ext_.data() + cell_ext_offset_[c], cell_ext_offset_[c + 1] - cell_ext_offset_[c]};
  }

  /// Exact y of edge e at abscissa x (x within the edge's x-range; e not vertical).
  ExactFT edge_y(std::uint32_t e, double x) const;
  /// Counter-clockwise corners (2 to 4 distinct exact points; a triangle has 3).
  std::vector<ExactPoint> polygon(std::size_t c) const;
  ExactFT area(std::size_t c) const;
  /// Exact ends of an extension, bottom then top.
  std::pair<ExactPoint, ExactPoint> segment(std::size_t x) const;

 private:
  const Environment* env_;
  std::vector<Trapezoid> cells_;
  std::vector<Extension> extensions_;
  std::vector<std::uint32_t> cell_ext_offset_, cell_ext_;
};

}  // namespace preimage::decompose
