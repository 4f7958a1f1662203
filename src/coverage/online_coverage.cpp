// SPDX-License-Identifier: Apache-2.0
// Online coverage: the planner of 6.2.4 (critical point sensing, the cycle algorithm, the
// incremental Reeb graph) driving the simulated robot of online_robot.hpp.
#include <preimage/coverage/online_coverage.hpp>
#include <preimage/geometry/clearance.hpp>
#include <preimage/geometry/local_frame.hpp>

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

namespace preimage::coverage {

std::string_view to_string(OnlineKind k) {
  switch (k) {
    case OnlineKind::Birth: return "birth";
    case OnlineKind::Death: return "death";
    case OnlineKind::Split: return "split";
    case OnlineKind::Merge: return "merge";
    case OnlineKind::Slice: return "slice";
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
// (one point, or a vertical wall), bottom to top. The kind is the critical point's own (the
// turn the boundary makes there); the node it belongs to is the surveyed piece of its slice.
struct Sensed {
  OnlineKind kind;
  std::vector<Stand> run;
  std::size_t path_index = 0;
  double x() const { return run.front().p.x(); }
  const Stand& lo() const { return run.front(); }
  const Stand& hi() const { return run.back(); }
};

// A boundary follow: every point driven (the start first), and the critical point where the
// lateral displacement turned back, if it did before the stop slice or on it.
struct Follow {
  std::vector<Stand> stands;
  std::optional<Sensed> cp;
  // Where a lap across the cell along the slice x meets this chain: where the chain runs
  // along the slice (a wall, or a vertex on it) its highest point for a floor and lowest for
  // a ceiling, else by interpolation of the odometry (the planner's own estimate, compared
  // with a stated tolerance).
  double y_at(double x, bool floor) const {
    bool on = false;
    double best = 0;
    for (const Stand& s : stands)
      if (s.p.x() == x) best = !on ? s.p.y() : floor ? std::max(best, s.p.y()) : std::min(best, s.p.y()), on = true;
    if (on) return best;
    for (std::size_t i = 1; i < stands.size(); ++i) {
      const Point &a = stands[i - 1].p, &b = stands[i].p;
      if ((a.x() <= x && x <= b.x()) || (b.x() <= x && x <= a.x())) return a.y() + (x - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
    }
    return NAN;
  }
};

// Which side of a closing critical point a cell is on: the critical point's own interval
// (birth, death), above it (on the floor), below it (on the ceiling), or around it (an
// obstacle starting between the floor and the ceiling).
enum class PortSide : std::uint8_t { Point, Up, Down, Both };

// A surveyed piece of a critical slice: the stops the robot made along it, bottom to top,
// what lies between consecutive stops, and the ports.
struct Piece {
  std::vector<Stand> stops;
  // Per gap between stops i and i + 1: 0 free on both sides (a lap), +1 a wall with its
  // obstacle towards +x, -1 towards -x.
  std::vector<int> gap;
  struct Port {
    bool right;
    std::size_t lo, hi;  // stop indices: the cell's floor and ceiling on the slice
  };
  std::vector<Port> ports;  // as OnlineNode::ports: the left ones, then the right ones, each bottom to top
};

struct Failure {
  std::string what;
};

std::string at_text(const Point& p) { return geometry::format_point(p); }
bool point_kind(OnlineKind k) { return k == OnlineKind::Birth || k == OnlineKind::Death; }

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
  // or reflex, so an obstacle ends). Arriving on the stop slice at a vertex, the robot drives
  // on (along the slice while the boundary runs along it, then one step) to see whether the
  // boundary turns back there, and if not returns to the chain's point on the slice that
  // faces the cell. `start_kind`: the robot starts where a lap across free space met the
  // boundary, so a boundary that turns back at once there is a critical point of that kind
  // (an obstacle's first point along the follow); otherwise that is an inconsistency.
  Follow follow(Side s, int delta, double stop_x, std::optional<OnlineKind> start_kind = std::nullopt) {
    Follow out;
    const int dir = s == Side::Floor ? delta : -delta;  // +1: the ring order, free space on the left
    out.stands.push_back(here());
    std::vector<double> along{0};
    double best = delta * R_.odometry().x();
    auto step = [&](double stop, bool& on_slice) {
      tick();
      if (!R_.follow_step(dir, stop, on_slice)) throw Failure{"boundary following started away from the boundary at " + at_text(R_.odometry())};
      out.stands.push_back(here());
      // The surface normal's component along the follow (the ring's minimum; sensor 0
      // looks along +x).
      const auto ring = R_.read_ring();
      along.push_back(delta * std::cos(R_.sensor_angle(ring.argmin)));
    };
    // The boundary turned back after the run first..last (the robot one step beyond it).
    auto sensed = [&](std::size_t first, std::size_t last) {
      Sensed cp;
      cp.run.assign(out.stands.begin() + static_cast<std::ptrdiff_t>(first), out.stands.begin() + static_cast<std::ptrdiff_t>(last) + 1);
      bool convex;
      if (first == 0) {
        if (!start_kind) throw Failure{"the boundary turns back at once from " + at_text(out.stands[0].p)};
        cp.kind = *start_kind;
        convex = point_kind(cp.kind);
      } else {
        const int turn = geometry::orientation(out.stands[first - 1].p, out.stands[first].p,
                                               first != last ? out.stands[last].p : out.stands[last + 1].p);
        convex = turn * dir > 0;  // free space on the inside of the turn
        if (delta > 0) cp.kind = convex ? OnlineKind::Death : OnlineKind::Merge;
        else cp.kind = convex ? OnlineKind::Birth : OnlineKind::Split;
      }
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
    };
    for (;;) {
      bool on_slice = false;
      step(stop_x, on_slice);
      if (on_slice) {
        if (R_.contact().vertex == Contact::kNone) return out;  // inside an edge: the chain crosses the slice
        const std::size_t first = out.stands.size() - 1;
        bool dummy = false;
        do step(NAN, dummy);
        while (R_.odometry().x() == stop_x);
        const std::size_t last = out.stands.size() - 2;
        if (delta * R_.odometry().x() < delta * stop_x) {
          sensed(first, last);
          return out;
        }
        // On beyond the slice: back to the chain's point on it that faces the cell.
        std::size_t k = first;
        for (std::size_t i = first; i <= last; ++i)
          if (s == Side::Floor ? out.stands[i].p.y() > out.stands[k].p.y() : out.stands[i].p.y() < out.stands[k].p.y()) k = i;
        for (std::size_t i = out.stands.size() - 1; i-- > k;) R_.retrace_to(out.stands[i].p, out.stands[i].c, Move::Follow);
        out.stands.resize(k + 1);
        return out;
      }
      const double x = delta * R_.odometry().x();
      if (x >= best) {
        best = x;
        continue;
      }
      // Turned back: the run of extreme abscissa ends at the previous point.
      const std::size_t last = out.stands.size() - 2;
      std::size_t first = last;
      while (first > 0 && out.stands[first - 1].p.x() == out.stands[last].p.x()) --first;
      sensed(first, last);
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
  bool wall_lap(bool up, bool& obstacle_right) {
    tick();
    if (!R_.wall_lap(up, obstacle_right)) return false;
    ++laps_;
    return true;
  }

  // --- the incremental Reeb graph ---------------------------------------------------------
  // The node of the piece of the critical slice holding a sensed critical point: a known one,
  // or a new one the robot surveys.
  std::uint32_t node_for(const Sensed& s) {
    for (std::uint32_t i = 0; i < nodes_.size(); ++i) {
      const OnlineNode& n = nodes_[i];
      if (n.x == s.x() && n.y_low <= s.lo().p.y() && s.hi().p.y() <= n.y_high) {
        order_.push_back(i);
        return i;
      }
    }
    return survey(s);
  }

  // Survey the piece of the slice through a sensed critical point: from the top of its run,
  // lap up along the slice (sliding along walls that run along it) until the boundary
  // crosses the slice; the same downwards from its bottom. Between two laps the robot
  // stopped at a boundary point that touches the slice from one side; which side, a short
  // boundary follow tells (its lateral displacement). Walls tell their side by contact, and
  // the run's by the critical point's kind. Then the ports: per side, the maximal stretches
  // of the piece free on that side, split where the obstacle touches from that side.
  std::uint32_t survey(const Sensed& cp) {
    goto_driven(cp.hi().p);
    const double c = cp.x();
    // The run's obstacle: a death or split lies on +x of its run, a birth or merge on -x.
    const int run_side = cp.kind == OnlineKind::Death || cp.kind == OnlineKind::Split ? 1 : -1;
    std::vector<Stand> above, below;
    std::vector<int> gap_above, gap_below;
    for (int pass = 0; pass < 2; ++pass) {
      const bool up = pass == 0;
      auto& st = up ? above : below;
      auto& gp = up ? gap_above : gap_below;
      if (!up) {
        for (std::size_t i = above.size(); i-- > 0;) R_.retrace_to(i > 0 ? above[i - 1].p : cp.hi().p, i > 0 ? above[i - 1].c : cp.hi().c, Move::Transit);
        along_run(cp.run, false);
      }
      for (;;) {
        bool right = false;
        // Stopped inside an edge, the boundary crosses the slice there: the piece ends.
        if (R_.contact().vertex == Contact::kNone && R_.contact().edge != Contact::kNone) break;
        if (wall_lap(up, right)) gp.push_back(right ? 1 : -1);
        else if (lap(up)) gp.push_back(0);
        else break;
        st.push_back(here());
        if (R_.odometry().x() != c) throw Failure{"a lap along the slice left it"};
      }
    }
    Piece pc;
    for (std::size_t i = below.size(); i-- > 0;) pc.stops.push_back(below[i]), pc.gap.push_back(gap_below[i]);
    for (std::size_t i = 0; i < cp.run.size(); ++i) {
      pc.stops.push_back(cp.run[i]);
      if (i > 0) pc.gap.push_back(run_side);
    }
    pc.gap.insert(pc.gap.end(), gap_above.begin(), gap_above.end());
    pc.stops.insert(pc.stops.end(), above.begin(), above.end());
    const std::size_t m = pc.stops.size() - 1;
    // Per stop, the side its obstacle touches the slice from (0: an end of the piece).
    std::vector<int> touch(m + 1, 0);
    for (std::size_t g = 0; g < m; ++g)
      if (pc.gap[g] != 0) touch[g] = touch[g + 1] = pc.gap[g];
    if (cp.run.size() == 1) touch[below.size()] = run_side;
    for (std::size_t i = 1; i < m; ++i) {
      if (touch[i] != 0) continue;
      // Between two laps: a boundary point touching the slice; follow it a short way.
      goto_driven(pc.stops[i].p);
      tick();
      bool on = false;
      if (!R_.follow_step(1, c - w_ / 2, on, c + w_ / 2) || R_.odometry().x() == c)
        throw Failure{"a boundary point where the slice goes on at " + at_text(pc.stops[i].p) + " does not touch it from one side"};
      touch[i] = R_.odometry().x() > c ? 1 : -1;
      R_.retrace_to(pc.stops[i].p, pc.stops[i].c, Move::Transit);
    }
    if (m == 0) {
      if (!point_kind(cp.kind))
        throw Failure{std::string("the slice through a ").append(to_string(cp.kind)).append(" critical point at ").append(at_text(cp.lo().p)).append(" is a single point")};
      pc.ports.push_back({cp.kind == OnlineKind::Birth, 0, 0});
    } else {
      for (int side : {-1, 1}) {
        constexpr std::size_t kClosed = SIZE_MAX;
        std::size_t open = kClosed;
        for (std::size_t g = 0; g < m; ++g) {
          const bool free = pc.gap[g] == 0 || pc.gap[g] == -side;
          if (free && open == kClosed) open = g;
          else if (free && touch[g] == side) pc.ports.push_back({side > 0, open, g}), open = g;
          else if (!free && open != kClosed) pc.ports.push_back({side > 0, open, g}), open = kClosed;
        }
        if (open != kClosed) pc.ports.push_back({side > 0, open, m});
      }
    }
    OnlineNode n{};
    n.at = cp.lo().p;  // the input frame's point is set at the end
    n.x = c, n.y_low = pc.stops.front().p.y(), n.y_high = pc.stops.back().p.y();
    n.sensed_at = cp.path_index;
    for (const auto& p : pc.ports) {
      n.left += p.right ? 0 : 1;
      n.ports.push_back(-1);
      n.spans.emplace_back(pc.stops[p.lo].p.y(), pc.stops[p.hi].p.y());
    }
    const std::size_t L = n.left, R = n.ports.size() - n.left;
    n.kind = L == 0 && R == 1   ? OnlineKind::Birth
             : L == 1 && R == 0 ? OnlineKind::Death
             : L == 1 && R == 2 ? OnlineKind::Split
             : L == 2 && R == 1 ? OnlineKind::Merge
                                : OnlineKind::Slice;
    if (L + R < 1 || (L == 1 && R == 1))
      throw Failure{"the slice through a critical point at " + at_text(cp.lo().p) + " joins " + std::to_string(L) + " cell(s) on the left and " +
                    std::to_string(R) + " on the right"};
    nodes_.push_back(std::move(n));
    pieces_.push_back(std::move(pc));
    order_.push_back(static_cast<std::uint32_t>(nodes_.size() - 1));
    return static_cast<std::uint32_t>(nodes_.size() - 1);
  }

  // The port of node `node` on side `right` a cell closing at critical point c arrives through.
  int closing_port(std::uint32_t node, bool right, const Sensed& cp, PortSide ps) const {
    const Piece& pc = pieces_[node];
    const double a = cp.lo().p.y(), b = cp.hi().p.y();
    int found = -1;
    for (std::size_t k = 0; k < pc.ports.size(); ++k) {
      if (pc.ports[k].right != right) continue;
      const double lo = pc.stops[pc.ports[k].lo].p.y(), hi = pc.stops[pc.ports[k].hi].p.y();
      bool in = false;
      switch (ps) {
        case PortSide::Point: in = lo <= a && b <= hi; break;
        case PortSide::Up: in = lo <= b && b < hi; break;
        case PortSide::Down: in = lo < a && a <= hi; break;
        case PortSide::Both: in = lo < a && b < hi; break;
      }
      if (!in) continue;
      if (found >= 0) throw Failure{"a cell closing at " + at_text(cp.lo().p) + " fits two ports of its critical slice"};
      found = static_cast<int>(k);
    }
    return found;
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
  // To a point the robot has driven through, shortest over its driven path.
  void goto_driven(const Point& p) {
    if (R_.odometry() == p) return;
    std::vector<double> dist;
    std::vector<std::uint32_t> pred;
    dijkstra(dist, pred);
    if (!std::isfinite(distance_to(dist, p))) throw Failure{"no driven path to " + at_text(p)};
    transit(pred, p);
  }

  // --- covering a cell --------------------------------------------------------------------
  struct Closing {
    Sensed cp;
    PortSide ps = PortSide::Point;
  };

  // Cover the cell leaving node `from` through `port` (the robot stands at the port's
  // floor point on the slice); returns its closing critical point.
  //
  // The cell is swept strip by strip. The strip from the last lap (slice x0, floor point F0,
  // ceiling point C0, the bridge between them driven) towards x0 + d w is explored so that
  // the *first* critical point along the sweep is the one that closes the cell, however
  // many the strip holds:
  //  1. forward phase on the floor: follow it from F0 to the target slice; a critical point
  //     sensed there (on the target slice too) moves the target to its slice;
  //  2. back to F0, across the bridge to C0, and the same on the ceiling (the reverse
  //     phase's boundary following, driven forward): its critical point moves the target
  //     again if it comes first;
  //  3. closing phase on the target slice: lap from the ceiling towards the floor (from the
  //     floor when the ceiling has a critical point there). Arriving where the other chain
  //     (or its critical point) crosses the slice proves the strip clear: the chains are
  //     monotone and an obstacle starting inside the strip would still cross the target
  //     slice (every obstacle of the configuration space is wider than 2r >= w). Hitting an
  //     obstacle instead: follow it back against the sweep to its first point, a critical
  //     point nearer than the target or on it, which becomes the target; then lap from there
  //     both ways, again until both laps arrive on the chains.
  // Each step moves the target back or keeps it on its slice while the laps progress along
  // it, so this ends; the target's critical point (if any) closes the cell. Otherwise the lap
  // across the target slice is the next lap.
  Closing cover_cell(std::uint32_t from, int port) {
    const Piece& pc = pieces_[from];
    const Piece::Port pt = pc.ports[static_cast<std::size_t>(port)];
    const int d = pt.right ? 1 : -1;
    auto blocked = [&](const char* what) {
      return Failure{std::string("a lap ").append(what).append(" from ").append(at_text(R_.odometry())).append(" is blocked")};
    };
    // The first lap: the port's stretch of the slice, as surveyed.
    std::vector<Stand> bridge(pc.stops.begin() + static_cast<std::ptrdiff_t>(pt.lo), pc.stops.begin() + static_cast<std::ptrdiff_t>(pt.hi) + 1);
    if (R_.odometry() != bridge.front().p) throw Failure{"the robot is not at the port's floor"};
    const OnlineKind between_kind = d > 0 ? OnlineKind::Split : OnlineKind::Merge;  // an obstacle starts
    if (!o_.cycle) return raster(bridge, d);
    for (;;) {
      const double x0 = bridge.front().p.x();
      double xt = x0 + d * w_;
      std::optional<Sensed> target;  // the critical point on the target slice
      PortSide tps = PortSide::Point;
      auto sooner = [&](const Sensed& cp, PortSide side) {
        if (target && cp.x() == xt && side != PortSide::Both) return;  // the same slice: the first one names it
        xt = cp.x(), target = cp;
        tps = point_kind(cp.kind) ? PortSide::Point : side;
      };
      // 1. The floor.
      Follow F = follow(Side::Floor, d, xt);
      if (F.cp) sooner(*F.cp, PortSide::Up);
      // 2. Back, across, the ceiling.
      back_along(F.stands, 0);
      for (std::size_t i = 1; i < bridge.size(); ++i) R_.retrace_to(bridge[i].p, bridge[i].c, Move::Transit);
      Follow C = follow(Side::Ceiling, d, xt);
      if (C.cp) {
        if (d * C.cp->x() > d * xt) throw Failure{"the ceiling turned back beyond the target slice"};
        sooner(*C.cp, PortSide::Down);
      }
      // The critical points of each chain on the target slice.
      const Sensed* fcp = F.cp && F.cp->x() == xt ? &*F.cp : nullptr;
      const Sensed* ccp = C.cp && C.cp->x() == xt ? &*C.cp : nullptr;
      bool same_run = false;
      if (fcp && ccp)
        for (const Stand& a : fcp->run)
          for (const Stand& b : ccp->run) same_run = same_run || a.p == b.p;
      if (same_run) {
        // Floor and ceiling meet there: a death (birth) closes the cell.
        if (!point_kind(fcp->kind) || fcp->kind != ccp->kind) throw Failure{"the floor and the ceiling meet at a critical point of two kinds"};
        return {*fcp, PortSide::Point};
      }
      if (fcp && ccp && !(fcp->hi().p.y() < ccp->lo().p.y()))
        throw Failure{"the floor's and the ceiling's critical points on the slice x = " + geometry::format_number(xt) + " overlap"};
      // An obstacle starting in the strip, met as below.
      const auto first_point = [&](bool on_floor, const Point& met, std::optional<OnlineKind> start_kind) {
        const Follow O = follow(on_floor ? Side::Floor : Side::Ceiling, -d, x0, start_kind);
        if (!O.cp) throw Failure{"an obstacle met in a strip at " + at_text(met) + " does not start inside the strip"};
        if (O.cp->kind != between_kind)
          throw Failure{std::string("an obstacle met in a strip starts at a ").append(to_string(O.cp->kind)).append(" critical point")};
        if (d * O.cp->x() > d * xt) throw Failure{"an obstacle met in a strip starts beyond the target slice"};
        return *O.cp;
      };
      std::optional<Sensed> obs;
      if (fcp && ccp && point_kind(fcp->kind) && point_kind(ccp->kind)) {
        // Two pockets, one of the floor and one of the ceiling, end on the target slice: what
        // separates them starts inside the strip, and the ceiling's pocket leads there. The
        // robot stands on the ceiling's critical point: on around it, back against the sweep,
        // to the boundary's next turn.
        obs = first_point(true, R_.odometry(), std::nullopt);
      } else {
        // 3. Across the target slice, from a side whose critical point there (if any) is not a
        // pocket's end: towards the ceiling's critical point if it has one there, else
        // towards the floor.
        const bool from_floor = ccp && !(fcp && point_kind(fcp->kind));
        if (from_floor) {
          // Back to the floor, and along it to the target slice again, to the top of its
          // critical point there.
          back_along(C.stands, 0);
          for (std::size_t i = bridge.size() - 1; i-- > 0;) R_.retrace_to(bridge[i].p, bridge[i].c, Move::Transit);
          const Follow F2 = follow(Side::Floor, d, xt);
          if (F2.cp && F2.cp->x() != xt) throw Failure{"the floor turned back where it did not before"};
          if (!F2.cp != !fcp) throw Failure{"the floor's critical point on the target slice changed"};
          if (F2.cp) along_run(F2.cp->run, true);
        } else if (ccp) {
          along_run(ccp->run, false);
        }
        const Stand lap_from = here();
        const double expect = from_floor ? ccp->lo().p.y() : fcp ? fcp->hi().p.y() : F.y_at(xt, true);
        if (!lap(from_floor)) throw blocked("across the cell");
        const Stand lap_to = here();
        if (std::fabs(lap_to.p.y() - expect) <= tol_) {
          if (target) return {*target, tps};
          // The strip is clear: the lap across the target slice is the next lap.
          bridge = from_floor ? std::vector<Stand>{lap_from, lap_to} : std::vector<Stand>{lap_to, lap_from};
          continue;
        }
        if (from_floor ? !(lap_to.p.y() < expect) : !(lap_to.p.y() > expect))
          throw Failure{"a lap across the cell from " + at_text(lap_from.p) + " went through the other side"};
        // An obstacle between: back against the sweep along it to where it starts (the new
        // target), then lap from there both ways along its slice until both laps arrive on
        // the chains. Another obstacle met on the way is followed back the same way: if it
        // starts on the same slice the laps go on from its far side, if sooner it is the new
        // target.
        obs = first_point(!from_floor, lap_to.p, between_kind);
      }
      sooner(*obs, PortSide::Both);
      for (bool again = true; again;) {
        again = false;
        // The chains where they cross the obstacle's slice.
        const double floor_y = F.y_at(xt, true), ceiling_y = C.y_at(xt, false);
        for (int pass = 0; pass < 2 && !again; ++pass) {
          const bool up = pass == 1;
          goto_driven(up ? obs->hi().p : obs->lo().p);
          Sensed cur = *obs;
          for (;;) {
            along_run(cur.run, up);
            if (!lap(up)) throw blocked(up ? "up from an obstacle's first point" : "down from an obstacle's first point");
            const double want = up ? ceiling_y : floor_y;
            if (std::fabs(R_.odometry().y() - want) <= tol_) break;
            if (up ? !(R_.odometry().y() < want) : !(R_.odometry().y() > want))
              throw Failure{std::string("a lap ").append(up ? "up" : "down").append(" at ").append(at_text(R_.odometry())).append(" went past the ").append(up ? "ceiling" : "floor")};
            const Point met = R_.odometry();
            const Sensed next = first_point(!up, met, between_kind);
            if (next.x() == xt) {
              cur = next;
              continue;
            }
            obs = next;
            sooner(*obs, PortSide::Both);
            again = true;
            break;
          }
        }
      }
      return {*target, PortSide::Both};
    }
  }

  // Without the cycle algorithm: a plain raster scan. Follow the side the last lap ended on
  // forward one lap width, lap across, and on; a critical point on the followed side closes
  // the cell. The other side is never followed, so its critical points go unseen (Fig. 6.22).
  Closing raster(std::vector<Stand> bridge, int d) {
    Side s = Side::Floor;
    for (;;) {
      const Follow f = follow(s, d, bridge.front().p.x() + d * w_);
      if (f.cp) return {*f.cp, point_kind(f.cp->kind) ? PortSide::Point : s == Side::Floor ? PortSide::Up : PortSide::Down};
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
      const bool right = pieces_[bn].ports[static_cast<std::size_t>(bp)].right;
      transit(pred, anchor(bn, bp).p);
      const std::size_t begin = R_.path().size() - 1;
      const std::size_t laps0 = laps_;
      const Closing c = cover_cell(bn, bp);
      const std::size_t end = R_.path().size() - 1, laps = laps_ - laps0;
      const std::uint32_t to = node_for(c.cp);
      const int tp = closing_port(to, !right, c.cp, c.ps);
      if (tp < 0) throw Failure{"the closing critical point of a cell at " + at_text(c.cp.lo().p) + " has no port for it"};
      if (nodes_[to].ports[tp] >= 0)
        throw Failure{"cell from critical point " + std::to_string(bn) + " closes at critical point " + std::to_string(to) +
                      " through a port already explored"};
      if (to == bn) throw Failure{"a cell closes at its own critical slice"};
      const int e = static_cast<int>(edges_.size());
      edges_.push_back({bn, to, laps, begin, end});
      nodes_[bn].ports[bp] = e, nodes_[to].ports[tp] = e;
    }
  }
  // Where a cell through a port starts: its floor point on the slice.
  const Stand& anchor(std::uint32_t node, int port) const {
    const Piece& pc = pieces_[node];
    return pc.stops[pc.ports[static_cast<std::size_t>(port)].lo];
  }

  OnlineRobot& R_;
  const OnlineOptions& o_;
  double w_;
  std::size_t budget_, steps_ = 0, laps_ = 0, ring_disagreements_ = 0;
  double tol_;  // odometry comparisons: a lap arrives on a chain it was estimated to reach
  std::vector<OnlineNode> nodes_;
  std::vector<Piece> pieces_;
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

namespace {

OnlineReport plan_online_in_frame(const Environment& env, const OnlineOptions& o) {
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

}  // namespace

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
    const std::size_t L = n.left, R = n.ports.size() - n.left;
    if (L != S[bj].cells_left || R != S[bj].cells_right) {
      c.detail = "sensed critical slice " + std::to_string(i) + " joins " + std::to_string(L) + " | " + std::to_string(R) +
                 " cells (left | right), offline critical slice " + std::to_string(bj) + " " + std::to_string(S[bj].cells_left) + " | " +
                 std::to_string(S[bj].cells_right);
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

OnlineReport plan_online_coverage(const Environment& env, const OnlineOptions& o) {
  const geometry::LocalFrame frame = geometry::LocalFrame::canonical(env);
  if (frame.identity()) return plan_online_in_frame(env, o);
  // In the plan's canonical frame (the same for every exact translate): sense and plan there
  // with the robot frame.margin() wider, then certify the path rounded back to input
  // coordinates (as plan_coverage).
  const double r = o.robot_radius;
  if (!(r > 0) || !std::isfinite(r)) throw InputError("--radius: online coverage needs a robot radius > 0");
  const geometry::Clearance clear(env, r);
  if (o.start && !clear.admits(*o.start))
    throw InputError("start " + geometry::format_point(*o.start) + ": a robot of radius " + geometry::format_number(r) + " does not fit there");
  const double w = o.width > 0 ? o.width : 2 * r;
  if (!(o.width >= 0) || !std::isfinite(o.width) || w > 2 * r)
    throw InputError("--width " + geometry::format_number(o.width) + ": online coverage needs 0 < w <= 2r = " + geometry::format_number(2 * r) +
                     " (a wider tool could pass an obstacle between two laps unseen)");
  OnlineOptions lo = o;
  lo.width = w, lo.range = o.range > 0 ? o.range : 10 * r;
  if (o.start) lo.start = frame.to_local(*o.start);
  const Environment local = frame.to_local(env);
  for (const double extra : {0.0, frame.margin()}) {
    lo.robot_radius = r + extra;
    OnlineReport rep = plan_online_in_frame(local, lo);
    for (OnlineNode& n : rep.nodes) n.at = frame.to_input(n.at);
    const std::size_t bad = frame.to_input_certified(rep.path, clear);
    if (bad == rep.path.size()) {
      rep.robot_radius = r;
      return rep;
    }
    if (extra > 0)
      throw std::logic_error("online coverage: segment " + std::to_string(bad) + " from " + geometry::format_point(rep.path[bad]) +
                             " failed certification in input coordinates");
  }
  throw std::logic_error("online coverage: unreachable");
}

OnlineComparison compare_with_offline(const Environment& env, const OnlineReport& rep, double tol) {
  const geometry::LocalFrame frame = geometry::LocalFrame::canonical(env);
  if (!frame.identity()) {
    // The online report's sweep coordinates are those of the local frame: compare there.
    OnlineReport local = rep;
    for (Point& p : local.path) p = frame.to_local(p);
    for (OnlineNode& n : local.nodes) n.at = frame.to_local(n.at);
    return compare_with_offline(frame.to_local(env), local, tol);
  }
  const geometry::ConfigurationSpace cs(env, rep.robot_radius);
  std::size_t comp = 0;
  if (!rep.path.empty())
    if (const auto k = cs.component_of(rep.path.front())) comp = *k;
  if (cs.components().empty()) return {};
  const BoustrophedonDecomposition b(cs.components()[comp], rep.angle);
  return compare_with_offline(b, rep, tol);
}

}  // namespace preimage::coverage
