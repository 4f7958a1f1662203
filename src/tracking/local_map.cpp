// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/tracking/local_map.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <cmath>

namespace preimage::tracking {

const char* to_string(EdgeKind k) {
  switch (k) {
    case EdgeKind::Solid: return "solid";
    case EdgeKind::Occlusion: return "occlusion";
    case EdgeKind::Range: return "range";
    case EdgeKind::FieldOfView: return "field-of-view";
  }
  return "?";
}

std::size_t LocalMap::count(EdgeKind k) const {
  std::size_t c = 0;
  for (auto e : edges) c += e == k;
  return c;
}

double LocalMap::area() const {
  double a = 0;
  for (std::size_t i = 0; i < size(); ++i) {
    const Point& p = vertices[i];
    const Point& q = vertices[next(i)];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a / 2;
}

// CGAL's exact point-in-polygon test (Polygon_2 algorithms, LGPL), as Environment uses.
bool LocalMap::contains(const Point& p) const {
  return CGAL::bounded_side_2(vertices.begin(), vertices.end(), p, geometry::Kernel()) != CGAL::ON_UNBOUNDED_SIDE;
}
bool LocalMap::strictly_contains(const Point& p) const {
  return CGAL::bounded_side_2(vertices.begin(), vertices.end(), p, geometry::Kernel()) == CGAL::ON_BOUNDED_SIDE;
}

void LocalMap::validate(const std::string& what) const {
  const std::size_t n = size();
  if (n < 3) throw InputError(what + ": a visibility polygon needs at least 3 vertices, got " + std::to_string(n));
  if (edges.size() != n || corner.size() != n)
    throw InputError(what + ": " + std::to_string(n) + " vertices but " + std::to_string(edges.size()) + " edge tags and " +
                     std::to_string(corner.size()) + " corner entries");
  if (!std::isfinite(observer.x()) || !std::isfinite(observer.y())) throw InputError(what + ": the observer is not finite");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(vertices[i].x()) || !std::isfinite(vertices[i].y()))
      throw InputError(what + ": vertex " + std::to_string(i) + " is not finite");
  // The message is built only on failure: validate runs once per scan in TRACK.
  auto edge_name = [&](std::size_t i, std::size_t j) {
    return std::string(what).append(": edge ").append(std::to_string(i)).append(" (vertices ").append(std::to_string(i))
        .append("-").append(std::to_string(j)).append(")");
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = next(i);
    if (vertices[i] == vertices[j]) throw InputError(edge_name(i, j) + " has zero length");
    if (edges[i] == EdgeKind::Occlusion) {
      if (corner[i] != i && corner[i] != j)
        throw InputError(edge_name(i, j) + ": an occlusion edge needs its corner at one of its endpoints");
    } else if (corner[i] != kNone) {
      throw InputError(edge_name(i, j) + ": only occlusion edges have a corner");
    }
    const bool at_observer = i == observer_vertex || j == observer_vertex;
    if (at_observer) {
      if (edges[i] != EdgeKind::FieldOfView)
        throw InputError(edge_name(i, j) + ": edges at the observer must be field-of-view bounds");
      continue;
    }
    if (edges[i] == EdgeKind::FieldOfView) throw InputError(edge_name(i, j) + ": a field-of-view bound must end at the observer");
    // Angular order about the observer: no edge may turn clockwise (the sweep needs V
    // star-shaped, so that the line through the target crosses it once).
    const int turn = geometry::orientation(observer, vertices[i], vertices[j]);
    if (turn < 0)
      throw InputError(edge_name(i, j) + " turns clockwise about the observer: vertices are not in counter-clockwise angular order");
    if (turn == 0 && geometry::on_segment(vertices[i], vertices[j], observer))
      throw InputError(edge_name(i, j) + " passes through the observer");
  }
  if (observer_vertex == kNone) {
    if (!strictly_contains(observer)) throw InputError(what + ": the observer is not inside its visibility polygon");
  } else if (observer_vertex >= n || vertices[observer_vertex] != observer) {
    throw InputError(what + ": observer_vertex does not hold the observer");
  } else if (geometry::orientation(vertices[prev(observer_vertex)], observer, vertices[next(observer_vertex)]) < 0) {
    throw InputError(what + ": the field of view is wider than 180 deg (only cones up to 180 deg or full 360 deg are supported)");
  }
  if (area() <= 0) throw InputError(what + ": the polygon is not counter-clockwise");
}

void straighten_occlusion_edges(LocalMap& m) {
  const Point& o = m.observer;
  for (std::size_t e = 0; e < m.size(); ++e) {
    if (m.edges[e] == EdgeKind::FieldOfView) continue;
    const std::size_t f = m.next(e);
    if (geometry::orientation(o, m.vertices[e], m.vertices[f]) >= 0) continue;
    // Turn the far end about the observer, counter-clockwise if it is the edge's second
    // endpoint and clockwise if its first, by steps growing from ~1e-15 rad, until the
    // exact predicate accepts the edge. (A solid edge seen edge-on is radial too.)
    const bool far_is_second = m.edges[e] == EdgeKind::Occlusion
                                   ? m.corner[e] == e
                                   : CGAL::compare_distance_to_point(o, m.vertices[f], m.vertices[e]) == CGAL::LARGER;
    Point& far = m.vertices[far_is_second ? f : e];
    const double dx = far.x() - o.x(), dy = far.y() - o.y();
    for (double a = 1e-15; a < 1e-6; a *= 2) {
      const double t = far_is_second ? a : -a, c = std::cos(t), sn = std::sin(t);
      far = Point(o.x() + c * dx - sn * dy, o.y() + sn * dx + c * dy);
      if (geometry::orientation(o, m.vertices[e], m.vertices[f]) >= 0) break;
    }
  }
}

LocalMap local_map_from_visibility(const geometry::VisibilityPolygon& vis) {
  if (vis.location.kind != geometry::Location::Kind::Interior)
    throw InputError("observer at (" + std::to_string(vis.query.x()) + ", " + std::to_string(vis.query.y()) +
                     ") is on the boundary; a local map needs it in the open free space");
  LocalMap m;
  m.observer = vis.query;
  const std::size_t n = vis.vertices.size();
  m.vertices.reserve(n);
  for (auto& v : vis.vertices) m.vertices.push_back(v.approx);
  m.edges.resize(n);
  m.corner.assign(n, kNone);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& e = vis.edges[i];
    if (e.kind == geometry::VisibilityEdge::Kind::Solid) {
      m.edges[i] = EdgeKind::Solid;
      continue;
    }
    m.edges[i] = EdgeKind::Occlusion;
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const auto& a = vis.vertices[i];
    m.corner[i] = static_cast<std::uint32_t>(
        a.kind == geometry::VisibilityVertex::Kind::EnvironmentVertex && a.vertex == e.reflex ? i : j);
  }
  // Distinct symbolic vertices may round to one point (a ray through two aligned
  // vertices): merge them, keeping the edge that leaves the merged point.
  std::vector<std::uint32_t> index_of(n);
  LocalMap c;
  c.observer = m.observer;
  for (std::size_t i = 0; i < n; ++i) {
    if (!c.vertices.empty() && m.vertices[i] == c.vertices.back()) {
      index_of[i] = static_cast<std::uint32_t>(c.vertices.size() - 1);
      c.edges.back() = m.edges[i];
      c.corner.back() = m.corner[i];
      continue;
    }
    index_of[i] = static_cast<std::uint32_t>(c.vertices.size());
    c.vertices.push_back(m.vertices[i]);
    c.edges.push_back(m.edges[i]);
    c.corner.push_back(m.corner[i]);
  }
  while (c.vertices.size() > 1 && c.vertices.back() == c.vertices.front()) {
    for (auto& k : index_of)
      if (k == c.vertices.size() - 1) k = 0;
    c.vertices.pop_back();
    c.edges.pop_back();
    c.corner.pop_back();
  }
  for (auto& k : c.corner)
    if (k != kNone) k = index_of[k];
  // A corner merged into the far end of its own edge leaves a one-vertex "edge": keep the
  // corner at the nearer endpoint.
  for (std::size_t e = 0; e < c.size(); ++e)
    if (c.corner[e] != kNone && c.corner[e] != e && c.corner[e] != c.next(e)) c.corner[e] = static_cast<std::uint32_t>(e);
  m = std::move(c);
  straighten_occlusion_edges(m);
  try {
    m.validate("visibility polygon");
  } catch (const InputError& e) {
    // Rays from an observer exactly (or within rounding) in line with two obstacle
    // vertices hit nearly one point; rounded to doubles, their hits can swap order.
    throw InputError("observer at " + geometry::format_point(vis.query) +
                     ": its visibility polygon, rounded to doubles, is not star-shaped (the observer is in line "
                     "with obstacle vertices, so rays through them nearly coincide); move it off that line. " +
                     e.what());
  }
  return m;
}

}  // namespace preimage::tracking
