// SPDX-License-Identifier: Apache-2.0
// Closed-loop tracking runs (section V.B's experiments, in simulation): an observer
// running TRACK on simulated scans at a fixed rate against a target that moves
// unpredictably, and the two baselines of the issue — a naive follower and the
// SDE-maximising strategy of equation (2).
#pragma once
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/scene.hpp>
#include <preimage/tracking/tracker.hpp>

#include <string>
#include <vector>

namespace preimage::tracking {

enum class TargetPolicy { Scripted, Random, Adversarial };
enum class Strategy { Risk, Sde, Naive };
const char* to_string(TargetPolicy p);
const char* to_string(Strategy s);
TargetPolicy parse_target_policy(const std::string& s);  // InputError on anything else
Strategy parse_strategy(const std::string& s);

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
};

struct SimulationParams {
  TargetPolicy policy = TargetPolicy::Scripted;
  Strategy strategy = Strategy::Risk;
  std::size_t steps = 300;
  double dt = 0.1;               // TRACK runs at 1/dt Hz (the paper: about 10 Hz)
  double speed_ratio = 0.5;      // adversarial target speed / observer v_max
  std::uint64_t seed = 1;
  LaserSpec laser{2 * M_PI, 360, 8.0, 0.01};
  TrackerParams tracker;         // its detection radius and risk delta come from the scenario's target
  bool stop_at_escape = false;
};

struct SimulationResult {
  std::vector<Pose> observer;     // one per step, world frame, including the start
  std::vector<Point> target;
  std::vector<char> visible;      // the target's centre in the observer's line of sight, range and cone
  std::vector<char> tracked;      // TRACK detected it
  double escape_time = -1;        // first loss of sight (seconds); -1: never within the run
  double visible_fraction = 0;
  double observer_length = 0, target_length = 0;
  double dt = 0.1;
};

SimulationResult simulate(const TrackingScenario& scenario, const SimulationParams& params);

/// Shortest path for the target between two free points (visibility graph of the
/// environment's vertices + Dijkstra); empty if unreachable.
std::vector<Point> shortest_path(const geometry::Environment& env, const Point& from, const Point& to);

/// The map in world coordinates: local_map_from_visibility of the exact V at `at`.
LocalMap exact_local_map(const geometry::VisibilityIndex& index, const Point& at);

}  // namespace preimage::tracking
