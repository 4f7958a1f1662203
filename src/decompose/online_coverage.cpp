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
Side other(Side s) { return s == Side::Floor ? Side::Ceiling : Side::Floor; }

// A boundary point the robot stood at.
struct Stand {
  Point p;
  Contact c;
};

// A sensed critical point: its kind and the run of extreme abscissa (lo..hi) the robot's
// odometry recorded while following.
struct Sensed {
  OnlineKind kind;
  Stand lo, hi;
  std::size_t path_index;
};

struct FollowResult {
  enum Status : std::uint8_t { Reached, Critical, Lost } status = Lost;
  std::optional<Sensed> cp;
  bool matched = false;          // Reached: ended at the hint
  std::vector<Stand> stands;     // every point of the follow, the start first
};

// A lap of the cell being covered: its slice and its two ends.
struct LapEnds {
  double x;
  Stand lo, hi;
  const Stand& end(Side s) const { return s == Side::Floor ? lo : hi; }
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

class OnlinePlanner {
 public:
  OnlinePlanner(OnlineRobot& robot, const OnlineOptions& o, double w, std::size_t budget)
      : R_(robot), o_(o), w_(w), budget_(budget), same_(w / 4) {}

  void run(OnlineReport& rep) {
    try {
      explore();
      rep.complete = true;
    } catch (const Failure& f) {
      rep.inconsistency = f.what;
    }
    rep.nodes = nodes_, rep.edges = edges_, rep.sensing_order = order_, rep.laps = laps_, rep.steps = steps_;
    if (rep.complete)
      for (const auto& n : nodes_)
        for (int p : n.ports)
          if (p < 0) rep.complete = false, rep.inconsistency = "a critical point has an unexplored port";
  }

 private:
  // --- sensing --------------------------------------------------------------------------
  // Sign of the ring's normal estimate across the sweep: +1 up, -1 down, 0 along the sweep.
  int across(const detail::RingReading& r) const {
    const std::size_t n = R_.sensors(), i = r.argmin;
    if (i == 0 || 2 * i == n) return 0;
    return 2 * i < n ? 1 : -1;
  }
  double along(const detail::RingReading& r) const { return std::cos(R_.sensor_angle(r.argmin)); }

  void tick() {
    if (++steps_ > budget_) throw Failure{"step budget of " + std::to_string(budget_) + " primitives exhausted"};
  }

  // Boundary following along side s towards delta (+1: +x), stopping on the slice x = stop_x
  // (at the hint when the slice holds a vertical run through it) or where a critical point
  // is sensed: the sign of the normal estimate across the sweep flips.
  FollowResult follow(Side s, int delta, double stop_x, const Point* hint, bool from_critical = false) {
    FollowResult out = follow_(s, delta, stop_x, hint, from_critical);
    return out;
  }
  // From a critical point (`from_critical`) the first reading is ignored: the normal is
  // parallel to the sweep there, either way within the resolution.
  FollowResult follow_(Side s, int delta, double stop_x, const Point* hint, bool from_critical) {
    FollowResult out;
    const int dir = s == Side::Floor ? delta : -delta;
    auto ring = R_.read_ring();
    out.stands.push_back({R_.odometry(), R_.contact()});
    std::vector<int> signs{from_critical ? 0 : across(ring)};
    std::vector<double> alongs{along(ring)};
    double best = delta * R_.odometry().x();
    for (;;) {
      tick();
      bool on_slice = false;
      if (!R_.follow_step(dir, stop_x, on_slice)) throw Failure{"boundary following started away from the boundary"};
      out.stands.push_back({R_.odometry(), R_.contact()});
      if (on_slice) {
        // A vertical run on the slice: drive along it to the hint.
        while (hint && R_.odometry() != *hint && R_.contact().vertex != Contact::kNone) {
          const std::uint32_t v = R_.contact().vertex;
          (void)v;
          const Point before = R_.odometry();
          const Contact cbefore = R_.contact();
          bool dummy = false;
          tick();
          R_.follow_step(dir, NAN, dummy);
          if (R_.odometry().x() != stop_x) {
            R_.retrace_to(before, cbefore, Move::Follow);
            break;
          }
          out.stands.push_back({R_.odometry(), R_.contact()});
        }
        out.status = FollowResult::Reached;
        out.matched = hint && std::fabs(R_.odometry().y() - hint->y()) <= 1e-9 * (1 + std::fabs(hint->y()));
        return out;
      }
      ring = R_.read_ring();
      const int sg = across(ring);
      signs.push_back(sg), alongs.push_back(along(ring));
      best = std::max(best, delta * R_.odometry().x());
      int last = 0;
      std::size_t last_at = 0;
      for (std::size_t i = signs.size() - 1; i-- > 0;)
        if (signs[i] != 0) {
          last = signs[i], last_at = i;
          break;
        }
      if (sg != 0 && last != 0 && sg != last) {
        // Sensed: the normal turned through the sweep direction. Which way it pointed along
        // the sweep while turning tells the kind; the extreme abscissa driven is the place.
        double a = 0;
        for (std::size_t i = last_at; i < alongs.size(); ++i) a += alongs[i];
        Sensed cp;
        if (delta > 0) cp.kind = a > 0 ? OnlineKind::Death : OnlineKind::Merge;
        else cp.kind = a > 0 ? OnlineKind::Split : OnlineKind::Birth;
        bool first = true;
        for (const Stand& st : out.stands)
          if (delta * st.p.x() == best) {
            if (first || st.p.y() < cp.lo.p.y()) cp.lo = st;
            if (first || st.p.y() > cp.hi.p.y()) cp.hi = st;
            first = false;
          }
        cp.path_index = R_.path().size() - 1;
        out.cp = cp;
        out.status = FollowResult::Critical;
        return out;
      }
      if (delta * R_.odometry().x() < best - 2 * w_)
        throw Failure{"the boundary near " + geometry::format_point(R_.odometry()) +
                      " turned back but the ring sensed no critical point"};
    }
  }

  // Drive back along a follow's stands to stand k.
  void back_to(const FollowResult& f, std::size_t k) {
    for (std::size_t i = f.stands.size() - 1; i-- > k;) R_.retrace_to(f.stands[i].p, f.stands[i].c, Move::Transit);
  }
  std::size_t stand_of(const FollowResult& f, const Point& p) const {
    for (std::size_t i = f.stands.size(); i-- > 0;)
      if (f.stands[i].p == p) return i;
    throw Failure{"a critical point is not on the follow that sensed it"};
  }

  bool lap(bool up) {
    tick();
    if (!R_.lap(up)) return false;
    ++laps_;
    return true;
  }

  // --- the incremental Reeb graph ---------------------------------------------------------
  std::uint32_t node_for(const Sensed& s) {
    for (std::uint32_t i = 0; i < nodes_.size(); ++i) {
      const OnlineNode& n = nodes_[i];
      if (n.kind != s.kind || std::fabs(n.x - s.lo.p.x()) > same_) continue;
      const double gap = std::max({0.0, s.lo.p.y() - n.y_high, n.y_low - s.hi.p.y()});
      if (gap <= same_) {
        order_.push_back(i);
        return i;
      }
    }
    OnlineNode n;
    n.kind = s.kind;
    n.x = s.lo.p.x(), n.y_low = s.lo.p.y(), n.y_high = s.hi.p.y();
    n.sensed_at = s.path_index;
    n.ports.assign(s.kind == OnlineKind::Birth || s.kind == OnlineKind::Death ? 1 : 3, -1);
    nodes_.push_back(n);
    anchors_.push_back({s.lo, s.hi});
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
    if (it == ids_.end()) throw Failure{"no driven path to " + geometry::format_point(p)};
    std::vector<std::uint32_t> chain;
    for (std::uint32_t v = it->second; v != UINT32_MAX; v = pred[v]) chain.push_back(v);
    for (auto k = chain.rbegin(); k != chain.rend(); ++k) R_.retrace_to(gpts_[*k].p, gpts_[*k].c, Move::Transit);
  }

  // --- the cycle algorithm ----------------------------------------------------------------
  struct Closing {
    Sensed cp;
    PortSide ps = PortSide::Point;
  };

  // Cover the cell leaving node `from` through `port`; returns its closing critical point.
  Closing cover_cell(std::uint32_t from, int port) {
    bool right = false;
    PortSide ps = PortSide::Point;
    port_of(nodes_[from].kind, port, right, ps);
    const int d = right ? 1 : -1;
    const Stand lo = anchors_[from].first, hi = anchors_[from].second;
    LapEnds L{lo.p.x(), lo, hi};
    Side s = Side::Floor;
    auto here = [&]() { return Stand{R_.odometry(), R_.contact()}; };
    auto blocked = [&](const char* what) {
      return Failure{std::string("a lap ").append(what).append(" from ").append(geometry::format_point(R_.odometry())).append(" is blocked")};
    };
    switch (ps) {
      case PortSide::Point: L = {lo.p.x(), lo, hi}, s = Side::Floor; break;
      case PortSide::Up:
        if (!lap(true)) throw blocked("up from a critical point");
        L = {hi.p.x(), hi, here()}, s = Side::Ceiling;
        break;
      case PortSide::Down:
        if (!lap(false)) throw blocked("down from a critical point");
        L = {lo.p.x(), here(), lo}, s = Side::Floor;
        break;
      case PortSide::Both: {
        if (!lap(true)) throw blocked("up through a critical point");
        const Stand top = here();
        R_.retrace_to(hi.p, hi.c, Move::Transit);
        if (lo.p != hi.p) R_.retrace_to(lo.p, lo.c, Move::Transit);
        if (!lap(false)) throw blocked("down through a critical point");
        L = {lo.p.x(), here(), top}, s = Side::Floor;
        break;
      }
    }
    // Passed critical points sensed on the way, registered when the cell closes elsewhere.
    auto also = [&](const std::optional<Sensed>& cp) {
      if (cp) node_for(*cp);
    };
    const OnlineKind end_kind = d > 0 ? OnlineKind::Death : OnlineKind::Birth;   // free space ends ahead
    const OnlineKind pass_kind = d > 0 ? OnlineKind::Merge : OnlineKind::Split;  // an obstacle ends
    const OnlineKind hole_kind = d > 0 ? OnlineKind::Split : OnlineKind::Merge;  // an obstacle starts
    for (;;) {
      const Side s2 = other(s);
      double xt = L.x + d * w_;
      // Forward phase: follow the side the last lap ended on.
      FollowResult A = follow(s, d, xt, nullptr, L.lo.p == L.hi.p);
      std::optional<Sensed> evA;
      if (A.status == FollowResult::Critical) {
        evA = A.cp;
        if (evA->kind == end_kind) {
          if (!o_.cycle) return {*evA, PortSide::Point};
          // The boundary goes on back as the other side: reverse phase along it, from the
          // turn (the ring may have sensed it an edge later).
          back_to(A, stand_of(A, s == Side::Floor ? evA->hi.p : evA->lo.p));
          FollowResult B = follow(s2, -d, L.x, &L.end(s2).p, true);
          if (B.status == FollowResult::Critical) {
            if (B.cp->kind != hole_kind) throw Failure{"a reverse follow sensed a " + std::string(to_string(B.cp->kind)) + " inside a cell"};
            also(evA);
            return {*B.cp, PortSide::Both};
          }
          if (B.matched) return {*evA, PortSide::Point};
          also(evA);
          return closing_phase(s2, d, L);
        }
        if (evA->kind != pass_kind) throw Failure{"a forward follow sensed a " + std::string(to_string(evA->kind))};
        // An obstacle of this side ends: back to its extreme, and lap across from there.
        back_to(A, stand_of(A, s == Side::Floor ? evA->hi.p : evA->lo.p));
        xt = R_.odometry().x();
      }
      // Reverse phase: lap across, follow the other side back to the last lap's slice.
      const Stand before = here();
      if (!lap(s == Side::Floor)) throw blocked("across the cell");
      const LapEnds N = s == Side::Floor ? LapEnds{xt, before, here()} : LapEnds{xt, here(), before};
      if (!o_.cycle) {
        if (evA) return {*evA, s == Side::Floor ? PortSide::Up : PortSide::Down};
        L = N, s = s2;
        continue;
      }
      FollowResult B = follow(s2, -d, L.x, &L.end(s2).p);
      if (B.status == FollowResult::Critical) {
        if (B.cp->kind != hole_kind) throw Failure{"a reverse follow sensed a " + std::string(to_string(B.cp->kind)) + " inside a cell"};
        also(evA);
        return {*B.cp, PortSide::Both};
      }
      if (!B.matched) {
        also(evA);
        return closing_phase(s2, d, L);
      }
      if (evA) return {*evA, s == Side::Floor ? PortSide::Up : PortSide::Down};
      // The strip is clean: back along the other side to the new lap, and on.
      back_to(B, 0);
      L = N, s = s2;
    }
  }

  // Closing phase: the reverse follow met the last lap's slice beyond the lap's end, so an
  // obstacle lies between: lap towards it and follow it forward to its extreme.
  Closing closing_phase(Side s2, int d, const LapEnds& L) {
    const double y = R_.odometry().y(), yend = L.end(s2).p.y();
    if (s2 == Side::Floor ? y >= yend : y <= yend)
      throw Failure{"a reverse follow came back to the last lap's slice at " + geometry::format_point(R_.odometry()) + ", inside the lap"};
    if (!lap(s2 == Side::Floor)) throw Failure{"the closing phase cannot lap from " + geometry::format_point(R_.odometry())};
    FollowResult C = follow(s2 == Side::Floor ? Side::Ceiling : Side::Floor, d, L.x + d * 2 * w_, nullptr);
    const OnlineKind pass_kind = d > 0 ? OnlineKind::Merge : OnlineKind::Split;
    if (C.status != FollowResult::Critical || C.cp->kind != pass_kind)
      throw Failure{"the closing phase found no closing critical point near " + geometry::format_point(R_.odometry())};
    // The cell lies on the far side of the obstacle from the robot.
    return {*C.cp, s2 == Side::Floor ? PortSide::Up : PortSide::Down};
  }

  // --- the exploration --------------------------------------------------------------------
  void explore() {
    // Find a first critical point: down to the floor, then follow it backwards (-x) to the
    // boundary's leftmost turn.
    if (!lap(false)) throw Failure{"the robot cannot lap down from its start"};
    FollowResult f = follow(Side::Floor, -1, -INFINITY, nullptr);
    if (f.status != FollowResult::Critical) throw Failure{"no critical point found from the start"};
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
          bool right = false;
          PortSide ps = PortSide::Point;
          port_of(nodes_[i].kind, p, right, ps);
          const Point& a = (ps == PortSide::Up || ps == PortSide::Both) ? anchors_[i].second.p : anchors_[i].first.p;
          const double dd = distance_to(dist, a);
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
      transit(pred, (ps == PortSide::Up || ps == PortSide::Both) ? anchors_[bn].second.p : anchors_[bn].first.p);
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

  OnlineRobot& R_;
  const OnlineOptions& o_;
  double w_;
  std::size_t budget_, steps_ = 0, laps_ = 0;
  double same_;
  std::vector<OnlineNode> nodes_;
  std::vector<std::pair<Stand, Stand>> anchors_;
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
