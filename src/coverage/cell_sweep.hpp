// SPDX-License-Identifier: Apache-2.0
// Private to coverage: the four ways to sweep one boustrophedon cell, built in the sweep
// frame and brought back to the input frame with exact certification (coverage.cpp).
#pragma once
#include <preimage/coverage/coverage.hpp>
#include <preimage/decompose/brushfire.hpp>
#include <preimage/decompose/morse.hpp>
#include <preimage/decompose/planner.hpp>
#include <preimage/decompose/trapezoidal.hpp>
#include <preimage/decompose/wavefront.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/geometry/visibility_graph.hpp>

namespace preimage::coverage {

// The decompositions coverage sweeps, by their names (private to coverage's sources).
using decompose::BoustrophedonCell;
using decompose::BrushfireCell;
using decompose::BrushfireDecomposition;
using decompose::CellChains;
using decompose::MorseDecomposition;
using decompose::SliceFamily;
using decompose::TrapezoidalDecomposition;
using decompose::TrapezoidalPlanner;
using decompose::WavefrontDecomposition;
using geometry::ExactFT;
using geometry::ExactPoint;

}  // namespace preimage::coverage

namespace preimage::coverage::detail {

/// A path point in the sweep frame with what it is: an environment vertex, a point on an
/// environment edge, or neither; `move` is the kind of the segment that ends here.
struct SweepPoint {
  Point p;
  std::uint32_t vertex = CellChains::kNoVertex;
  std::uint32_t edge = CellChains::kNoVertex;
  Move move = Move::Transit;
};

/// Laps at spacing w across a region of b: the trapezoids of a cell, or of cells merged
/// into one x-monotone region (cell_merging.hpp), left to right. From its left end (or
/// right end when from_right), the first lap going up (or down when first_down), joined by
/// boundary following along the floor or ceiling chain. Sweep-frame coordinates.
std::vector<SweepPoint> sweep_cell(const BoustrophedonDecomposition& b, const std::vector<std::uint32_t>& trapezoids, double w,
                                   bool from_right, bool first_down, std::size_t* laps);

/// The abscissae of the laps sweep_cell puts across that region (sweep frame); left_out:
/// how many of the boundary samples they are placed to cover no lap within the region's
/// ends can reach (a cell's side met only at its end; in a merged region, a step of the
/// boundary next to an end).
std::vector<double> lap_positions(const BoustrophedonDecomposition& b, const std::vector<std::uint32_t>& trapezoids, double w,
                                  std::size_t* left_out = nullptr);

/// A polyline in the input frame with the move of each segment.
struct Polyline {
  std::vector<Point> points;
  std::vector<Move> moves;  // moves[i]: points[i] -> points[i + 1]
  std::size_t detours = 0;
  double length() const;
  void append(const Point& p, Move m);
};

/// Sweep-frame points mapped back to the input environment `env` (the environment `b`
/// decomposed): certified segment by segment with `index` (exact). Quarter turns map back
/// exactly, so a failure there is a bug; at other angles a segment that rounding made graze
/// a wall is replaced by the shortest path `graph` gives (counted in `detours`).
/// `sweep_index` (non-quarter angles only) certifies the sweep-frame path first.
Polyline to_input_frame(const BoustrophedonDecomposition& b, const Environment& env, const std::vector<SweepPoint>& pts,
                        const geometry::VisibilityIndex& index, const geometry::VisibilityGraph& graph,
                        const geometry::VisibilityIndex* sweep_index);

}  // namespace preimage::coverage::detail
