// SPDX-License-Identifier: Apache-2.0
// Critical rays of the conservative cells (Choset et al. 6.3, Fig. 6.35) and the sight
// lines along them. Every decision is an orientation or dot-product sign on input points
// (a ray's carrier is the line through two environment vertices); only ray hits are
// constructed (lazy exact, by shoot_ray).
#include <preimage/pursuit/critical.hpp>

#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <stdexcept>

namespace preimage::pursuit {

using geometry::orientation;

bool tangent_at(const Environment& env, std::size_t v, const Point& p) {
  const Point& c = env.vertex(v);
  const int a = orientation(p, c, env.vertex(env.wedge_prev(v))), b = orientation(p, c, env.vertex(env.next(v)));
  return a * b >= 0;
}

bool is_reflex_wedge(const Environment& env, std::size_t v) { return env.wedge_turn(v) < 0; }

namespace {

// A look direction along a carrier: the line through input points tail -> head.
struct Direction {
  Point tail, head;
  // +1 left of the direction, -1 right, 0 on the line.
  int side(const Point& x) const { return orientation(tail, head, x); }
  // Sign of (to - from) . (head - tail).
  int along(const Point& from, const Point& to) const { return geometry::dot_sign(tail, head, from, to); }
  geometry::ExactKernel::Vector_2 vector() const { return geometry::to_exact(head) - geometry::to_exact(tail); }
};

// The obstacle side (relative to the look direction) of the boundary edge a -> b lying on
// the line: free space is left of every edge in ring order.
int wall_obstacle_side(const Environment& env, std::size_t a, std::size_t b, const Direction& d) {
  return d.along(env.vertex(a), env.vertex(b)) > 0 ? -1 : +1;  // obstacle on the edge's right
}

// Classifies vertex v met by the sight line in direction d. Returns false for a stop.
// At a contact the line arrives in one free wedge and is classified against that wedge's
// two edges (the wedge's id is what names the vertex): leaving into material or into
// another wedge through the point is a stop, since visibility is regularised (a line of
// sight through a contact point has no width).
bool classify(const Environment& env, std::size_t& v, const Direction& d, SightLine::Contact& c, std::size_t& wall_end) {
  if (env.is_contact(v)) {
    const ExactPoint behind = env.exact_vertex(v) - d.vector();
    const std::size_t w = geometry::wedge_toward(env, v, behind);
    if (w == SIZE_MAX) throw std::logic_error("pursuit: a sight line reaches contact vertex " + std::to_string(v) + " from material");
    v = w;
  }
  const Point& x = env.vertex(v);
  int off_side = 0, off_count = 0, wall_side = 0;
  bool forward_wall = false, backward_wall = false;
  std::size_t forward_end = kNone;
  for (std::size_t n : {env.wedge_prev(v), env.next(v)}) {
    const int s = d.side(env.vertex(n));
    if (s != 0) {
      if (off_count && s != off_side) return false;  // neighbours on both sides: the line enters the obstacle
      off_side = s, ++off_count;
      continue;
    }
    const bool edge_from_v = n == env.next(v);  // edge v -> n, else n -> v (into the wedge's point)
    const int w = edge_from_v ? wall_obstacle_side(env, v, n, d) : wall_obstacle_side(env, n, v, d);
    if (wall_side && w != wall_side) return false;  // cannot happen on a valid ring
    wall_side = w;
    if (d.along(x, env.vertex(n)) > 0) forward_wall = true, forward_end = n;
    else backward_wall = true;
  }
  if (off_count == 2) {
    c = {static_cast<std::uint32_t>(v), off_side, false};
  } else if (off_count == 1) {
    if (wall_side != off_side) return false;  // the obstacle wedge holds the line ahead
    c = {static_cast<std::uint32_t>(v), off_side, forward_wall};
  } else {
    if (!(forward_wall && backward_wall)) return false;
    c = {static_cast<std::uint32_t>(v), wall_side, true};
  }
  wall_end = forward_end;
  return true;
}

// Contacts from vertex `first` on, looking in direction d.
SightLine trace(const Environment& env, std::size_t first, const Direction& d) {
  SightLine out;
  std::size_t v = first;
  for (std::size_t guard = 0; guard <= env.num_vertices(); ++guard) {
    SightLine::Contact c;
    std::size_t wall_end = kNone;
    if (!classify(env, v, d, c, wall_end)) return out;  // (v: the wedge the line arrives in)
    out.contacts.push_back(c);
    if (c.wall_after) {
      v = wall_end;
      continue;
    }
    const auto hit = geometry::shoot_ray(env, env.exact_vertex(v), d.vector());
    if (!hit || !hit->vertex) return out;  // a transversal hit inside an edge
    v = *hit->vertex;
  }
  throw std::logic_error("pursuit: sight line from vertex " + std::to_string(first) + " does not end");
}

}  // namespace

std::vector<CriticalSegment> critical_segments(const Environment& env) {
  // Vertex ids name free wedges (at a contact, the wedge starting at the id's out-edge):
  // "reflex", "tangent" and the extended edges are the wedge's.
  const std::size_t n = env.num_vertices();
  std::vector<std::uint32_t> reflex;
  for (std::size_t v = 0; v < n; ++v)
    if (is_reflex_wedge(env, v)) reflex.push_back(static_cast<std::uint32_t>(v));

  // Rays as (origin, partner): the ray leaves `origin` in direction origin - partner.
  struct Ray {
    std::uint32_t origin, partner;
    CriticalGenerator gen;
  };
  std::vector<Ray> rays;
  for (std::uint32_t r : reflex)
    for (std::size_t u : {env.wedge_prev(r), env.next(r)})
      rays.push_back({r, static_cast<std::uint32_t>(u), {CriticalGenerator::Kind::Extension, r, static_cast<std::uint32_t>(u)}});
  // Does the ray from a away from b run along an edge at a (it then lies on the boundary)?
  auto along_own_edge = [&](std::size_t a, std::size_t b) {
    for (std::size_t u : {env.wedge_prev(a), env.next(a)})
      if (orientation(env.vertex(b), env.vertex(a), env.vertex(u)) == 0 &&
          geometry::dot_sign(env.vertex(b), env.vertex(a), env.vertex(a), env.vertex(u)) > 0)
        return true;
    return false;
  };
  // The line from wedge a's point towards point p leaves within wedge a.
  auto leaves_in = [&](std::size_t a, const Point& p) {
    return !env.is_contact(a) || geometry::wedge_toward(env, a, p) == a;
  };
  for (std::size_t i = 0; i < reflex.size(); ++i)
    for (std::size_t j = i + 1; j < reflex.size(); ++j) {
      const std::uint32_t u = reflex[i], w = reflex[j];
      if (env.vertex(u) == env.vertex(w)) continue;  // two wedges of one contact
      if (!tangent_at(env, u, env.vertex(w)) || !tangent_at(env, w, env.vertex(u))) continue;
      if (!leaves_in(u, env.vertex(w)) || !leaves_in(w, env.vertex(u))) continue;
      if (!geometry::visible(env, env.vertex(u), env.vertex(w))) continue;
      if (!along_own_edge(u, w)) rays.push_back({u, w, {CriticalGenerator::Kind::Bitangent, u, w}});
      if (!along_own_edge(w, u)) rays.push_back({w, u, {CriticalGenerator::Kind::Bitangent, w, u}});
    }
  // Contact rays: a contact point c is seen from one wedge there at most, and a shadow
  // pinched at c is one region only while c is hidden (the evader passes through the
  // point). Whether c is seen changes where the line of sight to c grazes a reflex wedge u
  // tangent to it: the ray from u away from c. (Where c's wedge is tangent too, this is a
  // bitangent ray, merged below.)
  for (std::size_t c = 0; c < n; ++c) {
    if (!env.is_contact(c)) continue;
    bool first = true;  // one id per contact point
    for (std::size_t w = env.same_point_next(c); w != c; w = env.same_point_next(w)) first = first && c < w;
    if (!first) continue;
    for (std::uint32_t u : reflex) {
      if (env.vertex(u) == env.vertex(c)) continue;
      if (!tangent_at(env, u, env.vertex(c)) || !leaves_in(u, env.vertex(c))) continue;
      if (geometry::wedge_toward(env, c, env.vertex(u)) == SIZE_MAX) continue;  // the line arrives at c from material
      if (along_own_edge(u, c) || !geometry::visible(env, env.vertex(u), env.vertex(c))) continue;
      rays.push_back({u, static_cast<std::uint32_t>(c), {CriticalGenerator::Kind::Contact, u, static_cast<std::uint32_t>(c)}});
    }
  }

  std::vector<CriticalSegment> segs;
  segs.reserve(rays.size());
  for (const Ray& r : rays) {
    const Direction d{env.vertex(r.partner), env.vertex(r.origin)};
    const auto hit = geometry::shoot_ray(env, env.exact_vertex(r.origin), d.vector());
    if (!hit || hit->along_edge)
      throw std::logic_error("pursuit: critical ray from vertex " + std::to_string(r.origin) + " does not enter free space");
    CriticalSegment s;
    s.origin = r.origin, s.partner = r.partner;
    s.from = env.exact_vertex(r.origin);
    s.to = hit->point;
    s.end = hit->vertex ? geometry::SegmentEnd{geometry::SegmentEnd::Kind::AtVertex, static_cast<std::uint32_t>(*hit->vertex)}
                        : geometry::SegmentEnd{geometry::SegmentEnd::Kind::OnEdge, static_cast<std::uint32_t>(hit->edge)};
    s.generators.push_back(r.gen);
    segs.push_back(std::move(s));
  }

  // Coinciding rays: equal end points (two critical segments whose interiors lie in open
  // free space and whose ends lie on the boundary either coincide or share no interior).
  auto key_less = [](const ExactPoint& a, const ExactPoint& b) { return CGAL::compare_xy(a, b) == CGAL::SMALLER; };
  struct Key {
    ExactPoint lo, hi;  // handles (shared, cheap to copy)
  };
  std::vector<Key> keys;
  keys.reserve(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const bool fwd = key_less(segs[i].from, segs[i].to);
    keys.push_back({fwd ? segs[i].from : segs[i].to, fwd ? segs[i].to : segs[i].from});
  }
  std::vector<std::size_t> order(segs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto c = CGAL::compare_xy(keys[a].lo, keys[b].lo);
    if (c != CGAL::EQUAL) return c == CGAL::SMALLER;
    const auto d = CGAL::compare_xy(keys[a].hi, keys[b].hi);
    if (d != CGAL::EQUAL) return d == CGAL::SMALLER;
    return a < b;
  });
  std::vector<CriticalSegment> out;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    if (k > 0) {
      const std::size_t p = order[k - 1];
      if (keys[i].lo == keys[p].lo && keys[i].hi == keys[p].hi) {
        auto& g = out.back().generators;
        g.insert(g.end(), segs[i].generators.begin(), segs[i].generators.end());
        continue;
      }
    }
    out.push_back(std::move(segs[i]));
  }
  // Sight lines along each segment, both ways.
  for (auto& s : out) {
    const Direction fwd{env.vertex(s.partner), env.vertex(s.origin)}, back{env.vertex(s.origin), env.vertex(s.partner)};
    s.backward = trace(env, s.origin, back);
    if (s.end.kind == geometry::SegmentEnd::Kind::AtVertex) s.forward = trace(env, s.end.index, fwd);
  }
  return out;
}

}  // namespace preimage::pursuit
