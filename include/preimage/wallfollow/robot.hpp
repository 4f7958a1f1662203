// SPDX-License-Identifier: Apache-2.0
// The wall-following robot of III.A: actions, touch and pebble sensors, and an exact
// simulator. Strategies see only `RobotInterface` (actions in, observations out), never
// coordinates; the simulator's ground truth is for tests and reports.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace preimage::wallfollow {

enum class Action { Init, RFollow, LFollow, Jump, Grab, Drop };
enum class Touch { Interior, Edge, Convex, Reflex };

const char* to_string(Action u);
const char* to_string(Touch t);
/// "INIT,DROP,LFOLLOW" (commas and/or whitespace). InputError names the token and its
/// position: "action 3 'JUMPP' at offset 10: unknown action (INIT, ...)".
std::vector<Action> parse_actions(const std::string& text);

/// y = (h_t, h_q): touch sensor and pebble sensor.
struct Observation {
  Touch touch = Touch::Interior;
  bool pebble = false;
  bool operator==(const Observation&) const = default;
};
std::string to_string(const Observation& y);

/// A point of E: interior, a vertex, or on an edge (exact point). `mark` names a
/// constructed boundary point (a cut endpoint: 2 * vertex + (left ? 0 : 1)) so that two
/// places built by the same jump compare equal without exact evaluation.
struct Place {
  enum class Kind { Interior, Vertex, Edge } kind = Kind::Interior;
  std::size_t index = 0;  // vertex or edge (edge e runs from vertex e to next(e))
  geometry::ExactPoint point;
  long mark = -1;
  static Place vertex(const geometry::Environment& env, std::size_t v);
  /// The place of point p (interior, vertex or edge); InputError "<what> (x, y) is not
  /// in the environment (it is outside)" otherwise.
  static Place of(const geometry::Environment& env, const geometry::Point& p, const std::string& what);
};
bool same_place(const Place& a, const Place& b);

/// What a strategy may use.
class RobotInterface {
 public:
  virtual ~RobotInterface() = default;
  /// Applies u and returns the observation at the new stage. Inapplicable actions throw.
  virtual Observation apply(Action u) = 0;
  /// The current observation.
  virtual Observation sense() const = 0;
};

/// Thrown for an action whose precondition fails ("JUMP: the robot is not at a reflex vertex").
class ActionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Simulator final : public RobotInterface {
 public:
  /// The robot at `start` (interior or boundary) facing `heading`, holding the pebble
  /// unless `pebble` gives where it lies. The environment must satisfy
  /// require_general_position (checked by the callers that load scenes).
  Simulator(const geometry::Environment& env, const geometry::Point& start, const geometry::Vector& heading,
            std::optional<Place> pebble = std::nullopt);
  // Keeps a pointer to the environment.
  Simulator(geometry::Environment&&, const geometry::Point&, const geometry::Vector&, std::optional<Place> = std::nullopt) = delete;

  Observation apply(Action u) override;
  Observation sense() const override;

  // Ground truth.
  const Place& robot() const { return robot_; }
  bool holding() const { return holding_; }
  const std::optional<Place>& pebble() const { return pebble_; }
  std::size_t actions() const { return actions_; }
  std::size_t jumps() const { return jumps_; }
  const geometry::Environment& environment() const { return *env_; }
  /// Where a JUMP from reflex vertex v lands, arriving along the edge before v
  /// (counter-clockwise travel, right cut) or after it (clockwise, left cut).
  Place cut_endpoint(std::size_t v, bool left) const;

 private:
  void follow(bool ccw);
  const geometry::Environment* env_;
  Place robot_;
  // Direction of motion: along an edge into the current place (edge index, ccw or not),
  // or a free direction (after INIT from the interior or a JUMP).
  std::optional<std::pair<std::size_t, bool>> arrived_along_;
  geometry::ExactKernel::Vector_2 heading_;
  bool holding_ = true;
  std::optional<Place> pebble_;
  std::size_t actions_ = 0, jumps_ = 0;
  mutable std::vector<std::optional<Place>> cut_cache_;  // 2 per vertex
};

}  // namespace preimage::wallfollow
