// SPDX-License-Identifier: Apache-2.0
// SVG figures for the landmark module: the swap cell decomposition (cells meeting the
// hull tinted), the hull or a patrol route, and a robot's path.
#pragma once
#include <preimage/landmarks/order_type.hpp>
#include <preimage/landmarks/swap_cells.hpp>
#include <preimage/render/svg.hpp>

#include <string>
#include <vector>

namespace preimage::landmarks {

struct LandmarkFigureOptions {
  std::vector<std::uint32_t> route;           // drawn closed, e.g. the learned hull or a patrol route
  std::string route_label = "convex hull";
  std::vector<geometry::Point> path;          // the robot's waypoints
  std::string path_label = "robot path";
  std::vector<std::uint32_t> highlight_cells;  // cells drawn in a strong colour
  std::string highlight_label = "goal cell";
};

/// The decomposition within a window around the landmarks (cells reaching beyond it are
/// cut by the frame).
render::SvgCanvas swap_cell_figure(const LandmarkSet& L, const SwapCellDecomposition& D, const LandmarkFigureOptions& o = {});

}  // namespace preimage::landmarks
