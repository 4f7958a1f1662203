// SPDX-License-Identifier: Apache-2.0
// A wall-following pursuit run as the CLI and the demo show it: the strategy through the
// simulator, its plan executed and checked by module pursuit's checker, and the figure
// (map of cuts, bitangent rays and the plan, then the labels at a few moments).
#pragma once
#include <preimage/pursuit/checker.hpp>
#include <preimage/wallfollow/pursuit.hpp>

#include <optional>
#include <string>
#include <vector>

namespace preimage::cli {

const char* strategy_name(wallfollow::PursuitSensor s);
wallfollow::PursuitSensor parse_sensor(const std::string& s);

struct PursuitRun {
  wallfollow::PursuitSensor sensor;
  wallfollow::PursuitReport rep;
  std::vector<geometry::ExactPoint> path;  // the executed plan
  std::optional<pursuit::CheckResult> check;
  std::size_t v1 = 0;  // the scene vertex the robot calls v1
};

/// `frames` > 0 records that many moments of the check for the figure; `check` false skips
/// the check unless frames are asked for.
PursuitRun run_pursuit(const geometry::Environment& env, const geometry::Point& start, const geometry::Vector& heading,
                       wallfollow::PursuitSensor sensor, std::size_t max_states, bool check, std::size_t frames);

/// The map and the moments of a run, as one SVG.
std::string pursuit_figure(const geometry::Environment& env, const PursuitRun& run);

}  // namespace preimage::cli
