// SPDX-License-Identifier: Apache-2.0
// pursue(): Strategy 1, then the pebble in hand, then the chosen strategy of section VI.
#include "strategies.hpp"

#include <chrono>

namespace preimage::wallfollow {
namespace {

struct OutOfTime {};

// The robot as the strategies drive it, refusing to move once the deadline has passed:
// learning, fetching the pebble and exploring (Strategy 2 executes every motion once, the
// long part on a large polygon) all stop at their next action.
class WatchedRobot final : public RobotInterface {
 public:
  WatchedRobot(RobotInterface& robot, const PursuitOptions& o) : r_(robot), o_(o) {}
  Observation apply(Action u) override {
    if (o_.on_action) o_.on_action();
    if (o_.deadline && std::chrono::steady_clock::now() >= *o_.deadline) throw OutOfTime{};
    return r_.apply(u);
  }
  Observation sense() const override { return r_.sense(); }

 private:
  RobotInterface& r_;
  const PursuitOptions& o_;
};

}  // namespace

const char* to_string(PursuitSensor s) {
  switch (s) {
    case PursuitSensor::Gap: return "gap";
    case PursuitSensor::Bitangent: return "bitangent";
    case PursuitSensor::Pebble: return "pebble";
    case PursuitSensor::None: return "none";
  }
  return "?";
}

Sensors sensors_of(PursuitSensor s) {
  Sensors out;
  out.gap = s == PursuitSensor::Gap;
  out.bitangent = s == PursuitSensor::Bitangent;
  out.pebble_visibility = s == PursuitSensor::Pebble;
  return out;
}

PursuitReport pursue(RobotInterface& unwatched, const PursuitOptions& options) {
  PursuitReport rep;
  WatchedRobot robot(unwatched, options);
  try {
    rep.learned = learn_cut_ordering(robot, options.learn);
    const OrderingMap m(rep.learned.ordering);
    Navigator nav(robot, m, Position{rep.learned.robot_at, static_cast<std::int8_t>(rep.learned.arrived)}, rep.learned.pebble_at);
    // Follows stop at a lying pebble; holding it keeps the moves those of the ordering.
    nav.grab();
    switch (options.sensor) {
      case PursuitSensor::Gap: gap_strategy(nav, m, options.max_states, options.deadline, rep); break;
      case PursuitSensor::Bitangent: bitangent_sensor_strategy(nav, m, options.max_states, options.deadline, rep); break;
      case PursuitSensor::Pebble: {
        const auto learned = learn_bitangents(nav, m);
        search_compounds(nav.at(), m, learned, options.max_states, rep, options.deadline);
        break;
      }
      case PursuitSensor::None:
        search_compounds(nav.at(), m, approximate_bitangents(m), options.max_states, rep, options.deadline);
        break;
    }
    rep.prepare_actions = nav.actions();
    rep.start = nav.at();
  } catch (const OutOfTime&) {
    rep.outcome = PursuitReport::Outcome::Budget;
    rep.out_of_time = true;
    rep.plan.clear();
    rep.labels_along.clear();
  }
  return rep;
}

std::optional<std::size_t> execute(RobotInterface& robot, const std::vector<Action>& plan) {
  if (robot.sense().detected) return 0;
  for (std::size_t k = 0; k < plan.size(); ++k)
    if (robot.apply(plan[k]).detected) return k + 1;
  return std::nullopt;
}

}  // namespace preimage::wallfollow
