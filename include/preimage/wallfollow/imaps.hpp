// SPDX-License-Identifier: Apache-2.0
// Derived I-maps of section IV (counting windings and vertices) as one incremental
// filter in the form of eq. (4); filter::replay evaluates it on a stored history.
// Model of section IV: INIT first, the pebble lies fixed at a vertex, the robot moves
// by RFOLLOW and LFOLLOW (other actions count as a_i = 0).
//
// Sign: a_i = +1 for RFOLLOW (counter-clockwise, the wall on the right), -1 for
// LFOLLOW, so that counter-clockwise winding is positive as section IV.A states. (The
// paper's line "a_i = 1 if u_i = LFOLLOW" contradicts its own proof of Prop. 1.)
#pragma once
#include <preimage/filter/history.hpp>
#include <preimage/wallfollow/robot.hpp>

#include <optional>

namespace preimage::wallfollow {

struct CountingIMaps {
  long stage = 0;            // k
  long k1 = 0;               // edges traversed, eq. (6)
  long k2 = 0;               // combinatorial distance, eq. (8)
  long k3 = 0;               // pebble contacts, eq. (9)
  std::optional<long> k4;    // stage of the first contact
  long k5 = 0;               // winding number about the pebble (Prop. 1)
  long k6 = 0;               // combinatorial distance since the first contact, eq. (11)
  std::optional<long> k7;    // first stage with k5 * k6 != 0
  long k8 = 0;               // vertex count once non-zero (Prop. 2)

  void start(const Observation& y1);
  void step(Action u, const Observation& y);

 private:
  // Winding by laps: after the first contact the robot is either at a lift of the
  // pebble (j * n in the universal cover of the boundary) or strictly between lifts
  // j * n and (j + 1) * n. A full pass through a lift moves j; a reversal at a lift
  // does not. Eq. (10) sums (a_{i-1} + a_i) / 2 over contacts after the first, which
  // agrees except when the path later passes back through the first contact (the
  // first contact's departure is never counted there); the lap form is exact.
  bool at_lift_ = true;
  long lap_ = 0;
};

static_assert(filter::DerivedIMap<CountingIMaps, Action, Observation>);

/// +1 RFOLLOW, -1 LFOLLOW, 0 otherwise.
int direction(Action u);

/// Counting vertices with a pebble (IV.B): INIT, DROP, then follow (counter-clockwise,
/// or clockwise) until Prop. 2 gives k8. Throws std::logic_error if no count comes
/// within `max_actions`. The robot must hold the pebble.
CountingIMaps count_by_following(RobotInterface& robot, bool clockwise, std::size_t max_actions);

}  // namespace preimage::wallfollow
