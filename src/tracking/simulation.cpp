// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/tracking/simulation.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <tuple>

namespace preimage::tracking {

const char* to_string(TargetPolicy p) {
  switch (p) {
    case TargetPolicy::Scripted: return "scripted";
    case TargetPolicy::Random: return "random";
    case TargetPolicy::Adversarial: return "adversarial";
    case TargetPolicy::Lookahead: return "lookahead";
    case TargetPolicy::Game: return "game";
  }
  return "?";
}
const char* to_string(Strategy s) {
  switch (s) {
    case Strategy::Risk: return "risk";
    case Strategy::Sde: return "sde";
    case Strategy::Naive: return "naive";
    case Strategy::Game: return "game";
    case Strategy::RiskGame: return "risk-game";
  }
  return "?";
}
TargetPolicy parse_target_policy(const std::string& s) {
  for (auto p : {TargetPolicy::Scripted, TargetPolicy::Random, TargetPolicy::Adversarial, TargetPolicy::Lookahead, TargetPolicy::Game})
    if (s == to_string(p)) return p;
  throw InputError("--target-policy: expected scripted, random, adversarial, lookahead or game, got \"" + s + "\"");
}
Strategy parse_strategy(const std::string& s) {
  for (auto p : {Strategy::Risk, Strategy::Sde, Strategy::Naive, Strategy::Game, Strategy::RiskGame})
    if (s == to_string(p)) return p;
  throw InputError("--strategy: expected risk, sde, naive, game or risk-game, got \"" + s + "\"");
}

namespace {
std::string xy(const Point& p) { return std::string("(").append(std::to_string(p.x())).append(", ").append(std::to_string(p.y())).append(")"); }
bool interior(const geometry::Environment& env, const Point& p) {
  return geometry::locate(env, p).kind == geometry::Location::Kind::Interior;
}
double planar_distance(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }
}  // namespace

TrackingScenario TrackingScenario::from_scene(const scene::Scene& sc) {
  const auto& env = sc.require_environment();
  if (!sc.tracking) throw InputError(sc.source + ": the scene has no \"tracking\" slot ($.tracking)");
  const auto& t = *sc.tracking;
  if (!t.observer) throw InputError(sc.source + ": $.tracking.observer is missing");
  if (!t.target) throw InputError(sc.source + ": $.tracking.target is missing");
  TrackingScenario s;
  s.name = sc.name.empty() ? sc.source : sc.name;
  s.environment = &env;
  s.observer = Pose{*t.observer, geometry::radians_from_degrees(t.heading)};
  s.target = Disc{*t.target, t.target_radius};
  s.target_speed = t.target_speed;
  s.target_path = t.target_path;
  if (!interior(env, *t.observer)) throw InputError(sc.source + ": $.tracking.observer " + xy(*t.observer) + " is not in the open free space");
  if (!interior(env, *t.target)) throw InputError(sc.source + ": $.tracking.target " + xy(*t.target) + " is not in the open free space");
  if (!geometry::visible(env, *t.observer, *t.target))
    throw InputError(sc.source + ": $.tracking.target is not visible from $.tracking.observer");
  Point prev = *t.target;
  for (std::size_t i = 0; i < t.target_path.size(); ++i) {
    if (!geometry::visible(env, prev, t.target_path[i]))
      throw InputError(sc.source + ": $.tracking.target_path[" + std::to_string(i) + "] " + xy(t.target_path[i]) +
                       " cannot be reached in a straight line from the previous point");
    prev = t.target_path[i];
  }
  return s;
}

std::vector<Point> shortest_path(const geometry::Environment& env, const Point& from, const Point& to) {
  if (geometry::visible(env, from, to)) return {from, to};
  const std::size_t n = env.num_vertices();
  std::vector<Point> nodes;
  for (std::size_t v = 0; v < n; ++v) nodes.push_back(env.vertex(v));
  nodes.push_back(from);
  nodes.push_back(to);
  const std::size_t m = nodes.size(), s = n, g = n + 1;
  std::vector<double> d(m, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> parent(m, m);
  std::vector<char> done(m, 0);
  d[s] = 0;
  for (std::size_t round = 0; round < m; ++round) {
    std::size_t u = m;
    for (std::size_t i = 0; i < m; ++i)
      if (!done[i] && std::isfinite(d[i]) && (u == m || d[i] < d[u])) u = i;
    if (u == m || u == g) break;
    done[u] = 1;
    for (std::size_t v = 0; v < m; ++v) {
      if (done[v] || v == s) continue;
      const double nd = d[u] + planar_distance(nodes[u], nodes[v]);
      if (nd < d[v] && geometry::visible(env, nodes[u], nodes[v])) { d[v] = nd; parent[v] = u; }
    }
  }
  if (!std::isfinite(d[g])) return {};
  std::vector<Point> path;
  for (std::size_t v = g; v != m; v = parent[v]) path.push_back(nodes[v]);
  std::reverse(path.begin(), path.end());
  return path;
}

LocalMap exact_local_map(const geometry::VisibilityIndex& index, const Point& at) {
  return local_map_from_visibility(index.compute(at));
}

Point to_sensor(const Pose& o, const Point& p) {
  const double dx = p.x() - o.position.x(), dy = p.y() - o.position.y(), c = std::cos(o.heading), s = std::sin(o.heading);
  return Point(c * dx + s * dy, -s * dx + c * dy);
}
Point to_world(const Pose& o, const Point& p) {
  const double c = std::cos(o.heading), s = std::sin(o.heading);
  return Point(o.position.x() + c * p.x() - s * p.y(), o.position.y() + s * p.x() + c * p.y());
}
Vec2 to_world(const Pose& o, const Vec2& v) {
  const double c = std::cos(o.heading), s = std::sin(o.heading);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

namespace {

Point offset(const Point& p, const Vec2& v) { return Point(p.x() + v.x, p.y() + v.y); }

// Walks `path` (from its first point) by `step`, consuming it; returns the new point.
Point walk(std::vector<Point>& path, double step) {
  Point at = path.front();
  while (path.size() >= 2 && step > 0) {
    const double d = planar_distance(path[0], path[1]);
    if (d <= step) {
      step -= d;
      path.erase(path.begin());
      at = path.front();
    } else {
      const double f = step / d;
      at = Point(path[0].x() + f * (path[1].x() - path[0].x()), path[0].y() + f * (path[1].y() - path[0].y()));
      path[0] = at;
      step = 0;
    }
  }
  return at;
}

// The polyline with each inner vertex moved c off the obstacle corner it bends round. A
// taut path turns round an obstacle that lies inside the turn, so the corner's free side
// is opposite the bisector of the two legs.
std::vector<Point> with_clearance(const std::vector<Point>& path, double c) {
  std::vector<Point> out = path;
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const Vec2 a = vec(path[i - 1]) - vec(path[i]), b = vec(path[i + 1]) - vec(path[i]);
    if (a.norm() == 0 || b.norm() == 0) continue;
    const Vec2 inner = a * (1 / a.norm()) + b * (1 / b.norm());
    if (inner.norm() > 1e-9) out[i] = offset(path[i], inner * (-c / inner.norm()));
  }
  return out;
}

// One run's world: the scene, the sensor, the strategy, and the observer's step.
class World {
 public:
  struct Observer {
    Pose pose;
    Command velocity;  // executed on the last step
    Point estimate;    // where it believes the target is (world frame)
    std::size_t misses = 0;  // scans since the target was last detected
  };

  World(const TrackingScenario& sc, const SimulationParams& sp)
      : env_(*sc.environment), index_(env_), sp_(sp), r_(sc.target.radius), cone_(sp.laser.fov < 2 * M_PI - 1e-9) {
    // The tracker knows the target's radius: detection fits it, the risk's delta is it.
    tp_ = sp.tracker;
    tp_.detect.radius = r_;
    tp_.risk.delta = r_;
    target_top_speed_ = sp.policy == TargetPolicy::Scripted || sp.policy == TargetPolicy::Random
                            ? sc.target_speed
                            : sp.speed_ratio * sp.tracker.control.v_max;
  }
  const geometry::Environment& env() const { return env_; }
  const geometry::VisibilityIndex& index() const { return index_; }
  /// The target's speed under this run's policy: the scene's for scripted and random
  /// targets, speed_ratio x the observer's top speed for the planning ones.
  double target_speed() const { return target_top_speed_; }

  bool interior(const Point& p) const { return geometry::locate(env_, p).kind == geometry::Location::Kind::Interior; }
  bool sees(const Pose& from, const Point& p) const {
    const Point q = to_sensor(from, p);
    if (std::hypot(q.x(), q.y()) > sp_.laser.max_range) return false;
    if (cone_ && std::abs(std::atan2(q.y(), q.x())) > sp_.laser.fov / 2) return false;
    return geometry::visible(env_, from.position, p);
  }
  // May the observer go from `from` to `to` with the target at t (it keeps off the target)?
  bool can_move(const Point& from, const Point& to, const Point& t) const {
    return interior(to) && geometry::visible(env_, from, to) && planar_distance(to, t) > r_ + 0.15;
  }
  // A target step from `from` to `to` in the open, straight.
  bool can_step(const Point& from, const Point& to) const { return interior(to) && geometry::visible(env_, from, to); }
  // A target step: taken if straight and into the open, else the target stays.
  Point target_step(const Point& from, const Point& to) const { return can_step(from, to) ? to : from; }

  // The strategy's command for a scan from o.pose with the target at t (range noise from
  // rng; none if null). TRACK's iteration goes to ts; o.estimate follows the detection.
  Command decide(Observer& o, const Point& t, std::mt19937_64* rng, TrackStep& ts) const {
    const Scan scan = simulate_scan(env_, o.pose, sp_.laser, Disc{t, r_}, rng);
    // The detection gate grows with the time since the last detection at the target's top
    // speed, from kGateSlack (fit noise and the disc's rim): the observer knows how fast a
    // target can move. With the fixed 1.5 m gate, a target brushing a lab chair merged
    // with it in the scan, and the estimate jumped 1.4 m to a desk corner in one scan
    // (five of the game strategy's seven lost winnable lab starts; fixture
    // lab_target_hugs_chair.json).
    TrackerParams tp = tp_;
    tp.detect.gate = std::min(tp_.detect.gate, kGateSlack + target_top_speed_ * sp_.dt * static_cast<double>(o.misses + 1));
    ts = track(scan, tp, to_sensor(o.pose, o.estimate));
    if (ts.detection.found) o.estimate = to_world(o.pose, ts.detection.center);
    o.misses = ts.detection.found ? 0 : o.misses + 1;
    const Command naive = naive_command(to_sensor(o.pose, o.estimate), tp_.control);
    if (sp_.strategy == Strategy::Risk) return ts.tracked ? ts.control.command : naive;
    if (sp_.strategy == Strategy::Sde) return sde_command(o, naive);
    if (sp_.strategy == Strategy::Game) return game_command(o, naive, true);
    if (sp_.strategy == Strategy::RiskGame) return game_command(o, ts.tracked ? ts.control.command : naive, false);
    return naive;
  }

  // The game target's step: towards the grid point of the game's optimal escape from the
  // nearest grid state, straight, if that step is free.
  Point game_target_step(const Point& observer, const Point& t, double step) const {
    const VisibilityGame& g = *sp_.game;
    const std::uint32_t go = g.nearest(observer), gt = g.nearest_target(t);
    if (go == VisibilityGame::kNoPoint || gt == VisibilityGame::kNoPoint) return t;
    const Point goal = g.point(g.target_policy(go, gt));
    const double d = planar_distance(t, goal);
    if (d == 0) return t;
    return target_step(t, d <= step ? goal : offset(t, (vec(goal) - vec(t)) * (step / d)));
  }

  // The world-frame velocity of a command (forward v, sideways lateral) at a heading.
  static Vec2 world_velocity(double heading, const Command& u) {
    const double c = std::cos(heading), s = std::sin(heading);
    return Vec2{c * u.v - s * u.lateral, s * u.v + c * u.lateral};
  }
  // The acceleration is a vector: a robot at speed v turning at omega accelerates by
  // v omega sideways, which the bounds on dv/dt and d(omega)/dt alone leave free (2 m/s^2 at
  // 1 m/s and 2 rad/s, four times the evaluation's 0.5). Where the world-frame velocity
  // would change by more than accel dt, the changes of speed, sideways speed and turn rate
  // are scaled back together (bisection on the share kept); if even keeping the last
  // period's command turns too fast (the speed grew), the turn rate is eased towards 0.
  void bound_acceleration(const Observer& o, Command& u) const {
    const double limit = sp_.accel * sp_.dt;
    const Vec2 w0 = world_velocity(o.pose.heading, o.velocity);  // now; after one period at the new heading:
    auto within = [&](const Command& c) { return (world_velocity(o.pose.heading + c.omega * sp_.dt, c) - w0).norm() <= limit; };
    if (within(u)) return;
    const Command from = o.velocity;
    auto blend = [&](double k) {
      return Command{from.v + k * (u.v - from.v), from.omega + k * (u.omega - from.omega), from.lateral + k * (u.lateral - from.lateral)};
    };
    Command keep = from;
    if (!within(keep)) {
      double lo = 0, hi = 1;  // the share of the turn rate kept, speed as before
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        (within(Command{from.v, mid * from.omega, from.lateral}) ? lo : hi) = mid;
      }
      u = Command{from.v, lo * from.omega, from.lateral};
      return;
    }
    double lo = 0, hi = 1;  // the share of the commanded change kept
    for (int i = 0; i < 40; ++i) {
      const double mid = 0.5 * (lo + hi);
      (within(blend(mid)) ? lo : hi) = mid;
    }
    u = blend(lo);
  }

  // Dynamics, then unicycle kinematics (equation 5) over one period. A blocked move stops
  // the observer (it turns on the spot).
  void move(Observer& o, const Command& cmd, const Point& t) const {
    const double dt = sp_.dt;
    Command u = cmd;
    if (sp_.accel > 0) u.v = o.velocity.v + std::clamp(cmd.v - o.velocity.v, -sp_.accel * dt, sp_.accel * dt);
    if (sp_.alpha > 0) u.omega = o.velocity.omega + std::clamp(cmd.omega - o.velocity.omega, -sp_.alpha * dt, sp_.alpha * dt);
    if (sp_.accel > 0) u.lateral = o.velocity.lateral + std::clamp(cmd.lateral - o.velocity.lateral, -sp_.accel * dt, sp_.accel * dt);
    if (sp_.accel > 0) bound_acceleration(o, u);
    const double th = o.pose.heading + u.omega * dt;
    // Forward along the new heading, sideways to its left (a holonomic base only; a
    // unicycle's step is computed as it always was, so that its runs stay bit for bit).
    const Point p = u.lateral == 0
                        ? Point(o.pose.position.x() + u.v * dt * std::cos(th), o.pose.position.y() + u.v * dt * std::sin(th))
                        : Point(o.pose.position.x() + (u.v * std::cos(th) - u.lateral * std::sin(th)) * dt,
                                o.pose.position.y() + (u.v * std::sin(th) + u.lateral * std::cos(th)) * dt);
    o.pose.heading = th;
    if ((u.v != 0 || u.lateral != 0) && can_move(o.pose.position, p, t)) o.pose.position = p;
    else u.v = u.lateral = 0;
    o.velocity = u;
  }

  // The adversarial target's step: along the shortest escape path in the exact V of the
  // observer at `observer`, kept its radius off corners and run on past the escape point;
  // if that step is blocked, along the next shortest. Without a tree (out of sight, or a
  // degenerate V) it walks on along `plan`, its last one.
  Point escape_step(const Point& observer, const Point& t, double step, std::vector<Point>& plan) const {
    std::optional<EscapePathTree> tree;
    LocalMap map;
    try {
      map = exact_local_map(index_, observer);
      tree = try_escape_path_tree(map, t);
    } catch (const InputError&) {
      // a degenerate V at this observer position: keep the last plan
    }
    if (tree && tree->shortest != kNone) {
      std::vector<std::uint32_t> order(tree->paths.size());
      for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return tree->paths[a].length < tree->paths[b].length; });
      for (std::uint32_t i : order) {
        std::vector<Point> path = with_clearance(tree->polyline(i), r_);
        const EscapePath& e = tree->paths[i];
        if (e.kind == EdgeKind::Occlusion) {
          const std::uint32_t k = map.corner[e.edge], far = k == e.edge ? static_cast<std::uint32_t>(map.next(e.edge)) : e.edge;
          wrap_corner(path, map.vertices[k], vec(map.vertices[far]) - vec(map.vertices[k]));
        }
        const Point& a = path[path.size() - 2];
        const Point& b = path.back();
        const double len = planar_distance(a, b);
        if (len > 0) path.push_back(Point(b.x() + (b.x() - a.x()) / len, b.y() + (b.y() - a.y()) / len));
        std::vector<Point> rest = path;
        const Point q = target_step(t, walk(rest, step));
        if (!(q == t)) {
          plan = std::move(rest);
          return q;
        }
      }
      return t;
    }
    if (plan.size() < 2) return t;
    return target_step(t, walk(plan, step));
  }

  // The look-ahead target's step (see TargetPolicy::Lookahead): the adversarial move,
  // unless a straight heading leaves sight sooner against the observer's simulated response.
  Point lookahead_step(const Observer& o, const Point& t, double step) const {
    const std::size_t k = std::max<std::size_t>(sp_.lookahead_steps, 1), H = sp_.lookahead_headings;
    std::size_t best_depth = k + 1;  // the depth at which the best candidate leaves sight; k + 1: not within k
    Point best = t;
    TrackStep scratch;
    for (std::size_t c = 0; c <= H; ++c) {  // c = 0: the adversarial move; then the headings
      const double heading = 2 * M_PI * static_cast<double>(c) / static_cast<double>(std::max<std::size_t>(H, 1));
      const Vec2 dir{std::cos(heading), std::sin(heading)};
      // A heading is taken only if it escapes sooner than the best so far.
      const std::size_t limit = c == 0 ? k : std::min(k, best_depth - 1);
      if (limit == 0) break;
      Observer O = o;
      Point T = t, first = t;
      std::vector<Point> plan;
      for (std::size_t depth = 1; depth <= limit; ++depth) {
        const Point next = c == 0 ? escape_step(O.pose.position, T, step, plan) : target_step(T, offset(T, dir * step));
        if (depth == 1) first = next;
        T = next;
        if (!sees(O.pose, T)) {
          best_depth = depth;
          best = first;
          break;
        }
        if (depth < limit) move(O, decide(O, T, nullptr, scratch), T);
      }
      if (c == 0 && best_depth > k) best = first;  // the default
    }
    return best;
  }

 private:
  // An escape point within the radius of the occluding corner k: the disc escapes past k
  // at its radius (the corner exit of eq. (4)), so the path ends on a circle of radius r
  // about k, from the side of its previous point round to the free edge's direction u,
  // the way round that stays in the open, in steps of at most 30 deg.
  void wrap_corner(std::vector<Point>& path, const Point& k, const Vec2& u) const {
    if (path.size() < 2 || u.norm() == 0 || planar_distance(path.back(), k) >= r_) return;
    const Vec2 from = vec(path[path.size() - 2]) - vec(k);
    if (from.norm() == 0) return;
    const double a0 = std::atan2(from.y, from.x), a1 = std::atan2(u.y, u.x);
    for (double turn : {+1.0, -1.0}) {
      double sweep = turn * (a1 - a0);
      while (sweep < 0) sweep += 2 * M_PI;
      while (sweep >= 2 * M_PI) sweep -= 2 * M_PI;
      const int n = std::max(1, static_cast<int>(std::ceil(sweep / (M_PI / 6))));
      std::vector<Point> arc;
      for (int j = 0; j <= n; ++j) {
        const double a = a0 + turn * sweep * j / n;
        arc.push_back(offset(k, Vec2{std::cos(a), std::sin(a)} * r_));
      }
      bool open = planar_distance(path[path.size() - 2], arc.front()) == 0 || can_step(path[path.size() - 2], arc.front());
      for (std::size_t j = 1; open && j < arc.size(); ++j) open = can_step(arc[j - 1], arc[j]);
      if (!open) continue;
      path.pop_back();
      path.insert(path.end(), arc.begin(), arc.end());
      return;
    }
  }

  // The game's grid points around a continuous target position: its nearest point and the
  // free corners of the grid cell it lies in. The game is played on the grid; a target
  // between grid points may be seen from where its nearest point is not, and the other way
  // round, so the strategies below judge a position against all of these.
  std::vector<std::uint32_t> target_cell(const Point& t) const {
    const VisibilityGame& g = *sp_.game;
    std::vector<std::uint32_t> out;
    const std::uint32_t n = g.nearest_target(t);
    if (n == VisibilityGame::kNoPoint) return out;
    out.push_back(n);
    const double h = g.params().resolution;
    for (std::uint32_t q : g.observer_moves(n))  // the grid points within the observer's reach, a superset of the cell
      if (std::abs(g.point(q).x() - t.x()) < h && std::abs(g.point(q).y() - t.y()) < h && q != n && g.target_may_stand(q))
        out.push_back(q);
    return out;
  }
  // How good the observer at grid point q is against a target in `cell` (its nearest grid
  // point first): the game's value for the nearest point; how many of the cell's points it
  // keeps; and its depth in the keeping region, the number of (observer move from q, cell
  // point) pairs that keep. The game's optimal play rides the border of the keeping
  // region, where a continuous target between grid points escapes (the adversary did,
  // in 2-7 s, from starts the game keeps); depth keeps the observer inside it.
  struct RobustValue {
    std::uint32_t value = 0;
    std::size_t corners = 0, depth = 0;
    auto operator<=>(const RobustValue&) const = default;
  };
  RobustValue robust_value(std::uint32_t q, const std::vector<std::uint32_t>& cell) const {
    const VisibilityGame& g = *sp_.game;
    RobustValue r;
    r.value = g.escape_steps(q, cell.front());
    for (std::uint32_t t : cell) r.corners += g.keeps(q, t);
    for (std::uint32_t m : g.observer_moves(q))
      for (std::uint32_t t : cell) r.depth += g.keeps(m, t);
    return r;
  }

  // Strategy::Game (holonomic) and Strategy::RiskGame (unicycle). The goal: of the
  // observer's grid moves within one game step, the best robust value, then the nearest
  // to the target (closing in shortens the line of sight the obstacles can cut).
  Command game_command(const Observer& o, const Command& preferred, bool holonomic) const {
    const VisibilityGame& g = *sp_.game;
    const ControlParams& cp = tp_.control;
    const double dt = sp_.dt;
    const std::vector<std::uint32_t> cell = target_cell(o.estimate);
    const std::uint32_t go = g.nearest(o.pose.position);
    if (cell.empty() || go == VisibilityGame::kNoPoint) return preferred;
    Point goal = g.point(go);
    RobustValue best;
    double best_len = 1e300;
    for (std::uint32_t q : g.observer_moves(go)) {
      const RobustValue v = robust_value(q, cell);
      const double len = planar_distance(g.point(q), o.estimate);
      if (v > best || (v == best && len < best_len)) {
        best = v;
        best_len = len;
        goal = g.point(q);
      }
    }
    if (holonomic) {
      // The game's own observer: a holonomic base whose sensor turns freely. Straight
      // towards the goal at up to v_max (stopping on it), the body turning to face the
      // target at up to omega_max.
      const Vec2 d = vec(goal) - vec(o.pose.position);
      const double len = d.norm(), speed = std::min(cp.v_max, len / dt);
      const double c = std::cos(o.pose.heading), s = std::sin(o.pose.heading);
      Command h;
      if (len > 0) {
        h.v = speed * (c * d.x + s * d.y) / len;
        h.lateral = speed * (-s * d.x + c * d.y) / len;
      }
      const Vec2 to_target = vec(o.estimate) - vec(o.pose.position);
      const double turn = std::remainder(std::atan2(to_target.y, to_target.x) - o.pose.heading, 2 * M_PI);
      h.omega = std::clamp(turn / dt, -cp.omega_max, cp.omega_max);
      return h;
    }
    // A unicycle: of the risk command and a fan of commands (backwards too where the sensor
    // allows), the one whose next pose (a) still has the target in the sensor, (b) has the
    // best game value there, (c) ends nearest the goal, (d) is nearest the risk command.
    // Like eq. (2)'s baseline, it predicts one period without the dynamics.
    bool best_sees = false;
    std::uint32_t best_value = 0;
    double best_cost = 1e300, best_dev = 1e300;
    Command cmd = preferred;
    bool any = false;
    auto consider = [&](const Command& c) {
      const double th = o.pose.heading + c.omega * dt;
      const Point p(o.pose.position.x() + c.v * dt * std::cos(th), o.pose.position.y() + c.v * dt * std::sin(th));
      if (c.v != 0 && !can_move(o.pose.position, p, o.estimate)) return;
      const bool in_view = sees(Pose{p, th}, o.estimate);
      const std::uint32_t q = g.nearest(p);
      const std::uint32_t value = q == VisibilityGame::kNoPoint ? 0 : g.escape_steps(q, cell.front());
      const double cost = planar_distance(p, goal), dev = std::abs(c.v - preferred.v) + std::abs(c.omega - preferred.omega);
      if (!any || std::tie(in_view, value) > std::tie(best_sees, best_value) ||
          (std::tie(in_view, value) == std::tie(best_sees, best_value) && std::tie(cost, dev) < std::tie(best_cost, best_dev))) {
        any = true;
        best_sees = in_view;
        best_value = value;
        best_cost = cost;
        best_dev = dev;
        cmd = c;
      }
    };
    consider(preferred);
    for (double fv : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
      if (fv < 0 && !cp.reverse) continue;
      for (double fw : {-1.0, -0.5, -0.25, 0.0, 0.25, 0.5, 1.0}) consider(Command{fv * cp.v_max, fw * cp.omega_max});
    }
    return cmd;
  }

  // Equation (2): the control whose next position maximises SDE for the target where it
  // is believed to be now. The baseline is given the map: SDE comes from the exact V there.
  Command sde_command(const Observer& o, const Command& naive) const {
    const ControlParams& cp = tp_.control;
    const double dt = sp_.dt;
    double best = -1, best_tie = 1e300;
    Command cmd = naive;
    for (double fv : {0.0, 0.5, 1.0}) {
      for (double fw : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        const Command c{fv * cp.v_max, fw * cp.omega_max};
        const double th = o.pose.heading + c.omega * dt;
        const Point p(o.pose.position.x() + c.v * dt * std::cos(th), o.pose.position.y() + c.v * dt * std::sin(th));
        if (c.v > 0 && !can_move(o.pose.position, p, o.estimate)) continue;
        if (!sees(Pose{p, th}, o.estimate)) continue;
        LocalMap m;
        try {
          m = exact_local_map(index_, p);
        } catch (const InputError&) {
          continue;  // a degenerate V at this candidate: skip it
        }
        const auto tree = try_escape_path_tree(m, o.estimate);
        if (!tree) continue;
        const double sde = std::min(tree->sde(), 1e9);
        const double tie = std::abs(c.v - naive.v) + std::abs(c.omega - naive.omega);
        if (sde > best + 1e-9 || (std::abs(sde - best) <= 1e-9 && tie < best_tie)) {
          best = sde;
          best_tie = tie;
          cmd = c;
        }
      }
    }
    return cmd;
  }

  const geometry::Environment& env_;
  const geometry::VisibilityIndex index_;
  const SimulationParams& sp_;
  TrackerParams tp_;
  double r_;
  bool cone_;
  double target_top_speed_ = 0;
  static constexpr double kGateSlack = 0.25;  // metres
};

double variation(const std::vector<Command>& cmds, double dt, double Command::*field) {
  if (cmds.size() < 2) return 0;
  double tv = 0;
  for (std::size_t i = 1; i < cmds.size(); ++i) tv += std::abs(cmds[i].*field - cmds[i - 1].*field);
  return tv / (static_cast<double>(cmds.size()) * dt);
}

}  // namespace

double SimulationResult::variation_v() const { return variation(commands, dt, &Command::v); }
double SimulationResult::variation_omega() const { return variation(commands, dt, &Command::omega); }

GameParams game_params(const TrackingScenario& sc, const SimulationParams& sp, double resolution) {
  GameParams g;
  g.resolution = resolution;
  g.observer_speed = sp.tracker.control.v_max;
  g.speed_ratio = sp.speed_ratio;
  g.range = sp.laser.max_range;
  g.separation = sc.target.radius + 0.15;  // World::can_move keeps the observer this far off
  // A point target: the simulated targets' centres may come within a few centimetres of
  // an obstacle face (their paths keep the radius off corners only), so a game whose target
  // keeps its disc clear judges states the simulated adversary escapes from as kept (the
  // game strategy built on it kept 3 of 84 winnable box starts; on the point game, 75 of 75).
  g.target_radius = 0;
  return g;
}

SimulationResult simulate(const TrackingScenario& sc, const SimulationParams& sp) {
  if (!sp.game && (sp.strategy == Strategy::Game || sp.strategy == Strategy::RiskGame || sp.policy == TargetPolicy::Game))
    throw InputError(std::string("the ") + (sp.policy == TargetPolicy::Game ? "game target policy" : "game strategies") +
                     " need a solved visibility game");
  const World world(sc, sp);
  const geometry::Environment& env = world.env();
  std::mt19937_64 rng(sp.seed);
  SimulationResult out;
  out.dt = sp.dt;
  Pose start = sc.observer;
  Point t = sc.target.center;
  if (sp.start_spread > 0 || sp.heading_spread > 0) {
    // Where this seed starts: both up to start_spread off the scene's start (uniform in a
    // disc), the heading up to heading_spread off, drawn from their own stream (so the
    // range noise is the same as without) until the observer sees the target, clear of it,
    // and a scripted target can walk straight to its first waypoint.
    std::mt19937_64 jitter(sp.seed ^ 0x9e3779b97f4a7c15ull);
    std::uniform_real_distribution<double> U(-1, 1);
    auto disc = [&](const Point& p) {
      for (;;) {
        const Vec2 d{U(jitter), U(jitter)};
        if (d.dot(d) <= 1) return offset(p, d * sp.start_spread);
      }
    };
    for (int tries = 0; tries < 1000; ++tries) {
      const Pose o{disc(sc.observer.position), sc.observer.heading + sp.heading_spread * U(jitter)};
      const Point q = disc(sc.target.center);
      if (!world.interior(o.position) || !world.interior(q) || planar_distance(o.position, q) < sc.target.radius + 0.35 ||
          !world.sees(o, q))
        continue;
      if (sp.policy == TargetPolicy::Scripted && !sc.target_path.empty() && !world.can_step(q, sc.target_path.front()))
        continue;
      start = o;
      t = q;
      break;
    }
  }
  World::Observer o{start, Command{}, t};  // it starts knowing where the target is

  std::vector<Point> plan;  // the target's remaining path
  auto random_free = [&]() {
    const auto box = env.bbox();
    std::uniform_real_distribution<double> X(box.xmin(), box.xmax()), Y(box.ymin(), box.ymax());
    for (;;) {
      Point p = geometry::random_point(rng, X, Y);
      if (world.interior(p)) return p;
    }
  };
  if (sp.policy == TargetPolicy::Scripted) {
    plan = sc.target_path;
    plan.insert(plan.begin(), t);
  }
  const double stride = world.target_speed() * sp.dt;  // how far the target goes per period

  std::size_t seen = 0;
  TrackStep ts;
  for (std::size_t step = 0; step <= sp.steps; ++step) {
    const bool vis = world.sees(o.pose, t);
    out.observer.push_back(o.pose);
    out.target.push_back(t);
    out.visible.push_back(vis);
    if (vis) ++seen;
    if (!vis && out.escape_time < 0) out.escape_time = static_cast<double>(step) * sp.dt;
    if (step == sp.steps || (sp.stop_at_escape && !vis)) { out.tracked.push_back(0); break; }

    // --- the observer: TRACK on a scan, or a baseline
    const Pose before = o.pose;
    const Command cmd = world.decide(o, t, &rng, ts);
    out.tracked.push_back(ts.tracked);
    out.commands.push_back(cmd);
    world.move(o, cmd, t);
    out.observer_length += planar_distance(before.position, o.pose.position);
    if (sp.on_step) sp.on_step(StepRecord{step, before, t, vis, o.estimate, &ts, cmd, o.velocity});

    // --- the target
    const Point t_before = t;
    switch (sp.policy) {
      case TargetPolicy::Scripted:
        if (plan.size() >= 2) t = walk(plan, stride);
        if (!world.interior(t)) t = t_before;  // a path along the boundary: stay in the open
        break;
      case TargetPolicy::Random: {
        while (plan.size() < 2) plan = with_clearance(shortest_path(env, t, random_free()), sc.target.radius);
        const Point q = world.target_step(t, walk(plan, stride));
        if (q == t) plan.clear();  // blocked (a passage narrower than the target): a new goal next step
        t = q;
        break;
      }
      case TargetPolicy::Adversarial: t = world.escape_step(o.pose.position, t, stride, plan); break;
      case TargetPolicy::Lookahead: t = world.lookahead_step(o, t, stride); break;
      case TargetPolicy::Game: t = world.game_target_step(o.pose.position, t, stride); break;
    }
    out.target_length += planar_distance(t_before, t);
  }
  out.visible_fraction = static_cast<double>(seen) / static_cast<double>(out.visible.size());
  return out;
}

namespace {

// phi-bar at `observer`, and what it was computed from: each escape path's tree nodes
// and corner, so two evaluations can be told to share their structure.
RiskAverage risk_at(const geometry::VisibilityIndex& index, const Point& observer, const Point& target, const RiskParams& rp,
                    Aggregation aggregation, std::vector<Point>* structure) {
  const LocalMap map = exact_local_map(index, observer);
  const EscapePathTree tree = escape_path_tree(map, target);
  const auto risks = escape_risks(map, tree, rp);
  if (structure) {
    structure->clear();
    for (const auto& r : risks) {
      const EscapePath& p = tree.paths[r.path];
      structure->push_back(map.vertices[map.corner[p.edge]]);
      for (std::uint32_t v = p.node; v != kNone; v = tree.nodes[v].parent) structure->push_back(tree.nodes[v].at);
    }
  }
  return aggregation == Aggregation::Recursive ? recursive_average(tree, risks) : plain_average(risks);
}

}  // namespace

RiskCheck check_risk_gradient(const geometry::VisibilityIndex& index, const Point& o, const Point& t, const RiskParams& rp,
                              Aggregation aggregation, double eps) {
  RiskCheck out;
  std::vector<Point> structure, moved;
  out.risk = risk_at(index, o, t, rp, aggregation, &structure);
  double phi[4] = {0, 0, 0, 0};
  out.stable = true;
  const Point at[4] = {Point(o.x() + eps, o.y()), Point(o.x() - eps, o.y()), Point(o.x(), o.y() + eps), Point(o.x(), o.y() - eps)};
  for (int i = 0; i < 4; ++i) {
    try {
      phi[i] = risk_at(index, at[i], t, rp, aggregation, &moved).phi;
      out.stable = out.stable && moved == structure;
    } catch (const InputError&) {
      out.stable = false;  // the target left V, or V is degenerate there
    }
  }
  out.difference = Vec2{(phi[0] - phi[1]) / (2 * eps), (phi[2] - phi[3]) / (2 * eps)};
  return out;
}

}  // namespace preimage::tracking
