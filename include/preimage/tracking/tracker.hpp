// SPDX-License-Identifier: Apache-2.0
// Algorithm TRACK (section IV) on one scan: local map, target detection, escape-path
// tree, grad phi^e per free edge, grad phi-bar, and the robot command (section V.A).
#pragma once
#include <preimage/tracking/escape_path_tree.hpp>
#include <preimage/tracking/risk.hpp>
#include <preimage/tracking/scan.hpp>

#include <optional>

namespace preimage::tracking {

struct DetectParams {
  double radius = 0.2;        // the target's known radius
  double jump = 0.1;          // successive points further apart start a new cluster
  double max_rms = 0.03;      // a circle fit worse than this (metres) is not the target
  std::size_t min_points = 3;
  double gate = 1.5;          // with a prior estimate, only clusters this close are considered
};

/// The target as detected in a scan (section V.A: a cluster of points that fits the
/// target's circle; the best fit is kept).
struct Detection {
  bool found = false;
  Point center;               // sensor frame
  double rms = 0;             // of the fit
  std::size_t first = 0, last = 0;  // beams that hit it
  std::size_t candidates = 0; // clusters that fitted
};

Detection detect_target(const Scan& scan, const DetectParams& params, const std::optional<Point>& prior = {});
/// The scan with the target's readings replaced as if it were not there, interpolating
/// the background across its shadow: the paper assumes no obstacle lies in the shadow.
Scan without_target(const Scan& scan, const Detection& detection);
/// V(q^o) from the scan with the detected target's shadow filled (the scan as is if the
/// target was not found).
LocalMap local_map_without_target(const Scan& scan, const Detection& detection, const MapParams& params);

struct ControlParams {
  double k_v = 1.0, k_omega = 1.5;      // equation (6)
  double k_distance = 0.8, k_bearing = 1.5;  // the regulator: preferred distance, centred target
  double preferred_distance = 1.5;
  double v_max = 1.0, omega_max = 2.0;
  bool reverse = false;                 // may the observer back up (needs a 360-deg sensor)
};
struct Command { double v = 0, omega = 0; };

/// Equation (6) steering along -grad (sensor frame, heading +x) plus the proportional
/// regulator on the target's distance and bearing; clamped to the limits.
Command risk_command(const Vec2& grad, const Point& target, const ControlParams& params);
/// The naive follower: only the regulator (steer at the target, keep the distance).
Command naive_command(const Point& target, const ControlParams& params);

enum class Aggregation { Recursive, Plain };
const char* to_string(Aggregation a);

struct TrackerParams {
  MapParams map;
  DetectParams detect;
  RiskParams risk;
  ControlParams control;
  Aggregation aggregation = Aggregation::Recursive;
};

/// Everything one TRACK iteration computed (sensor frame).
struct TrackStep {
  Detection detection;
  LocalMap map;
  EscapePathTree tree;
  std::vector<EdgeRisk> risks;
  Vec2 gradient;   // grad phi-bar
  Command command;
  bool tracked = false;  // target detected and inside V
};

/// One iteration of TRACK. `prior` is the last estimate (sensor frame) for gating.
TrackStep track(const Scan& scan, const TrackerParams& params, const std::optional<Point>& prior = {});

}  // namespace preimage::tracking
