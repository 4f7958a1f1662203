// SPDX-License-Identifier: Apache-2.0
// Ground truth of the section VI sensors (see sensors.hpp).
#include <preimage/wallfollow/sensors.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <stdexcept>

namespace preimage::wallfollow {

using geometry::Environment;
using geometry::ExactFT;
using geometry::ExactPoint;
using geometry::VisibilityPolygon;
using geometry::VisibilityVertex;

BoundaryPoint boundary_vertex(const Environment& env, std::uint32_t v, int nudge) {
  // A germ before v lies at the end of the edge arriving at v.
  if (nudge < 0) return {static_cast<std::uint32_t>(env.prev(v)), env.exact_vertex(v), -1};
  return {v, env.exact_vertex(v), nudge};
}

BoundaryPoint boundary_point(const Environment& env, const ExactPoint& p) {
  const auto loc = geometry::locate(env, p);
  if (loc.kind == geometry::Location::Kind::AtVertex) return boundary_vertex(env, static_cast<std::uint32_t>(loc.index));
  if (loc.kind == geometry::Location::Kind::OnEdge) return {static_cast<std::uint32_t>(loc.index), p, 0};
  throw InputError("point " + geometry::format_point(geometry::to_double(p)) + " is not on the boundary");
}

bool boundary_less(const Environment& env, const BoundaryPoint& a, const BoundaryPoint& b) {
  if (a.edge != b.edge) return a.edge < b.edge;
  const auto c = CGAL::compare_distance_to_point(env.exact_vertex(a.edge), a.point, b.point);
  if (c != CGAL::EQUAL) return c == CGAL::SMALLER;
  return a.nudge < b.nudge;
}

bool in_open_arc(const Environment& env, const BoundaryPoint& x, const BoundaryPoint& a, const BoundaryPoint& b) {
  const bool ax = boundary_less(env, a, x), xb = boundary_less(env, x, b);
  return boundary_less(env, a, b) ? ax && xb : ax || xb;
}

namespace {

// Boundary point of visibility vertex k of V.
BoundaryPoint point_of(const Environment& env, const VisibilityPolygon& V, std::size_t k) {
  const VisibilityVertex& w = V.vertices[k];
  switch (w.kind) {
    case VisibilityVertex::Kind::EnvironmentVertex: return boundary_vertex(env, w.vertex);
    case VisibilityVertex::Kind::RayHit: return {w.edge, V.exact(k), 0};
    case VisibilityVertex::Kind::Query: break;
  }
  if (V.location.kind == geometry::Location::Kind::AtVertex) return boundary_vertex(env, static_cast<std::uint32_t>(V.location.index));
  if (V.location.kind == geometry::Location::Kind::OnEdge) return {static_cast<std::uint32_t>(V.location.index), V.exact_query(), 0};
  throw std::logic_error("shadow_arcs: a free edge ends at an interior query point");
}

}  // namespace

std::vector<ShadowArc> shadow_arcs(const Environment& env, const VisibilityPolygon& V) {
  if (env.num_holes() > 0) throw std::logic_error("shadow_arcs: the environment is not simply connected");
  std::vector<ShadowArc> out;
  const std::size_t n = V.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (V.edges[i].kind != geometry::VisibilityEdge::Kind::Free) continue;
    const std::size_t k = (i + 1) % n;
    const ExactPoint A = V.exact(i), B = V.exact(k);
    // Ends and environment vertices strictly inside the free edge (the query in line with
    // two vertices): the shadow on the right splits at each such vertex.
    std::vector<std::pair<BoundaryPoint, long>> ends{{point_of(env, V, i), -1}};
    auto vertex_at = [&](std::size_t j) {
      return V.vertices[j].kind == VisibilityVertex::Kind::EnvironmentVertex ? static_cast<long>(V.vertices[j].vertex) : -1L;
    };
    ends.back().second = vertex_at(i);
    std::vector<std::pair<ExactPoint, std::uint32_t>> inner;
    for (std::uint32_t v = 0; v < env.num_vertices(); ++v) {
      const ExactPoint& e = env.exact_vertex(v);
      if (geometry::orientation(A, B, e) == 0 && CGAL::collinear_are_strictly_ordered_along_line(A, e, B)) inner.push_back({e, v});
    }
    std::sort(inner.begin(), inner.end(), [&](auto& x, auto& y) {
      return CGAL::compare_distance_to_point(A, x.first, y.first) == CGAL::SMALLER;
    });
    for (auto& [p, v] : inner) ends.push_back({boundary_vertex(env, v), static_cast<long>(v)});
    ends.push_back({point_of(env, V, k), vertex_at(k)});
    for (std::size_t s = 0; s + 1 < ends.size(); ++s) {
      const long a = ends[s].second, b = ends[s + 1].second;
      // A piece along an edge (the query in line with it) lies on the boundary: no shadow.
      if (a >= 0 && b >= 0 && (env.next(static_cast<std::size_t>(a)) == static_cast<std::size_t>(b) ||
                               env.next(static_cast<std::size_t>(b)) == static_cast<std::size_t>(a)))
        continue;
      ShadowArc arc{ends[s].first, ends[s + 1].first, {}};
      if (a >= 0) arc.germs.push_back(boundary_vertex(env, static_cast<std::uint32_t>(a), +1));
      if (b >= 0) arc.germs.push_back(boundary_vertex(env, static_cast<std::uint32_t>(b), -1));
      out.push_back(std::move(arc));
    }
  }
  if (V.location.kind != geometry::Location::Kind::Interior) {
    // Counter-clockwise from the query's own boundary point.
    BoundaryPoint q = V.location.kind == geometry::Location::Kind::AtVertex
                          ? boundary_vertex(env, static_cast<std::uint32_t>(V.location.index))
                          : BoundaryPoint{static_cast<std::uint32_t>(V.location.index), V.exact_query(), 0};
    std::sort(out.begin(), out.end(), [&](const ShadowArc& x, const ShadowArc& y) {
      const bool xa = boundary_less(env, q, x.from), ya = boundary_less(env, q, y.from);
      if (xa != ya) return xa;  // after q before wrapped around
      return boundary_less(env, x.from, y.from);
    });
  }
  return out;
}

bool corresponds(const Environment& env, const ShadowArc& a, const ShadowArc& b) {
  for (auto& g : b.germs)
    if (in_open_arc(env, g, a.from, a.to)) return true;
  for (auto& g : a.germs)
    if (in_open_arc(env, g, b.from, b.to)) return true;
  return false;
}

std::vector<VertexLine> vertex_lines(const geometry::VisibilityIndex& vis) {
  // A walk through the triangles the segment crosses, from u's fan: geometry::visible's
  // answer without its O(n) scan per pair (2,000 vertices: 15 s with the scan).
  const Environment& env = vis.environment();
  std::vector<VertexLine> lines;
  for (std::uint32_t u = 0; u < env.num_vertices(); ++u) {
    if (!env.is_reflex(u)) continue;
    for (std::uint32_t w = 0; w < env.num_vertices(); ++w)
      if (w != u && (!env.is_reflex(w) || w > u) && vis.visible_from_vertex(u, env.vertex(w))) lines.push_back({u, w});
  }
  return lines;
}

std::vector<VertexLine> vertex_lines(const Environment& env) { return vertex_lines(geometry::VisibilityIndex(env)); }

namespace {

// Interior parameters in (0, 1) where segment a -> b crosses a vertex line, sorted, distinct.
std::vector<ExactFT> events_on(const Environment& env, const std::vector<VertexLine>& lines, const ExactPoint& a,
                               const ExactPoint& b) {
  std::vector<ExactFT> ts;
  for (auto [u, w] : lines) {
    const ExactPoint &p = env.exact_vertex(u), &q = env.exact_vertex(w);
    const int sa = geometry::orientation(p, q, a), sb = geometry::orientation(p, q, b);
    if (sa * sb >= 0) continue;
    const auto d = q - p;
    const ExactFT ca = d.x() * (a.y() - p.y()) - d.y() * (a.x() - p.x());
    const ExactFT cb = d.x() * (b.y() - p.y()) - d.y() * (b.x() - p.x());
    ts.push_back(ca / (ca - cb));
  }
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

}  // namespace

GapReading gap_reading(const geometry::VisibilityIndex& vis, const std::vector<VertexLine>& lines,
                       const std::vector<ExactPoint>& path) {
  const Environment& env = vis.environment();
  GapReading r;
  if (path.empty()) return r;
  auto arcs_at = [&](const ExactPoint& q) { return shadow_arcs(env, vis.compute(q)); };
  std::vector<ShadowArc> prev = arcs_at(path.front());
  auto step = [&](std::vector<ShadowArc> next) {
    filter::ShadowEvent e{prev.size(), next.size(), {}};
    for (std::uint32_t i = 0; i < prev.size(); ++i)
      for (std::uint32_t j = 0; j < next.size(); ++j)
        if (corresponds(env, prev[i], next[j])) e.pairs.push_back({i, j});
    bool identity = prev.size() == next.size() && e.pairs.size() == prev.size();
    for (auto [i, j] : e.pairs) identity = identity && i == j;
    if (!identity) r.events.push_back(std::move(e));
    prev = std::move(next);
  };
  for (std::size_t s = 0; s + 1 < path.size(); ++s) {
    const ExactPoint &a = path[s], &b = path[s + 1];
    if (a == b) continue;
    // One sample between every two events (never on an event line inside the segment:
    // there V loses needles), and the segment's end.
    std::vector<ExactFT> cuts{0};
    for (auto& t : events_on(env, lines, a, b)) cuts.push_back(t);
    cuts.push_back(1);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const ExactFT mid = (cuts[k] + cuts[k + 1]) / 2;
      step(arcs_at(a + mid * (b - a)));
    }
    step(arcs_at(b));
  }
  r.gaps = prev.size();
  return r;
}

std::size_t gap_count(const geometry::VisibilityIndex& vis, const ExactPoint& q) {
  return shadow_arcs(vis.environment(), vis.compute(q)).size();
}

namespace {
// Both edges at v on one side of the line through v and w (tangent at v), exactly.
int tangent_side(const Environment& env, std::uint32_t v, std::uint32_t w) {
  const ExactPoint &p = env.exact_vertex(v), &q = env.exact_vertex(w);
  const int a = geometry::orientation(p, q, env.exact_vertex(env.prev(v)));
  const int b = geometry::orientation(p, q, env.exact_vertex(env.next(v)));
  return a == b ? a : 0;
}
}  // namespace

std::vector<Bitangent> bitangents(const Environment& env) {
  std::vector<Bitangent> out;
  const std::size_t n = env.num_vertices();
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!env.is_reflex(i)) continue;
    for (std::uint32_t j = i + 1; j < n; ++j) {
      if (!env.is_reflex(j)) continue;
      // Sides of the edges at v_i (w.r.t. the line i -> j) and at v_j (w.r.t. j -> i, the
      // opposite orientation: equal signs are opposite sides).
      const int si = tangent_side(env, i, j);
      if (si == 0) continue;
      const int sj = tangent_side(env, j, i);
      if (sj == 0 || !geometry::visible(env, env.vertex(i), env.vertex(j))) continue;
      Bitangent b{i, j, {}, {}, si == sj};
      const ExactPoint &pi = env.exact_vertex(i), &pj = env.exact_vertex(j);
      for (bool beyond_i : {true, false}) {
        const ExactPoint& from = beyond_i ? pi : pj;
        const auto hit = geometry::shoot_ray(env, from, beyond_i ? pi - pj : pj - pi);
        if (!hit) throw std::logic_error("bitangent ray leaves the environment");
        if (hit->vertex)
          throw InputError("$.environment.boundary: the line through vertices " + std::to_string(env.input_index(i)) + " and " +
                           std::to_string(env.input_index(j)) + " meets vertex " + std::to_string(env.input_index(*hit->vertex)) +
                           " (three collinear vertices: no general position)");
        (beyond_i ? b.b_ij : b.b_ji) = {static_cast<std::uint32_t>(hit->edge), hit->point, 0};
      }
      out.push_back(std::move(b));
    }
  }
  return out;
}

bool merged_side(const Environment& env, const Bitangent& b, bool at_j, const BoundaryPoint& x) {
  const BoundaryPoint v = boundary_vertex(env, at_j ? b.j : b.i), other = boundary_vertex(env, at_j ? b.i : b.j);
  const BoundaryPoint& end = at_j ? b.b_ji : b.b_ij;
  // The arc between the ray's ends without the other vertex.
  if (in_open_arc(env, other, end, v)) return in_open_arc(env, x, v, end);
  return in_open_arc(env, x, end, v);
}

bool sees_during(const VisibilityPolygon& Vp, const ExactPoint& a, const ExactPoint& b) {
  using K = geometry::ExactKernel;
  const auto loop = Vp.points();
  const std::size_t n = loop.size();
  if (a == b) {
    for (std::size_t i = 0; i < n; ++i)
      if (K::Segment_2(loop[i], loop[(i + 1) % n]).has_on(a)) return true;
    return geometry::winding_number(loop, a) != 0;
  }
  // A contact with the boundary of V other than at a, or b strictly inside.
  const K::Segment_2 ab(a, b);
  for (std::size_t i = 0; i < n; ++i) {
    const auto x = CGAL::intersection(ab, K::Segment_2(loop[i], loop[(i + 1) % n]));
    if (!x) continue;
    if (const auto* p = boost::get<ExactPoint>(&*x)) {
      if (!(*p == a)) return true;
    } else {
      return true;  // an overlap has an end other than a
    }
  }
  return geometry::winding_number(loop, b) != 0;
}

}  // namespace preimage::wallfollow
