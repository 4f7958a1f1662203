// SPDX-License-Identifier: Apache-2.0
#include "navigator.hpp"

#include <deque>
#include <set>
#include <stdexcept>

namespace preimage::wallfollow {

Motion motion_of(const Position& p, Action u) { return {p.at, u, static_cast<std::int8_t>(u == Action::Jump ? p.arrived : 0)}; }

Navigator::Navigator(RobotInterface& robot, const OrderingMap& map, Position at, std::optional<std::uint32_t> pebble)
    : R_(robot), m_(map), at_(at), pebble_(pebble), last_(robot.sense()) {}

const Observation& Navigator::act(Action u) {
  std::optional<Position> next;
  if (u == Action::RFollow || u == Action::LFollow || u == Action::Jump) {
    next = m_.move(at_, u, pebble_);
    if (!next) throw std::logic_error(std::string("navigator: ") + to_string(u) + " does not apply at " + m_.name(at_.at));
  }
  last_ = R_.apply(u);
  ++actions_;
  if (u == Action::Grab) pebble_.reset();
  if (u == Action::Drop) pebble_ = at_.at;
  if (!next) return last_;
  if (last_.touch != m_.touch_at(next->at))
    throw std::runtime_error(std::string("pursuit strategy: ") + to_string(u) + " from " + m_.name(at_.at) + " should reach " +
                             m_.name(next->at) + " (" + to_string(m_.touch_at(next->at)) + ") but the robot reads " +
                             to_string(last_.touch) + " (the robot does not behave as the model of III.A)");
  const Position from = at_;
  at_ = *next;
  if (seen_) seen_(motion_of(from, u), at_, last_);
  return last_;
}

std::vector<Action> Navigator::path_to(const std::function<bool(const Position&)>& goal) const {
  // Breadth-first over positions (point, arrival): at most 3 |M| of them.
  auto id = [](const Position& p) { return 3 * static_cast<std::size_t>(p.at) + static_cast<std::size_t>(p.arrived + 1); };
  std::vector<long> parent(3 * m_.size(), -2);
  std::vector<Action> via(3 * m_.size());
  std::vector<Position> pos(3 * m_.size());
  std::deque<Position> queue{at_};
  parent[id(at_)] = -1;
  pos[id(at_)] = at_;
  while (!queue.empty()) {
    const Position p = queue.front();
    queue.pop_front();
    if (goal(p)) {
      std::vector<Action> out;
      for (std::size_t k = id(p); parent[k] >= 0; k = static_cast<std::size_t>(parent[k])) out.push_back(via[k]);
      return {out.rbegin(), out.rend()};
    }
    for (Action u : {Action::RFollow, Action::LFollow, Action::Jump}) {
      const auto q = m_.move(p, u, pebble_);
      if (!q || parent[id(*q)] != -2) continue;
      parent[id(*q)] = static_cast<long>(id(p));
      via[id(*q)] = u;
      pos[id(*q)] = *q;
      queue.push_back(*q);
    }
  }
  throw std::logic_error("navigator: no way to the goal in the cut ordering");
}

void Navigator::go(std::uint32_t k, int arrived) {
  for (Action u : path_to([&](const Position& p) { return p.at == k && (arrived == 0 || p.arrived == arrived); })) act(u);
}

void Navigator::grab() {
  if (!pebble_) return;
  go(*pebble_);
  act(Action::Grab);
  if (!last_.pebble) throw std::runtime_error("pursuit strategy: GRAB found no pebble");
}

void Navigator::drop() { act(Action::Drop); }

void Navigator::explore(const std::function<void(const Motion&, const Position&, const Observation&)>& seen) {
  std::set<Motion> done;
  seen_ = [&](const Motion& mo, const Position& to, const Observation& y) {
    if (done.insert(mo).second) seen(mo, to, y);
  };
  auto open_here = [&](const Position& p) -> std::optional<Action> {
    for (Action u : {Action::RFollow, Action::LFollow, Action::Jump})
      if (m_.move(p, u, pebble_) && !done.count(motion_of(p, u))) return u;
    return std::nullopt;
  };
  for (;;) {
    bool any = false;
    for (std::uint32_t k = 0; k < m_.size() && !any; ++k)
      for (std::int8_t a : {-1, 0, 1})
        if (open_here(Position{k, a})) any = true;
    if (!any) break;
    for (Action u : path_to([&](const Position& p) { return open_here(p).has_value(); })) act(u);
    act(*open_here(at_));
  }
  seen_ = nullptr;
}

}  // namespace preimage::wallfollow
