// SPDX-License-Identifier: Apache-2.0
#include <preimage/wallfollow/imaps.hpp>

#include <cstdlib>
#include <stdexcept>

namespace preimage::wallfollow {

int direction(Action u) { return u == Action::RFollow ? 1 : u == Action::LFollow ? -1 : 0; }

void CountingIMaps::start(const Observation& y1) {
  *this = CountingIMaps{};
  stage = 1;
  if (y1.pebble) k3 = 1, k4 = 1;
}

void CountingIMaps::step(Action u, const Observation& y) {
  ++stage;
  const int a = direction(u);
  k1 += std::abs(a);
  k2 += a;
  if (k4) {
    // The action left a stage at or after the first contact: it counts in eq. (11)
    // (displacement since the first contact, including the move that leaves it).
    k6 += a;
    if (a != 0) {
      if (at_lift_) lap_ = a > 0 ? lap_ : lap_ - 1, at_lift_ = false;  // now between lifts lap_ and lap_ + 1
      if (y.pebble) lap_ = a > 0 ? lap_ + 1 : lap_, at_lift_ = true;
    }
    // Laps completed, rounded toward zero: between lifts j and j + 1 that is j for
    // j >= 0 and j + 1 below.
    k5 = at_lift_ ? lap_ : (lap_ >= 0 ? lap_ : lap_ + 1);
  }
  if (y.pebble) {
    ++k3;
    if (!k4) k4 = stage, at_lift_ = true, lap_ = 0;
  }
  if (!k7 && k5 * k6 != 0) k7 = stage, k8 = std::labs(k6);  // Prop. 2
}

CountingIMaps count_by_following(RobotInterface& robot, bool clockwise, std::size_t max_actions) {
  CountingIMaps k;
  k.start(robot.sense());
  for (Action u : {Action::Init, Action::Drop}) k.step(u, robot.apply(u));
  const Action follow = clockwise ? Action::LFollow : Action::RFollow;
  while (k.k8 == 0) {
    if (static_cast<std::size_t>(k.stage - 1) >= max_actions) throw std::logic_error("count: no vertex count within the action limit");
    k.step(follow, robot.apply(follow));
  }
  return k;
}

}  // namespace preimage::wallfollow
