// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/tracking/simulation.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace preimage::tracking {

const char* to_string(TargetPolicy p) {
  switch (p) {
    case TargetPolicy::Scripted: return "scripted";
    case TargetPolicy::Random: return "random";
    case TargetPolicy::Adversarial: return "adversarial";
  }
  return "?";
}
const char* to_string(Strategy s) {
  switch (s) {
    case Strategy::Risk: return "risk";
    case Strategy::Sde: return "sde";
    case Strategy::Naive: return "naive";
  }
  return "?";
}
TargetPolicy parse_target_policy(const std::string& s) {
  for (auto p : {TargetPolicy::Scripted, TargetPolicy::Random, TargetPolicy::Adversarial})
    if (s == to_string(p)) return p;
  throw InputError("--target-policy: expected scripted, random or adversarial, got \"" + s + "\"");
}
Strategy parse_strategy(const std::string& s) {
  for (auto p : {Strategy::Risk, Strategy::Sde, Strategy::Naive})
    if (s == to_string(p)) return p;
  throw InputError("--strategy: expected risk, sde or naive, got \"" + s + "\"");
}

namespace {
std::string xy(const Point& p) { return std::string("(").append(std::to_string(p.x())).append(", ").append(std::to_string(p.y())).append(")"); }
bool interior(const geometry::Environment& env, const Point& p) {
  return geometry::locate(env, p).kind == geometry::Location::Kind::Interior;
}
double dist(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }
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
  s.observer = Pose{*t.observer, t.heading * M_PI / 180};
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
      const double nd = d[u] + dist(nodes[u], nodes[v]);
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

namespace {

Point to_sensor(const Pose& o, const Point& p) {
  const double dx = p.x() - o.position.x(), dy = p.y() - o.position.y(), c = std::cos(o.heading), s = std::sin(o.heading);
  return Point(c * dx + s * dy, -s * dx + c * dy);
}
Point to_world(const Pose& o, const Point& p) {
  const double c = std::cos(o.heading), s = std::sin(o.heading);
  return Point(o.position.x() + c * p.x() - s * p.y(), o.position.y() + s * p.x() + c * p.y());
}

// Walks `path` (from its first point) by `step`, consuming it; returns the new point.
Point walk(std::vector<Point>& path, double step) {
  Point at = path.front();
  while (path.size() >= 2 && step > 0) {
    const double d = dist(path[0], path[1]);
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

}  // namespace

SimulationResult simulate(const TrackingScenario& sc, const SimulationParams& sp) {
  const geometry::Environment& env = *sc.environment;
  const geometry::VisibilityIndex index(env);
  std::mt19937_64 rng(sp.seed);
  SimulationResult out;
  out.dt = sp.dt;
  Pose o = sc.observer;
  Point t = sc.target.center;
  const double r = sc.target.radius;
  // The tracker knows the target's radius: detection fits it, the risk's delta is it.
  TrackerParams tp = sp.tracker;
  tp.detect.radius = r;
  tp.risk.delta = r;
  const ControlParams& cp = tp.control;
  const bool cone = sp.laser.fov < 2 * M_PI - 1e-9;

  std::vector<Point> plan;  // the target's remaining path
  auto random_free = [&]() {
    const auto box = env.bbox();
    std::uniform_real_distribution<double> X(box.xmin(), box.xmax()), Y(box.ymin(), box.ymax());
    for (;;) {
      Point p(X(rng), Y(rng));
      if (interior(env, p)) return p;
    }
  };
  if (sp.policy == TargetPolicy::Scripted) {
    plan = sc.target_path;
    plan.insert(plan.begin(), t);
  }
  auto sees = [&](const Pose& from, const Point& p) {
    const Point q = to_sensor(from, p);
    if (std::hypot(q.x(), q.y()) > sp.laser.max_range) return false;
    if (cone && std::abs(std::atan2(q.y(), q.x())) > sp.laser.fov / 2) return false;
    return geometry::visible(env, from.position, p);
  };
  auto can_move = [&](const Point& from, const Point& to) {
    return interior(env, to) && geometry::visible(env, from, to) && dist(to, t) > r + 0.15;
  };

  Point estimate = t;  // world frame; the observer starts knowing where the target is
  std::size_t seen = 0;
  for (std::size_t step = 0; step <= sp.steps; ++step) {
    const bool vis = sees(o, t);
    out.observer.push_back(o);
    out.target.push_back(t);
    out.visible.push_back(vis);
    if (vis) ++seen;
    if (!vis && out.escape_time < 0) out.escape_time = static_cast<double>(step) * sp.dt;
    if (step == sp.steps || (sp.stop_at_escape && !vis)) { out.tracked.push_back(0); break; }

    // --- the observer: TRACK on a scan, or a baseline
    const Scan scan = simulate_scan(env, o, sp.laser, Disc{t, r}, &rng);
    const TrackStep ts = track(scan, tp, to_sensor(o, estimate));
    out.tracked.push_back(ts.tracked);
    if (ts.detection.found) estimate = to_world(o, ts.detection.center);
    const Point est_s = to_sensor(o, estimate);
    Command cmd = naive_command(est_s, cp);
    if (sp.strategy == Strategy::Risk && ts.tracked) {
      cmd = ts.command;
    } else if (sp.strategy == Strategy::Sde) {
      // Equation (2): the control whose next position maximises SDE for the target where
      // it is now. The baseline is given the map: SDE comes from the exact V there.
      double best = -1;
      const Command naive = cmd;
      double best_tie = 1e300;
      for (double fv : {0.0, 0.5, 1.0}) {
        for (double fw : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
          const Command c{fv * cp.v_max, fw * cp.omega_max};
          const double th = o.heading + c.omega * sp.dt;
          const Point p(o.position.x() + c.v * sp.dt * std::cos(th), o.position.y() + c.v * sp.dt * std::sin(th));
          if (c.v > 0 && !can_move(o.position, p)) continue;
          if (!sees(Pose{p, th}, estimate)) continue;
          LocalMap m;
          try {
            m = exact_local_map(index, p);
          } catch (const InputError&) {
            continue;  // a degenerate V at this candidate: skip it
          }
          const auto tree = try_escape_path_tree(m, estimate);
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
    }
    // Unicycle kinematics, equation (5), integrated over one period.
    const double th = o.heading + cmd.omega * sp.dt;
    const Point p(o.position.x() + cmd.v * sp.dt * std::cos(th), o.position.y() + cmd.v * sp.dt * std::sin(th));
    const Point before = o.position;
    o.heading = th;
    if (cmd.v != 0 && can_move(before, p)) o.position = p;
    out.observer_length += dist(before, o.position);

    // --- the target
    const Point t_before = t;
    double speed = sc.target_speed;
    if (sp.policy == TargetPolicy::Random) {
      while (plan.size() < 2) plan = shortest_path(env, t, random_free());
    } else if (sp.policy == TargetPolicy::Adversarial) {
      speed = sp.speed_ratio * cp.v_max;
      // Run along the current shortest escape path from the observer's true position.
      LocalMap m;
      bool ok = true;
      try {
        m = exact_local_map(index, o.position);
      } catch (const InputError&) {
        ok = false;  // keep the previous plan
      }
      const auto tree = ok ? try_escape_path_tree(m, t) : std::nullopt;
      if (tree && tree->shortest != kNone) {
        plan = tree->polyline(tree->shortest);
        // and on past the escape point, out of sight
        const Point& a = plan[plan.size() - 2];
        const Point& b = plan.back();
        const double len = dist(a, b);
        if (len > 0) {
          const Point beyond(b.x() + (b.x() - a.x()) / len, b.y() + (b.y() - a.y()) / len);
          if (geometry::visible(env, b, beyond)) plan.push_back(beyond);
        }
      }
    }
    if (plan.size() >= 2) t = walk(plan, speed * sp.dt);
    if (!interior(env, t)) t = t_before;  // a path along the boundary: stay in the open
    out.target_length += dist(t_before, t);
  }
  out.visible_fraction = static_cast<double>(seen) / static_cast<double>(out.visible.size());
  return out;
}

}  // namespace preimage::tracking
