// SPDX-License-Identifier: Apache-2.0
// The robot moving by its cut ordering (internal to the section VI strategies): it
// predicts every move from the ordering, checks the touch sensor against the prediction,
// walks shortest action sequences to a point of the ordering, and can execute every
// motion once to read what a sensor says about it.
#pragma once
#include <preimage/wallfollow/pursuit.hpp>

#include <functional>
#include <map>

namespace preimage::wallfollow {

class Navigator {
 public:
  Navigator(RobotInterface& robot, const OrderingMap& map, Position at, std::optional<std::uint32_t> pebble);

  const Position& at() const { return at_; }
  bool holding() const { return !pebble_; }
  std::size_t actions() const { return actions_; }
  const Observation& last() const { return last_; }

  /// Applies u; throws std::runtime_error when the touch reading contradicts the ordering.
  const Observation& act(Action u);
  /// Walks a shortest action sequence to point k (arriving in direction `arrived`, if non-zero).
  void go(std::uint32_t k, int arrived = 0);
  void grab();
  void drop();
  /// Executes every motion at least once (walking between them), reporting each motion
  /// executed, with its observation, to `seen`.
  void explore(const std::function<void(const Motion&, const Position&, const Observation&)>& seen);

 private:
  std::vector<Action> path_to(const std::function<bool(const Position&)>& goal) const;
  RobotInterface& R_;
  const OrderingMap& m_;
  Position at_;
  std::optional<std::uint32_t> pebble_;
  std::size_t actions_ = 0;
  Observation last_;
  std::function<void(const Motion&, const Position&, const Observation&)> seen_;
};

}  // namespace preimage::wallfollow
