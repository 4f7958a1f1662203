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
  double rim = 0.03;          // neighbouring readings within radius + rim of the fitted centre are the target's too
};

/// The target as detected in a scan (section V.A: a cluster of points that fits the
/// target's circle; the best fit is kept).
struct Detection {
  bool found = false;
  Point center;               // sensor frame
  double rms = 0;             // of the fit
  /// Beams that hit it, first to last (round through the seam of a 360-deg scan when
  /// first > last): the fitted cluster, widened by the neighbours whose points lie on the
  /// fitted circle (a beam grazing the rim reads a point further out, which the cluster's
  /// jump test splits off; left in the scan it is a spike in V with a free edge a hair from
  /// the target).
  std::size_t first = 0, last = 0;
  std::size_t candidates = 0; // clusters that fitted
};

Detection detect_target(const Scan& scan, const DetectParams& params, const std::optional<Point>& prior = {});
/// The scan with the target's readings replaced as if it were not there. The paper (V.A)
/// assumes no obstacle lies in the target's shadow. If the readings either side of it
/// continue one surface (their ranges differ by at most the map's occlusion gap), the
/// surface is interpolated across; otherwise the nearer surface ends at the shadow's edge
/// and the shadow reads the farther one (max range if either side reads nothing), so the
/// free edge past the nearer surface's end stays in V. (Interpolating across a depth step
/// drew a wall through the shadow: a target touching the box corner hid the very free edge
/// it escaped through.)
Scan without_target(const Scan& scan, const Detection& detection, const MapParams& params = {});
/// V(q^o) from the scan with the detected target's shadow filled (the scan as is if the
/// target was not found).
LocalMap local_map_without_target(const Scan& scan, const Detection& detection, const MapParams& params);

struct ControlParams {
  double k_v = 1.0;           // equation (6), on log phi-bar (m^2/s): v_max when phi-bar changes by 100% per metre
  double k_omega = 1.5;       // equation (6)
  double k_distance = 0.8, k_bearing = 1.5;  // the regulator: preferred distance, centred target
  double preferred_distance = 1.5;
  double v_max = 1.0, omega_max = 2.0;
  bool reverse = false;       // may the observer back up (needs a 360-deg sensor)
  bool centre_target = false; // a sensor cone: the regulator also turns to keep the target in it
};
/// A velocity command: forward speed (m/s), turn rate (rad/s), and a sideways speed
/// (m/s, to the left) that only a holonomic base executes (the game strategy's observer).
struct Command { double v = 0, omega = 0, lateral = 0; };

/// The risk strategy's command and its parts (sensor frame, heading +x), for logging.
struct ControlTerms {
  Vec2 descent;     // k_v (-grad phi-bar) / phi-bar = k_v (-grad log phi-bar)
  Vec2 pull;        // the regulator: k_distance (|q^t| - preferred distance) towards the target
  Command command;  // equation (6) on descent + pull, the centring term with a cone, clamped
};

/// The risk strategy's control (V.A). The desired motion is D = descent + pull, mapped to
/// the unicycle by equation (6): v = n . D, omega = k_omega (n x D) / |D|, plus k_bearing
/// times the target's bearing when `centre_target` (a sensor cone), clamped to the limits.
/// Two departures from a literal eq. (6) on grad phi-bar, both found on the box scene
/// (docs/tracking.md):
///  * it descends log phi-bar (the same direction): |grad phi^e| is proportional to r_o, so
///    eq. (6)'s speed, k_v |grad phi-bar|, vanishes as the observer nears the occluding
///    corner although the target is about to escape; |grad log phi^e| = |2 grad r_o / r_o -
///    (m + 2) grad h / h| does not, and does not depend on the arbitrary c of eq. (3);
///  * the regulator's distance term joins D instead of being added to (v, omega), and it
///    turns to centre the target only with a cone: otherwise it turned the observer back
///    towards the target, cancelling the turn of eq. (6) towards -grad phi-bar.
ControlTerms risk_control(const RiskAverage& risk, const Point& target, const ControlParams& params);
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
  RiskAverage risk;      // phi-bar and grad phi-bar
  ControlTerms control;  // control.command is the command
  bool tracked = false;  // target detected and inside V
};

/// One iteration of TRACK. `prior` is the last estimate (sensor frame) for gating.
TrackStep track(const Scan& scan, const TrackerParams& params, const std::optional<Point>& prior = {});

}  // namespace preimage::tracking
