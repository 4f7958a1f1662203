// SPDX-License-Identifier: Apache-2.0
// The section VI strategies behind pursue() (internal): each takes the robot (holding
// the pebble, its cut ordering learned) and fills the report's search fields.
#pragma once
#include "navigator.hpp"

namespace preimage::wallfollow {

/// Strategy 2: explore every motion with the gap sensor, then search I_gap.
void gap_strategy(Navigator& nav, const OrderingMap& m, std::size_t max_states, const Deadline& deadline, PursuitReport& rep);

/// Strategy 3: explore every motion with the bitangent sensor, then search I_bit.
void bitangent_sensor_strategy(Navigator& nav, const OrderingMap& m, std::size_t max_states, const Deadline& deadline,
                               PursuitReport& rep);

/// Strategy 4: the bitangents among the candidates and where their rays end, with the
/// pebble visibility sensor. The robot ends holding the pebble.
std::vector<KnownBitangent> learn_bitangents(Navigator& nav, const OrderingMap& m);

}  // namespace preimage::wallfollow
