// SPDX-License-Identifier: Apache-2.0
// Closed-loop tracking runs (section V.B's experiments, in simulation): an observer
// running TRACK on simulated scans at a fixed rate against a target that moves
// unpredictably, and the two baselines — a naive follower and the SDE-maximising
// strategy of equation (2). The observer is a unicycle (equation 5), optionally with
// bounded linear and angular acceleration, which the strategies do not model (the
// "un-modeled observer dynamics" of section III.C).
#pragma once
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/tracking/tracker.hpp>
#include <preimage/tracking/visibility_game.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace preimage::tracking {

/// How the target moves:
///  * Scripted: along the scene's $.tracking.target_path at its target_speed, then stays.
///  * Random: to random free points by shortest paths, at target_speed.
///  * Adversarial: along its current shortest escape path SEP(q^t, q^o) in the exact V of
///    the observer's true position, re-planned every step, at speed_ratio x v_max.
///  * Lookahead: at speed_ratio x v_max, plays the adversarial move and each of
///    `lookahead_headings` straight headings for `lookahead_steps` steps against the
///    observer's actual response (its strategy, run on noise-free scans), and takes the
///    first step of the one that leaves sight soonest; the adversarial move if none does
///    sooner than it. Re-planned every step.
///  * Game: at speed_ratio x v_max, towards the grid point the solved visibility game's
///    optimal escape (VisibilityGame::target_policy) picks for the nearest grid state;
///    re-planned every step (needs SimulationParams::game).
/// The random and planning targets pass obstacle corners their radius off: a disc wraps a
/// corner (as the risk of eq. (3)-(4) assumes), and a path through the corner itself would
/// put the target's centre on the boundary, where the adversary used to stall.
enum class TargetPolicy { Scripted, Random, Adversarial, Lookahead, Game };
/// The observer's strategies: TRACK's risk descent, the SDE maximiser of eq. (2), the
/// naive follower, and two that consult the solved visibility game (SimulationParams::game):
///  * Game: the game's own observer — a holonomic base with a sensor that turns freely
///    (Command::lateral) — heading straight for the grid point, within one game step, with
///    the best game value against the target's grid cell, then the deepest in the keeping
///    region, then the nearest the target; the body turning to face the target.
///  * RiskGame: a unicycle (like risk) steering for the same grid point: of TRACK's risk
///    command and a fan of commands, the one that keeps the target in the sensor, then has
///    the best game value, then ends nearest that point, then is nearest the risk command.
enum class Strategy { Risk, Sde, Naive, Game, RiskGame };
const char* to_string(TargetPolicy p);
const char* to_string(Strategy s);
TargetPolicy parse_target_policy(const std::string& s);  // InputError on anything else
Strategy parse_strategy(const std::string& s);

/// Sensor frame (observer at the origin, heading +x) to world and back.
Point to_world(const Pose& pose, const Point& sensor);
Point to_sensor(const Pose& pose, const Point& world);
Vec2 to_world(const Pose& pose, const Vec2& sensor);  // a direction

/// A scene's environment and its tracking slot, checked: both start points in free
/// space, the target visible from the observer, the scripted path walkable.
struct TrackingScenario {
  std::string name;
  const geometry::Environment* environment = nullptr;
  Pose observer;
  Disc target;
  double target_speed = 0.5;
  std::vector<Point> target_path;
  static TrackingScenario from_scene(const scene::Scene& scene);
  static TrackingScenario from_scene(scene::Scene&&) = delete;  // keeps a pointer to the environment
};

/// What the observer computed on one step, handed to SimulationParams::on_step.
struct StepRecord {
  std::size_t step = 0;
  Pose observer;               // before the step's motion (world frame)
  Point target;                // true position
  bool visible = false;
  Point estimate;              // the observer's estimate of the target after this scan (world)
  const TrackStep* track = nullptr;  // TRACK on this step's scan (sensor frame; every strategy detects with it)
  Command command;             // the strategy's command
  Command velocity;            // what the observer executed (differs from command with dynamics)
};

struct SimulationParams {
  TargetPolicy policy = TargetPolicy::Scripted;
  Strategy strategy = Strategy::Risk;
  std::size_t steps = 300;
  double dt = 0.1;               // TRACK runs at 1/dt Hz (the paper: about 10 Hz)
  double speed_ratio = 0.5;      // adversarial and look-ahead target speed / observer v_max
  std::uint64_t seed = 1;
  LaserSpec laser{2 * M_PI, 360, 8.0, 0.01};
  TrackerParams tracker;         // its detection radius and risk delta come from the scenario's target
  /// Observer dynamics: the executed (v, omega) moves towards the command by at most
  /// accel dt and alpha dt per period (m/s^2, rad/s^2); 0 leaves that bound off. accel
  /// bounds the acceleration as a vector: the change of the world-frame velocity in a
  /// period, turning at speed included (v omega), is at most accel dt; where the command
  /// would exceed it, the changes of speed and turn rate are scaled back together.
  double accel = 0, alpha = 0;
  std::size_t lookahead_headings = 8, lookahead_steps = 5;
  /// Each seed starts the observer and the target up to start_spread metres off the
  /// scenario's start (uniform in a disc) and the heading up to heading_spread radians off,
  /// keeping the target in view; 0 and 0: the scenario's start.
  double start_spread = 0, heading_spread = 0;
  bool stop_at_escape = false;
  std::function<void(const StepRecord&)> on_step;  // called on every step but the last
  /// The solved game for Strategy::Game, Strategy::RiskGame and TargetPolicy::Game
  /// (InputError without it).
  std::shared_ptr<const VisibilityGame> game;
};

/// The game a run's settings describe: the observer's v_max, the target's speed ratio, the
/// laser's range, the target's radius + 0.15 m as the separation, and a point target (the
/// simulated targets do not keep their disc clear of obstacle faces).
GameParams game_params(const TrackingScenario& scenario, const SimulationParams& params, double resolution);

struct SimulationResult {
  std::vector<Pose> observer;     // one per step, world frame, including the start
  std::vector<Point> target;
  std::vector<char> visible;      // the target's centre in the observer's line of sight, range and cone
  std::vector<char> tracked;      // TRACK detected it
  std::vector<Command> commands;  // the strategy's command on each step but the last
  double escape_time = -1;        // first loss of sight (seconds); -1: never within the run
  double visible_fraction = 0;
  double observer_length = 0, target_length = 0;
  double dt = 0.1;
  /// Control smoothness: total variation of the commands, sum |v_k - v_k-1| and
  /// sum |omega_k - omega_k-1|, divided by the run's duration (m/s per s, rad/s per s).
  double variation_v() const;
  double variation_omega() const;
};

SimulationResult simulate(const TrackingScenario& scenario, const SimulationParams& params);

/// Shortest path for the target between two free points (visibility graph of the
/// environment's vertices + Dijkstra); empty if unreachable.
std::vector<Point> shortest_path(const geometry::Environment& env, const Point& from, const Point& to);

/// The map in world coordinates: local_map_from_visibility of the exact V at `at`.
LocalMap exact_local_map(const geometry::VisibilityIndex& index, const Point& at);

/// phi-bar and grad phi-bar on the exact map (world frame), and central differences of
/// phi-bar with V, the tree and the risks recomputed at observer +- eps along x and y.
/// `stable` says whether all four displaced trees kept the structure (the corners, last
/// pivots and tree shape): only then is the difference quotient the derivative of the
/// same function. Throws InputError if V or the tree cannot be built at the observer.
struct RiskCheck {
  RiskAverage risk;
  Vec2 difference;
  bool stable = false;
};
RiskCheck check_risk_gradient(const geometry::VisibilityIndex& index, const Point& observer, const Point& target,
                              const RiskParams& params, Aggregation aggregation, double eps = 1e-6);

}  // namespace preimage::tracking
