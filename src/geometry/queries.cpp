// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/queries.hpp>

#include <cmath>
#include <stdexcept>

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

namespace {
// Input vertices in the query's number type: doubles for input points, lazy-exact for
// constructed ones, so every predicate below is exact either way.
template <class P>
const P& vertex_as(const Environment& env, std::size_t v);
template <>
const Point& vertex_as<Point>(const Environment& env, std::size_t v) { return env.vertex(v); }
template <>
const ExactPoint& vertex_as<ExactPoint>(const Environment& env, std::size_t v) { return env.exact_vertex(v); }

template <class P>
bool strictly_between(const P& a, const P& b, const P& c) {
  return CGAL::orientation(a, b, c) == CGAL::COLLINEAR && CGAL::collinear_are_strictly_ordered_along_line(a, c, b);
}

template <class P>
Location locate_as(const Environment& env, const P& q) {
  std::size_t inside_ring = SIZE_MAX;
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    int winding = 0;
    for (std::size_t v = env.ring_begin(r); v < env.ring_end(r); ++v) {
      const P &a = vertex_as<P>(env, v), &b = vertex_as<P>(env, env.next(v));
      if (q == a) return {Location::Kind::AtVertex, v};
      if (q == b) return {Location::Kind::AtVertex, env.next(v)};
      // Half-open crossing rule with exact comparisons and one orientation test.
      const auto ay = CGAL::compare_y(a, q), by = CGAL::compare_y(b, q);
      if (ay != CGAL::LARGER) {
        if (by == CGAL::LARGER) {
          const auto o = CGAL::orientation(a, b, q);
          if (o == CGAL::LEFT_TURN) ++winding;
          else if (o == CGAL::COLLINEAR) return {Location::Kind::OnEdge, v};
        } else if (by == CGAL::EQUAL && strictly_between(a, b, q)) {
          return {Location::Kind::OnEdge, v};
        }
      } else if (by != CGAL::LARGER) {
        const auto o = CGAL::orientation(a, b, q);
        if (o == CGAL::RIGHT_TURN) --winding;
        else if (o == CGAL::COLLINEAR) return {Location::Kind::OnEdge, v};
      }
    }
    if (winding != 0 && r > 0) inside_ring = r;
    if (winding == 0 && r == 0) inside_ring = 0;  // outside the outer boundary
  }
  if (inside_ring == 0) return {Location::Kind::Outside, 0};
  if (inside_ring != SIZE_MAX) return {Location::Kind::InHole, inside_ring - 1};
  return {Location::Kind::Interior, 0};
}
}  // namespace

Location locate(const Environment& env, const Point& q) { return locate_as(env, q); }
Location locate(const Environment& env, const ExactPoint& q) { return locate_as(env, q); }

std::optional<RayHit> shoot_ray(const Environment& env, const ExactPoint& o, const ExactKernel::Vector_2& d) {
  // Decisions by orientation predicates on stored points; the hit parameter t is
  // constructed only for edges met strictly ahead, and the hit point once at the end,
  // so a query builds few lazy-exact nodes.
  const ExactPoint q = o + d;
  const ExactFT dx = d.x(), dy = d.y();
  std::optional<ExactFT> best_t;
  std::size_t best_e = 0;
  std::optional<std::size_t> best_vtx;
  bool best_along = false;
  auto offer = [&](const ExactFT& t, std::size_t e, std::optional<std::size_t> vtx, bool along) {
    if (!best_t || t < *best_t) best_t = t, best_e = e, best_vtx = vtx, best_along = along;
  };
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    const ExactPoint &a = env.exact_vertex(e), &b = env.exact_vertex(env.next(e));
    const int sa = CGAL::orientation(o, q, a), sb = CGAL::orientation(o, q, b);
    if (sa == 0 && sb == 0) {
      // The edge lies on the ray's line: contact at the nearer endpoint ahead of the origin.
      const ExactFT dd = d * d;
      ExactFT ta = (a - o) * d / dd, tb = (b - o) * d / dd;
      const bool swapped = ta > tb;
      if (swapped) std::swap(ta, tb);
      if (tb <= 0) continue;
      const bool from_origin = ta <= 0;
      const std::size_t vtx = from_origin != swapped ? env.next(e) : e;
      offer(from_origin ? tb : ta, e, vtx, from_origin);
      continue;
    }
    if (sa == sb) continue;  // both strictly on one side
    // o + t d meets the line ab at t = cross(a-o, b-a) / cross(d, b-a). The numerator has
    // the sign of orientation(o, a, b); the denominator cross(d, b-o) - cross(d, a-o) has
    // the sign of sb - sa because sa != sb. Only t > 0 counts.
    const int oab = CGAL::orientation(o, a, b);
    if (oab == 0 || oab * (sb - sa) < 0) continue;
    const ExactFT abx = b.x() - a.x(), aby = b.y() - a.y();
    const ExactFT t = ((a.x() - o.x()) * aby - (a.y() - o.y()) * abx) / (dx * aby - dy * abx);
    std::optional<std::size_t> vtx;
    if (sa == 0) vtx = e;
    else if (sb == 0) vtx = env.next(e);
    if (vtx && best_vtx == vtx) continue;  // the same vertex from its other edge: an exact tie
    offer(t, vtx ? *vtx : e, vtx, false);
  }
  if (!best_t) return std::nullopt;
  const ExactPoint hit = best_vtx ? env.exact_vertex(*best_vtx) : o + *best_t * d;
  return RayHit{hit, best_e, best_vtx, best_along};
}

namespace {
// Is the direction c -> t in the closed sector left of u -> c and of c -> w?
template <class P>
bool in_sector_as(const P& u, const P& c, const P& w, const P& t) {
  const auto turn = CGAL::orientation(u, c, w);
  const bool left_of_out = CGAL::orientation(c, w, t) != CGAL::RIGHT_TURN;  // t on the free side of edge c->w
  const bool left_of_in = CGAL::orientation(u, c, t) != CGAL::RIGHT_TURN;   // t on the free side of edge u->c
  if (turn == CGAL::LEFT_TURN) return left_of_out && left_of_in;
  if (turn == CGAL::RIGHT_TURN) return left_of_out || left_of_in;
  return left_of_out;
}
template <class P>
bool in_ring_free_wedge_as(const Environment& env, std::size_t v, const P& t) {
  // Free space is to the left of prev(v) -> v and of v -> next(v).
  return in_sector_as(vertex_as<P>(env, env.prev(v)), vertex_as<P>(env, v), vertex_as<P>(env, env.next(v)), t);
}
template <class P>
std::size_t wedge_toward_as(const Environment& env, std::size_t v, const P& t) {
  std::size_t w = v;
  do {
    if (in_sector_as(vertex_as<P>(env, env.wedge_prev(w)), vertex_as<P>(env, w), vertex_as<P>(env, env.next(w)), t)) return w;
    w = env.same_point_next(w);
  } while (w != v);
  return SIZE_MAX;
}
// At a contact the free directions are those outside every ring's material sector there.
template <class P>
bool in_free_wedge_as(const Environment& env, std::size_t v, const P& t) {
  std::size_t w = v;
  do {
    if (!in_ring_free_wedge_as(env, w, t)) return false;
    w = env.same_point_next(w);
  } while (w != v);
  return true;
}

// Is t on the closed free side of the edge e (whose relative interior contains the point)?
template <class P>
bool free_side_of_edge(const Environment& env, std::size_t e, const P& t) {
  return CGAL::orientation(vertex_as<P>(env, e), vertex_as<P>(env, env.next(e)), t) != CGAL::RIGHT_TURN;
}
template <class P>
bool direction_free(const Environment& env, const Location& at, const P& t) {
  switch (at.kind) {
    case Location::Kind::Interior: return true;
    case Location::Kind::OnEdge: return free_side_of_edge(env, at.index, t);
    case Location::Kind::AtVertex: return in_free_wedge_as(env, at.index, t);
    default: return false;
  }
}

template <class P>
bool visible_as(const Environment& env, const P& p, const P& q) {
  const Location lp = locate_as(env, p), lq = locate_as(env, q);
  if (!lp.in_free_space() || !lq.in_free_space()) return false;
  if (p == q) return true;
  if (!direction_free(env, lp, q) || !direction_free(env, lq, p)) return false;
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    const P &a = vertex_as<P>(env, e), &b = vertex_as<P>(env, env.next(e));
    const int o1 = CGAL::orientation(p, q, a), o2 = CGAL::orientation(p, q, b);
    const int o3 = CGAL::orientation(a, b, p), o4 = CGAL::orientation(a, b, q);
    if (o1 * o2 < 0 && o3 * o4 < 0) return false;  // proper crossing
    // A vertex strictly inside pq: the segment must pass within the free wedge both ways
    // (each ring at a contact is met as its own vertex e).
    if (o1 == 0 && strictly_between(p, q, a))
      if (!in_ring_free_wedge_as(env, e, p) || !in_ring_free_wedge_as(env, e, q)) return false;
    // p or q strictly inside edge e while the other lies strictly across it.
    if (o3 == 0 && strictly_between(a, b, p) && o4 < 0) return false;
    if (o4 == 0 && strictly_between(a, b, q) && o3 < 0) return false;
  }
  return true;
}
}  // namespace

bool in_free_wedge(const Environment& env, std::size_t v, const Point& t) { return in_free_wedge_as(env, v, t); }
std::size_t wedge_toward(const Environment& env, std::size_t v, const Point& t) { return wedge_toward_as(env, v, t); }
std::size_t wedge_toward(const Environment& env, std::size_t v, const ExactPoint& t) { return wedge_toward_as(env, v, t); }

double ray_range(const Environment& env, const Point& origin, double angle, double max_range) {
  const double dx = std::cos(angle), dy = std::sin(angle), ox = origin.x(), oy = origin.y();
  double best = max_range;
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    const Point& a = env.vertex(e);
    const Point& b = env.vertex(env.next(e));
    const double ex = b.x() - a.x(), ey = b.y() - a.y();
    const double den = dx * ey - dy * ex;
    if (den == 0) continue;  // parallel: a grazing beam returns from the next edge
    const double ax = a.x() - ox, ay = a.y() - oy;
    const double t = (ax * ey - ay * ex) / den;  // along the beam
    const double s = (ax * dy - ay * dx) / den;  // along the edge
    if (t > 0 && t < best && s >= 0 && s <= 1) best = t;
  }
  return best;
}

bool visible(const Environment& env, const Point& p, const Point& q) { return visible_as(env, p, q); }
bool visible(const Environment& env, const ExactPoint& p, const ExactPoint& q) { return visible_as(env, p, q); }

long winding_number(std::span<const ExactPoint> loop, const ExactPoint& c) {
  // Signed crossings of the ray from c towards +x (half-open in y, so a vertex at c's
  // height is counted once): upward with c on the left +1, downward with c on the right -1.
  // "Above c" is read off the coordinates' intervals where they decide it (no rounding-mode
  // switch per vertex: the filtered predicate's was most of the pursuit checker's point-in-V
  // tests), else exactly.
  const auto cy = c.approx().y();
  const double clo = cy.inf(), chi = cy.sup();
  auto up = [&](const ExactPoint& p) {
    const auto py = p.approx().y();
    if (py.inf() > chi) return true;
    if (py.sup() <= clo) return false;
    return CGAL::compare_y(p, c) == CGAL::LARGER;
  };
  long w = 0;
  bool q_up = loop.empty() ? false : up(loop[0]);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const ExactPoint &p = loop[i], &q = loop[(i + 1) % loop.size()];
    const bool p_up = q_up;
    q_up = up(q);
    if (!p_up && q_up && CGAL::orientation(p, q, c) == CGAL::LEFT_TURN) ++w;
    if (p_up && !q_up && CGAL::orientation(p, q, c) == CGAL::RIGHT_TURN) --w;
  }
  return w;
}

std::vector<PolylineCrossing> polyline_crossings(std::span<const ExactPoint> path, const ExactPoint& a,
                                                 const ExactPoint& b, bool ray) {
  std::vector<PolylineCrossing> out;
  auto through_end = [&]() { throw std::invalid_argument("polyline_crossings: the polyline passes through an end of the segment"); };
  // Side of ab's line, with points on the line counted as left (perturbed leftwards).
  auto side = [&](const ExactPoint& x) {
    const auto o = CGAL::orientation(a, b, x);
    if (o == CGAL::COLLINEAR && (x == a || (!ray && x == b))) through_end();
    return o == CGAL::RIGHT_TURN ? -1 : +1;
  };
  // x on ab's line, not at a: is it on the open segment (ray)?
  auto within = [&](const ExactPoint& x) {
    return ray ? CGAL::angle(b, a, x) == CGAL::ACUTE : CGAL::collinear_are_strictly_ordered_along_line(a, x, b);
  };
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const ExactPoint &p = path[i], &q = path[i + 1];
    const int sp = side(p), sq = side(q);
    if (sp == sq) continue;
    // The segment meets ab's line once; a perturbed on-line vertex meets it at itself.
    auto meet = [&]() -> std::optional<ExactPoint> {
      for (const ExactPoint* x : {&p, &q})
        if (CGAL::orientation(a, b, *x) == CGAL::COLLINEAR) {
          if (within(*x)) return *x;
          return std::nullopt;
        }
      // p and q strictly on opposite sides: the segment meets the line at one point.
      const auto o3 = CGAL::orientation(p, q, a), o4 = CGAL::orientation(p, q, b);
      if (o3 == CGAL::COLLINEAR || (!ray && o4 == CGAL::COLLINEAR)) through_end();
      if (!ray && o3 == o4) return std::nullopt;
      const auto hit = CGAL::intersection(ExactKernel::Line_2(p, q), ExactKernel::Line_2(a, b));
      const ExactPoint X = *boost::get<ExactPoint>(&*hit);
      if (ray && !within(X)) return std::nullopt;
      return X;
    };
    const auto at = meet();
    if (!at) continue;
    out.push_back({i, *at, sp < 0 ? +1 : -1});
  }
  // Several crossings on one polyline segment: in order from its start.
  std::stable_sort(out.begin(), out.end(), [&](const PolylineCrossing& u, const PolylineCrossing& v) {
    if (u.segment != v.segment) return u.segment < v.segment;
    return CGAL::compare_distance_to_point(path[u.segment], u.at, v.at) == CGAL::SMALLER;
  });
  return out;
}

}  // namespace preimage::geometry
