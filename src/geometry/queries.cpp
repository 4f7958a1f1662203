// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/queries.hpp>

namespace preimage::geometry {

const char* to_string(Location::Kind k) {
  switch (k) {
    case Location::Kind::Interior: return "interior";
    case Location::Kind::OnEdge: return "on-edge";
    case Location::Kind::AtVertex: return "at-vertex";
    case Location::Kind::InHole: return "in-obstacle";
    case Location::Kind::Outside: return "outside";
  }
  return "?";
}

Location locate(const Environment& env, const Point& q) {
  const auto& P = env.vertices();
  std::size_t inside_ring = SIZE_MAX;
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    int winding = 0;
    for (std::size_t v = env.ring_begin(r); v < env.ring_end(r); ++v) {
      const Point &a = P[v], &b = P[env.next(v)];
      if (q == a) return {Location::Kind::AtVertex, v};
      if (q == b) return {Location::Kind::AtVertex, env.next(v)};
      // Half-open crossing rule with exact comparisons and one orientation test.
      if (a.y() <= q.y()) {
        if (b.y() > q.y()) {
          int o = orientation(a, b, q);
          if (o > 0) ++winding;
          else if (o == 0) return {Location::Kind::OnEdge, v};
        } else if (b.y() == q.y() && strictly_inside_segment(a, b, q)) {
          return {Location::Kind::OnEdge, v};
        }
      } else if (b.y() <= q.y()) {
        int o = orientation(a, b, q);
        if (o < 0) --winding;
        else if (o == 0) return {Location::Kind::OnEdge, v};
      }
    }
    if (winding != 0 && r > 0) inside_ring = r;
    if (winding == 0 && r == 0) inside_ring = 0;  // outside the outer boundary
  }
  if (inside_ring == 0) return {Location::Kind::Outside, 0};
  if (inside_ring != SIZE_MAX) return {Location::Kind::InHole, inside_ring - 1};
  return {Location::Kind::Interior, 0};
}

std::optional<RayHit> shoot_ray(const Environment& env, const ExactPoint& o, const ExactKernel::Vector_2& d) {
  using EK = ExactKernel;
  std::optional<RayHit> best;
  ExactFT best_t = 0;
  auto offer = [&](const ExactFT& t, std::size_t e, std::optional<std::size_t> vtx, bool along) {
    if (!best || t < best_t) {
      best_t = t;
      best = RayHit{o + t * d, e, vtx, along};
    }
  };
  const ExactFT dd = d * d;
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    const ExactPoint a = to_exact(env.vertex(e)), b = to_exact(env.vertex(env.next(e)));
    const auto sa = CGAL::orientation(d, a - o), sb = CGAL::orientation(d, b - o);
    if (sa == CGAL::COLLINEAR && sb == CGAL::COLLINEAR) {
      // The edge lies on the ray's line: contact at the nearer endpoint ahead of the origin.
      ExactFT ta = (a - o) * d / dd, tb = (b - o) * d / dd;
      if (ta > tb) std::swap(ta, tb);
      if (tb <= 0) continue;
      const bool from_origin = ta <= 0;
      ExactFT t = from_origin ? tb : ta;
      std::size_t vtx = ((o + t * d) == a) ? e : env.next(e);
      offer(t, e, vtx, from_origin);
      continue;
    }
    if (sa == sb) continue;  // both strictly on one side
    // Line crossing parameter: o + t d on segment ab.
    const EK::Vector_2 ab = b - a;
    const ExactFT denom = d.x() * ab.y() - d.y() * ab.x();
    const EK::Vector_2 ao = a - o;
    const ExactFT t = (ao.x() * ab.y() - ao.y() * ab.x()) / denom;
    if (t <= 0) continue;
    std::optional<std::size_t> vtx;
    if (sa == CGAL::COLLINEAR) vtx = e;
    else if (sb == CGAL::COLLINEAR) vtx = env.next(e);
    offer(t, vtx ? *vtx : e, vtx, false);
  }
  return best;
}

bool in_free_wedge(const Environment& env, std::size_t v, const Point& t) {
  const Point &u = env.vertex(env.prev(v)), &c = env.vertex(v), &w = env.vertex(env.next(v));
  // Free space is to the left of u->c and of c->w.
  const int turn = orientation(u, c, w);
  const int left_of_out = orientation(c, w, t);   // >= 0: t on the free side of edge c->w
  const int left_of_in = orientation(u, c, t);    // >= 0: t on the free side of edge u->c
  if (turn > 0) return left_of_out >= 0 && left_of_in >= 0;
  if (turn < 0) return left_of_out >= 0 || left_of_in >= 0;
  return left_of_out >= 0;
}

namespace {
// Is t on the closed free side of the edge e (whose relative interior contains the point)?
bool free_side_of_edge(const Environment& env, std::size_t e, const Point& t) {
  return orientation(env.vertex(e), env.vertex(env.next(e)), t) >= 0;
}
bool direction_free(const Environment& env, const Location& at, const Point& t) {
  switch (at.kind) {
    case Location::Kind::Interior: return true;
    case Location::Kind::OnEdge: return free_side_of_edge(env, at.index, t);
    case Location::Kind::AtVertex: return in_free_wedge(env, at.index, t);
    default: return false;
  }
}
}  // namespace

bool visible(const Environment& env, const Point& p, const Point& q) {
  const Location lp = locate(env, p), lq = locate(env, q);
  if (!lp.in_free_space() || !lq.in_free_space()) return false;
  if (p == q) return true;
  if (!direction_free(env, lp, q) || !direction_free(env, lq, p)) return false;
  const auto& P = env.vertices();
  for (std::size_t e = 0; e < P.size(); ++e) {
    const Point &a = P[e], &b = P[env.next(e)];
    const int o1 = orientation(p, q, a), o2 = orientation(p, q, b);
    const int o3 = orientation(a, b, p), o4 = orientation(a, b, q);
    if (o1 * o2 < 0 && o3 * o4 < 0) return false;  // proper crossing
    // A vertex strictly inside pq: the segment must pass within the free wedge both ways.
    if (o1 == 0 && strictly_inside_segment(p, q, a))
      if (!in_free_wedge(env, e, p) || !in_free_wedge(env, e, q)) return false;
    // p or q strictly inside edge e while the other lies strictly across it.
    if (o3 == 0 && strictly_inside_segment(a, b, p) && o4 < 0) return false;
    if (o4 == 0 && strictly_inside_segment(a, b, q) && o3 < 0) return false;
  }
  return true;
}

}  // namespace preimage::geometry
