// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/landmarks/robot.hpp>

#include <algorithm>
#include <stdexcept>

namespace preimage::landmarks {
namespace {

using geometry::ExactPoint;

std::size_t position(const Reading& r, std::uint32_t x) {
  const auto it = std::find(r.begin(), r.end(), x);
  if (it == r.end()) throw std::logic_error("landmark robot: label missing from the reading");
  return static_cast<std::size_t>(it - r.begin());
}

// Labels strictly after `from` and strictly before `to`, counter-clockwise.
std::vector<std::uint32_t> between(const Reading& r, std::uint32_t from, std::uint32_t to) {
  std::vector<std::uint32_t> out;
  const std::size_t n = r.size();
  for (std::size_t k = (position(r, from) + 1) % n; r[k] != to; k = (k + 1) % n) out.push_back(r[k]);
  std::sort(out.begin(), out.end());
  return out;
}

std::uint32_t after(const Reading& r, std::uint32_t x) { return r[(position(r, x) + 1) % r.size()]; }

bool contains(const Reading& r, std::uint32_t x) { return std::find(r.begin(), r.end(), x) != r.end(); }

}  // namespace

Simulator::Simulator(std::vector<geometry::Point> landmarks, const geometry::Point& start) {
  require_general_position(landmarks);
  for (auto& p : landmarks) P_.push_back(geometry::to_exact(p));
  pos_ = geometry::to_exact(start);
  // The detector's order is only defined off the lines through two landmarks.
  for (std::size_t i = 0; i < P_.size(); ++i) {
    if (P_[i] == pos_) {
      at_ = static_cast<std::uint32_t>(i);
      return;
    }
    for (std::size_t j = i + 1; j < P_.size(); ++j)
      if (geometry::orientation(P_[i], P_[j], pos_) == 0)
        throw InputError("robot start " + geometry::format_point(start) + " lies on the line through landmarks " +
                         std::to_string(i) + " and " + std::to_string(j));
  }
}

Simulator::Simulator(std::vector<geometry::Point> landmarks, std::uint32_t at_landmark)
    : Simulator(landmarks, landmarks.at(at_landmark)) {}

Reading Simulator::reading(const ExactPoint& c, std::optional<std::uint32_t> at, const std::optional<ExactPoint>& special) const {
  // Around c, counter-clockwise from east: every landmark by its own direction, except
  // the one at c: left out, or (a vanishing step away) seen in the direction c -> special.
  const std::uint32_t n = static_cast<std::uint32_t>(P_.size());
  auto dir = [&](std::uint32_t k) -> const ExactPoint& { return at && k == *at ? *special : P_[k]; };
  Reading r;
  for (std::uint32_t k = 0; k < n; ++k)
    if (!(at && k == *at) || special) r.push_back(k);
  std::sort(r.begin(), r.end(), [&](std::uint32_t a, std::uint32_t b) { return geometry::ccw_less(c, dir(a), dir(b)); });
  return r;
}

Reading Simulator::lcd() const { return at_ ? reading(P_[*at_], at_, std::nullopt) : reading(pos_, std::nullopt, std::nullopt); }

TrackReadings Simulator::track(std::uint32_t i) {
  if (i >= P_.size()) throw std::invalid_argument("track: no landmark " + std::to_string(i));
  if (at_ && *at_ == i) return {lcd(), lcd()};  // already there: nothing to do
  const ExactPoint from = at_ ? P_[*at_] : pos_;
  TrackReadings t;
  // Just after setting off from a landmark, it lies straight behind: at 2 from - target.
  t.after_start = at_ ? reading(from, at_, CGAL::ORIGIN + ((from - CGAL::ORIGIN) * 2 - (P_[i] - CGAL::ORIGIN))) : lcd();
  // Just before arriving, the target lies straight ahead: at 2 target - from.
  t.before_arrival = reading(P_[i], i, CGAL::ORIGIN + ((P_[i] - CGAL::ORIGIN) * 2 - (from - CGAL::ORIGIN)));
  pos_ = P_[i];
  at_ = i;
  ++primitives_;
  return t;
}

std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> lemma1(const Reading& r, std::uint32_t i, std::uint32_t j) {
  // [X, i, Y, j, Z]: counter-clockwise from j back to i is the left of p_i -> p_j.
  return {between(r, j, i), between(r, i, j)};
}

std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> learn_lambda(RobotInterface& robot, std::uint32_t i,
                                                                               std::uint32_t j) {
  if (contains(robot.lcd(), i)) robot.track(i);  // until i disappears: the robot is at p_i
  return lemma1(robot.track(j).after_start, i, j);
}

std::pair<std::uint32_t, std::uint32_t> find_hull_pair(RobotInterface& robot) {
  const std::size_t n = robot.num_landmarks();
  if (n < 3) throw std::invalid_argument("find_hull_pair: needs three landmarks");
  std::uint32_t i = 0, next = 1;
  if (contains(robot.lcd(), i)) robot.track(i);
  // Theorem 2: the iteration ends within O(n) tracks; the bound only guards a bug.
  for (std::size_t step = 0; step < 4 * n + 8; ++step) {
    const TrackReadings t = robot.track(next);
    const auto [left, right] = lemma1(t.after_start, i, next);
    if (right.empty()) return {i, next};  // nothing left of next -> i: i -> next is counter-clockwise
    if (left.empty()) return {next, i};
    const std::uint32_t following = after(t.before_arrival, next);
    i = next;
    next = following;
  }
  throw std::logic_error("find_hull_pair: no hull pair within 4n + 8 tracks");
}

std::vector<std::uint32_t> learn_hull(RobotInterface& robot) {
  const auto [first, second] = find_hull_pair(robot);
  // Arrive at `second` from `first`: the landmark right after it, counter-clockwise,
  // is the next hull landmark (Strategy 5).
  if (contains(robot.lcd(), first)) robot.track(first);
  std::vector<std::uint32_t> hull{first};
  std::uint32_t cur = second;
  for (std::size_t step = 0; step <= robot.num_landmarks(); ++step) {
    const std::uint32_t next = after(robot.track(cur).before_arrival, cur);
    hull.push_back(cur);
    if (next == first) return hull;
    cur = next;
  }
  throw std::logic_error("learn_hull: the hull did not close");
}

std::vector<std::uint32_t> learn_order_type(RobotInterface& robot) {
  const std::uint32_t n = static_cast<std::uint32_t>(robot.num_landmarks());
  std::vector<std::uint32_t> lambda(std::size_t(n) * n, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j) {
      const auto [ij, ji] = learn_lambda(robot, i, j);
      lambda[std::size_t(i) * n + j] = static_cast<std::uint32_t>(ij.size());
      lambda[std::size_t(j) * n + i] = static_cast<std::uint32_t>(ji.size());
    }
  return lambda;
}

}  // namespace preimage::landmarks
