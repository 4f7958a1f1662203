// SPDX-License-Identifier: Apache-2.0
// Environments with known pursuit answers, for tests, the demo and the benchmark.
#pragma once
#include <preimage/geometry/environment.hpp>

namespace preimage::pursuit::examples {

/// A straight corridor with `rooms` rooms above it, each behind a narrow door: one
/// pursuer suffices (it looks into every room from its door).
geometry::Environment corridor_with_rooms(std::size_t rooms);

/// A square hub with three corridors leaving it (right, up, left), each bending twice so
/// that its far end cannot be seen from the hub nor the hub from it. Simply connected,
/// and one pursuer is not enough: while it clears one arm, an evader can pass the
/// unwatched hub from a contaminated arm into a cleared one.
geometry::Environment three_arms(double leg = 5.0);

/// The nested-U family of Fig. 6.40 (simply connected, O(log n) pursuers needed): level 1
/// is a dead end; level L a corridor (the hub) with three arms, each bending twice (up,
/// right, up) so that the hub sees nothing past the bends, and ending in a level L - 1
/// copy. Level 2 is three bent arms around a hub (two pursuers); each level needs one
/// more pursuer than the one below (three branches that each need k, joined where none
/// of them can be seen, need k + 1: Guibas et al. 1999). Corridors 1 m wide on a 1 m grid.
geometry::Environment nested_u(std::size_t level);

/// A square room around a square pillar: the smallest environment with a hole (one
/// pursuer can never clear it, Guibas et al. 1999).
geometry::Environment room_with_pillar();

}  // namespace preimage::pursuit::examples
