// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/robot.hpp>

#include <cctype>
#include <cmath>

namespace preimage::wallfollow {

using geometry::ExactPoint;

const char* to_string(Action u) {
  switch (u) {
    case Action::Init: return "INIT";
    case Action::RFollow: return "RFOLLOW";
    case Action::LFollow: return "LFOLLOW";
    case Action::Jump: return "JUMP";
    case Action::Grab: return "GRAB";
    case Action::Drop: return "DROP";
  }
  return "?";
}

const char* to_string(Touch t) {
  switch (t) {
    case Touch::Interior: return "INTERIOR";
    case Touch::Edge: return "EDGE";
    case Touch::Convex: return "CONVEX";
    case Touch::Reflex: return "REFLEX";
  }
  return "?";
}

std::string to_string(const Observation& y) { return std::string(to_string(y.touch)).append(y.pebble ? "+pebble" : ""); }

std::vector<Action> parse_actions(const std::string& text) {
  static constexpr Action all[] = {Action::Init, Action::RFollow, Action::LFollow, Action::Jump, Action::Grab, Action::Drop};
  std::vector<Action> out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ',' || std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    const std::size_t b = i;
    while (i < text.size() && text[i] != ',' && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    std::string tok = text.substr(b, i - b);
    for (auto& c : tok) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    bool found = false;
    for (Action u : all)
      if (tok == to_string(u)) out.push_back(u), found = true;
    if (!found)
      throw InputError(std::string("action ").append(std::to_string(out.size() + 1)).append(" '").append(text.substr(b, i - b))
                           .append("' at offset ").append(std::to_string(b))
                           .append(": unknown action (INIT, RFOLLOW, LFOLLOW, JUMP, GRAB, DROP)"));
  }
  return out;
}

Place Place::vertex(const geometry::Environment& env, std::size_t v) {
  Place p;
  p.kind = Kind::Vertex;
  p.index = v;
  p.point = env.exact_vertex(v);
  return p;
}

Place Place::of(const geometry::Environment& env, const geometry::Point& p, const std::string& what) {
  const auto loc = geometry::locate(env, p);
  Place q;
  q.point = geometry::to_exact(p);
  q.index = loc.index;
  switch (loc.kind) {
    case geometry::Location::Kind::Interior: return q;
    case geometry::Location::Kind::AtVertex: return vertex(env, loc.index);
    case geometry::Location::Kind::OnEdge: q.kind = Kind::Edge; return q;
    default: break;
  }
  throw InputError(std::string(what).append(" ").append(geometry::format_point(p)).append(" is not in the environment (it is ")
                       .append(geometry::to_string(loc.kind)).append(")"));
}

bool same_place(const Place& a, const Place& b) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case Place::Kind::Vertex: return a.index == b.index;
    case Place::Kind::Edge: return a.index == b.index && ((a.mark >= 0 && a.mark == b.mark) || a.point == b.point);
    case Place::Kind::Interior: return a.point == b.point;
  }
  return false;
}

Simulator::Simulator(const geometry::Environment& env, const geometry::Point& start, const geometry::Vector& heading,
                     std::optional<Place> pebble)
    : env_(&env), heading_(heading.x(), heading.y()), holding_(!pebble), pebble_(std::move(pebble)), cut_cache_(2 * env.num_vertices()) {
  if (heading.x() == 0 && heading.y() == 0) throw InputError("the robot's heading must be a non-zero direction");
  robot_ = Place::of(env, start, "start");
}

Observation Simulator::sense() const {
  Observation y;
  switch (robot_.kind) {
    case Place::Kind::Interior: y.touch = Touch::Interior; break;
    case Place::Kind::Edge: y.touch = Touch::Edge; break;
    case Place::Kind::Vertex: y.touch = env_->turn(robot_.index) > 0 ? Touch::Convex : Touch::Reflex; break;
  }
  y.pebble = holding_ || (pebble_ && same_place(*pebble_, robot_));
  return y;
}

Place Simulator::cut_endpoint(std::size_t v, bool left) const {
  auto& slot = cut_cache_[2 * v + (left ? 0 : 1)];
  if (!slot) {
    const Cut c = shoot_cut(*env_, static_cast<std::uint32_t>(v), left);
    Place p;
    p.kind = Place::Kind::Edge;
    p.index = c.edge;
    p.point = c.end;
    p.mark = static_cast<long>(2 * v + (left ? 0 : 1));
    slot = p;
  }
  return *slot;
}

// Along the boundary to the next vertex in the given direction; stops early at a lying
// pebble strictly ahead on the way (III.A).
void Simulator::follow(bool ccw) {
  const auto& E = *env_;
  std::size_t e, target;
  if (robot_.kind == Place::Kind::Vertex) {
    e = ccw ? robot_.index : E.prev(robot_.index);
    target = ccw ? E.next(robot_.index) : E.prev(robot_.index);
  } else {
    e = robot_.index;
    target = ccw ? E.next(e) : e;
  }
  arrived_along_ = std::make_pair(e, ccw);
  heading_ = E.exact_vertex(ccw ? E.next(e) : e) - E.exact_vertex(ccw ? e : E.next(e));
  if (!holding_ && pebble_ && pebble_->kind == Place::Kind::Edge && pebble_->index == e && !same_place(*pebble_, robot_)) {
    // Strictly inside edge e: ahead unless it lies behind the robot on the same edge.
    bool ahead = true;
    if (robot_.kind == Place::Kind::Edge) {
      const ExactPoint& start = E.exact_vertex(e);
      const bool robot_first = CGAL::has_smaller_distance_to_point(start, robot_.point, pebble_->point);
      ahead = ccw ? robot_first : !robot_first;
    }
    if (ahead) {
      robot_ = *pebble_;
      return;
    }
  }
  robot_ = Place::vertex(E, target);
}

Observation Simulator::apply(Action u) {
  const auto& E = *env_;
  switch (u) {
    case Action::Init:
      if (robot_.kind == Place::Kind::Interior) {
        const auto hit = geometry::shoot_ray(E, robot_.point, heading_);
        if (!hit) throw std::logic_error("INIT: ray from the interior left the environment");
        if (hit->vertex) {
          robot_ = Place::vertex(E, *hit->vertex);
          arrived_along_.reset();
          break;
        }
        robot_.kind = Place::Kind::Edge;
        robot_.index = hit->edge;
        robot_.point = hit->point;
        robot_.mark = -1;
      }
      if (robot_.kind == Place::Kind::Edge) {
        // Wall-follow with the wall on the right to the next vertex (INIT ignores the pebble).
        const std::size_t e = robot_.index;
        robot_ = Place::vertex(E, E.next(e));
        arrived_along_ = std::make_pair(e, true);
        heading_ = E.exact_vertex(E.next(e)) - E.exact_vertex(e);
      }
      break;
    case Action::RFollow:
    case Action::LFollow:
      if (robot_.kind == Place::Kind::Interior)
        throw ActionError(std::string(to_string(u)).append(": the robot is not in contact with the boundary (apply INIT first)"));
      follow(u == Action::RFollow);
      break;
    case Action::Jump: {
      if (robot_.kind != Place::Kind::Vertex || E.turn(robot_.index) > 0)
        throw ActionError("JUMP: the robot is not at a reflex vertex");
      const std::size_t v = robot_.index;
      if (!arrived_along_) throw ActionError("JUMP: the robot did not arrive at this vertex along an edge");
      const auto [e, ccw] = *arrived_along_;
      if (ccw ? E.next(e) != v : e != v) throw ActionError("JUMP: the robot did not arrive at this vertex along an edge");
      robot_ = cut_endpoint(v, !ccw);
      heading_ = robot_.point - E.exact_vertex(v);
      arrived_along_.reset();
      ++jumps_;
      break;
    }
    case Action::Grab:
      if (holding_) throw ActionError("GRAB: the robot already holds the pebble");
      if (!pebble_ || !same_place(*pebble_, robot_)) throw ActionError("GRAB: the pebble is not at the robot's position");
      holding_ = true;
      pebble_.reset();
      break;
    case Action::Drop:
      if (!holding_) throw ActionError("DROP: the robot does not hold the pebble");
      holding_ = false;
      pebble_ = robot_;
      break;
  }
  ++actions_;
  return sense();
}

}  // namespace preimage::wallfollow
