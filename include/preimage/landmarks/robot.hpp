// SPDX-License-Identifier: Apache-2.0
// The landmark robot of section 2: a point that senses only the counter-clockwise cyclic
// order of the landmarks around it (the landmark cyclic-order detector lcd) and moves
// only by track(i), straight to landmark i, and (section 8.2) by repel(i, j), away from
// p_j along the swap line that starts at p_i. Strategies see RobotInterface, never
// coordinates; Simulator implements it exactly from a landmark set.
//
// Ties (section 2): on a swap line the two aligned landmarks keep the order they had
// before the alignment until the crossing is completed; a robot leaving a landmark
// along a swap line (repel) sees the nearer landmark first.
#pragma once
#include <preimage/geometry/kernel.hpp>
#include <preimage/landmarks/order_type.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <optional>
#include <utility>
#include <vector>

namespace preimage::landmarks {

/// A cyclic permutation of landmark indices (counter-clockwise; any rotation).
using Reading = std::vector<std::uint32_t>;

/// The rotation that starts with the least label: one representative per cyclic order.
Reading normalized(Reading r);
/// The rotation of r that starts with `first` (which must be in r).
Reading rotated_to(Reading r, std::uint32_t first);
/// r with the labels a and b exchanged.
Reading transposed(Reading r, std::uint32_t a, std::uint32_t b);
/// True iff b comes right after a, counter-clockwise.
bool follows(const Reading& r, std::uint32_t a, std::uint32_t b);
/// "7 2 8 5" (labels given by index, or by `labels`).
std::string format_reading(const Reading& r, const std::vector<std::string>& labels = {});

/// The reading of the landmark detector at c (without landmark `at`, or with it seen
/// straight behind when the robot leaves it towards `toward`); two landmarks aligned
/// with c are ordered as the robot sees them stepping towards `toward` (a before b iff
/// it steps to the left of p_a -> p_b), else as in `before`, else nearer first.
Reading angular_reading(std::span<const geometry::ExactPoint> P, const geometry::ExactPoint& c,
                        std::optional<std::uint32_t> at, const geometry::ExactPoint* toward, const Reading& before);

/// What the detector shows while track(i) runs: just after the robot sets off, and just
/// before i disappears on arrival (both at generic points of the path).
struct TrackReadings {
  Reading after_start, before_arrival;
};

/// When a motion primitive halts (feedback on the readings only).
struct StopRule {
  enum class Kind {
    Arrive,   // track: at the landmark; repel: at the environment boundary (contact)
    Aligned,  // on the swap line where landmarks a and b align (before they swap)
    Reads,    // just inside the first cell whose reading is one of `goals`
  };
  Kind kind = Kind::Arrive;
  std::uint32_t a = 0, b = 0;
  std::vector<Reading> goals;  // normalized
  static StopRule arrive() { return {}; }
  static StopRule aligned(std::uint32_t a, std::uint32_t b) { return {Kind::Aligned, a, b, {}}; }
  static StopRule reads(std::vector<Reading> goals);
};

/// Everything the detector showed during one primitive: the reading on each piece of the
/// path between two sensor events, in order, and what changed at each event (the pairs
/// that swapped, or a landmark the robot passed over, which vanishes for an instant).
struct MotionTrace {
  struct Event {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> swaps;
    std::optional<std::uint32_t> passed;
  };
  std::vector<Reading> readings;  // readings[t] on piece t; events[t] between t and t + 1
  std::vector<Event> events;
  bool halted = false;  // the stop rule fired before the end of the motion
};

class RobotInterface {
 public:
  virtual ~RobotInterface() = default;
  virtual std::size_t num_landmarks() const = 0;
  /// The current reading (at a landmark, without that landmark).
  virtual Reading lcd() const = 0;
  /// Moves straight to landmark i (one motion primitive); the first and last readings.
  virtual TrackReadings track(std::uint32_t i) = 0;
  /// track(i) with every reading on the way, halting by `stop`.
  virtual MotionTrace track(std::uint32_t i, const StopRule& stop) = 0;
  /// repel(i, j) (section 8.2): from p_i or a point of the swap line that starts at p_i
  /// and points away from p_j, move along it away from both landmarks.
  virtual MotionTrace repel(std::uint32_t i, std::uint32_t j, const StopRule& stop) = 0;
  virtual std::size_t primitives() const = 0;
};

/// Exact simulation on a landmark set in general position. The robot starts at `start`
/// (a point on no line through two landmarks) or at a landmark.
class Simulator : public RobotInterface {
 public:
  /// InputError if the start lies on a line through two landmarks (named by `labels`).
  Simulator(std::vector<geometry::Point> landmarks, const geometry::Point& start, const std::vector<std::string>& labels = {});
  Simulator(std::vector<geometry::Point> landmarks, std::uint32_t at_landmark);
  std::size_t num_landmarks() const override { return P_.size(); }
  Reading lcd() const override { return cur_; }
  TrackReadings track(std::uint32_t i) override;
  MotionTrace track(std::uint32_t i, const StopRule& stop) override;
  MotionTrace repel(std::uint32_t i, std::uint32_t j, const StopRule& stop) override;
  std::size_t primitives() const override { return primitives_; }

  std::optional<std::uint32_t> at() const { return at_; }
  const geometry::ExactPoint& position() const { return pos_; }
  /// Where the robot has been: the start, then the end of every primitive (for figures).
  const std::vector<geometry::ExactPoint>& waypoints() const { return waypoints_; }
  /// Strategy 2's control error: each track(i) that leaves a landmark sets off in a
  /// direction rotated by `error()` radians; the tracking feedback still brings the robot
  /// to p_i, so only the reading just after setting off is affected.
  void set_heading_error(std::function<double()> error) { heading_error_ = std::move(error); }
  /// Recompute every reading of a trace by an exact angular sort at a point of its piece
  /// and throw std::logic_error on a difference (for tests of the event bookkeeping).
  void set_self_check(bool on) { self_check_ = on; }

 private:
  Reading sorted_reading(const geometry::ExactPoint& c, std::optional<std::uint32_t> at,
                         const geometry::ExactPoint* toward, const Reading& before) const {
    return angular_reading(P_, c, at, toward, before);
  }
  MotionTrace move(const geometry::ExactPoint& target, std::optional<std::uint32_t> target_landmark, const StopRule& stop);
  Reading leaving(std::uint32_t c, std::uint32_t t) const;
  OrderType order_;  // the angular order around each landmark: readings at and next to landmarks in O(n)
  std::vector<geometry::ExactPoint> P_;
  geometry::ExactPoint pos_;
  std::optional<std::uint32_t> at_;
  Reading cur_;
  std::vector<geometry::ExactPoint> waypoints_;
  std::size_t primitives_ = 0;
  std::function<double()> heading_error_;
  bool self_check_ = false;
};

/// Lemma 1: from a reading taken on the open segment p_i p_j heading to p_j,
/// Lambda(i, j) (sorted) and Lambda(j, i).
std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> lemma1(const Reading& r, std::uint32_t i, std::uint32_t j);

/// Strategy 1: Lambda(i, j) and Lambda(j, i) with at most two tracks.
std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> learn_lambda(RobotInterface& robot, std::uint32_t i,
                                                                               std::uint32_t j);
/// Strategy 2: the orientation of triangle p_i p_j p_k (+1 counter-clockwise) by Strategy 1
/// along each edge and a majority vote, robust to a heading error below pi/2 (see docs).
int triangle_orientation(RobotInterface& robot, std::uint32_t i, std::uint32_t j, std::uint32_t k);
/// Strategy 3: the robot stands on a swap line of i and j (they are aligned in its
/// reading); returns the nearer of the two. One track: tracking i passes over p_j first
/// iff j is the nearer one.
std::uint32_t nearer_on_swap_line(RobotInterface& robot, std::uint32_t i, std::uint32_t j);
/// Strategy 4: a pair (i, j) of consecutive hull landmarks with Lambda(j, i) empty
/// (i -> j runs counter-clockwise along the hull), with O(n) tracks (Theorem 2).
std::pair<std::uint32_t, std::uint32_t> find_hull_pair(RobotInterface& robot);
/// Strategy 5: the hull boundary, counter-clockwise, starting at the pair's first landmark.
std::vector<std::uint32_t> learn_hull(RobotInterface& robot);
/// Strategy 1 for every pair: the whole order type as lambda (n x n, row-major).
std::vector<std::uint32_t> learn_order_type(RobotInterface& robot);

}  // namespace preimage::landmarks
