// SPDX-License-Identifier: Apache-2.0
// A coverage path made drivable by a robot that cannot turn in place (issue 49, item 3).
//
// The pattern's path is a polyline with corners; a car-like robot with turning radius R
// drives along arcs of radius >= R (forward; reversing only where it must). The straight
// stretches that cover floor (every lap, and boundary following at least R long) are kept;
// the corners between them become Dubins curves (turn_model.hpp). Where the room is too
// tight for the turn — the U-turn between two laps w < 2R apart at a wall — the lap's end
// is cut back (a headland: the robot turns in the floor it leaves uncovered) by as little
// as lets a certified curve fit.
// Where no single curve fits (a dead end, a door at an angle), hybrid A* finds a way with
// forward and reverse arcs (car_search.hpp); a stretch the robot cannot reach at all is
// skipped and counted, never dropped silently. Every segment and every arc is certified
// with exact clearance tests (ArcCertifier) before it is kept.
#include "coverage_internal.hpp"
#include "car_search.hpp"
#include "coverage_raster.hpp"

#include <preimage/coverage/turn_model.hpp>

#include <algorithm>
#include <numbers>

namespace preimage::coverage::detail {

namespace {

// Where to go next: a straight keeper of the plan to drive from a to b, or a touch-up
// point a to pass, facing any way.
struct Goal {
  bool keeper = false;
  Point a, b;
  Move move = Move::Transit;
  std::size_t lap = 0;  // keeper: its index among the keepers
};

// Where the robot is: driving a straight track from `from` towards `to` with `heading`; it
// may leave the track anywhere between (from == to: standing at a pose).
struct Track {
  Point from, to;
  double heading = 0;
  Move move = Move::Transit;
  std::size_t lap = SIZE_MAX;
  bool any_heading = false;  // the start: the robot stands, facing wherever it likes
};

double heading_of(const Point& a, const Point& b) { return std::atan2(b.y() - a.y(), b.x() - a.x()); }
Point along(const Point& a, double h, double t) { return Point(a.x() + t * std::cos(h), a.y() + t * std::sin(h)); }

// Cutting a lap short by 1 m loses w m^2 of floor; a metre of extra turning costs a metre.
// Floor lost weighs this many metres of path per metre cut.
constexpr double kCutCost = 4;
// Curves tried per connection, cheapest first, before a search.
constexpr std::size_t kMaxTries = 1000;
// Poses a search expands before the goal is given up. Searches that succeed on the shipped
// plans mostly need < 1,500; getting through a door off a corridor 2R narrow takes more
// (house 1451 at W = 0.5, R = 0.5: 94.9 % covered with a cap of 4,000, 99.86 % with this).
constexpr std::size_t kMaxExpansions = 30000;

class Driver {
 public:
  Driver(const Planning& P, double R)
      : P_(P), R_(R), scale_(scale_of(P.env, R)), cert_(P.env, P.cs.radius()),
        search_(P.E, cert_.clearance(), cert_, R, std::max(P.w / 2, R / 4), 1e-9 * scale_) {
    for (const double f : {0.0, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0}) cuts_.push_back(f * R);
  }

  void drive_plan(const Polyline& plan);
  void touch_up();
  void finish(CoverageReport& rep);

 private:
  struct Candidate {
    double cost;
    double depart_cut;
    Pose arrive;
    DubinsCurve curve;
  };
  // The drivable path so far.
  Polyline out_;
  std::vector<CoverageArc> arcs_;
  std::vector<char> shortened_;
  Track at_;
  std::vector<std::size_t> cusps_;
  bool reversing_ = false;
  std::size_t skipped_ = 0, touch_ups_ = 0, unreached_ = 0;

  const Planning& P_;
  double R_, scale_;
  ArcCertifier cert_;
  CarSearch search_;
  std::vector<double> cuts_;

  struct Arrival {
    Pose pose;
    double cut;
    Point end;
  };
  static double scale_of(const Environment& env, double R) {
    const auto box = env.bbox();
    return std::fabs(box.xmin()) + std::fabs(box.xmax()) + std::fabs(box.ymin()) + std::fabs(box.ymax()) + R;
  }
  Point off_the_wall(const Point& v) const;
  std::vector<std::pair<Pose, double>> departures(const Track& at) const;
  std::vector<Arrival> arrivals(const Goal& g) const;
  bool connect(Track& at, const Goal& g);
  bool search(Track& at, const Goal& g);
  bool reach(Track& at, const Goal& g) { return connect(at, g) || search(at, g); }
  void arrive(Track& at, const Goal& g, const Arrival& arr, double depart_cut);
  void emit_piece(const Pose& p, const DrivePiece& piece, bool reverse, const std::vector<Point>& samples);
  void emit_curve(const DubinsCurve& c, const std::vector<std::vector<Point>>& samples);
};

// A touch-up point (a raster sample's centre) may lie on the configuration space boundary,
// where no arc's capsule fits: it moves 5 % of R (at most w/8, so its sample stays covered)
// away from the nearest obstacle when that keeps it in free space (a choice; the curves
// through it are certified).
Point Driver::off_the_wall(const Point& v) const {
  const double by = std::min(0.05 * R_, P_.w / 8);
  const Point n = cert_.clearance().nearest(v);
  const double dx = v.x() - n.x(), dy = v.y() - n.y(), d = std::hypot(dx, dy);
  if (!(d > 0) || d >= P_.cs.radius() + by) return v;
  const Point q(v.x() + dx / d * by, v.y() + dy / d * by);
  return cert_.clearance().admits(q) ? q : v;
}

// Departures from a track: its end, or cut back by one of cuts_ (not behind where it
// began); from the start, facing any of 16 ways.
std::vector<std::pair<Pose, double>> Driver::departures(const Track& at) const {
  std::vector<std::pair<Pose, double>> out;
  if (at.any_heading) {
    for (int k = 0; k < 16; ++k) out.push_back({{at.from, k * std::numbers::pi / 8}, 0.0});
    return out;
  }
  const double track_len = planar_distance(at.from, at.to);
  for (const double t : cuts_)
    if (t <= track_len) out.push_back({{t == 0 ? at.to : t == track_len ? at.from : along(at.to, at.heading, -t), at.heading}, t});
  return out;
}

// Arrivals: a keeper's start (or its end, for a lap driven backwards), moved in by a cut;
// a touch-up point facing any of 8 ways.
std::vector<Driver::Arrival> Driver::arrivals(const Goal& g) const {
  std::vector<Arrival> out;
  if (g.keeper) {
    const double len = planar_distance(g.a, g.b);
    const bool reversible = g.move == Move::Lap;
    for (int dir = 0; dir < (reversible ? 2 : 1); ++dir) {
      const Point &s = dir ? g.b : g.a, &e = dir ? g.a : g.b;
      const double h = heading_of(s, e);
      for (const double t : cuts_)
        if (t <= len / 2) out.push_back({{t == 0 ? s : along(s, h, t), h}, t, e});
      // A lap shorter than the cuts is joined at its middle too (its ends touch walls,
      // where no curve's last arc keeps r).
      if (len / 2 < cuts_[1]) out.push_back({{along(s, h, len / 2), h}, len / 2, e});
    }
    return out;
  }
  const Point v = off_the_wall(g.a);
  for (int k = 0; k < 8; ++k) out.push_back({{v, k * std::numbers::pi / 4}, 0, v});
  return out;
}

void Driver::emit_piece(const Pose& p, const DrivePiece& piece, bool reverse, const std::vector<Point>& samples) {
  if (samples.empty()) return;
  if (reverse != reversing_) cusps_.push_back(out_.points.size() - 1), reversing_ = reverse;
  if (piece.turn == 0) {
    out_.append(samples.back(), Move::Transit);
    return;
  }
  const std::size_t first = out_.points.size() - 1;
  // The centre lies on the side the arc turns to, seen in the direction of travel.
  const double h = reverse ? p.heading + std::numbers::pi : p.heading, side = piece.turn > 0 ? 1.0 : -1.0;
  const Point centre(p.at.x() - side * R_ * std::sin(h), p.at.y() + side * R_ * std::cos(h));
  for (const Point& q : samples) out_.append(q, Move::Turn);
  arcs_.push_back({centre, R_, piece.turn, first, out_.points.size() - 1, reverse});
}

void Driver::emit_curve(const DubinsCurve& c, const std::vector<std::vector<Point>>& samples) {
  Pose p = c.from;
  for (std::size_t k = 0; k < 3; ++k) {
    if (samples[k].empty()) continue;
    p.at = out_.points.back();
    emit_piece(p, c.pieces[k], false, samples[k]);
    p = drive(p, c.pieces[k], R_);
  }
}

void Driver::arrive(Track& at, const Goal& g, const Arrival& arr, double depart_cut) {
  if (depart_cut > 0 && at.lap != SIZE_MAX && at.move == Move::Lap) shortened_[at.lap] = 1;
  if (arr.cut > 0 && g.keeper && g.move == Move::Lap) shortened_[g.lap] = 1;
  at = g.keeper ? Track{arr.pose.at, arr.end, arr.pose.heading, g.move, g.lap} : Track{arr.pose.at, arr.pose.at, arr.pose.heading, Move::Transit, SIZE_MAX};
}

// One Dubins curve from a departure to an arrival, the cheapest certified one (cutting a
// lap costs kCutCost per metre on top of the curve's length).
bool Driver::connect(Track& at, const Goal& g) {
  const auto departs = departures(at);
  const auto arrs = arrivals(g);
  const bool cut_depart_costs = at.move == Move::Lap || at.move == Move::Follow;
  const bool cut_arrive_costs = g.keeper && (g.move == Move::Lap || g.move == Move::Follow);
  struct Candidate {
    double cost;
    std::size_t depart, arrive;
    DubinsCurve curve;
  };
  std::vector<Candidate> cands;
  for (std::size_t d = 0; d < departs.size(); ++d)
    for (std::size_t k = 0; k < arrs.size(); ++k)
      for (const DubinsCurve& c : dubins_curves(departs[d].first, arrs[k].pose, R_))
        cands.push_back({c.length() + kCutCost * ((cut_depart_costs ? departs[d].second : 0) + (cut_arrive_costs ? arrs[k].cut : 0)), d, k, c});
  std::sort(cands.begin(), cands.end(), [](const Candidate& x, const Candidate& y) { return x.cost < y.cost; });
  std::vector<std::vector<Point>> samples;
  for (std::size_t n = 0; n < cands.size() && n < kMaxTries; ++n) {
    const Candidate& c = cands[n];
    const Point depart = c.curve.from.at;
    if (depart != at.from && !cert_.segment(at.from, depart)) continue;
    if (!certify_curve(cert_, c.curve, arrs[c.arrive].pose, 1e-9 * scale_, samples)) continue;
    out_.append(depart, at.move);
    emit_curve(c.curve, samples);
    arrive(at, g, arrs[c.arrive], departs[c.depart].second);
    return true;
  }
  return false;
}

// Where no single curve fits: hybrid A* from the track's end (or the start, facing any
// way) to any arrival, with reverse steps.
bool Driver::search(Track& at, const Goal& g) {
  std::vector<std::pair<Pose, double>> departs = departures(at);
  if (!at.any_heading) departs.resize(1);  // the track's end
  const auto arrs = arrivals(g);
  std::vector<Pose> starts, goals;
  for (const auto& d : departs) starts.push_back(d.first);
  for (const auto& a : arrs) goals.push_back(a.pose);
  const auto res = search_.search(starts, goals, kMaxExpansions);
  if (!res.found) return false;
  Pose p = starts[res.start];
  if (p.at != at.from && !cert_.segment(at.from, p.at)) return false;
  out_.append(p.at, at.move);
  for (const CarStep& s : res.steps) {
    Pose after;
    std::vector<Point> pts = step_samples(p, s, R_, after);
    emit_piece(p, s.piece, s.reverse, pts);
    p = after;
    p.at = pts.back();
  }
  DubinsCurve finish = res.finish;
  emit_curve(finish, res.finish_samples);
  arrive(at, g, arrs[res.goal], departs[res.start].second);
  return true;
}

void Driver::drive_plan(const Polyline& plan) {
  // The plan without repeated points; collinear corners stay (they cost nothing: a Dubins
  // curve between collinear poses is straight).
  Polyline p;
  for (std::size_t i = 0; i < plan.points.size(); ++i) p.append(plan.points[i], i ? plan.moves[i - 1] : Move::Transit);
  if (p.points.empty()) return;
  std::vector<Goal> goals;
  const std::size_t m = p.moves.size();
  // Keepers: the stretches that cover floor (laps, and boundary following at least R long).
  // A transit only gets somewhere: the curve or search to the next keeper finds its own way.
  auto keeper = [&](std::size_t i) {
    return p.moves[i] == Move::Lap || (p.moves[i] == Move::Follow && planar_distance(p.points[i], p.points[i + 1]) >= R_);
  };
  std::size_t keepers = 0;
  for (std::size_t i = 0; i < m; ++i)
    if (keeper(i)) goals.push_back({true, p.points[i], p.points[i + 1], p.moves[i], keepers++});
  shortened_.assign(keepers, 0);
  // The start: standing at the plan's first point, facing any way.
  at_ = Track{p.points[0], p.points[0], 0.0, Move::Transit, SIZE_MAX, true};
  out_.points.push_back(at_.from);
  // Each keeper by one curve, else by a search with reverse steps, else skipped.
  for (const Goal& goal : goals)
    if (!reach(at_, goal)) ++skipped_;
}

// Touch-ups for a robot that cannot turn in place: the nearest sample the path left
// uncovered, reached by a certified curve (or a search with reverse steps when no curve
// fits), until at most kTouchUpLeft of the samples is left; a sample nothing reaches is
// given up with the samples within max(w/2, R/2) of it, and counted.
void Driver::touch_up() {
  const CoverageRaster R(P_.E, P_.index, P_.w, 0);
  Polyline so_far = out_;
  so_far.append(at_.to, at_.move);
  Uncovered u = uncovered(R, so_far, P_.w);
  auto& open = u.open;
  std::size_t& left = u.left;
  const std::size_t allowed = u.allowed;
  const double half = P_.w / 2;
  auto close = [&](const Point& a, const Point& b) {
    R.capsule(a, b, half, half, [&](std::size_t c, bool) {
      if (open[c]) open[c] = 0, --left;
    });
  };
  while (left > allowed) {
    const Point here = at_.to;
    std::size_t best = open.size();
    double best_d = INFINITY;
    for (std::size_t id = 0; id < open.size(); ++id)
      if (open[id] && planar_distance(here, R.centre(id)) < best_d) best_d = planar_distance(here, R.centre(id)), best = id;
    if (best == open.size()) break;
    const Point q = R.centre(best);
    const std::size_t before = out_.points.size();
    const Goal goal{false, q, q, Move::Transit, 0};
    const bool reached = reach(at_, goal);
    for (std::size_t k = before > 0 ? before - 1 : 0; k + 1 < out_.points.size(); ++k) close(out_.points[k], out_.points[k + 1]);
    if (reached) {
      ++touch_ups_;
    } else {
      ++unreached_;
      // Nearby samples are as hard to reach: given up with it.
      R.capsule(q, q, std::max(half, R_ / 2), 0, [&](std::size_t c, bool) {
        if (open[c]) open[c] = 0, --left;
      });
      if (open[best]) open[best] = 0, --left;
    }
  }
}

void Driver::finish(CoverageReport& rep) {
  // Drive the last track to its end.
  if (at_.to != at_.from) {
    if (!cert_.segment(at_.from, at_.to)) throw std::logic_error("coverage: the last stretch of a drivable path failed certification");
    out_.append(at_.to, at_.move);
  }
  const std::size_t n = out_.points.size();
  finish_path(P_, std::move(out_), rep, n);  // certified piece by piece above
  // A curvature-limited path changes heading only along its arcs (every join is tangent):
  // a run of arcs turning one way is one turn.
  rep.turns = rep.sharp_turns = 0, rep.rotation_deg = 0;
  double run = 0;
  for (std::size_t k = 0; k < arcs_.size(); ++k) {
    run += std::fabs(arcs_[k].turn);
    rep.rotation_deg += std::fabs(arcs_[k].turn) * 180 / std::numbers::pi;
    const bool joins = k + 1 < arcs_.size() && arcs_[k + 1].first == arcs_[k].last && (arcs_[k + 1].turn > 0) == (arcs_[k].turn > 0);
    if (joins) continue;
    const double deg = run * 180 / std::numbers::pi;
    rep.turns += deg > 1.0, rep.sharp_turns += deg > 15.0;
    run = 0;
  }
  rep.arcs = std::move(arcs_);
  rep.min_turn_radius = R_;
  rep.shortened_laps = static_cast<std::size_t>(std::count(shortened_.begin(), shortened_.end(), 1));
  rep.skipped = skipped_;
  rep.touch_ups = touch_ups_;
  rep.unreached = unreached_;
  rep.cusps = std::move(cusps_);
}

}  // namespace

void make_drivable(const Planning& P, CoverageReport& rep, double R) {
  if (rep.path.empty()) return;
  Polyline plan;
  plan.points = std::move(rep.path), plan.moves = std::move(rep.moves);
  straighten_follows(P, plan);
  Driver d(P, R);
  d.drive_plan(plan);
  d.touch_up();
  d.finish(rep);
}

}  // namespace preimage::coverage::detail
