// SPDX-License-Identifier: Apache-2.0
// Figures for the pursuit module: the conservative cells (Fig. 6.34/6.35) and a plan as
// small multiples (pursuer positions, V, cleared and contaminated regions at several
// moments, from the independent checker's frames).
#pragma once
#include <preimage/pursuit/cells.hpp>
#include <preimage/pursuit/checker.hpp>
#include <preimage/render/svg.hpp>

#include <string>

namespace preimage::pursuit {

/// Critical segments (extension rays and bitangent rays in two colours) and, when the
/// cells are few enough to read, each cell's number of gaps at its sample point.
void draw_cells(render::SvgCanvas& canvas, const ConservativeCells& cells, bool labels = true);

/// The plan's paths over the environment, with the start marked.
void draw_paths(render::SvgCanvas& canvas, const Paths& paths);

/// Small multiples: one panel per recorded frame, `columns` per row, each showing the
/// pursuers, their V, the contaminated regions (red) and the cleared rest (white).
/// `captions` replace the panels' default captions; `first_panel` (a canvas of the same
/// panel width, e.g. a map of the plan) is placed before the frames.
std::string plan_frames_figure(const geometry::Environment& env, const Paths& paths, const std::vector<CheckFrame>& frames,
                               std::size_t columns = 3, const std::vector<std::string>& captions = {},
                               const render::SvgCanvas* first_panel = nullptr);
/// The width of one panel of plan_frames_figure.
constexpr double kFramePanelWidth = 320;

/// A panel of plan_frames_figure's width mapping a plan: each pursuer's path in its colour
/// and the static guards' posts, captioned (the `first_panel` of the small multiples).
render::SvgCanvas plan_map_panel(const geometry::Environment& env, const Paths& paths, const std::vector<Point>& guards,
                                 const std::string& caption);

/// Waypoints for `count` evenly spread frames of a plan with `waypoints` points.
std::vector<std::size_t> frame_waypoints(std::size_t waypoints, std::size_t count);

}  // namespace preimage::pursuit
