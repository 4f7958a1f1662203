// SPDX-License-Identifier: Apache-2.0
// The visibility game with the observer's velocity in the state: ground truth for an
// observer whose acceleration is bounded (the "un-modeled observer dynamics" of the
// tracking paper, 002 section III.C, which its controllers do not plan for).
//
// Same grid, sight, separation, target and target moves as VisibilityGame (it is built on
// a solved one); the observer is a holonomic base whose sensor turns freely, with each
// component of its acceleration bounded by `accel` (m/s^2). Two models of its step:
//
// * SemiImplicit: from (o, v) it picks v' = v + a, each component of a in {-k..k} grid
//   steps per game step, |v'| within its reach, and goes to o + v' along a free straight
//   segment (semi-implicit Euler: the new velocity moves it). accel * step^2 must be k grid
//   steps: resolution = k * speed_ratio^2 * v_max^2 / (2 accel) with the game's usual step
//   (0.25 m at 0.5 m/s^2, half speed and 1 m/s). It moves the observer accel * step^2 per
//   step where a robot can go accel * step^2 / 2: it favours the observer.
// * ConstantAcceleration: exactly what a robot does holding the acceleration (v' - v) /
//   step for the step: it goes to o + (v + v') step / 2 along a parabola, which lies in
//   the triangle o, o + v step / 2, o + (v + v') step / 2 (its Bezier control polygon);
//   the move is allowed when the triangle's three sides are free and it holds no vertex of
//   the environment, so the parabola is in free space. Velocities are whole multiples of
//   2 resolution / step (so the corners are grid points), and accel * step^2 must be
//   2 k resolution: the VisibilityGame's step must be constant_acceleration_step(h,
//   accel) (1 s at 0.25 m and 0.5 m/s^2). Positions and velocities on the grid are the
//   only restriction of the robot; sight is checked at the steps' ends only.
//
// With no allowed v' (too fast towards a wall to stop) the observer has lost. Backward
// induction over (observer, velocity, target) states as in VisibilityGame; with the
// semi-implicit step the winning region is contained in the one without dynamics at the
// same grid (the observer's moves are a subset of its moves there), and equals it when k
// spans every velocity in one step.
#pragma once
#include <preimage/tracking/visibility_game.hpp>

#include <array>
#include <cmath>
#include <memory>

namespace preimage::tracking {

enum class ObserverStep { SemiImplicit, ConstantAcceleration };

struct DynamicGameParams {
  double accel = 0.5;  // the observer's acceleration bound per axis (m/s^2)
  ObserverStep step = ObserverStep::SemiImplicit;
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

  /// InputError when the game's resolution and step do not make the acceleration whole
  /// (the message names what does), or too many states.
  DynamicVisibilityGame(std::shared_ptr<const VisibilityGame> game, const DynamicGameParams& params);

  /// The step (s) for ObserverStep::ConstantAcceleration at this resolution: accel *
  /// step^2 = 2 resolution (set it as GameParams::step_time).
  static double constant_acceleration_step(double resolution, double accel) { return std::sqrt(2 * resolution / accel); }
  /// The game to build it on, for these params: with the semi-implicit step, `solved` if
  /// given (it must be `game` solved on `env`), else `game` solved here; with the constant
  /// acceleration, `game` solved with the step the acceleration makes whole.
  static std::shared_ptr<const VisibilityGame> base_game(const geometry::Environment& env, GameParams game,
                                                         const DynamicGameParams& params,
                                                         std::shared_ptr<const VisibilityGame> solved = nullptr);

  const VisibilityGame& game() const { return *game_; }
  const DynamicGameParams& params() const { return params_; }
  const DynamicGameStats& stats() const { return stats_; }
  /// The acceleration in velocity units per step (a whole number >= 1).
  int accel_steps() const { return accel_steps_; }

  std::size_t num_velocities() const { return velocities_.size(); }
  /// Velocity v in units of resolution / step (SemiImplicit) or 2 resolution / step
  /// (ConstantAcceleration) m/s; index 0 is standing still.
  std::array<int, 2> velocity(std::uint32_t v) const { return velocities_[v]; }
  /// The velocity's unit, m/s.
  double velocity_unit() const { return unit_; }

  /// Steps in which the target forces a loss from (observer o moving at v, target t), the
  /// target to move; 0 if lost already, kForever if kept forever. Escape times longer than
  /// 253 steps read 253.
  std::uint32_t escape_steps(std::uint32_t o, std::uint32_t v, std::uint32_t t) const;
  bool keeps(std::uint32_t o, std::uint32_t v, std::uint32_t t) const { return escape_steps(o, v, t) == kForever; }
  /// Where the observer at o moving at v goes when it chooses w, one of v's next
  /// velocities (kNone: not an allowed move, or w not one of them).
  std::uint32_t destination(std::uint32_t o, std::uint32_t v, std::uint32_t w) const {
    if (v >= velocities_.size() || w >= velocities_.size()) return kNone;
    const std::uint32_t e = edge_of_[static_cast<std::size_t>(v) * velocities_.size() + w];
    return e == kNone ? kNone : dest_[static_cast<std::size_t>(o) * next_.size() + e];
  }
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
  double unit_ = 0;
  std::vector<std::uint32_t> next_begin_, next_;  // CSR: velocities reachable in one step; its entries are the edges
  std::vector<std::uint32_t> edge_of_;            // per (v, w): the edge v -> w, kNone if w is not next to v
  std::vector<std::uint32_t> dest_, src_;         // per (point, edge v -> w): where it goes, and where it comes from
  std::vector<std::uint8_t> level_;               // per state: escape steps, 255 forever
};

}  // namespace preimage::tracking
