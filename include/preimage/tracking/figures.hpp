// SPDX-License-Identifier: Apache-2.0
// SVG figures for the tracking module: V(q^o) with solid and free edges and the
// escape-path tree (the paper's Figs. 2-3), and a tracking run with both paths.
#pragma once
#include <preimage/tracking/simulation.hpp>

#include <string>

namespace preimage::tracking {

/// V (world frame) with its edges by kind, the escape-path tree, the shortest escape path
/// and, if given, -grad phi-bar drawn from the observer. `env` may be null.
std::string escape_path_tree_figure(const geometry::Environment* env, const LocalMap& map, const EscapePathTree& tree,
                                    const Vec2* descent = nullptr, const Vec2* plain_descent = nullptr);

struct ReplayScan;
/// One replayed scan (sensor frame): its returns, V with edges by kind, the detected
/// circle, the escape-path tree and the risk descent direction; `title` is written in a
/// corner; `legend` false leaves the legend out (panels after the first).
std::string replay_scan_figure(const ReplayScan& scan, const std::string& title, double width_px = 420, bool legend = true);

/// A closed-loop run: observer path, target path, where sight was lost.
std::string tracking_run_figure(const geometry::Environment& env, const SimulationResult& run, const std::string& title);

/// The visibility game's winning region for one target grid point: every observer grid
/// point drawn as a square, green where the observer keeps the target forever, shaded by
/// escape time elsewhere (white: lost at once); the target, and `observer` if given.
std::string game_region_figure(const geometry::Environment& env, const VisibilityGame& game, std::uint32_t target,
                               const Point* observer, const std::string& title);

}  // namespace preimage::tracking
