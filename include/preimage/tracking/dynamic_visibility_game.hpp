// SPDX-License-Identifier: Apache-2.0
// The visibility game with the observer's velocity in the state: ground truth for an
// observer whose acceleration is bounded (the "un-modeled observer dynamics" of the
// tracking paper, 002 section III.C, which its controllers do not plan for).
//
// Same grid, sight, separation, target and target moves as VisibilityGame (it is built on
// a solved one); the observer, a holonomic base whose sensor turns freely, moves at the
// velocity it chose for the step: from (o, v) it picks v' = v + a with each component of
// a in {-1, 0, 1} grid steps per game step, |v'| within its reach, and goes to o + v'
// along a free straight segment (semi-implicit Euler: the new velocity moves it). With no
// such v' (too fast towards a wall to stop) the observer has lost. The acceleration bound
// `accel` (m/s^2 per axis) is one grid step per game step squared: resolution =
// accel_steps * speed_ratio^2 * v_max^2 / (2 accel) for an integer accel_steps >= 1
// (0.25 m at the evaluation's 0.5 m/s^2, half speed and 1 m/s), anything else is refused:
// the velocities must carry grid points to grid points.
//
// Backward induction over (observer, velocity, target) states as in VisibilityGame; the
// winning region here is contained in the one without dynamics at the same grid (the
// observer's moves are a subset of its moves there), and equals it when accel_steps spans
// every velocity in one step.
#pragma once
#include <preimage/tracking/visibility_game.hpp>

#include <array>
#include <memory>

namespace preimage::tracking {

struct DynamicGameParams {
  double accel = 0.5;  // the observer's acceleration bound per axis (m/s^2)
  unsigned threads = 0;  // 0: one per hardware thread
  std::size_t max_states = 400'000'000;  // (observer, velocity, target) states; 2 bytes each
  std::function<void(double)> progress;  // share of the induction's states decided (a guess until the end)
};

struct DynamicGameStats {
  std::size_t velocities = 0;   // velocity vectors (grid steps per game step)
  std::size_t states = 0;       // points^2 * velocities
  std::size_t seen = 0;         // states where the observer sees the target
  std::size_t winning = 0;      // states kept forever
  std::size_t winning_at_rest = 0;  // of them, with the observer standing still
  std::uint32_t levels = 0;     // the longest finite escape time, in steps
  std::size_t memory_bytes = 0;
  double seconds = 0;
};

class DynamicVisibilityGame {
 public:
  static constexpr std::uint32_t kForever = VisibilityGame::kForever;
  static constexpr std::uint32_t kNone = VisibilityGame::kNoPoint;

  /// InputError when the resolution does not make accel a whole number of grid steps per
  /// step squared (the message names the resolutions that do), or too many states.
  DynamicVisibilityGame(std::shared_ptr<const VisibilityGame> game, const DynamicGameParams& params);

  const VisibilityGame& game() const { return *game_; }
  const DynamicGameParams& params() const { return params_; }
  const DynamicGameStats& stats() const { return stats_; }
  /// The acceleration in grid steps per game step squared (a whole number >= 1).
  int accel_steps() const { return accel_steps_; }

  std::size_t num_velocities() const { return velocities_.size(); }
  /// Velocity v in grid steps per game step (resolution / step_time() m/s each); index 0
  /// is standing still.
  std::array<int, 2> velocity(std::uint32_t v) const { return velocities_[v]; }

  /// Steps in which the target forces a loss from (observer o moving at v, target t), the
  /// target to move; 0 if lost already, kForever if kept forever. Escape times longer than
  /// 253 steps read 253.
  std::uint32_t escape_steps(std::uint32_t o, std::uint32_t v, std::uint32_t t) const;
  bool keeps(std::uint32_t o, std::uint32_t v, std::uint32_t t) const { return escape_steps(o, v, t) == kForever; }
  /// Where velocity v' carries the observer from o (kNone: not a free straight move).
  std::uint32_t destination(std::uint32_t o, std::uint32_t v) const { return dest_[static_cast<std::size_t>(o) * velocities_.size() + v]; }
  /// The velocities the observer at velocity v may choose next (v + a, within reach).
  std::span<const std::uint32_t> next_velocities(std::uint32_t v) const;

  /// After the target moved to t: the observer's best next velocity from (o, v) (the
  /// largest escape_steps at its destination; ties: the slowest, then the lowest index),
  /// kNone when it has no move at all.
  std::uint32_t observer_policy(std::uint32_t o, std::uint32_t v, std::uint32_t t) const;
  /// The target's optimal escape from (o, v, t): the move minimising the observer's best
  /// answer. Ties: the lowest index.
  std::uint32_t target_policy(std::uint32_t o, std::uint32_t v, std::uint32_t t) const;

 private:
  std::size_t index(std::uint32_t o, std::uint32_t v, std::uint32_t t) const {
    return (static_cast<std::size_t>(o) * velocities_.size() + v) * game_->num_points() + t;
  }
  std::uint32_t answer_value(std::uint32_t o, std::uint32_t v, std::uint32_t t) const;

  std::shared_ptr<const VisibilityGame> game_;
  DynamicGameParams params_;
  DynamicGameStats stats_;
  int accel_steps_ = 1;
  std::vector<std::array<int, 2>> velocities_;
  std::vector<std::uint32_t> next_begin_, next_;  // CSR: velocities reachable in one step
  std::vector<std::uint32_t> dest_, src_;         // per (point, velocity): o + v, and the o with o + v = point
  std::vector<std::uint8_t> level_;               // per state: escape steps, 255 forever
};

}  // namespace preimage::tracking
