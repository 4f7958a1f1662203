// SPDX-License-Identifier: Apache-2.0
// The wall-following robot of III.A: actions, touch and pebble sensors, and an exact
// simulator. Strategies see only `RobotInterface` (actions in, observations out), never
// coordinates; the simulator's ground truth is for tests and reports.
#pragma once
#include <preimage/filter/shadow_labels.hpp>
#include <preimage/geometry/environment.hpp>

#include <memory>
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

/// What the bitangent sensor of VI.C reports when the robot crosses a bitangent ray
/// (Fig. 11): the two reflex vertices, which of them is closer (the crossed ray starts
/// there), and where the other ray ends in the cut ordering. Vertices and edges are named
/// relative to where the action ends (counter-clockwise vertex steps from the robot's
/// vertex, or from the start vertex of its edge): the robot converts them into its own
/// labels, which the sensor cannot know.
struct BitangentCrossing {
  std::uint32_t closer = 0, farther = 0;  // v_i (the crossed ray's vertex) and v_j, relative
  std::uint32_t other_edge = 0;           // edge holding b_ji, relative (edge e runs from e to e + 1)
  std::uint32_t other_after = 0;          // cut endpoints of that edge before b_ji
  bool operator==(const BitangentCrossing&) const = default;
};

/// y = (h_t, h_q): touch sensor and pebble sensor, and the sensors of section VI when
/// the simulator is given them (otherwise they read false / empty).
struct Observation {
  Touch touch = Touch::Interior;
  bool pebble = false;
  /// h_d (VI.A): the evader was visible at some moment of the last action after its
  /// start (at stage 1: now).
  bool detected = false;
  /// h_p (VI.D) now, and at some moment of the last action after its start.
  bool pebble_visible = false;
  bool pebble_seen = false;
  /// Gap sensor (VI.B): the shadow components now, in counter-clockwise order of their
  /// gaps around the robot, and the events of the last action in the order they
  /// happened, each a correspondence of components (appear, disappear, split, merge).
  std::size_t gaps = 0;
  std::vector<filter::ShadowEvent> gap_events;
  /// Bitangent sensor (VI.C): the bitangent rays crossed during the last action.
  std::vector<BitangentCrossing> bitangents;
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

/// Which sensors of section VI the simulator provides (all off: the model of III.A).
struct Sensors {
  bool detection = false;  // h_d, needs an evader
  bool pebble_visibility = false;
  bool gap = false;
  bool bitangent = false;
};

struct SensorState;  // robot.cpp: what the section VI sensors need

class Simulator final : public RobotInterface {
 public:
  /// The robot at `start` (interior or boundary) facing `heading`, holding the pebble
  /// unless `pebble` gives where it lies. The environment must satisfy
  /// require_general_position (checked by the callers that load scenes).
  Simulator(const geometry::Environment& env, const geometry::Point& start, const geometry::Vector& heading,
            std::optional<Place> pebble = std::nullopt);
  // Keeps a pointer to the environment.
  Simulator(geometry::Environment&&, const geometry::Point&, const geometry::Vector&, std::optional<Place> = std::nullopt) = delete;

  ~Simulator() override;
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  /// Turns on sensors of section VI (the environment must pass require_general_position
  /// and have distinct cut and bitangent endpoints for the gap and bitangent sensors).
  void enable(const Sensors& s);
  /// An evader standing at p (the detection sensor reads whether the robot saw it during
  /// an action); move it between actions to model a moving evader.
  void set_evader(const geometry::ExactPoint& p);

  Observation apply(Action u) override;
  Observation sense() const override;

  // Ground truth.
  const Place& robot() const { return robot_; }
  bool holding() const { return holding_; }
  const std::optional<Place>& pebble() const { return pebble_; }
  std::size_t actions() const { return actions_; }
  std::size_t jumps() const { return jumps_; }
  /// Every point the robot has been at, in order (INIT's wall contact included): its path.
  const std::vector<geometry::ExactPoint>& path() const { return path_; }
  const geometry::Environment& environment() const { return *env_; }
  /// Where a JUMP from reflex vertex v lands, arriving along the edge before v
  /// (counter-clockwise travel, right cut) or after it (clockwise, left cut).
  Place cut_endpoint(std::size_t v, bool left) const;

 private:
  void follow(bool ccw);
  void read_sensors(const std::vector<geometry::ExactPoint>& motion, bool held_before, const Place& start);
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
  std::vector<geometry::ExactPoint> path_;
  Sensors sensors_;
  std::unique_ptr<SensorState> state_;
  std::optional<geometry::ExactPoint> evader_;
  Observation reading_;  // section VI readings of the last action
};

}  // namespace preimage::wallfollow
