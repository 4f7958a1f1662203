// SPDX-License-Identifier: Apache-2.0
// The landmark robot of section 2: a point that senses only the counter-clockwise cyclic
// order of the landmarks around it (the landmark cyclic-order detector lcd) and moves
// only by track(i), straight to landmark i. Strategies see RobotInterface, never
// coordinates; Simulator implements it exactly from a landmark set.
#pragma once
#include <preimage/geometry/kernel.hpp>
#include <preimage/landmarks/order_type.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace preimage::landmarks {

/// A cyclic permutation of landmark indices (counter-clockwise; any rotation).
using Reading = std::vector<std::uint32_t>;

/// What the detector shows while track(i) runs: just after the robot sets off, and just
/// before i disappears on arrival (both at generic points of the path).
struct TrackReadings {
  Reading after_start, before_arrival;
};

class RobotInterface {
 public:
  virtual ~RobotInterface() = default;
  virtual std::size_t num_landmarks() const = 0;
  /// The current reading (at a landmark, without that landmark).
  virtual Reading lcd() const = 0;
  /// Moves straight to landmark i (one motion primitive).
  virtual TrackReadings track(std::uint32_t i) = 0;
  virtual std::size_t primitives() const = 0;
};

/// Exact simulation on a landmark set in general position. The robot starts at `start`
/// (a point on no line through two landmarks) or at a landmark.
class Simulator : public RobotInterface {
 public:
  Simulator(std::vector<geometry::Point> landmarks, const geometry::Point& start);
  Simulator(std::vector<geometry::Point> landmarks, std::uint32_t at_landmark);
  std::size_t num_landmarks() const override { return P_.size(); }
  Reading lcd() const override;
  TrackReadings track(std::uint32_t i) override;
  std::size_t primitives() const override { return primitives_; }
  std::optional<std::uint32_t> at() const { return at_; }

 private:
  // The reading at c, or a vanishing step away from landmark `at` = c in which that
  // landmark shows in the direction c -> special.
  Reading reading(const geometry::ExactPoint& c, std::optional<std::uint32_t> at,
                  const std::optional<geometry::ExactPoint>& special) const;
  std::vector<geometry::ExactPoint> P_;
  geometry::ExactPoint pos_;
  std::optional<std::uint32_t> at_;
  std::size_t primitives_ = 0;
};

/// Lemma 1: from a reading taken on the open segment p_i p_j heading to p_j,
/// Lambda(i, j) (sorted) and Lambda(j, i).
std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> lemma1(const Reading& r, std::uint32_t i, std::uint32_t j);

/// Strategy 1: Lambda(i, j) and Lambda(j, i) with at most two tracks.
std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> learn_lambda(RobotInterface& robot, std::uint32_t i,
                                                                               std::uint32_t j);
/// Strategy 4: a pair (i, j) of consecutive hull landmarks with Lambda(j, i) empty
/// (i -> j runs counter-clockwise along the hull), with O(n) tracks (Theorem 2).
std::pair<std::uint32_t, std::uint32_t> find_hull_pair(RobotInterface& robot);
/// Strategy 5: the hull boundary, counter-clockwise, starting at the pair's first landmark.
std::vector<std::uint32_t> learn_hull(RobotInterface& robot);
/// Strategy 1 for every pair: the whole order type as lambda (n x n, row-major).
std::vector<std::uint32_t> learn_order_type(RobotInterface& robot);

}  // namespace preimage::landmarks
