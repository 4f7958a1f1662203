// SPDX-License-Identifier: Apache-2.0
#include "cell_directions.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/kernel.hpp>

#include <cmath>
#include <optional>

namespace preimage::coverage::detail {

using decompose::BoustrophedonDecomposition;

double cell_score(const BoustrophedonDecomposition& b, std::size_t c, double w) {
  const auto& T = b.trapezoids().cells();
  const auto& cell = b.cells()[c];
  return 1 + std::ceil((T[cell.trapezoids.back()].x_right - T[cell.trapezoids.front()].x_left) / w);
}

double direction_score(const BoustrophedonDecomposition& b, double w) {
  double score = 0;
  for (std::size_t c = 0; c < b.cells().size(); ++c) score += cell_score(b, c, w);
  return score;
}

namespace {

// The cell's outline as an environment of its own, decomposed at the perpendicular
// direction. polygon() gives the outline exactly at quarter turns (environment vertices,
// and slice ends on axis-parallel walls; a slice end inside a slanted wall is rounded, and
// the sweeps' certification decides whether the turned cell is kept).
std::optional<TurnedCell> turn(const BoustrophedonDecomposition& b, std::size_t c) {
  TurnedCell r{c, nullptr, nullptr};
  try {
    r.env = std::make_unique<Environment>(Environment::make(b.polygon(c), {}));
    r.dec = std::make_unique<BoustrophedonDecomposition>(*r.env, b.angle() + 90);
  } catch (const InputError&) {
    return std::nullopt;  // not a valid polygon in doubles: the cell keeps the base direction
  }
  return r;
}

}  // namespace

CellDirections choose_directions(const BoustrophedonDecomposition& b, double w) {
  CellDirections out;
  const bool quarter = std::fmod(b.angle(), 90.0) == 0;
  for (std::size_t c = 0; c < b.cells().size(); ++c) {
    const double here = cell_score(b, c, w);
    if (quarter)
      if (auto r = turn(b, c)) {
        if (const double there = direction_score(*r->dec, w); there < here) {
          out.score += there;
          out.turned.push_back(std::move(*r));
          continue;
        }
      }
    out.kept.push_back(c);
    out.score += here;
  }
  return out;
}

}  // namespace preimage::coverage::detail
