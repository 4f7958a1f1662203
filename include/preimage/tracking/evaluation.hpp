// SPDX-License-Identifier: Apache-2.0
// Strategy evaluation: many seeded runs per cell (scene x sensor x dynamics x target
// policy x strategy), escape-time distributions with 95% confidence intervals, control
// smoothness, and the paired risk - SDE difference, so that the paper's claim (section
// III.C: the escape risk keeps a target in view better than maximising SDE, above all
// with dynamics) can be tested rather than read off a handful of runs.
#pragma once
#include <preimage/tracking/simulation.hpp>

#include <functional>
#include <string>
#include <vector>

namespace preimage::tracking {

/// The sensor of simulate and evaluate: "360" (360 beams round, may back up) or "180" (361
/// beams over the half-plane ahead, as in V, which keeps the target centred). InputError
/// for anything else.
void set_sensor(SimulationParams& params, double fov_degrees);

struct EvaluationParams {
  std::size_t seeds = 100, steps = 300;
  std::vector<double> fovs{360, 180};
  std::vector<bool> dynamics{false, true};
  std::vector<TargetPolicy> policies{TargetPolicy::Scripted, TargetPolicy::Random, TargetPolicy::Adversarial,
                                     TargetPolicy::Lookahead};
  std::vector<Strategy> strategies{Strategy::Risk, Strategy::Sde, Strategy::Naive};
  double accel = 0.5, alpha = 1.5;  // the dynamics of the "with dynamics" cells
  double speed_ratio = 0.5;
  std::size_t lookahead_headings = 8, lookahead_steps = 5;
  /// Start of each seed's runs (the same for the three strategies): up to this far off
  /// the scene's start, so that the seeds sample situations, not only range noise.
  double start_spread = 0.5, heading_spread = 15 * M_PI / 180;
  std::size_t jobs = 1;             // worker threads
  /// The visibility game that says which starts are winnable (and that the game
  /// strategies and target consult) is solved per scene at this grid resolution (m); 0:
  /// no game (then no game strategy or target either). 0.125 m, not the game's 0.25 m
  /// default: at 0.25 m the game keeps lab starts the continuous adversary wins (19 of 20
  /// starts winnable, 10 of 20 at 0.125 m), and its policy loses the box's winnable starts.
  double game_resolution = 0.125;
  /// Cells with dynamics judge their starts in the game with the observer's velocity in
  /// the state instead (DynamicVisibilityGame with ObserverStep::ConstantAcceleration: a
  /// holonomic robot accelerating at most `accel` per axis, at rest at the start, which
  /// can do whatever the simulated robots do, their acceleration being bounded by accel
  /// as a vector), with the same point target, on a grid of max(game_resolution,
  /// dynamic_game_resolution) m (the lab at 0.125 m would take 3 G states). The game
  /// without dynamics changes the observer's velocity at once, so its winnable starts
  /// need not be winnable with dynamics. 0: the game without dynamics for every cell.
  double dynamic_game_resolution = 0.25;
  /// Called while each scene's game is solved: the scene's name and the share done.
  std::function<void(const std::string&, double)> game_progress;
};

/// A two-sided 95% interval about an estimate.
struct Interval {
  double value = 0, low = 0, high = 0;
};

struct CellResult {
  std::string scene;
  double fov = 360;
  bool dynamics = false;
  TargetPolicy policy = TargetPolicy::Scripted;
  Strategy strategy = Strategy::Risk;
  double horizon = 0;                // seconds; a run never lost counts as escaping at the horizon
  std::vector<double> escape_times;  // per seed (seed 1 first), the horizon if never lost
  std::size_t escaped = 0;
  Interval escaped_fraction;         // Wilson score interval
  Interval mean_escape;              // mean of min(t_esc, horizon), normal interval
  Interval median_escape;            // distribution-free (order statistics) interval
  double variation_v = 0, variation_omega = 0;  // mean total variation of the commands per second
  /// Against the game: per seed, whether the start (both players snapped to the game's
  /// grid) is kept forever in the game; how many are, how many of those runs this
  /// strategy kept for the whole horizon (Wilson interval of the fraction), and how many
  /// the game's own policy keeps, played on its grid against the game's optimal target
  /// for the horizon (a check of the solver: it must be all of them).
  double game_resolution = 0;  // 0: no game in this evaluation
  /// The starts were judged with the observer's velocity in the state (a cell with
  /// dynamics, EvaluationParams::dynamic_game_resolution > 0), on a grid of
  /// game_resolution m; "the game's policy on its grid" is then that game's.
  bool observer_dynamics = false;
  std::vector<char> winnable;
  std::size_t winnable_runs = 0, kept_winnable = 0, grid_kept = 0;
  Interval kept_winnable_fraction;
};

/// Wilson score 95% interval for k successes of n.
Interval wilson(std::size_t k, std::size_t n);

/// Runs every cell's seeds (1..seeds) on `jobs` threads, stopping each run at the first
/// loss of sight. `progress(done, total)` is called after each run (from the calling
/// thread's point of view, serialised). Results come in the order scenario, sensor,
/// dynamics, policy, strategy, independent of `jobs`.
std::vector<CellResult> evaluate(const std::vector<TrackingScenario>& scenarios, const EvaluationParams& params,
                                 const std::function<void(std::size_t, std::size_t)>& progress = {});

/// Statistics of one cell from its escape times (exposed for tests).
void summarise(CellResult& cell);

/// Paired difference of mean escape time, a - b, over the seeds both ran (the same seed
/// gives both runs the same noise and random target): mean and normal 95% interval.
Interval paired_difference(const CellResult& a, const CellResult& b);

/// Escape-time CDFs, one panel per scene x sensor x dynamics x policy, one curve per
/// strategy (fraction of runs that lost the target by time t).
std::string escape_time_cdf_figure(const std::vector<CellResult>& cells, const std::string& title);

}  // namespace preimage::tracking
