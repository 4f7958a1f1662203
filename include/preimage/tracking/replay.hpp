// SPDX-License-Identifier: Apache-2.0
// Replay of recorded scans: TRACK's local map and escape-path tree on real laser logs.
//
// Formats, one scan per line (other lines are skipped):
//  * CARMEN: `FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_timestamp host
//    logger_timestamp`, the first beam at -90 deg and the spacing CARMEN's own
//    (flaser_angle_increment), and `ROBOTLASER1 type start_angle
//    fov resolution max_range accuracy remission_mode n r1..rn ...`. ODOM, PARAM, NEFF
//    and other messages and `#` comments are skipped.
//  * Plain text: `timestamp angle_min angle_increment r1 r2 ... rn` (radians, metres);
//    `#` starts a comment line.
#pragma once
#include <preimage/tracking/escape_path_tree.hpp>
#include <preimage/tracking/tracker.hpp>

#include <optional>
#include <string>

namespace preimage::tracking {

/// Spacing of the n beams of a FLASER line, as CARMEN's carmen_laser_get_angle_increment
/// gives it: pi/180 for 180 or 181 beams (1 deg; 180 beams are 181 with the last dropped,
/// so they span 179 deg), pi/360 for 360 or 361, pi/720 for 400 or 401, else the beams
/// spread over 180 deg (pi / (n - 1)).
double flaser_angle_increment(std::size_t n);

/// The scan on one log line, or nothing for a line that carries none. `max_range` is the
/// saturation range for formats that do not state it. Throws InputError
/// "<where>: token K (\"...\"): ..." naming the bad token.
std::optional<Scan> parse_log_line(const std::string& line, double max_range, const std::string& where);

/// What replay reports for one scan.
struct ReplayScan {
  std::size_t index = 0;
  double timestamp = 0;
  std::size_t vertices = 0, solid = 0, occlusion = 0, range = 0;
  std::string target_rule;  // "detected" (a circle of the target's radius), "ahead", or "none"
  Point target;
  bool has_tree = false;
  double sde = 0;
  std::size_t tree_nodes = 0, escape_paths = 0;
  Vec2 gradient;            // grad phi-bar (sensor frame)
  double micros = 0;        // local map + detection + tree + risk, wall clock

  // What was computed, for figures and JSON (sensor frame, metres; kept after timing).
  std::vector<Point> points;             // the scan's returns short of max_range
  LocalMap map;                          // V(q^o) with its edges by kind
  std::optional<EscapePathTree> tree;    // when has_tree
  std::optional<Point> detected;         // centre of the detected circle, if any
  double detected_radius = 0;
};

/// TRACK's steps on one recorded scan. The target is the detected circle nearest the
/// sensor if there is one, else a point straight ahead (half the range read there, at
/// most `ahead` metres), else half-way along the longest beam.
ReplayScan replay_scan(const Scan& scan, const TrackerParams& params, double ahead = 1.0);

}  // namespace preimage::tracking
