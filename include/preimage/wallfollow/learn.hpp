// SPDX-License-Identifier: Apache-2.0
// Strategy 1 of V.C: learning the cut ordering through the robot interface only
// (INIT, DROP, GRAB, follows and jumps; touch and pebble sensors).
//  1. INIT, DROP, LFOLLOW until the pebble: n and which vertices are reflex (v_1 is
//     the pebble's vertex).
//  2. For every cut: walk to its reflex vertex arriving in its direction, JUMP, follow
//     on to the pebble counting the steps: the edge of the cut endpoint.
//  3. Order the endpoints on each edge with the pebble: drop it at one endpoint, jump
//     along another cut and RFOLLOW: meeting the pebble before the next vertex means the
//     dropped endpoint comes after. `Sort::AllPairs` compares every pair as the paper
//     says; `Sort::Quick` drops the pebble once per pivot and tests the rest against it
//     (expected O(k log k) instead of k(k-1)/2 tests for k endpoints on an edge).
#pragma once
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/robot.hpp>

#include <cstdint>
#include <optional>

namespace preimage::wallfollow {

struct LearnOptions {
  enum class Sort { Quick, AllPairs } sort = Sort::Quick;
  std::uint64_t seed = 1;  // pivot choice
};

struct LearnReport {
  CutOrdering ordering;          // in the robot's labels: v_1 = the pebble's vertex
  std::size_t actions = 0;       // all primitives executed
  std::size_t phase_actions[3] = {0, 0, 0};
  std::size_t comparisons = 0;   // pebble tests in phase 3
  std::size_t max_edge_load = 0; // most cut endpoints on one edge
  /// Actions this run may take by the per-phase counts in learn.cpp:
  /// (n + 2) + 2m (2n + 3) + pivots (2n + 8) + comparisons (n + 6). With O(1) endpoints
  /// per edge this is O(n^2) (Proposition 5).
  std::size_t action_bound = 0;
  /// Where the robot ends (index into ordering.points) and how it arrived there (+1 after
  /// RFOLLOW, -1 after LFOLLOW, 0 after a JUMP), and where the pebble lies (none: held).
  std::uint32_t robot_at = 0;
  int arrived = 0;
  std::optional<std::uint32_t> pebble_at;
};

LearnReport learn_cut_ordering(RobotInterface& robot, const LearnOptions& options = {});

}  // namespace preimage::wallfollow
