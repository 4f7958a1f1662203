// SPDX-License-Identifier: Apache-2.0
// G and the regions out of the library: JSON, Graphviz DOT (parallel edges merged
// into one arrow with a list of labels, as in the paper's Fig. 7(b)), and SVG.
#pragma once
#include <preimage/beams/arrangement.hpp>
#include <preimage/beams/homotopy.hpp>
#include <preimage/render/svg.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace preimage::beams {

nlohmann::json graph_json(const BeamArrangement& arrangement);
std::string graph_dot(const BeamArrangement& arrangement);

/// Region boundary cycles as double polylines (for drawing).
std::vector<std::vector<geometry::Point>> region_rings(const BeamArrangement& arrangement, std::uint32_t region);

struct FigureOptions {
  std::vector<std::uint32_t> highlight;      // regions filled strongly (e.g. the final I-state)
  std::vector<geometry::Point> path;         // a body path or sample path
  std::string path_label = "path";
  bool region_ids = true;
};
/// Regions (pale fills), highlighted regions, beams with labels and direction ticks,
/// landmarks, and an optional path.
render::SvgCanvas arrangement_figure(const BeamArrangement& arrangement, const FigureOptions& options = {});

/// The arrangement with a loop basis drawn over it: basis beams dashed in green with
/// their generator names, and (if `loops`) the basis loop of each generator (Fig. 16).
render::SvgCanvas basis_figure(const BeamArrangement& arrangement, const LoopBasis& basis, const FigureOptions& options = {},
                               bool loops = true);

}  // namespace preimage::beams
