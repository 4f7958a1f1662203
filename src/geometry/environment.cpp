// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/environment.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/geometry/segment_sweep.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <type_traits>
#include <utility>

namespace preimage::geometry {

std::string format_number(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

std::string format_point(double x, double y) {
  char buf[96];
  // + 0.0 turns a negative zero (a rounded exact 0) into "0".
  std::snprintf(buf, sizeof buf, "(%.12g, %.12g)", x + 0.0, y + 0.0);
  return buf;
}

namespace {

// Exact orientation of a simple ring: the turn at its lexicographically smallest vertex.
int ring_orientation(const Ring& r) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < r.size(); ++i)
    if (lex_less_xy(r[i], r[k])) k = i;
  const std::size_t n = r.size();
  return orientation(r[(k + n - 1) % n], r[k], r[(k + 1) % n]);
}

// Which rings strictly contain a vertex q of another ring: those a horizontal ray from q to
// the right crosses an odd number of times (rings are disjoint, so q lies on none). Edges
// are bucketed by y, so a query reads only the edges near q's height: O(n) to build, and a
// query costs the edges sharing its bucket, not all n (one bounded_side_2 per pair of
// rings was quadratic in the number of holes).
class RingIndex {
 public:
  RingIndex(const std::vector<Point>& pts, const std::vector<std::size_t>& begin, const std::vector<std::uint32_t>& ring_of)
      : pts_(pts), ring_of_(ring_of) {
    double lo = pts.empty() ? 0 : pts[0].y(), hi = lo;
    for (const Point& p : pts) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
    y0_ = lo;
    buckets_ = std::max<std::size_t>(pts.size(), 1);
    scale_ = hi > lo ? static_cast<double>(buckets_) / (hi - lo) : 0;
    // Bucket k holds the edges whose closed y-range meets its slab. bucket() is monotone
    // in y, so an edge reaching q.y is in q's bucket whatever the rounding.
    std::vector<std::uint32_t> count(buckets_ + 1, 0);
    auto each_edge = [&](auto&& fn) {
      for (std::size_t r = 0; r + 1 < begin.size(); ++r)
        for (std::size_t v = begin[r]; v < begin[r + 1]; ++v) {
          const std::size_t w = v + 1 == begin[r + 1] ? begin[r] : v + 1;
          if (pts[v].y() == pts[w].y()) continue;  // a horizontal edge never crosses the ray
          const std::size_t a = bucket(std::min(pts[v].y(), pts[w].y())), b = bucket(std::max(pts[v].y(), pts[w].y()));
          for (std::size_t k = a; k <= b; ++k) fn(k, static_cast<std::uint32_t>(v), static_cast<std::uint32_t>(w));
        }
    };
    each_edge([&](std::size_t k, std::uint32_t, std::uint32_t) { ++count[k + 1]; });
    std::partial_sum(count.begin(), count.end(), count.begin());
    first_ = count;
    edges_.resize(count.back());
    each_edge([&](std::size_t k, std::uint32_t v, std::uint32_t w) { edges_[count[k]++] = {v, w}; });
  }

  std::vector<std::uint32_t> around(std::uint32_t q) const {
    const Point& p = pts_[q];
    std::vector<std::uint32_t> odd;  // rings crossed an odd number of times so far
    const std::size_t k = bucket(p.y());
    for (std::size_t i = first_[k]; i < first_[k + 1]; ++i) {
      auto [v, w] = edges_[i];
      if (ring_of_[v] == ring_of_[q]) continue;
      const Point *a = &pts_[v], *b = &pts_[w];
      if (a->y() > b->y()) std::swap(a, b);
      // Half-open in y, so a ray through a vertex counts the two edges there once.
      if (!(a->y() <= p.y() && p.y() < b->y()) || orientation(*a, *b, p) <= 0) continue;
      const auto it = std::find(odd.begin(), odd.end(), ring_of_[v]);
      if (it == odd.end()) odd.push_back(ring_of_[v]);
      else odd.erase(it);
    }
    return odd;
  }

 private:
  std::size_t bucket(double y) const {
    const double k = std::floor((y - y0_) * scale_);
    return k <= 0 ? 0 : std::min(static_cast<std::size_t>(k), buckets_ - 1);
  }
  const std::vector<Point>& pts_;
  const std::vector<std::uint32_t>& ring_of_;
  double y0_ = 0, scale_ = 0;
  std::size_t buckets_ = 1;
  std::vector<std::uint32_t> first_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges_;
};

}  // namespace

Environment Environment::make(Ring outer, std::vector<Ring> holes, const std::string& outer_name,
                              const std::string& hole_prefix) {
  std::vector<Ring*> rings{&outer};
  for (auto& h : holes) rings.push_back(&h);
  std::vector<std::string> names{outer_name};
  for (std::size_t i = 0; i < holes.size(); ++i)
    names.push_back(hole_prefix + "[" + std::to_string(i) + "]");

  // Shape of each ring and finite coordinates.
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r];
    if (ring.size() < 3)
      throw InputError(names[r] + ": a polygon needs at least 3 vertices, got " + std::to_string(ring.size()));
    for (std::size_t i = 0; i < ring.size(); ++i)
      for (double c : {ring[i].x(), ring[i].y()})
        if (auto why = coordinate_problem(c); !why.empty())
          throw InputError(names[r] + ": vertex " + std::to_string(i) + ": " + why);
  }

  // Flatten (input order for now) so every error speaks in input indices.
  std::vector<Point> pts;
  std::vector<std::uint32_t> ring_of;
  std::vector<std::size_t> local;
  std::vector<std::size_t> begin{0};
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t i = 0; i < rings[r]->size(); ++i) {
      pts.push_back((*rings[r])[i]);
      ring_of.push_back(static_cast<std::uint32_t>(r));
      local.push_back(i);
    }
    begin.push_back(pts.size());
  }

  // Repeated vertices: within a ring an error; in different rings a contact (the rings
  // touch there). rep[v] is the smallest vertex at v's point, so edges of different rings
  // meeting at a contact share an endpoint index in the sweep below and may meet there.
  std::vector<std::uint32_t> rep(pts.size());
  std::iota(rep.begin(), rep.end(), 0u);
  std::vector<std::vector<std::uint32_t>> touching(rings.size());  // rings sharing a contact with r
  {
    std::vector<std::size_t> ord(pts.size());
    std::iota(ord.begin(), ord.end(), 0);
    std::sort(ord.begin(), ord.end(), [&](auto a, auto b) {
      return lex_less_xy(pts[a], pts[b]) || (pts[a] == pts[b] && a < b);
    });
    for (std::size_t k = 0; k < ord.size();) {
      std::size_t m = k + 1;
      while (m < ord.size() && pts[ord[m]] == pts[ord[k]]) ++m;
      for (std::size_t i = k; i < m; ++i)
        for (std::size_t j = k; j < i; ++j) {
          const auto a = ord[j], b = ord[i];
          if (ring_of[a] == ring_of[b])
            throw InputError(names[ring_of[a]] + ": vertices " + std::to_string(local[a]) + " and " +
                             std::to_string(local[b]) + " are repeated at " + format_point(pts[a]));
          touching[ring_of[a]].push_back(ring_of[b]);
          touching[ring_of[b]].push_back(ring_of[a]);
        }
      for (std::size_t i = k; i < m; ++i) rep[ord[i]] = static_cast<std::uint32_t>(ord[k]);
      k = m;
    }
  }

  // Edges of all rings: no two may meet except consecutive edges at their shared vertex and
  // edges of different rings at a contact (collinear overlap there is still a contact).
  {
    std::vector<IndexedSegment> segs;
    segs.reserve(pts.size());
    for (std::size_t r = 0; r + 1 < begin.size(); ++r)
      for (std::size_t v = begin[r]; v < begin[r + 1]; ++v)
        segs.push_back({rep[v], rep[v + 1 == begin[r + 1] ? begin[r] : v + 1]});
    if (auto c = find_segment_contact(pts, segs)) {
      auto e = c->first, f = c->second;  // segment index == start vertex index
      std::string near = " near " + format_point(c->near);
      if (ring_of[e] == ring_of[f])
        throw InputError(names[ring_of[e]] + ": edges " + std::to_string(local[e]) + " and " +
                         std::to_string(local[f]) + " intersect" + near);
      throw InputError(names[ring_of[f]] + " edge " + std::to_string(local[f]) + " touches " +
                       names[ring_of[e]] + " edge " + std::to_string(local[e]) + near);
    }
  }

  // Holes inside the outer boundary and not inside one another (boundaries do not cross
  // now, so one vertex decides for a whole ring). The parity is meaningless for a ring the
  // vertex lies on (a contact): for two rings that touch, the order of their edges around
  // the contact decides instead (check_contacts, below).
  if (!holes.empty()) {
    const RingIndex index(pts, begin, ring_of);
    for (std::size_t h = 0; h < holes.size(); ++h) {
      const auto& near = touching[h + 1];
      auto touches = [&](std::uint32_t g) { return std::find(near.begin(), near.end(), g) != near.end(); };
      const std::vector<std::uint32_t> around = index.around(static_cast<std::uint32_t>(begin[h + 1]));
      if (!touches(0) && std::find(around.begin(), around.end(), 0u) == around.end())
        throw InputError(names[h + 1] + ": lies outside " + outer_name);
      std::uint32_t inside = 0;  // the first hole holding it, as the message names one
      for (std::uint32_t g : around)
        if (g != 0 && !touches(g) && (inside == 0 || g < inside)) inside = g;
      if (inside != 0) throw InputError(names[h + 1] + ": lies inside " + names[inside]);
    }
  }

  // Normalise: outer counter-clockwise, holes clockwise.
  Environment env;
  env.ring_begin_ = begin;
  env.ring_names_ = names;
  env.pts_.reserve(pts.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = *rings[r];
    const int want = r == 0 ? +1 : -1;
    const bool flip = ring_orientation(ring) != want;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      std::size_t src = flip ? (ring.size() - i) % ring.size() : i;  // keep vertex 0 first
      env.pts_.push_back(ring[src]);
      env.input_index_.push_back(src);
      env.ring_of_.push_back(static_cast<std::uint32_t>(r));
    }
  }
  env.link_contacts(names, rep);
  env.exact_pts_.reserve(env.pts_.size());
  for (const Point& p : env.pts_) env.exact_pts_.push_back(to_exact(p));
  env.exact_lines_.reserve(env.pts_.size());
  for (std::size_t e = 0; e < env.pts_.size(); ++e)
    env.exact_lines_.emplace_back(env.exact_pts_[e], env.exact_pts_[env.next(e)]);
  return env;
}

// Around each contact: sort the rings' edge directions counter-clockwise and check that
// every ring's material sector (from its in-edge to its out-edge, counter-clockwise) holds
// no other direction; then the free wedges are the gaps out(v) -> in(u) between sectors.
// Directions are compared exactly (half-plane, then orientation), never as angles.
void Environment::link_contacts(const std::vector<std::string>& names, const std::vector<std::uint32_t>& input_rep) {
  const std::size_t n = pts_.size();
  same_next_.resize(n), wedge_end_.resize(n), wedge_start_.resize(n);
  std::iota(same_next_.begin(), same_next_.end(), 0u);
  std::iota(wedge_end_.begin(), wedge_end_.end(), 0u);
  std::iota(wedge_start_.begin(), wedge_start_.end(), 0u);
  // Group stored vertices by the input representative of their point.
  std::vector<std::uint32_t> input_id(n);  // stored vertex -> flat input index
  for (std::size_t v = 0; v < n; ++v) input_id[v] = static_cast<std::uint32_t>(ring_begin_[ring_of_[v]] + input_index_[v]);
  std::vector<std::uint32_t> by_rep(n, UINT32_MAX);  // input rep -> first stored vertex
  std::vector<std::uint32_t> stored_of_input(n);
  for (std::size_t v = 0; v < n; ++v) stored_of_input[input_id[v]] = static_cast<std::uint32_t>(v);
  for (std::size_t v = 0; v < n; ++v) {
    const std::uint32_t r = input_rep[input_id[v]];
    if (r == input_id[v]) continue;
    // v joins the cycle of its representative's stored vertex.
    const std::uint32_t head = stored_of_input[r];
    same_next_[v] = same_next_[head];
    same_next_[head] = static_cast<std::uint32_t>(v);
    by_rep[r] = head;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (by_rep[i] == UINT32_MAX) continue;
    ++num_contacts_;
    std::vector<std::uint32_t> group;
    for (std::uint32_t v = by_rep[i];;) {
      group.push_back(v);
      v = same_next_[v];
      if (v == by_rep[i]) break;
    }
    contact_merges_ += group.size() - 1;
    const Point& p = pts_[group[0]];
    // Directions: (vertex id, is_out) for every ring at p.
    struct Dir { std::uint32_t v; bool out; const Point* to; };
    std::vector<Dir> dirs;
    for (std::uint32_t v : group) dirs.push_back({v, false, &pts_[prev(v)]}), dirs.push_back({v, true, &pts_[next(v)]});
    std::sort(dirs.begin(), dirs.end(), [&](const Dir& a, const Dir& b) { return ccw_less(p, *a.to, *b.to); });
    auto name = [&](std::uint32_t v) {
      return names[ring_of_[v]] + " vertex " + std::to_string(input_index_[v]);
    };
    const std::size_t m = dirs.size();
    for (std::size_t k = 0; k < m; ++k) {
      const Dir &d = dirs[k], &e = dirs[(k + 1) % m];
      if (!d.out && (!e.out || e.v != d.v))
        throw InputError(name(e.v) + " and " + name(d.v) + " overlap at " + format_point(p) +
                         ": rings may touch at a contact, not cross or overlap there");
      if (d.out) wedge_end_[d.v] = e.v, wedge_start_[e.v] = d.v;  // e is an in-edge (checked at e)
    }
  }
}

std::size_t Environment::edge_between(std::size_t a, std::size_t b) const {
  if (next(a) == b) return a;
  if (!has_contacts()) return SIZE_MAX;
  for (std::size_t x = a;;) {
    if (pts_[next(x)] == pts_[b]) return x;
    x = same_next_[x];
    if (x == a) return SIZE_MAX;
  }
}

Ring Environment::ring(std::size_t r) const {
  return Ring(pts_.begin() + static_cast<std::ptrdiff_t>(ring_begin(r)),
              pts_.begin() + static_cast<std::ptrdiff_t>(ring_end(r)));
}

ExactFT Environment::exact_area() const {
  // Summed in the exact number type itself: a lazy sum of n terms is a chain n deep, which
  // CGAL evaluates recursively when a comparison needs it (it overflowed the stack at 10^5
  // vertices).
  using Exact = std::decay_t<decltype(CGAL::exact(std::declval<ExactFT>()))>;
  Exact twice = 0;
  for (std::size_t v = 0; v < pts_.size(); ++v) {
    const Point &a = pts_[v], &b = pts_[next(v)];
    twice += Exact(a.x()) * Exact(b.y()) - Exact(b.x()) * Exact(a.y());
  }
  return ExactFT(twice / 2);  // holes are clockwise, so they subtract themselves
}

double Environment::area() const {
  // Cross products about the first vertex, not the origin: a plan 1e10 from the origin would
  // otherwise sum terms of 1e20 whose rounding (16384 each) swamps its area.
  if (pts_.empty()) return 0;
  const double ox = pts_[0].x(), oy = pts_[0].y();
  double twice = 0;
  for (std::size_t v = 0; v < pts_.size(); ++v) {
    const Point &a = pts_[v], &b = pts_[next(v)];
    const double ax = a.x() - ox, ay = a.y() - oy, bx = b.x() - ox, by = b.y() - oy;
    twice += ax * by - bx * ay;
  }
  return twice / 2;
}

Environment Environment::translated(double dx, double dy) const {
  // The caller guarantees exact differences (LocalFrame), so orientations, contacts and
  // wedges are those of *this and only the coordinates change.
  Environment env = *this;
  for (std::size_t v = 0; v < pts_.size(); ++v) {
    env.pts_[v] = Point(pts_[v].x() - dx, pts_[v].y() - dy);
    env.exact_pts_[v] = to_exact(env.pts_[v]);
  }
  for (std::size_t e = 0; e < pts_.size(); ++e) env.exact_lines_[e] = ExactKernel::Line_2(env.exact_pts_[e], env.exact_pts_[env.next(e)]);
  return env;
}

CGAL::Bbox_2 Environment::bbox() const {
  CGAL::Bbox_2 b;
  for (std::size_t v = ring_begin(0); v < ring_end(0); ++v) b += pts_[v].bbox();
  return b;
}

}  // namespace preimage::geometry
