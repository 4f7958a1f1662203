// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/robot.hpp>
#include <preimage/wallfollow/sensors.hpp>

#include <cctype>
#include <climits>
#include <cmath>
#include <map>

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

// What the section VI sensors need, built once when they are enabled.
struct SensorState {
  explicit SensorState(const geometry::Environment& env) : vis(env) {}
  geometry::VisibilityIndex vis;
  std::vector<VertexLine> lines;
  std::vector<Bitangent> bitangents;
  TrueCuts cuts;
  struct Cached {
    std::size_t gaps = 0;
    std::vector<filter::ShadowEvent> gap_events;
    std::vector<BitangentCrossing> bitangents;
    bool has_gap = false, has_bitangent = false;
  };
  std::map<std::pair<long, long>, Cached> readings;  // by (start, end) place
};

Simulator::Simulator(const geometry::Environment& env, const geometry::Point& start, const geometry::Vector& heading,
                     std::optional<Place> pebble)
    : env_(&env), heading_(heading.x(), heading.y()), holding_(!pebble), pebble_(std::move(pebble)), cut_cache_(2 * env.num_vertices()) {
  if (heading.x() == 0 && heading.y() == 0) throw InputError("the robot's heading must be a non-zero direction");
  robot_ = Place::of(env, start, "start");
  path_.push_back(robot_.point);
}

Simulator::~Simulator() = default;

void Simulator::enable(const Sensors& s) {
  sensors_ = s;
  if (!state_) state_ = std::make_unique<SensorState>(*env_);
  if ((s.gap || s.bitangent) && state_->lines.empty()) {
    state_->lines = vertex_lines(state_->vis);
    state_->bitangents = bitangents(*env_);
    state_->cuts = true_cut_ordering(*env_);
    // Bitangent endpoints must not fall on cut endpoints (general position, V.A).
    for (const Bitangent& b : state_->bitangents)
      for (const BoundaryPoint* e : {&b.b_ij, &b.b_ji})
        for (const Cut& c : state_->cuts.cuts)
          if (c.edge == e->edge && c.end == e->point)
            throw InputError("the bitangent of vertices " + std::to_string(env_->input_index(b.i)) + " and " +
                             std::to_string(env_->input_index(b.j)) + " ends where a cut ends, at " +
                             geometry::format_point(geometry::to_double(c.end)) + " (no general position)");
  }
  reading_ = Observation{};
  if (s.gap) reading_.gaps = gap_count(state_->vis, robot_.point);
  if (s.detection && evader_) reading_.detected = sees_during(state_->vis.compute(*evader_), robot_.point, robot_.point);
  if (s.pebble_visibility && pebble_ && !holding_)
    reading_.pebble_visible = sees_during(state_->vis.compute(pebble_->point), robot_.point, robot_.point);
}

void Simulator::set_evader(const geometry::ExactPoint& p) {
  if (!geometry::locate(*env_, p).in_free_space())
    throw InputError("evader " + geometry::format_point(geometry::to_double(p)) + " is not in the environment");
  evader_ = p;
}

Observation Simulator::sense() const {
  Observation y;
  switch (robot_.kind) {
    case Place::Kind::Interior: y.touch = Touch::Interior; break;
    case Place::Kind::Edge: y.touch = Touch::Edge; break;
    case Place::Kind::Vertex: y.touch = env_->turn(robot_.index) > 0 ? Touch::Convex : Touch::Reflex; break;
  }
  y.pebble = holding_ || (pebble_ && same_place(*pebble_, robot_));
  y.detected = reading_.detected;
  y.pebble_visible = reading_.pebble_visible;
  y.pebble_seen = reading_.pebble_seen;
  y.gaps = reading_.gaps;
  y.gap_events = reading_.gap_events;
  y.bitangents = reading_.bitangents;
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
  const std::size_t from = path_.size() - 1;
  const bool held_before = holding_;
  const Place start = robot_;
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
        path_.push_back(robot_.point);
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
  if (!(path_.back() == robot_.point)) path_.push_back(robot_.point);
  read_sensors(std::vector<geometry::ExactPoint>(path_.begin() + static_cast<long>(from), path_.end()), held_before, start);
  return sense();
}

// The section VI readings of the action whose motion is `motion` (a polyline; one point
// when the robot did not move).
void Simulator::read_sensors(const std::vector<geometry::ExactPoint>& motion, bool held_before, const Place& start) {
  reading_ = Observation{};
  if (!state_) return;
  const auto& E = *env_;
  auto seen_along = [&](const geometry::ExactPoint& target) {
    const auto V = state_->vis.compute(target);
    if (motion.size() == 1) return sees_during(V, motion[0], motion[0]);
    for (std::size_t k = 0; k + 1 < motion.size(); ++k)
      if (sees_during(V, motion[k], motion[k + 1])) return true;
    return false;
  };
  if (sensors_.detection && evader_) reading_.detected = seen_along(*evader_);
  // The pebble is seen while it lies (dropped during the action: from then on).
  if (sensors_.pebble_visibility && pebble_ && !holding_) {
    const auto V = state_->vis.compute(pebble_->point);
    reading_.pebble_visible = sees_during(V, robot_.point, robot_.point);
    reading_.pebble_seen = held_before || seen_along(pebble_->point);
  }
  // Gap and bitangent readings depend on the motion only: kept for motions between
  // vertices and cut endpoints, which strategies repeat while walking about.
  auto id = [](const Place& p) -> long {
    if (p.kind == Place::Kind::Vertex) return static_cast<long>(p.index);
    if (p.kind == Place::Kind::Edge && p.mark >= 0) return -2 - p.mark;
    return LONG_MIN;
  };
  const auto key = std::make_pair(id(start), id(robot_));
  const bool cacheable = key.first != LONG_MIN && key.second != LONG_MIN;
  if (cacheable) {
    const auto it = state_->readings.find(key);
    if (it != state_->readings.end()) {
      if (sensors_.gap) reading_.gaps = it->second.gaps, reading_.gap_events = it->second.gap_events;
      if (sensors_.bitangent) reading_.bitangents = it->second.bitangents;
      if ((!sensors_.gap || it->second.has_gap) && (!sensors_.bitangent || it->second.has_bitangent)) return;
    }
  }
  if (sensors_.gap) {
    auto g = gap_reading(state_->vis, state_->lines, motion);
    reading_.gaps = g.gaps;
    reading_.gap_events = std::move(g.events);
  }
  if (sensors_.bitangent && robot_.kind != Place::Kind::Interior && motion.size() >= 2 &&
      geometry::locate(E, motion.front()).kind != geometry::Location::Kind::Interior) {
    // A ray is crossed when the robot changes sides of it (VI.C); names relative to where
    // the action ends.
    const BoundaryPoint a = boundary_point(E, motion.front()), b = boundary_point(E, motion.back());
    const std::size_t n = E.num_vertices(), ref = robot_.index;
    auto rel = [&](std::size_t v) { return static_cast<std::uint32_t>((v + n - ref) % n); };
    for (const Bitangent& t : state_->bitangents)
      for (bool at_j : {false, true}) {
        if (merged_side(E, t, at_j, a) == merged_side(E, t, at_j, b)) continue;
        const BoundaryPoint& other = at_j ? t.b_ij : t.b_ji;
        std::uint32_t before = 0;
        for (const Cut& c : state_->cuts.cuts)
          if (c.edge == other.edge && CGAL::has_smaller_distance_to_point(E.exact_vertex(other.edge), c.end, other.point)) ++before;
        reading_.bitangents.push_back({rel(at_j ? t.j : t.i), rel(at_j ? t.i : t.j), rel(other.edge), before});
      }
  }
  if (cacheable) {
    auto& c = state_->readings[key];
    if (sensors_.gap) c.gaps = reading_.gaps, c.gap_events = reading_.gap_events, c.has_gap = true;
    if (sensors_.bitangent) c.bitangents = reading_.bitangents, c.has_bitangent = true;
  }
}

}  // namespace preimage::wallfollow
