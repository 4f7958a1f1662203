// SPDX-License-Identifier: Apache-2.0
// Private to coverage: a sweep direction per region (issue 49). A boustrophedon
// decomposition sweeps every cell the same way, so a cell lying across the sweep (a room
// turned the other way, a corridor across the laps) takes many short laps, and every lap
// costs two quarter turns. Here a cell that the perpendicular direction sweeps with fewer
// laps is decomposed again, on its own, at that direction.
#pragma once
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/geometry/environment.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace preimage::coverage::detail {

/// A cell of `base` swept at base.angle() + 90: its outline as an environment of its own,
/// and that environment's decomposition at the perpendicular direction.
struct TurnedCell {
  std::size_t base_cell;
  std::unique_ptr<Environment> env;
  std::unique_ptr<decompose::BoustrophedonDecomposition> dec;
};

/// A sweep direction per cell: what it costs, the cells turned and the cells kept.
struct CellDirections {
  std::vector<TurnedCell> turned;
  std::vector<std::size_t> kept;  // cells of base swept at its own direction
  double score = 0;               // laps and cells, as cell_score counts them
};

/// Laps and the cell itself: 1 + ceil(width / w), the way ETH's planner ranks directions
/// by the cells' altitudes.
double cell_score(const decompose::BoustrophedonDecomposition& b, std::size_t cell, double w);
double direction_score(const decompose::BoustrophedonDecomposition& b, double w);

/// Quarter-turn angles only (elsewhere every cell is kept, since rotating by another angle
/// would round the outline): a cell is turned when its outline decomposed at the
/// perpendicular direction scores lower. An outline that is not a valid environment in
/// doubles keeps its cell. (Grouping adjacent turned cells into one region, so fragments
/// between pillars would join into long laps, was tried: on the four floor plans at
/// W = 0.3, 0.5 and 1 no two adjacent cells were both better turned, so it is not built.)
CellDirections choose_directions(const decompose::BoustrophedonDecomposition& base, double w);

}  // namespace preimage::coverage::detail
