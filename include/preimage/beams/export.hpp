// SPDX-License-Identifier: Apache-2.0
// G and the regions out of the library: JSON, Graphviz DOT and SVG. G is listed as the
// multigraph of the paper (4.1), one edge per beam piece and direction, each naming its
// piece; the merged view lists one edge per (from, observation, to) with the pieces
// behind it (JSON), or one arrow per region pair with a list of labels (DOT, as in the
// paper's Fig. 7(b)).
#pragma once
#include <preimage/beams/arrangement.hpp>
#include <preimage/beams/homotopy.hpp>
#include <preimage/render/svg.hpp>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace preimage::beams {

/// "beam 3 piece 1, right to left": the beam piece of half-edge h (see
/// BeamArrangement::piece) and the side it is crossed from, relative to the beam's
/// from -> to (right to left is the positive crossing).
std::string piece_name(const BeamArrangement& arrangement, std::uint32_t half_edge);

nlohmann::json graph_json(const BeamArrangement& arrangement, bool merged = false);
std::string graph_dot(const BeamArrangement& arrangement, bool merged = false);

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
