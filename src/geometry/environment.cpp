// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/environment.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/geometry/segment_sweep.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

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
  auto where = [&](std::size_t v) { return names[ring_of[v]] + " vertex " + std::to_string(local[v]); };

  // Repeated vertices (within a ring, or two rings touching at a vertex).
  {
    std::vector<std::size_t> ord(pts.size());
    std::iota(ord.begin(), ord.end(), 0);
    std::sort(ord.begin(), ord.end(), [&](auto a, auto b) {
      return lex_less_xy(pts[a], pts[b]) || (pts[a] == pts[b] && a < b);
    });
    for (std::size_t k = 0; k + 1 < ord.size(); ++k) {
      auto a = ord[k], b = ord[k + 1];
      if (pts[a] != pts[b]) continue;
      if (ring_of[a] == ring_of[b])
        throw InputError(names[ring_of[a]] + ": vertices " + std::to_string(local[a]) + " and " +
                         std::to_string(local[b]) + " are repeated at " + format_point(pts[a]));
      throw InputError(where(b) + " touches " + where(a) + " at " + format_point(pts[a]));
    }
  }

  // Edges of all rings: no two may meet except consecutive edges at their shared vertex.
  {
    std::vector<IndexedSegment> segs;
    segs.reserve(pts.size());
    for (std::size_t r = 0; r + 1 < begin.size(); ++r)
      for (std::size_t v = begin[r]; v < begin[r + 1]; ++v)
        segs.push_back({static_cast<std::uint32_t>(v),
                        static_cast<std::uint32_t>(v + 1 == begin[r + 1] ? begin[r] : v + 1)});
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

  // Holes inside the outer boundary and not inside one another (boundaries are disjoint
  // now, so one vertex decides for a whole ring).
  for (std::size_t h = 0; h < holes.size(); ++h) {
    if (CGAL::bounded_side_2(outer.begin(), outer.end(), holes[h][0], Kernel()) != CGAL::ON_BOUNDED_SIDE)
      throw InputError(names[h + 1] + ": lies outside " + outer_name);
    for (std::size_t g = 0; g < holes.size(); ++g)
      if (g != h &&
          CGAL::bounded_side_2(holes[g].begin(), holes[g].end(), holes[h][0], Kernel()) == CGAL::ON_BOUNDED_SIDE)
        throw InputError(names[h + 1] + ": lies inside " + names[g + 1]);
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
  env.exact_pts_.reserve(env.pts_.size());
  for (const Point& p : env.pts_) env.exact_pts_.push_back(to_exact(p));
  env.exact_lines_.reserve(env.pts_.size());
  for (std::size_t e = 0; e < env.pts_.size(); ++e)
    env.exact_lines_.emplace_back(env.exact_pts_[e], env.exact_pts_[env.next(e)]);
  return env;
}

Ring Environment::ring(std::size_t r) const {
  return Ring(pts_.begin() + static_cast<std::ptrdiff_t>(ring_begin(r)),
              pts_.begin() + static_cast<std::ptrdiff_t>(ring_end(r)));
}

ExactFT Environment::exact_area() const {
  ExactFT twice = 0;
  for (std::size_t v = 0; v < pts_.size(); ++v) {
    const Point &a = pts_[v], &b = pts_[next(v)];
    twice += ExactFT(a.x()) * ExactFT(b.y()) - ExactFT(b.x()) * ExactFT(a.y());
  }
  return twice / 2;  // holes are clockwise, so they subtract themselves
}

double Environment::area() const {
  double twice = 0;
  for (std::size_t v = 0; v < pts_.size(); ++v) {
    const Point &a = pts_[v], &b = pts_[next(v)];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return twice / 2;
}

CGAL::Bbox_2 Environment::bbox() const {
  CGAL::Bbox_2 b;
  for (std::size_t v = ring_begin(0); v < ring_end(0); ++v) b += pts_[v].bbox();
  return b;
}

}  // namespace preimage::geometry
