// SPDX-License-Identifier: Apache-2.0
// Online coverage: the planner of 6.2.4 (critical point sensing, the cycle algorithm, the
// incremental Reeb graph) driving the simulated robot of online_robot.hpp.
#include <preimage/decompose/online_coverage.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/queries.hpp>

#include "coverage_internal.hpp"
#include "online_robot.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <queue>
#include <set>

namespace preimage::decompose {

std::string_view to_string(OnlineKind k) {
  switch (k) {
    case OnlineKind::Birth: return "birth";
    case OnlineKind::Death: return "death";
    case OnlineKind::Split: return "split";
    case OnlineKind::Merge: return "merge";
  }
  return "?";
}

namespace {

using detail::Contact;
using detail::OnlineRobot;
using detail::SweepPoint;

enum class Side : std::uint8_t { Floor, Ceiling };

// A boundary point the robot stood at.
struct Stand {
  Point p;
  Contact c;
};

// A sensed critical point: its kind and the run of extreme abscissa the robot drove through
// (one point, or a vertical wall), bottom to top.
struct Sensed {
  OnlineKind kind;
  std::vector<Stand> run;
  std::size_t path_index = 0;
  double x() const { return run.front().p.x(); }
  const Stand& lo() const { return run.front(); }
  const Stand& hi() const { return run.back(); }
};

// A boundary follow: every point driven (the start first), and the critical point where the
// lateral displacement turned back, if it did before the stop slice.
struct Follow {
  std::vector<Stand> stands;
  std::optional<Sensed> cp;
  // The chain's ordinate at abscissa x (x between the start and the end), by interpolation
  // of the odometry: the planner's own estimate, compared with a stated tolerance.
  double y_at(double x) const {
    for (std::size_t i = 1; i < stands.size(); ++i) {
      const Point &a = stands[i - 1].p, &b = stands[i].p;
      if ((a.x() <= x && x <= b.x()) || (b.x() <= x && x <= a.x())) {
        if (a.x() == b.x()) return a.y();
        return a.y() + (x - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
      }
    }
    return NAN;
  }
};

// Which port of a node a cell uses.
enum class PortSide : std::uint8_t { Point, Up, Down, Both };

int port_index(OnlineKind k, bool right, PortSide ps) {
  switch (k) {
    case OnlineKind::Birth: return right && ps == PortSide::Point ? 0 : -1;
    case OnlineKind::Death: return !right && ps == PortSide::Point ? 0 : -1;
    case OnlineKind::Split:
      if (!right) return ps == PortSide::Both ? 0 : -1;
      return ps == PortSide::Up ? 1 : ps == PortSide::Down ? 2 : -1;
    case OnlineKind::Merge:
      if (right) return ps == PortSide::Both ? 2 : -1;
      return ps == PortSide::Up ? 0 : ps == PortSide::Down ? 1 : -1;
  }
  return -1;
}
// The inverse: side and kind of a port.
void port_of(OnlineKind k, int port, bool& right, PortSide& ps) {
  switch (k) {
    case OnlineKind::Birth: right = true, ps = PortSide::Point; return;
    case OnlineKind::Death: right = false, ps = PortSide::Point; return;
    case OnlineKind::Split: right = port != 0, ps = port == 0 ? PortSide::Both : port == 1 ? PortSide::Up : PortSide::Down; return;
    case OnlineKind::Merge: right = port == 2, ps = port == 2 ? PortSide::Both : port == 0 ? PortSide::Up : PortSide::Down; return;
  }
}

struct Failure {
  std::string what;
};

std::string at_text(const Point& p) { return geometry::format_point(p); }
class OnlinePlanner {
 public:
  OnlinePlanner(OnlineRobot& robot, const OnlineOptions& o, double w, std::size_t budget)
      : R_(robot), o_(o), w_(w), budget_(budget), tol_(1e-6 * w) {}

  void run(OnlineReport& rep) {
    try {
      explore();
      rep.complete = true;
    } catch (const Failure& f) {
      rep.inconsistency = f.what;
    }
    rep.nodes = nodes_, rep.edges = edges_, rep.sensing_order = order_, rep.laps = laps_, rep.steps = steps_;
    rep.ring_disagreements = ring_disagreements_;
    if (rep.complete)
      for (const auto& n : nodes_)
        for (int p : n.ports)
          if (p < 0) rep.complete = false, rep.inconsistency = "a critical point has an unexplored port";
  }

 private:
  void tick() {
    if (++steps_ > budget_) throw Failure{std::string("step budget of ").append(std::to_string(budget_)).append(" primitives exhausted")};
  }
  Stand here() const { return {R_.odometry(), R_.contact()}; }

  // --- sensing --------------------------------------------------------------------------
  // Boundary following along side s (the floor has free space above it) towards delta (+1:
  // +x), stopping on the slice x = stop_x or where a critical point is sensed: the lateral
  // displacement turns back. The boundary is followed vertex to vertex, so the extreme is a
  // vertex or a vertical run, the place where the boundary's normal cone holds the sweep
  // direction (Lemma 5.5.2); the robot then stands on the run's last point. Its kind: the
  // turn the boundary makes there (odometry: is the free wedge convex, so free space ends,
  // or reflex, so an obstacle ends), which the ring must confirm: the direction of the
  // ring's minimum (the surface normal) points along the sweep towards the obstacle side.
  Follow follow(Side s, int delta, double stop_x) {
    Follow out;
    const int dir = s == Side::Floor ? delta : -delta;  // +1: the ring order, free space on the left
    out.stands.push_back(here());
    std::vector<double> along{0};
    double best = delta * R_.odometry().x();
    for (;;) {
      tick();
      bool on_slice = false;
      if (!R_.follow_step(dir, stop_x, on_slice)) throw Failure{"boundary following started away from the boundary at " + at_text(R_.odometry())};
      out.stands.push_back(here());
      if (on_slice) return out;
      const auto ring = R_.read_ring();
      // The surface normal's component along the follow (the ring's minimum; sensor 0 looks
      // along +x).
      along.push_back(delta * std::cos(R_.sensor_angle(ring.argmin)));
      const double x = delta * R_.odometry().x();
      if (x >= best) {
        best = x;
        continue;
      }
      // Turned back: the run of extreme abscissa ends at the previous point.
      const std::size_t last = out.stands.size() - 2;
      std::size_t first = last;
      while (first > 0 && out.stands[first - 1].p.x() == out.stands[last].p.x()) --first;
      if (first == 0) throw Failure{"the boundary turns back at once from " + at_text(out.stands[0].p)};
      Sensed cp;
      cp.run.assign(out.stands.begin() + static_cast<std::ptrdiff_t>(first), out.stands.begin() + static_cast<std::ptrdiff_t>(last) + 1);
      const int turn = geometry::orientation(out.stands[first - 1].p, out.stands[first].p,
                                             first != last ? out.stands[last].p : out.stands[last + 1].p);
      const bool convex = turn * dir > 0;  // free space on the inside of the turn
      if (delta > 0) cp.kind = convex ? OnlineKind::Death : OnlineKind::Merge;
      else cp.kind = convex ? OnlineKind::Birth : OnlineKind::Split;
      // The ring's view of it: where an obstacle ends (reflex) the nearest obstacle point,
      // the ring's minimum, should lie behind. Counted, not trusted: near another obstacle
      // (a passage barely 2r wide) or beside a sharp tip the minimum points elsewhere.
      if (!convex) {
        bool behind = false;
        for (std::size_t i = first; i <= last; ++i) behind = behind || along[i] < 0;
        if (!behind) ++ring_disagreements_;
      }
      std::sort(cp.run.begin(), cp.run.end(), [](const Stand& u, const Stand& v) { return u.p.y() < v.p.y(); });
      R_.retrace_to(out.stands[last].p, out.stands[last].c, Move::Follow);
      out.stands.pop_back();
      cp.path_index = R_.path().size() - 1;
      out.cp = std::move(cp);
      return out;
    }
  }

  // Drive back along stands from the last to stand k.
  void back_along(const std::vector<Stand>& st, std::size_t k) {
    for (std::size_t i = st.size() - 1; i-- > k;) R_.retrace_to(st[i].p, st[i].c, Move::Transit);
  }
  // Drive along a run (bottom to top, or the reverse) from where the robot is on it.
  void along_run(const std::vector<Stand>& run, bool to_top) {
    std::size_t k = 0;
    while (k < run.size() && run[k].p != R_.odometry()) ++k;
    if (k == run.size()) throw Failure{"the robot is not on the critical point's run"};
    if (to_top)
      for (std::size_t i = k + 1; i < run.size(); ++i) R_.retrace_to(run[i].p, run[i].c, Move::Transit);
    else
      for (std::size_t i = k; i-- > 0;) R_.retrace_to(run[i].p, run[i].c, Move::Transit);
  }

  bool lap(bool up) {
    tick();
    if (!R_.lap(up)) return false;
    ++laps_;
    return true;
  }

  // --- the incremental Reeb graph ---------------------------------------------------------
  std::uint32_t node_for(const Sensed& s) {
    const double y0 = s.lo().p.y(), y1 = s.hi().p.y();
    for (std::uint32_t i = 0; i < nodes_.size(); ++i) {
      const OnlineNode& n = nodes_[i];
      if (n.kind != s.kind || n.x != s.x()) continue;
      if (y0 <= n.y_high + tol_ && n.y_low <= y1 + tol_) {
        order_.push_back(i);
        return i;
      }
    }
    OnlineNode n;
    n.kind = s.kind;
    n.x = s.x(), n.y_low = y0, n.y_high = y1;
    n.sensed_at = s.path_index;
    n.ports.assign(s.kind == OnlineKind::Birth || s.kind == OnlineKind::Death ? 1 : 3, -1);
    nodes_.push_back(n);
    runs_.push_back(s.run);
    order_.push_back(static_cast<std::uint32_t>(nodes_.size() - 1));
    return static_cast<std::uint32_t>(nodes_.size() - 1);
  }

  // --- transit over what the robot has driven ----------------------------------------------
  void sync_graph() {
    const auto& P = R_.path();
    for (; synced_ < P.size(); ++synced_) {
      const auto key = std::make_pair(P[synced_].p.x(), P[synced_].p.y());
      auto [it, fresh] = ids_.emplace(key, static_cast<std::uint32_t>(gpts_.size()));
      if (fresh) {
        Contact c;
        if (P[synced_].vertex != CellChains::kNoVertex) c.vertex = P[synced_].vertex;
        else if (P[synced_].edge != CellChains::kNoVertex) c.edge = P[synced_].edge;
        gpts_.push_back({P[synced_].p, c}), adj_.emplace_back();
      }
      if (synced_ > 0) {
        const std::uint32_t a = ids_.at({P[synced_ - 1].p.x(), P[synced_ - 1].p.y()}), b = it->second;
        if (a != b) {
          const double len = std::hypot(P[synced_].p.x() - P[synced_ - 1].p.x(), P[synced_].p.y() - P[synced_ - 1].p.y());
          adj_[a].emplace_back(b, len), adj_[b].emplace_back(a, len);
        }
      }
    }
  }
  // Shortest distances over the driven graph from the robot, and the predecessors.
  void dijkstra(std::vector<double>& dist, std::vector<std::uint32_t>& pred) {
    sync_graph();
    dist.assign(gpts_.size(), INFINITY), pred.assign(gpts_.size(), UINT32_MAX);
    const std::uint32_t src = ids_.at({R_.odometry().x(), R_.odometry().y()});
    using QE = std::pair<double, std::uint32_t>;
    std::priority_queue<QE, std::vector<QE>, std::greater<>> q;
    dist[src] = 0, q.emplace(0, src);
    while (!q.empty()) {
      auto [d, u] = q.top();
      q.pop();
      if (d > dist[u]) continue;
      for (auto [v, l] : adj_[u])
        if (d + l < dist[v]) dist[v] = d + l, pred[v] = u, q.emplace(dist[v], v);
    }
  }
  double distance_to(const std::vector<double>& dist, const Point& p) const {
    auto it = ids_.find({p.x(), p.y()});
    return it == ids_.end() ? INFINITY : dist[it->second];
  }
  void transit(const std::vector<std::uint32_t>& pred, const Point& p) {
    const auto it = ids_.find({p.x(), p.y()});
    if (it == ids_.end()) throw Failure{"no driven path to " + at_text(p)};
    std::vector<std::uint32_t> chain;
    for (std::uint32_t v = it->second; v != UINT32_MAX; v = pred[v]) chain.push_back(v);
    for (auto k = chain.rbegin(); k != chain.rend(); ++k) R_.retrace_to(gpts_[*k].p, gpts_[*k].c, Move::Transit);
  }

  // --- covering a cell --------------------------------------------------------------------
  struct Closing {
    Sensed cp;
    PortSide ps = PortSide::Point;
  };

  // Cover the cell leaving node `from` through `port` (the robot stands at the port's
  // anchor); returns its closing critical point.
  //
  // The cell is swept strip by strip. The strip from the last lap (slice x0, floor point F0,
  // ceiling point C0, the bridge between them driven) towards x0 + d w is explored so that
  // the *first* critical point along the sweep is the one that closes the cell, however
  // many the strip holds:
  //  1. forward phase on the floor: follow it from F0 to the target slice; a critical point
  //     sensed there moves the target to its slice;
  //  2. back to F0, across the bridge to C0, and the same on the ceiling (the reverse
  //     phase's boundary following, driven forward): its critical point moves the target
  //     again if it comes first;
  //  3. closing phase on the target slice: lap from the ceiling towards the floor. Arriving
  //     where the floor crosses the slice (odometry) proves the strip clear: the chains are
  //     monotone and an obstacle starting inside the strip would still cross the target
  //     slice (every obstacle of the configuration space is wider than 2r >= w). Hitting an
  //     obstacle instead: follow it back against the sweep to its first point, a critical
  //     point nearer than the target, which becomes the target; then lap from there both
  //     ways, again until both laps arrive on the chains.
  // Each step moves the target strictly back, so this ends; the target's critical point
  // (if any) closes the cell. Otherwise the lap across the target slice is the next lap.
  Closing cover_cell(std::uint32_t from, int port) {
    bool right = false;
    PortSide ps = PortSide::Point;
    port_of(nodes_[from].kind, port, right, ps);
    const int d = right ? 1 : -1;
    const std::vector<Stand> run = runs_[from];
    auto blocked = [&](const char* what) {
      return Failure{std::string("a lap ").append(what).append(" from ").append(at_text(R_.odometry())).append(" is blocked")};
    };
    // The first lap: the bridge from the floor's start to the ceiling's, as driven.
    std::vector<Stand> bridge;
    switch (ps) {
      case PortSide::Point: bridge = run; break;
      case PortSide::Up: {
        const Stand h = R_.odometry() == run.back().p ? run.back() : run.front();
        if (!lap(true)) throw blocked("up from a critical point");
        bridge = {h, here()};
        break;
      }
      case PortSide::Down: {
        const Stand l = R_.odometry() == run.front().p ? run.front() : run.back();
        if (!lap(false)) throw blocked("down from a critical point");
        bridge = {here(), l};
        break;
      }
      case PortSide::Both: {
        along_run(run, true);
        if (!lap(true)) throw blocked("up through a critical point");
        const Stand top = here();
        R_.retrace_to(run.back().p, run.back().c, Move::Transit);
        along_run(run, false);
        if (!lap(false)) throw blocked("down through a critical point");
        bridge.push_back(here());
        bridge.insert(bridge.end(), run.begin(), run.end());
        bridge.push_back(top);
        break;
      }
    }
    // To the floor's start.
    if (R_.odometry() != bridge.front().p) {
      std::size_t k = 0;
      while (k < bridge.size() && bridge[k].p != R_.odometry()) ++k;
      if (k == bridge.size()) throw Failure{"the robot lost the first lap of a cell"};
      for (std::size_t i = k; i-- > 0;) R_.retrace_to(bridge[i].p, bridge[i].c, Move::Transit);
    }
    const OnlineKind between_kind = d > 0 ? OnlineKind::Split : OnlineKind::Merge;  // an obstacle starts
    if (!o_.cycle) return raster(bridge, d);
    for (;;) {
      const double x0 = bridge.front().p.x();
      double xt = x0 + d * w_;
      std::optional<Sensed> target;  // the critical point on the target slice
      PortSide tps = PortSide::Point;
      auto sooner = [&](const Sensed& cp, PortSide side) {
        if (target) node_for(*target);  // passed over: a critical point of another cell
        xt = cp.x(), target = cp;
        tps = (cp.kind == OnlineKind::Birth || cp.kind == OnlineKind::Death) ? PortSide::Point : side;
      };
      // 1. The floor.
      Follow F = follow(Side::Floor, d, xt);
      if (F.cp) sooner(*F.cp, PortSide::Up);
      // 2. Back, across, the ceiling.
      back_along(F.stands, 0);
      if (F.cp) R_.retrace_to(F.stands.front().p, F.stands.front().c, Move::Transit);
      for (std::size_t i = 1; i < bridge.size(); ++i) R_.retrace_to(bridge[i].p, bridge[i].c, Move::Transit);
      Follow C = follow(Side::Ceiling, d, xt);
      if (C.cp) {
        if (target && C.cp->x() == xt) {
          // The same slice: the death where floor and ceiling meet, or a degenerate pair.
          if (target->kind != C.cp->kind || C.cp->lo().p.y() > target->hi().p.y() + tol_)
            throw Failure{"two critical points on one slice at x = " + geometry::format_number(xt) + " in one cell"};
        } else {
          if (target && d * C.cp->x() > d * xt) throw Failure{"the ceiling turned back beyond the target slice"};
          sooner(*C.cp, PortSide::Down);
        }
      }
      // 3. Across the target slice, towards the side the target's critical point is on (from
      // the ceiling when it is on the floor or there is none).
      const bool from_floor = target && C.cp && target->x() == C.cp->x();
      const bool point_kind = target && (target->kind == OnlineKind::Birth || target->kind == OnlineKind::Death);
      if (from_floor) {
        // Back to the floor, and along it to the target slice again.
        back_along(C.stands, 0);
        for (std::size_t i = bridge.size() - 1; i-- > 0;) R_.retrace_to(bridge[i].p, bridge[i].c, Move::Transit);
        const Follow F2 = follow(Side::Floor, d, xt);
        if (F2.cp) throw Failure{"the floor turned back where it did not before"};
      }
      const Stand lap_from = here();
      if (point_kind)
        for (const Stand& st : target->run)
          if (st.p == lap_from.p) return {*target, PortSide::Point};  // floor and ceiling meet there
      const double expect = !target ? F.y_at(xt) : from_floor ? target->lo().p.y() : target->hi().p.y();
      if (!lap(from_floor)) {
        // Against a point where floor and ceiling meet: the strip closes there.
        bool on_run = false;
        if (point_kind)
          for (const Stand& st : target->run) on_run = on_run || st.p == lap_from.p;
        if (on_run) return {*target, PortSide::Point};
        throw blocked("across the cell");
      }
      const Stand lap_to = here();
      if (std::fabs(lap_to.p.y() - expect) <= tol_) {
        if (target) return {*target, tps};
        // The strip is clear: the lap across the target slice is the next lap.
        bridge = {lap_to, lap_from};
        continue;
      }
      if (from_floor ? !(lap_to.p.y() < expect) : !(lap_to.p.y() > expect))
        throw Failure{"a lap across the cell from " + at_text(lap_from.p) + " went through the other side"};
      const Stand floor_pt = lap_to;
      // An obstacle between: back against the sweep along its top to where it starts, then
      // lap from there both ways until both laps arrive on the chains.
      Stand from_pt = floor_pt;
      bool towards_floor = !from_floor;  // the lap that hit the obstacle went down
      for (;;) {
        const Follow O = follow(towards_floor ? Side::Floor : Side::Ceiling, -d, x0);
        if (!O.cp) throw Failure{"an obstacle met in a strip at " + at_text(from_pt.p) + " does not start inside the strip"};
        if (O.cp->kind != between_kind)
          throw Failure{std::string("an obstacle met in a strip starts at a ").append(to_string(O.cp->kind)).append(" critical point")};
        sooner(*O.cp, PortSide::Both);
        tps = PortSide::Both;
        // Down from its bottom to the floor.
        along_run(target->run, false);
        if (!lap(false)) throw blocked("down from an obstacle's first point");
        if (std::fabs(R_.odometry().y() - F.y_at(xt)) > tol_) {
          if (!(R_.odometry().y() > F.y_at(xt))) throw Failure{"a lap down at " + at_text(R_.odometry()) + " went below the floor"};
          from_pt = here(), towards_floor = true;
          continue;
        }
        R_.retrace_to(target->lo().p, target->lo().c, Move::Transit);
        along_run(target->run, true);
        if (!lap(true)) throw blocked("up from an obstacle's first point");
        if (std::fabs(R_.odometry().y() - C.y_at(xt)) > tol_) {
          if (!(R_.odometry().y() < C.y_at(xt))) throw Failure{"a lap up at " + at_text(R_.odometry()) + " went above the ceiling"};
          from_pt = here(), towards_floor = false;
          continue;
        }
        return {*target, PortSide::Both};
      }
    }
  }

  // Without the cycle algorithm: a plain raster scan. Follow the side the last lap ended on
  // forward one lap width, lap across, and on; a critical point on the followed side closes
  // the cell. The other side is never followed, so its critical points go unseen (Fig. 6.22).
  Closing raster(std::vector<Stand> bridge, int d) {
    Side s = Side::Floor;
    for (;;) {
      const Follow f = follow(s, d, bridge.front().p.x() + d * w_);
      if (f.cp) return {*f.cp, (f.cp->kind == OnlineKind::Birth || f.cp->kind == OnlineKind::Death) ? PortSide::Point
                                : s == Side::Floor                                                  ? PortSide::Up
                                                                                                    : PortSide::Down};
      if (!lap(s == Side::Floor)) throw Failure{"a lap across the cell from " + at_text(R_.odometry()) + " is blocked"};
      bridge = {here()};
      s = s == Side::Floor ? Side::Ceiling : Side::Floor;
    }
  }

  // --- the exploration --------------------------------------------------------------------
  void explore() {
    // Find a first critical point: down to the floor, then follow it backwards (-x) to the
    // boundary's first turn.
    if (!lap(false)) throw Failure{"the robot cannot lap down from its start"};
    const Follow f = follow(Side::Floor, -1, -INFINITY);
    if (!f.cp) throw Failure{"no critical point found from the start"};
    node_for(*f.cp);
    for (;;) {
      std::vector<double> dist;
      std::vector<std::uint32_t> pred;
      dijkstra(dist, pred);
      double best = INFINITY;
      std::uint32_t bn = 0;
      int bp = -1;
      for (std::uint32_t i = 0; i < nodes_.size(); ++i)
        for (int p = 0; p < static_cast<int>(nodes_[i].ports.size()); ++p) {
          if (nodes_[i].ports[p] >= 0) continue;
          const double dd = distance_to(dist, anchor(i, p).p);
          if (dd < best) best = dd, bn = i, bp = p;
        }
      if (bp < 0) {
        for (const auto& n : nodes_)
          for (int p : n.ports)
            if (p < 0) throw Failure{"a critical point with an unexplored port cannot be reached over the driven path"};
        return;
      }
      bool right = false;
      PortSide ps = PortSide::Point;
      port_of(nodes_[bn].kind, bp, right, ps);
      transit(pred, anchor(bn, bp).p);
      const std::size_t begin = R_.path().size() - 1;
      const std::size_t laps0 = laps_;
      const Closing c = cover_cell(bn, bp);
      const std::uint32_t to = node_for(c.cp);
      const int tp = port_index(nodes_[to].kind, !right, c.ps);
      if (tp < 0) throw Failure{"the closing critical point of a cell has no port for it"};
      if (nodes_[to].ports[tp] >= 0)
        throw Failure{"cell from critical point " + std::to_string(bn) + " closes at critical point " + std::to_string(to) +
                      " through a port already explored"};
      if (to == bn && tp == bp) throw Failure{"a cell closes at its own port"};
      const int e = static_cast<int>(edges_.size());
      edges_.push_back({bn, to, laps_ - laps0, begin, R_.path().size() - 1});
      nodes_[bn].ports[bp] = e, nodes_[to].ports[tp] = e;
    }
  }
  // Where a cell through a port starts: the run's top for the upper cells, else its bottom.
  const Stand& anchor(std::uint32_t node, int port) const {
    bool right = false;
    PortSide ps = PortSide::Point;
    port_of(nodes_[node].kind, port, right, ps);
    return ps == PortSide::Up ? runs_[node].back() : runs_[node].front();
  }

  OnlineRobot& R_;
  const OnlineOptions& o_;
  double w_;
  std::size_t budget_, steps_ = 0, laps_ = 0, ring_disagreements_ = 0;
  double tol_;  // odometry comparisons: a lap arrives on a chain it was estimated to reach
  std::vector<OnlineNode> nodes_;
  std::vector<std::vector<Stand>> runs_;
  std::vector<OnlineEdge> edges_;
  std::vector<std::uint32_t> order_;
  // the driven graph
  std::map<std::pair<double, double>, std::uint32_t> ids_;
  std::vector<Stand> gpts_;
  std::vector<std::vector<std::pair<std::uint32_t, double>>> adj_;
  std::size_t synced_ = 0;
};

// A start inside the component: the middle of the first free stretch of a vertical line.
std::optional<Point> default_start(const Environment& Q) {
  const auto box = Q.bbox();
  for (int k = 1; k < 16; ++k) {
    const double x = box.xmin() + (box.xmax() - box.xmin()) * (k % 2 ? 0.5 + k / 32.0 : 0.5 - k / 32.0);
    const geometry::ExactPoint from(x, box.ymin() - 1);
    const auto h1 = geometry::shoot_ray(Q, from, geometry::ExactKernel::Vector_2(0, 1));
    if (!h1 || h1->along_edge) continue;
    const auto h2 = geometry::shoot_ray(Q, h1->point, geometry::ExactKernel::Vector_2(0, 1));
    if (!h2) continue;
    const Point mid(x, CGAL::to_double((h1->point.y() + h2->point.y()) / 2));
    if (geometry::locate(Q, mid).kind == geometry::Location::Kind::Interior) return mid;
  }
  return std::nullopt;
}

Environment rotate_workspace(const Environment& env, const BoustrophedonDecomposition& b) {
  std::vector<geometry::Ring> rings;
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    geometry::Ring ring = env.ring(r);
    for (Point& p : ring) p = b.to_sweep(p);
    rings.push_back(std::move(ring));
  }
  geometry::Ring outer = std::move(rings.front());
  rings.erase(rings.begin());
  return Environment::make(std::move(outer), std::move(rings));
}

}  // namespace

double online_tolerance(const OnlineReport& rep) {
  return std::max(rep.robot_radius * std::sin(rep.resolution), 1e-9 * (1 + rep.width));
}

OnlineReport plan_online_coverage(const Environment& env, const OnlineOptions& o) {
  const double r = o.robot_radius;
  if (!(r > 0) || !std::isfinite(r)) throw InputError("--radius: online coverage needs a robot radius > 0");
  const double w = o.width > 0 ? o.width : 2 * r;
  if (!(o.width >= 0) || !std::isfinite(o.width) || w > 2 * r)
    throw InputError("--width " + geometry::format_number(o.width) + ": online coverage needs 0 < w <= 2r = " + geometry::format_number(2 * r) +
                     " (a wider tool could pass an obstacle between two laps unseen)");
  if (o.sensors < 8 || o.sensors % 4 != 0 || o.sensors > 4096)
    throw InputError("--sensors " + std::to_string(o.sensors) + ": the ring needs a multiple of 4 sensors, 8 to 4096");
  const double range = o.range > 0 ? o.range : 10 * r;
  if (!(range > r) || !std::isfinite(range)) throw InputError("--range " + geometry::format_number(o.range) + ": the sensors' range must exceed the robot radius");
  if (!(o.noise >= 0) || !std::isfinite(o.noise)) throw InputError("--noise " + geometry::format_number(o.noise) + ": must be a finite number >= 0");
  if (!std::isfinite(o.angle_deg)) throw InputError("--angle: must be a finite number of degrees");
  {
    const auto box = env.bbox();
    if (std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin()) / w > kMaxLapsAcross)
      throw InputError("--width " + geometry::format_number(w) + ": too narrow for this environment (more than 1e5 laps across)");
  }
  const geometry::ConfigurationSpace cs(env, r);
  if (cs.components().empty()) throw InputError("a robot of radius " + geometry::format_number(r) + " fits nowhere in this environment");
  std::size_t comp = 0;
  if (o.start) {
    if (!cs.admits(*o.start))
      throw InputError("start " + geometry::format_point(*o.start) + ": a robot of radius " + geometry::format_number(r) + " does not fit there");
    const auto c = cs.component_of(*o.start);
    if (!c) throw InputError("start " + geometry::format_point(*o.start) + " is too close to the configuration space's boundary: move it inwards");
    comp = *c;
  }
  const Environment& E = cs.components()[comp];
  if (E.has_contacts()) throw InputError("online coverage: the configuration space touches itself at a point; use another radius");
  const BoustrophedonDecomposition b(E, o.angle_deg);
  const Environment& Q = b.sweep_environment();
  const Environment W = rotate_workspace(env, b);
  std::optional<Point> start;
  if (o.start) {
    start = b.to_sweep(*o.start);
    if (geometry::locate(Q, *start).kind != geometry::Location::Kind::Interior)
      throw InputError("start " + geometry::format_point(*o.start) + " is on the configuration space's boundary: move it inwards");
  } else {
    start = default_start(Q);
    if (!start) throw InputError("online coverage: found no start inside the configuration space");
  }
  OnlineOptions opts = o;
  opts.range = range;
  OnlineRobot robot(Q, W, opts, *start);
  const auto box = Q.bbox();
  const double area_laps = (box.xmax() - box.xmin()) * (box.ymax() - box.ymin()) / (w * w);
  const std::size_t budget = o.max_steps ? o.max_steps : static_cast<std::size_t>(200 * (area_laps + static_cast<double>(Q.num_vertices())) + 10000);
  OnlineReport rep;
  OnlinePlanner planner(robot, opts, w, budget);
  planner.run(rep);
  rep.angle = o.angle_deg, rep.width = w, rep.robot_radius = r, rep.range = range, rep.noise = o.noise;
  rep.sensors = o.sensors, rep.readings = robot.readings();
  rep.resolution = std::numbers::pi / static_cast<double>(o.sensors);
  rep.target_area = E.area();

  // Back to the input frame, segment by segment (indices of nodes and edges follow), and
  // certified like every coverage path.
  const geometry::VisibilityIndex index(E);
  const geometry::VisibilityGraph graph(index);
  std::optional<geometry::VisibilityIndex> sweep_index;
  if (std::fmod(o.angle_deg, 90.0) != 0) sweep_index.emplace(Q);
  const auto& sp = robot.path();
  std::vector<std::size_t> where(sp.size(), 0);
  detail::Polyline path;
  for (std::size_t i = 0; i < sp.size(); ++i) {
    std::vector<SweepPoint> seg;
    if (i > 0) seg.push_back(sp[i - 1]);
    seg.push_back(sp[i]);
    const detail::Polyline part = detail::to_input_frame(b, E, seg, index, graph, sweep_index ? &*sweep_index : nullptr);
    for (std::size_t k = i > 0 ? 1 : 0; k < part.points.size(); ++k) path.append(part.points[k], k > 0 ? part.moves[k - 1] : Move::Transit);
    where[i] = path.points.empty() ? 0 : path.points.size() - 1;
  }
  CoverageOptions co;
  co.robot_radius = r, co.width = w;
  const detail::Planning P{env, cs, E, index, graph, co, w, std::nullopt};
  CoverageReport cr;
  detail::finish_path(P, std::move(path), cr);
  rep.path = std::move(cr.path), rep.moves = std::move(cr.moves);
  rep.length = cr.length, rep.transit_length = cr.transit_length;
  for (auto& n : rep.nodes) {
    n.sensed_at = where[std::min(n.sensed_at, where.size() - 1)];
    n.at = b.to_input(Point(n.x, (n.y_low + n.y_high) / 2));
  }
  for (auto& e : rep.edges) e.path_begin = where[e.path_begin], e.path_end = where[e.path_end];
  return rep;
}

OnlineComparison compare_with_offline(const BoustrophedonDecomposition& off, const OnlineReport& rep, double tol) {
  OnlineComparison c;
  const auto& S = off.critical_slices();
  const auto& C = off.cells();
  c.offline_nodes = S.size(), c.offline_edges = C.size();
  c.offline_of.assign(rep.nodes.size(), -1);
  std::vector<int> online_of(S.size(), -1);
  for (std::size_t i = 0; i < rep.nodes.size(); ++i) {
    const OnlineNode& n = rep.nodes[i];
    double best = INFINITY;
    int bj = -1;
    for (std::size_t j = 0; j < S.size(); ++j) {
      const double lo = CGAL::to_double(S[j].y_low), hi = CGAL::to_double(S[j].y_high);
      const double dy = std::max({0.0, lo - n.y_high, n.y_low - hi});
      const double dd = std::hypot(n.x - S[j].x, dy);
      if (dd < best) best = dd, bj = static_cast<int>(j);
    }
    if (bj < 0 || best > tol) {
      c.detail = "sensed " + std::string(to_string(n.kind)) + " critical point " + std::to_string(i) + " at (" +
                 geometry::format_number(n.x) + ", " + geometry::format_number(n.y_low) + ") (sweep frame) matches no offline critical slice";
      return c;
    }
    if (online_of[bj] >= 0) {
      c.detail = "sensed critical points " + std::to_string(online_of[bj]) + " and " + std::to_string(i) + " match the same offline critical slice";
      return c;
    }
    online_of[bj] = static_cast<int>(i), c.offline_of[i] = bj;
    c.max_offset = std::max(c.max_offset, best);
  }
  for (std::size_t j = 0; j < S.size(); ++j)
    if (online_of[j] < 0) {
      c.detail = "offline critical slice " + std::to_string(j) + " at x = " + geometry::format_number(S[j].x) + " (sweep frame) was never sensed";
      return c;
    }
  std::multiset<std::pair<int, int>> a, z;
  for (const auto& e : rep.edges) {
    const int u = c.offline_of[e.from], v = c.offline_of[e.to];
    a.emplace(std::min(u, v), std::max(u, v));
  }
  for (const auto& cell : C) z.emplace(std::min<int>(cell.left_slice, cell.right_slice), std::max<int>(cell.left_slice, cell.right_slice));
  if (a != z) {
    c.detail = "the cells differ: " + std::to_string(rep.edges.size()) + " online, " + std::to_string(C.size()) + " offline";
    for (const auto& p : z)
      if (!a.count(p)) {
        c.detail += "; offline cell between critical slices " + std::to_string(p.first) + " and " + std::to_string(p.second) + " missing online";
        break;
      }
    return c;
  }
  c.isomorphic = true;
  return c;
}

OnlineComparison compare_with_offline(const Environment& env, const OnlineReport& rep, double tol) {
  const geometry::ConfigurationSpace cs(env, rep.robot_radius);
  std::size_t comp = 0;
  if (!rep.path.empty())
    if (const auto k = cs.component_of(rep.path.front())) comp = *k;
  if (cs.components().empty()) return {};
  const BoustrophedonDecomposition b(cs.components()[comp], rep.angle);
  return compare_with_offline(b, rep, tol);
}

}  // namespace preimage::decompose
