// SPDX-License-Identifier: Apache-2.0
// Private to coverage: getting a car-like robot from one pose to another where no single
// Dubins curve fits (out of a dead end, through a door at an angle), by hybrid A* (Dolgov,
// Thrun, Montemerlo, Diebel 2008): a search over continuous poses, forward and reverse arcs
// of the turning radius and straight steps, pruned on a grid of (x, y, heading), guided by
// the obstacle-aware distance to the goal on a coarse grid, and finished by a Dubins curve
// that reaches the goal pose exactly. Every step and the final curve are certified
// (ArcCertifier) before they are expanded or returned.
#pragma once
#include <preimage/coverage/turn_model.hpp>
#include <preimage/geometry/environment.hpp>

#include <cstdint>
#include <vector>

namespace preimage::coverage::detail {

/// A piece driven forward or backward (a cusp is where the direction of travel changes).
struct CarStep {
  DrivePiece piece;
  bool reverse = false;
};

/// A certified curve's chord ends, piece by piece (empty for a piece of length 0); `curve`
/// ends exactly at `arrive.at` (its last chord end is that point). False if any piece fails
/// or the curve misses the arrival by more than `tolerance` (the formulas' rounding).
bool certify_curve(const ArcCertifier& cert, const DubinsCurve& curve, const Pose& arrive, double tolerance,
                   std::vector<std::vector<Point>>& samples);

/// The chord ends of a step from pose p, and the pose after it.
std::vector<Point> step_samples(const Pose& p, const CarStep& s, double radius, Pose& after);

class CarSearch {
 public:
  /// `E`: the component the robot's centre moves in (for the guiding grid); `cell`: the
  /// guiding grid's side.
  CarSearch(const geometry::Environment& E, const geometry::Clearance& clear, const ArcCertifier& cert, double radius, double cell,
            double tolerance);

  struct Result {
    bool found = false;
    std::size_t start = 0, goal = 0;     // which start and goal pose
    std::vector<CarStep> steps;          // from the start pose
    DubinsCurve finish;                  // then forward to the goal pose
    std::vector<std::vector<Point>> finish_samples;
    std::size_t expansions = 0;
  };
  /// A certified path from one of `starts` to one of `goals`; gives up after
  /// `max_expansions` poses.
  Result search(const std::vector<Pose>& starts, const std::vector<Pose>& goals, std::size_t max_expansions) const;

 private:
  const ArcCertifier& cert_;
  double R_, cell_, tol_;
  double x0_ = 0, y0_ = 0;
  std::size_t nx_ = 0, ny_ = 0;
  std::vector<char> free_;  // guiding grid: cell centre admitted
  std::vector<double> distance_to(const std::vector<Pose>& goals) const;
  long cell_of(const Point& p) const;
};

}  // namespace preimage::coverage::detail
