// SPDX-License-Identifier: Apache-2.0
// Ground truth for target tracking: the discrete pursuit-evasion game "keep the target in
// view". Both players stand on the points of a grid over the free space; each step the
// target moves first, up to its reach, along a free straight segment; the observer then
// answers, up to its own reach. The observer loses when it no longer sees the target
// (a line of sight through free space that touches no obstacle corner, decided exactly
// between grid points, within the sensor's range) or the target comes within
// `separation` of it.
//
// Backward value iteration over all (observer, target) pairs gives, for every state, the
// number of steps in which the target can force a loss against every observer answer
// (its escape time), or "forever": the observer's winning region. The environment and
// every visibility and motion decision are exact; the grid (positions and the step) is
// the only approximation, and its resolution is stated with every answer.
//
// The paper behind the tracking module (002, section III) compares its risk controller
// with simpler strategies only; this solver answers what any controller could achieve.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

namespace preimage::tracking {

using geometry::Point;

struct GameParams {
  double resolution = 0.25;      // grid spacing (m)
  double observer_speed = 1.0;   // the observer's v_max (m/s)
  double speed_ratio = 0.5;      // target speed / observer speed (> 0)
  /// Sensor range (m); infinity for none. A field of view narrower than 360 degrees is
  /// not part of the state: the game's sensor turns freely (a pan unit), so its winning
  /// region bounds from above what a robot that must turn its body can keep.
  double range = 8.0;
  double separation = 0.35;      // the target within this distance of the observer is a loss (its radius + 0.15 m)
  /// The target is a disc: its centre stands only on grid points at least this far from
  /// every obstacle (decided exactly). A point target (0) hugs a small obstacle so closely
  /// that no observer kept off it by the separation can see round it: at 0.1 m the lab's
  /// 0.3 m chairs made every state a loss.
  double target_radius = 0.2;
  /// Seconds per step; 0: the target's one diagonal grid step (resolution * sqrt 2) over
  /// its speed. Longer steps let each player move farther (the game with the observer's
  /// velocity in the state needs the step its acceleration makes whole, see
  /// DynamicVisibilityGame::constant_acceleration_step).
  double step_time = 0;
  unsigned threads = 0;          // 0: one per hardware thread
  std::size_t max_states = 200'000'000;  // more (observer, target) pairs than this (or 2^32 - 1): InputError (6 bytes each)
  /// Called with the share of the work done (0..1), from one thread at a time: the sight
  /// table up to 0.4, then induction by the share of the seen states decided (a guess
  /// until the end: the kept ones are decided last, all at once).
  std::function<void(double)> progress;
};

struct GameStats {
  std::size_t points = 0;         // free grid points
  std::size_t states = 0;         // points^2
  std::size_t seen = 0;           // states where the observer sees the target
  std::size_t winning = 0;        // states kept forever
  std::uint32_t levels = 0;       // the longest finite escape time, in steps
  std::size_t memory_bytes = 0;   // peak of the solver's tables
  double seconds_visibility = 0;  // the exact line-of-sight table
  double seconds_solve = 0;       // backward induction
};

/// The solved game. Points are indexed 0..num_points()-1; a state is (observer, target).
class VisibilityGame {
 public:
  static constexpr std::uint32_t kForever = std::numeric_limits<std::uint32_t>::max();
  static constexpr std::uint32_t kNoPoint = std::numeric_limits<std::uint32_t>::max();

  /// Solves the game on `env` (InputError for a non-positive resolution, speed or ratio,
  /// no free grid point, or more states than params.max_states).
  VisibilityGame(const geometry::Environment& env, const GameParams& params);

  const GameParams& params() const { return params_; }
  const GameStats& stats() const { return stats_; }
  /// Seconds per step: the target's reach (one diagonal grid step, resolution * sqrt 2)
  /// over its speed, unless GameParams::step_time sets it. The reaches are the speeds
  /// times the step.
  double step_time() const { return step_; }
  double target_reach() const { return target_reach_; }
  double observer_reach() const { return observer_reach_; }

  std::size_t num_points() const { return points_.size(); }
  const Point& point(std::uint32_t i) const { return points_[i]; }
  /// The free grid point nearest p (kNoPoint if none within two grid steps), and the
  /// nearest one where the target may stand (its radius clear of the obstacles).
  std::uint32_t nearest(const Point& p) const { return nearest_where(p, false); }
  std::uint32_t nearest_target(const Point& p) const { return nearest_where(p, true); }
  bool target_may_stand(std::uint32_t i) const { return target_ok_[i] != 0; }
  /// The grid offset (di, dj) of point j from point i, in grid steps (exact: both lie on
  /// the grid).
  std::array<int, 2> offset(std::uint32_t i, std::uint32_t j) const;
  /// The environment's vertices (for tests of regions the moves sweep).
  const std::vector<Point>& environment_vertices() const { return vertices_; }

  /// Where each player may go in one step from point i (i itself first; the target only
  /// between points where it may stand, none from elsewhere).
  std::span<const std::uint32_t> observer_moves(std::uint32_t i) const;
  std::span<const std::uint32_t> target_moves(std::uint32_t i) const;

  /// Steps in which the target forces a loss from (observer o, target t), the target to
  /// move: 0 if lost already (not seen, or within separation, or t a point where the
  /// target cannot stand), kForever if the observer keeps it in view forever.
  std::uint32_t escape_steps(std::uint32_t o, std::uint32_t t) const { return level_[index(o, t)]; }
  bool keeps(std::uint32_t o, std::uint32_t t) const { return escape_steps(o, t) == kForever; }
  /// After the target moved to t: the best the observer at o can do (the largest
  /// escape_steps over its moves), and the move that achieves it (ties: the shortest move,
  /// then the lowest index).
  std::uint32_t answer_value(std::uint32_t o, std::uint32_t t) const;
  std::uint32_t observer_policy(std::uint32_t o, std::uint32_t t) const;
  /// The target's optimal escape: the move minimising answer_value; in a state the
  /// observer keeps (no escape exists), the move that leaves the observer the fewest
  /// keeping answers. Ties: the lowest index.
  std::uint32_t target_policy(std::uint32_t o, std::uint32_t t) const;

  /// For a fixed target point: every observer point that keeps it (escape_steps forever).
  std::vector<std::uint32_t> keeping_observers(std::uint32_t t) const;

 private:
  std::uint32_t nearest_where(const Point& p, bool target) const;
  std::size_t index(std::uint32_t o, std::uint32_t t) const { return static_cast<std::size_t>(o) * points_.size() + t; }

  GameParams params_;
  GameStats stats_;
  double step_ = 0, target_reach_ = 0, observer_reach_ = 0;
  double x0_ = 0, y0_ = 0;           // grid origin (the environment's lower-left corner)
  std::int64_t columns_ = 0, rows_ = 0;
  std::vector<Point> points_;
  std::vector<Point> vertices_;               // the environment's
  std::vector<std::uint32_t> cell_to_point_;  // row-major grid cell -> point, kNoPoint where not free
  std::vector<char> target_ok_;               // per point: the target's disc fits there
  std::vector<std::uint32_t> observer_moves_, target_moves_;              // CSR lists
  std::vector<std::uint32_t> observer_begin_, target_begin_;
  std::vector<std::uint32_t> level_;  // escape steps per state
};

/// Plays the game on the grid from (o, t): each step the target moves by `target` (a
/// function of the state returning one of target_moves(t)), then the observer by the
/// game's policy. Returns the step at which the target was first lost (0: at the start),
/// or kForever if still kept after `steps` steps.
template <class TargetMove>
std::uint32_t play(const VisibilityGame& game, std::uint32_t o, std::uint32_t t, std::size_t steps, TargetMove&& target) {
  if (game.escape_steps(o, t) == 0) return 0;
  for (std::size_t k = 1; k <= steps; ++k) {
    t = target(o, t);
    o = game.observer_policy(o, t);
    if (game.escape_steps(o, t) == 0) return static_cast<std::uint32_t>(k);
  }
  return VisibilityGame::kForever;
}

}  // namespace preimage::tracking
