// SPDX-License-Identifier: Apache-2.0
#include "online_robot.hpp"

#include <preimage/geometry/queries.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace preimage::coverage::detail {

OnlineRobot::OnlineRobot(const Environment& Q, const Environment& W, const OnlineOptions& o, const Point& start)
    : Q_(Q), W_(W), n_(o.sensors), range_(o.range), noise_(o.noise), rng_(o.seed), pos_(start) {
  for (std::size_t e = 0; e < W.num_vertices(); ++e) wboxes_.push_back(W.vertex(e).bbox() + W.vertex(W.next(e)).bbox());
  path_.push_back({start, CellChains::kNoVertex, CellChains::kNoVertex, Move::Transit});
}

double OnlineRobot::sensor_angle(std::size_t i) const { return 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n_); }

RingReading OnlineRobot::read_ring() {
  // Ray casting from the centre against the workspace, in double (a measurement): only the
  // edges whose box comes within the range can answer.
  ++readings_;
  RingReading r;
  r.ranges.assign(n_, range_);
  const double ox = pos_.x(), oy = pos_.y();
  for (std::size_t e = 0; e < W_.num_vertices(); ++e) {
    const CGAL::Bbox_2& b = wboxes_[e];
    if (b.xmin() > ox + range_ || b.xmax() < ox - range_ || b.ymin() > oy + range_ || b.ymax() < oy - range_) continue;
    const Point& a = W_.vertex(e);
    const Point& z = W_.vertex(W_.next(e));
    const double ex = z.x() - a.x(), ey = z.y() - a.y(), ax = a.x() - ox, ay = a.y() - oy;
    for (std::size_t i = 0; i < n_; ++i) {
      const double th = sensor_angle(i), dx = std::cos(th), dy = std::sin(th);
      const double den = dx * ey - dy * ex;
      if (den == 0) continue;
      const double t = (ax * ey - ay * ex) / den, s = (ax * dy - ay * dx) / den;
      if (t > 0 && t < r.ranges[i] && s >= 0 && s <= 1) r.ranges[i] = t;
    }
  }
  if (noise_ > 0) {
    std::normal_distribution<double> g(0, noise_);
    for (double& v : r.ranges) v = std::clamp(v + g(rng_), 0.0, range_);
  }
  for (std::size_t i = 1; i < n_; ++i)
    if (r.ranges[i] < r.ranges[r.argmin]) r.argmin = i;
  return r;
}

void OnlineRobot::go(const Point& p, const Contact& c, Move m) {
  pos_ = p, at_ = c;
  if (path_.back().p == p) return;
  path_.push_back({p, c.vertex == Contact::kNone ? CellChains::kNoVertex : c.vertex,
                   c.edge == Contact::kNone ? CellChains::kNoVertex : c.edge, m});
}

bool OnlineRobot::lap(bool up) {
  // Exact ray shooting in the configuration space: the centre's first contact. The contact
  // point is rounded along the slice towards the robot, so the lap stays in free space.
  const auto hit = geometry::shoot_ray(Q_, geometry::to_exact(pos_), geometry::ExactKernel::Vector_2(0, up ? 1 : -1));
  if (!hit || hit->along_edge) return false;
  Point p;
  Contact c;
  if (hit->vertex) {
    p = Q_.vertex(*hit->vertex), c.vertex = static_cast<std::uint32_t>(*hit->vertex);
  } else {
    const auto iy = CGAL::to_interval(CGAL::exact(hit->point.y()));
    p = Point(pos_.x(), up ? iy.first : iy.second), c.edge = static_cast<std::uint32_t>(hit->edge);
  }
  if (p == pos_ || !geometry::visible(Q_, pos_, p)) return false;  // against the boundary that way
  go(p, c, Move::Lap);
  return true;
}

bool OnlineRobot::wall_lap(bool up, bool& obstacle_right) {
  if (at_.vertex == Contact::kNone) return false;
  const std::uint32_t v = at_.vertex;
  const auto along = [&](std::size_t u) {
    const Point& q = Q_.vertex(u);
    return q.x() == pos_.x() && (up ? q.y() > pos_.y() : q.y() < pos_.y());
  };
  // Free space is on the left of every edge in ring order: a wall driven up in ring order
  // has its obstacle towards +x, one driven up against ring order towards -x.
  const std::size_t n = Q_.next(v), p = Q_.prev(v);
  std::size_t to;
  if (along(n)) to = n, obstacle_right = up;
  else if (along(p)) to = p, obstacle_right = !up;
  else return false;
  go(Q_.vertex(to), Contact{static_cast<std::uint32_t>(to), Contact::kNone}, Move::Lap);
  return true;
}

bool OnlineRobot::follow_step(int dir, double stop_x, bool& on_slice, double stop_x2) {
  on_slice = false;
  if (!at_.on_boundary()) return false;
  std::uint32_t e;  // the edge driven along, from its start (dir > 0) or end (dir < 0)
  if (at_.edge != Contact::kNone) e = at_.edge;
  else e = dir > 0 ? at_.vertex : static_cast<std::uint32_t>(Q_.prev(at_.vertex));
  const std::uint32_t target = dir > 0 ? static_cast<std::uint32_t>(Q_.next(e)) : e;
  const Point& v = Q_.vertex(target);
  // Does the edge reach the slice x = stop_x strictly beyond the robot? (Exact: all doubles.)
  const double x0 = pos_.x(), x1 = v.x();
  const auto reaches = [&](double s) { return x0 != s && ((x0 < s && s <= x1) || (x0 > s && s >= x1)); };
  if (!reaches(stop_x) && !std::isnan(stop_x2) && reaches(stop_x2)) stop_x = stop_x2;
  if (reaches(stop_x)) {
    on_slice = true;
    if (x1 == stop_x) {
      go(v, Contact{target, Contact::kNone}, Move::Follow);
      return true;
    }
    // The exact point of the edge on the slice, rounded into free space (free space is on
    // the left of the edge in ring order: above it when the edge runs towards +x).
    const geometry::ExactPoint &a = Q_.exact_vertex(e), &b = Q_.exact_vertex(Q_.next(e));
    const ExactFT y = a.y() + (ExactFT(stop_x) - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
    const auto iy = CGAL::to_interval(CGAL::exact(y));
    const bool free_above = Q_.vertex(Q_.next(e)).x() > Q_.vertex(e).x();
    go(Point(stop_x, free_above ? iy.second : iy.first), Contact{Contact::kNone, e}, Move::Follow);
    return true;
  }
  go(v, Contact{target, Contact::kNone}, Move::Follow);
  return true;
}

void OnlineRobot::retrace_to(const Point& p, const Contact& c, Move m) { go(p, c, m); }

}  // namespace preimage::coverage::detail
