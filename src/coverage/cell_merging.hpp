// SPDX-License-Identifier: Apache-2.0
// Private to coverage: boustrophedon cells merged into x-monotone regions (issue 49). A
// cell gets whole laps, so every cell rounds its width up to a multiple of w, and the
// order search pays a transit from one cell's last lap to the next cell's first. Where one
// cell ends on a critical slice and an adjacent one starts there, their union is still
// monotone in the sweep direction (every slice meets it in one interval), so one run of
// laps sweeps both.
#pragma once
#include <preimage/decompose/boustrophedon.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace preimage::coverage::detail {

/// An x-monotone region of a boustrophedon decomposition: its cells left to right, each
/// ending on the critical slice where the next starts and sharing a piece of it, and their
/// trapezoids left to right (what sweep_cell sweeps).
struct SweepRegion {
  std::vector<std::uint32_t> cells;
  std::vector<std::uint32_t> trapezoids;
};

/// Each cell of `cells` (cells of b) on its own.
std::vector<SweepRegion> single_cells(const decompose::BoustrophedonDecomposition& b, const std::vector<std::size_t>& cells);

/// The cells of `cells` merged into monotone regions where that saves laps: the pairs
/// across a critical slice (the left one's last trapezoid meeting the right one's first on
/// an extension) by the laps their union saves (lap_positions at spacing w, counted on the
/// regions merged so far), most first; a cell joins at most one region on each side. A
/// merge is kept when it saves at least one lap and its laps still reach every boundary
/// sample the parts' laps reached (lap_positions' left_out).
std::vector<SweepRegion> merge_monotone_cells(const decompose::BoustrophedonDecomposition& b, const std::vector<std::size_t>& cells,
                                              double w);

}  // namespace preimage::coverage::detail
