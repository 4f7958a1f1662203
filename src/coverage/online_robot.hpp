// SPDX-License-Identifier: Apache-2.0
// Private to coverage: the simulated robot of online coverage (online_coverage.hpp). It owns
// the map — the configuration space component in the sweep frame, where its centre moves,
// and the workspace in the same frame, which its range sensors see — and offers only the
// motion primitives of 6.2.4 and the sensor ring. Every decision that touches the map
// (contact, where a follow stops, whether a retraced segment is free) is exact.
#pragma once
#include <preimage/coverage/online_coverage.hpp>

#include "cell_sweep.hpp"

#include <cmath>
#include <random>

namespace preimage::coverage::detail {

/// Where the robot is on the contact boundary (or nowhere on it).
struct Contact {
  static constexpr std::uint32_t kNone = UINT32_MAX;
  std::uint32_t vertex = kNone;  // at this vertex of the configuration space polygon
  std::uint32_t edge = kNone;    // inside this edge (the point rounded a few ulps into free space)
  bool on_boundary() const { return vertex != kNone || edge != kNone; }
};

/// One reading of the ring: the readings and the sensor holding the minimum.
struct RingReading {
  std::vector<double> ranges;
  std::size_t argmin = 0;
};

class OnlineRobot {
 public:
  /// `Q`: the configuration space component in the sweep frame; `W`: the workspace in the
  /// same frame. Both must outlive the robot.
  OnlineRobot(const Environment& Q, const Environment& W, const OnlineOptions& o, const Point& start);

  // --- what the planner may use ---------------------------------------------------------
  const Point& odometry() const { return pos_; }
  const Contact& contact() const { return at_; }
  /// The ring, read where the robot is (Gaussian noise added, clipped to [0, range]).
  RingReading read_ring();
  double sensor_angle(std::size_t i) const;  // sweep frame, sensor 0 along +x
  std::size_t sensors() const { return n_; }
  /// Lap along the slice (+y when up) until contact. False if the robot cannot move that way
  /// (it is against the boundary in that direction); the robot then stays.
  bool lap(bool up);
  /// One step of boundary following, keeping the boundary on the ring direction `dir` (+1:
  /// the polygon's ring order, free space on the left; -1: the reverse): to the next vertex,
  /// or onto the slice x = stop_x if the current edge reaches it first (then `on_slice`).
  /// False if the robot is not on the boundary.
  /// A second stop slice `stop_x2` (NaN: none) bounds the lateral displacement both ways.
  bool follow_step(int dir, double stop_x, bool& on_slice, double stop_x2 = NAN);
  /// A lap along a wall: where the boundary runs along the slice from the robot's vertex
  /// (up: +y), slide along it to the wall's far end, the next vertex (the robot keeps
  /// contact with it on one side: `obstacle_right` says the wall's obstacle is towards +x).
  /// False if no wall runs along the slice from here that way; the robot then stays.
  bool wall_lap(bool up, bool& obstacle_right);
  /// Drive back to a point of its own path (a known free segment), exactly checked.
  void retrace_to(const Point& p, const Contact& c, Move m);
  const std::vector<SweepPoint>& path() const { return path_; }
  std::size_t readings() const { return readings_; }

 private:
  void go(const Point& p, const Contact& c, Move m);
  const Environment& Q_;
  const Environment& W_;
  std::size_t n_;
  double range_, noise_;
  std::mt19937_64 rng_;
  Point pos_;
  Contact at_;
  std::vector<SweepPoint> path_;
  std::size_t readings_ = 0;
  std::vector<CGAL::Bbox_2> wboxes_;
};

}  // namespace preimage::coverage::detail
