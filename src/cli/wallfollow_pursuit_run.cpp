// SPDX-License-Identifier: Apache-2.0
#include "wallfollow_pursuit_run.hpp"

#include <preimage/error.hpp>
#include <preimage/pursuit/figures.hpp>
#include <preimage/wallfollow/pursuit_figure.hpp>
#include <preimage/wallfollow/sensors.hpp>

#include <stdexcept>

namespace preimage::cli {

using namespace wallfollow;

const char* strategy_name(PursuitSensor s) {
  switch (s) {
    case PursuitSensor::Gap: return "Strategy 2 (gap sensor)";
    case PursuitSensor::Bitangent: return "Strategy 3 (bitangent sensor)";
    case PursuitSensor::Pebble: return "Strategies 4 + 5 (pebble visibility)";
    case PursuitSensor::None: return "Strategy 6 (no special sensor)";
  }
  return "?";
}

PursuitSensor parse_sensor(const std::string& s) {
  for (PursuitSensor x : {PursuitSensor::Gap, PursuitSensor::Bitangent, PursuitSensor::Pebble, PursuitSensor::None})
    if (s == to_string(x)) return x;
  throw InputError("--sensor: expected gap, bitangent, pebble or none, got '" + s + "'");
}

PursuitRun run_pursuit(const geometry::Environment& env, const geometry::Point& start, const geometry::Vector& heading,
                       PursuitSensor sensor, std::size_t max_states, bool check, std::size_t frames) {
  Simulator sim(env, start, heading);
  sim.enable(sensors_of(sensor));
  PursuitOptions o;
  o.sensor = sensor;
  o.max_states = max_states;
  PursuitRun r{sensor, pursue(sim, o), {}, std::nullopt, 0};
  // The robot's labels start at the vertex INIT reached: which scene vertex is its v1.
  const TrueCuts T = true_cut_ordering(env);
  while (r.v1 < env.num_vertices() && !(T.ordering.relabelled(r.v1) == r.rep.learned.ordering)) ++r.v1;
  if (r.v1 == env.num_vertices()) throw std::logic_error("wallfollow pursue: the learned cut ordering is not the true one");
  if (r.rep.outcome != PursuitReport::Outcome::Plan) return r;
  const std::size_t from = sim.path().size() - 1;
  execute(sim, r.rep.plan);
  r.path.assign(sim.path().begin() + static_cast<long>(from), sim.path().end());
  if (check || frames > 0) {
    pursuit::CheckOptions co;
    if (frames > 0) co.frames = pursuit::frame_waypoints(r.path.size(), frames);
    r.check = pursuit::check_exact_paths(env, pursuit::ExactPaths{r.path}, co);
  }
  return r;
}

std::string pursuit_figure(const geometry::Environment& env, const PursuitRun& run) {
  const auto& rep = run.rep;
  const char* outcome = rep.outcome == PursuitReport::Outcome::Plan     ? "plan"
                        : rep.outcome == PursuitReport::Outcome::NoPlan ? "no plan"
                                                                        : "search stopped";
  const auto map = pursuit_map(env, true_cut_ordering(env), bitangents(env), run.path, pursuit::kFramePanelWidth,
                               std::string(strategy_name(run.sensor)) + ": " + outcome);
  const pursuit::Paths dp = pursuit::to_double(pursuit::ExactPaths{run.path});
  std::vector<std::string> captions;
  std::vector<pursuit::CheckFrame> frames;
  if (run.check) frames = run.check->frames;
  for (auto& f : frames)
    captions.push_back((f.waypoint ? "after " + std::string(to_string(rep.plan[f.waypoint - 1])) + " (" + std::to_string(f.waypoint) + ")"
                                   : std::string("start")) +
                       ": " + rep.labels_along.at(f.waypoint));
  return pursuit::plan_frames_figure(env, dp, frames, 3, captions, &map);
}

}  // namespace preimage::cli
