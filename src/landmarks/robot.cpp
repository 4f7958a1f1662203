// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/landmarks/robot.hpp>

#include <algorithm>
#include <cmath>
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

Reading normalized(Reading r) {
  std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
  return r;
}

Reading rotated_to(Reading r, std::uint32_t first) {
  std::rotate(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(position(r, first)), r.end());
  return r;
}

Reading transposed(Reading r, std::uint32_t a, std::uint32_t b) {
  std::swap(r[position(r, a)], r[position(r, b)]);
  return r;
}

bool follows(const Reading& r, std::uint32_t a, std::uint32_t b) {
  const auto it = std::find(r.begin(), r.end(), a);
  return it != r.end() && r[(static_cast<std::size_t>(it - r.begin()) + 1) % r.size()] == b;
}

std::string format_reading(const Reading& r, const std::vector<std::string>& labels) {
  std::string out;
  for (auto k : r) {
    if (!out.empty()) out += ' ';
    out += k < labels.size() ? labels[k] : std::to_string(k);
  }
  return out;
}

StopRule StopRule::reads(std::vector<Reading> goals) {
  for (auto& g : goals) g = normalized(std::move(g));
  return {Kind::Reads, 0, 0, std::move(goals)};
}

Simulator::Simulator(std::vector<geometry::Point> landmarks, const geometry::Point& start, const std::vector<std::string>& labels) {
  require_general_position(landmarks, labels);
  order_ = OrderType::of(landmarks);
  for (auto& p : landmarks) P_.push_back(geometry::to_exact(p));
  pos_ = geometry::to_exact(start);
  for (std::size_t i = 0; i < P_.size() && !at_; ++i)
    if (P_[i] == pos_) at_ = static_cast<std::uint32_t>(i);
  // The detector's order is only defined off the lines through two landmarks.
  for (std::size_t i = 0; i < P_.size() && !at_; ++i)
    for (std::size_t j = i + 1; j < P_.size(); ++j)
      if (geometry::orientation(P_[i], P_[j], pos_) == 0)
        throw InputError("robot start " + geometry::format_point(start) + " lies on the line through landmarks '" +
                         (i < labels.size() ? labels[i] : std::to_string(i)) + "' and '" +
                         (j < labels.size() ? labels[j] : std::to_string(j)) + "'");
  cur_ = sorted_reading(pos_, at_, nullptr, {});
  waypoints_.push_back(pos_);
}

Simulator::Simulator(std::vector<geometry::Point> landmarks, std::uint32_t at_landmark)
    : Simulator(landmarks, landmarks.at(at_landmark)) {}

Reading angular_reading(std::span<const ExactPoint> P, const ExactPoint& c, std::optional<std::uint32_t> at,
                        const ExactPoint* toward, const Reading& before) {
  // Around c, counter-clockwise from east: every landmark by its own direction, except
  // the one at c: left out, or (a vanishing step towards `toward`) seen straight behind.
  const std::uint32_t n = static_cast<std::uint32_t>(P.size());
  std::optional<ExactPoint> behind;
  if (at && toward) behind = CGAL::ORIGIN + ((c - CGAL::ORIGIN) * 2 - (*toward - CGAL::ORIGIN));
  auto dir = [&](std::uint32_t k) -> const ExactPoint& { return at && k == *at ? *behind : P[k]; };
  auto pos = [&](std::uint32_t k) -> const ExactPoint& { return at && k == *at ? c : P[k]; };
  // Two aligned landmarks (c on their swap line): the robot stepping to the left of
  // p_a -> p_b sees a right before b; along the line the order from before persists.
  auto tie_first = [&](std::uint32_t a, std::uint32_t b) {
    if (toward) {
      const int s = geometry::orientation(pos(a), pos(b), *toward);
      if (s != 0) return s > 0;
    }
    if (follows(before, a, b)) return true;
    if (follows(before, b, a)) return false;
    return CGAL::compare_distance_to_point(c, pos(a), pos(b)) == CGAL::SMALLER;  // nearer first
  };
  Reading r;
  for (std::uint32_t k = 0; k < n; ++k)
    if (!(at && k == *at) || behind) r.push_back(k);
  std::sort(r.begin(), r.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (geometry::ccw_less(c, dir(a), dir(b))) return true;
    if (geometry::ccw_less(c, dir(b), dir(a))) return false;
    return tie_first(a, b);
  });
  return r;
}

Reading Simulator::leaving(std::uint32_t c, std::uint32_t t) const {
  // Just after leaving p_c towards p_t: the others in their order around p_c (no two are
  // aligned with it), and c straight behind, right after the lambda(c, t) landmarks that
  // follow t within the half-turn (those left of p_c -> p_t). The same as an angular sort
  // at a point of the path (set_self_check compares), in O(n).
  const auto around = order_.around(c);
  const std::size_t m = around.size(), r = static_cast<std::size_t>(std::find(around.begin(), around.end(), t) - around.begin());
  const std::size_t left = order_.lambda(c, t);
  Reading out;
  out.reserve(m + 1);
  for (std::size_t q = 0; q < m; ++q) {
    out.push_back(around[(r + q) % m]);
    if (q == left) out.push_back(c);
  }
  return out;
}

TrackReadings Simulator::track(std::uint32_t i) {
  if (i >= P_.size()) throw std::invalid_argument("track: no landmark " + std::to_string(i));
  if (at_ && *at_ == i) return {cur_, cur_};  // already there: nothing to do
  const ExactPoint from = at_ ? P_[*at_] : pos_;
  TrackReadings t;
  if (heading_error_ && at_) {
    // The departure direction, rotated by the error (a physical perturbation: the
    // rotation is rounded, every decision on the result stays exact).
    const double e = heading_error_();
    const geometry::Point f = geometry::to_double(from), p = geometry::to_double(P_[i]);
    const double dx = p.x() - f.x(), dy = p.y() - f.y();
    const ExactPoint toward =
        from + geometry::ExactKernel::Vector_2(dx * std::cos(e) - dy * std::sin(e), dx * std::sin(e) + dy * std::cos(e));
    t.after_start = sorted_reading(from, at_, &toward, cur_);
  } else {
    t.after_start = at_ ? leaving(*at_, i) : sorted_reading(from, std::nullopt, &P_[i], cur_);
  }
  // Just before arriving the robot is where it would be just after leaving p_i back
  // towards where it came from.
  t.before_arrival = at_ ? leaving(i, *at_) : sorted_reading(P_[i], i, &from, cur_);
  const auto around = order_.around(i);
  Reading at_i(around.begin(), around.end());
  if (self_check_) {
    const ExactPoint& toward = P_[i];
    if ((!heading_error_ && normalized(t.after_start) != normalized(sorted_reading(from, at_, &toward, cur_))) ||
        normalized(t.before_arrival) != normalized(sorted_reading(P_[i], i, &from, cur_)) ||
        normalized(at_i) != normalized(sorted_reading(P_[i], i, nullptr, t.before_arrival)))
      throw std::logic_error("landmark simulator: a reading of track(" + std::to_string(i) + ") disagrees with an angular sort");
  }
  pos_ = P_[i];
  at_ = i;
  cur_ = std::move(at_i);
  waypoints_.push_back(pos_);
  ++primitives_;
  return t;
}

MotionTrace Simulator::track(std::uint32_t i, const StopRule& stop) {
  if (i >= P_.size()) throw std::invalid_argument("track: no landmark " + std::to_string(i));
  if (at_ && *at_ == i) return {{cur_}, {}, false};
  ++primitives_;
  return move(P_[i], i, stop);
}

MotionTrace Simulator::repel(std::uint32_t i, std::uint32_t j, const StopRule& stop) {
  if (i >= P_.size() || j >= P_.size() || i == j) throw std::invalid_argument("repel: needs two landmarks");
  const bool on_line = (at_ && *at_ == i) ||
                       (!at_ && geometry::orientation(P_[j], P_[i], pos_) == 0 &&
                        CGAL::collinear_are_strictly_ordered_along_line(P_[j], P_[i], pos_));
  if (!on_line)
    throw std::logic_error("repel(" + std::to_string(i) + ", " + std::to_string(j) + "): the robot is not on that swap line");
  ++primitives_;
  return move(pos_ + (P_[i] - P_[j]), std::nullopt, stop);
}

MotionTrace Simulator::move(const ExactPoint& T, std::optional<std::uint32_t> target, const StopRule& stop) {
  using geometry::ExactFT;
  const ExactPoint A = pos_;
  const auto d = T - A;
  const std::uint32_t n = static_cast<std::uint32_t>(P_.size());
  const bool unbounded = !target;  // repel: the whole ray from A through T
  // Sensor events: crossings of swap lines (the line of p_k p_l outside the segment
  // between them) and passing over a landmark, at parameter t of A + t d.
  struct Ev {
    ExactFT t;
    std::uint32_t k, l;  // l == n: passing over landmark k
  };
  std::vector<Ev> ev;
  auto skip = [&](std::uint32_t k) { return (at_ && k == *at_) || (target && k == *target); };
  std::vector<int> side(n, 0);
  for (std::uint32_t k = 0; k < n; ++k) {
    if (skip(k)) continue;
    side[k] = geometry::orientation(A, T, P_[k]);
    if (side[k] == 0 && (unbounded ? CGAL::angle(T, A, P_[k]) == CGAL::ACUTE  // ahead on the ray
                                   : CGAL::collinear_are_strictly_ordered_along_line(A, P_[k], T)))
      ev.push_back({((P_[k] - A) * d) / d.squared_length(), k, n});
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    if (skip(k) || side[k] == 0) continue;
    for (std::uint32_t l = k + 1; l < n; ++l) {
      // Both on one side of the path: the path meets their line outside p_k p_l.
      if (skip(l) || side[l] != side[k]) continue;
      const int oA = geometry::orientation(P_[k], P_[l], A);
      if (oA == 0) continue;  // leaving (or moving along) that line: resolved at the start
      if (unbounded) {
        // Ahead iff the signed distance to the line moves towards zero.
        const auto c = CGAL::compare_signed_distance_to_line(P_[k], P_[l], T, A);
        if (c == CGAL::EQUAL || (c == CGAL::LARGER) == (oA > 0)) continue;
      } else {
        const int oT = geometry::orientation(P_[k], P_[l], T);
        if (oT == 0 || oT == oA) continue;
      }
      const auto e = P_[l] - P_[k];
      const ExactFT fA = CGAL::determinant(e, A - P_[k]), fT = CGAL::determinant(e, T - P_[k]);
      ev.push_back({fA / (fA - fT), k, l});
    }
  }
  std::sort(ev.begin(), ev.end(), [](const Ev& a, const Ev& b) { return a.t < b.t; });
  const ExactFT end = unbounded ? (ev.empty() ? ExactFT(1) : ev.back().t + 1) : ExactFT(1);
  auto at_t = [&](const ExactFT& t) { return A + d * t; };

  MotionTrace tr;
  tr.readings.push_back(sorted_reading(A, at_, &T, cur_));
  std::vector<std::pair<ExactFT, ExactFT>> spans{{0, ev.empty() ? end : ev.front().t}};  // of each piece
  auto goal = [&](const Reading& r) {
    return stop.kind == StopRule::Kind::Reads &&
           std::find(stop.goals.begin(), stop.goals.end(), normalized(r)) != stop.goals.end();
  };
  auto halt_at = [&](const ExactPoint& p) {
    pos_ = p;
    at_.reset();
    cur_ = tr.readings.back();
    tr.halted = true;
  };
  bool done = false;
  if (goal(tr.readings.back())) {  // just after setting off, inside the first cell
    halt_at(at_t((spans[0].first + spans[0].second) / 2));
    done = true;
  }
  for (std::size_t g = 0; !done && g < ev.size();) {
    std::size_t h = g;
    while (h < ev.size() && ev[h].t == ev[g].t) ++h;  // one event: concurrent crossings
    MotionTrace::Event event;
    bool aligned = false;
    for (std::size_t q = g; q < h; ++q) {
      if (ev[q].l == n)
        event.passed = ev[q].k;
      else
        event.swaps.emplace_back(ev[q].k, ev[q].l);
      if (stop.kind == StopRule::Kind::Aligned && ev[q].l != n &&
          std::minmax(ev[q].k, ev[q].l) == std::minmax(stop.a, stop.b))
        aligned = true;
    }
    if (aligned) {  // halt on the line; the aligned pair keeps its order until crossed
      halt_at(at_t(ev[g].t));
      done = true;
      break;
    }
    const ExactFT next = h < ev.size() ? ev[h].t : end;
    Reading r = tr.readings.back();
    if (event.passed) {
      // Over a landmark the order is rebuilt: that landmark jumps to the opposite side.
      r = sorted_reading(at_t((ev[g].t + next) / 2), std::nullopt, &T, r);
    } else {
      for (auto [k, l] : event.swaps) {
        if (!follows(r, k, l) && !follows(r, l, k))
          throw std::logic_error("landmark simulator: swapped landmarks were not adjacent");
        r = transposed(std::move(r), k, l);
      }
    }
    tr.readings.push_back(std::move(r));
    tr.events.push_back(std::move(event));
    spans.emplace_back(ev[g].t, next);
    if (goal(tr.readings.back())) {
      halt_at(at_t((ev[g].t + next) / 2));
      done = true;
    }
    g = h;
  }
  if (self_check_)
    for (std::size_t t = 0; t < tr.readings.size(); ++t) {
      const ExactPoint mid = at_t((spans[t].first + spans[t].second) / 2);
      if (normalized(sorted_reading(mid, std::nullopt, &T, tr.readings[t])) != normalized(tr.readings[t]))
        throw std::logic_error("landmark simulator: reading " + std::to_string(t) + " of a motion disagrees with an angular sort");
    }
  if (!done) {
    if (target) {
      pos_ = P_[*target];
      at_ = target;
      cur_ = sorted_reading(pos_, at_, nullptr, tr.readings.back());
    } else {  // repel: stopped by the environment boundary, beyond every crossing
      pos_ = at_t(end);
      at_.reset();
      cur_ = tr.readings.back();
    }
  }
  waypoints_.push_back(pos_);
  return tr;
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

int triangle_orientation(RobotInterface& robot, std::uint32_t i, std::uint32_t j, std::uint32_t k) {
  // Strategy 2: one vote per edge, each read just after leaving its first landmark. A
  // vote from vertex v fails only if the heading error exceeds pi minus the interior
  // angle at v; below pi/2 only an obtuse angle can fail, so two votes agree with the
  // truth (the paper states 2 pi / 3; docs/landmarks.md gives the counterexample).
  const int votes = (contains(learn_lambda(robot, i, j).first, k) ? 1 : -1) +
                    (contains(learn_lambda(robot, j, k).first, i) ? 1 : -1) +
                    (contains(learn_lambda(robot, k, i).first, j) ? 1 : -1);
  return votes > 0 ? 1 : -1;
}

std::uint32_t nearer_on_swap_line(RobotInterface& robot, std::uint32_t i, std::uint32_t j) {
  // Strategy 3. Stepping off the line towards a third landmark cannot tell: the aligned
  // pair's order then depends only on the side (i before j iff left of p_i -> p_j), on
  // either swap line. Tracking i along the line instead passes over p_j first iff p_j
  // is the nearer one, and the detector shows j vanish for an instant.
  const MotionTrace t = robot.track(i, StopRule::arrive());
  for (const auto& e : t.events)
    if (e.passed == j) return j;
  return i;
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
