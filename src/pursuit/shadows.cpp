// SPDX-License-Identifier: Apache-2.0
// Shadow components from the visibility polygon: the visible pieces of each boundary ring
// in ring order; between two consecutive pieces lies an invisible stretch, which joins
// the gap leaving the first piece to the gap entering the second (their shadows are one
// region bounded by both gaps and the stretch).
#include <preimage/pursuit/shadows.hpp>

#include <preimage/union_find.hpp>

#include <algorithm>
#include <stdexcept>

namespace preimage::pursuit {

using geometry::ExactPoint;

using geometry::VisibilityEdge;
using geometry::VisibilityVertex;

std::uint32_t Shadows::component_of(std::uint32_t v) const {
  auto it = std::lower_bound(gaps.begin(), gaps.end(), v, [](const Gap& g, std::uint32_t x) { return g.reflex < x; });
  return it != gaps.end() && it->reflex == v ? it->component : geometry::kNone;
}

std::vector<std::uint32_t> Shadows::gap_vertices(std::uint32_t c) const {
  std::vector<std::uint32_t> out;
  for (auto& g : gaps)
    if (g.component == c) out.push_back(g.reflex);
  return out;
}

bool Shadows::operator==(const Shadows& o) const {
  if (gaps.size() != o.gaps.size() || num_components != o.num_components) return false;
  for (std::size_t i = 0; i < gaps.size(); ++i)
    if (gaps[i].reflex != o.gaps[i].reflex || gaps[i].component != o.gaps[i].component) return false;
  return true;
}

Shadows shadows_of(const geometry::VisibilityPolygon& V) {
  const geometry::Environment& env = *V.environment;
  const std::size_t m = V.edges.size();
  std::vector<std::uint32_t> free_index(m, geometry::kNone);
  std::vector<std::size_t> free_edges;
  for (std::size_t i = 0; i < m; ++i)
    if (V.edges[i].kind == VisibilityEdge::Kind::Free) {
      if (V.edges[(i + 1) % m].kind == VisibilityEdge::Kind::Free)
        throw std::logic_error("pursuit: two consecutive gaps in V" + geometry::format_point(V.query) +
                               " (the point lies on a critical line)");
      free_index[i] = static_cast<std::uint32_t>(free_edges.size());
      free_edges.push_back(i);
    }
  UnionFind uf(free_edges.size());

  // Visible boundary pieces per ring, in ring order: (edge, start vertex index in V).
  struct Piece {
    std::uint32_t edge;
    std::size_t index;  // V edge index
  };
  std::vector<std::vector<Piece>> per_ring(env.num_rings());
  for (std::size_t i = 0; i < m; ++i)
    if (V.edges[i].kind == VisibilityEdge::Kind::Solid) per_ring[env.ring_of(V.edges[i].edge)].push_back({V.edges[i].edge, i});
  // Boundary points of V compared symbolically: a ray hit lies strictly inside its edge, and
  // two hits on one edge are the same point iff their rays coincide. Only the pursuer's own
  // position (on the boundary) needs exact coordinates.
  using K = VisibilityVertex::Kind;
  const ExactPoint& q = V.exact_query();
  auto same_point = [&](std::size_t i, std::size_t j) {
    const VisibilityVertex &a = V.vertices[i], &b = V.vertices[j];
    if (a.kind == K::Query || b.kind == K::Query) return V.exact(i) == V.exact(j);
    if (a.kind != b.kind) return false;
    if (a.kind == K::EnvironmentVertex) return a.vertex == b.vertex;
    return a.edge == b.edge && (a.vertex == b.vertex || CGAL::orientation(q, env.exact_vertex(a.vertex), env.exact_vertex(b.vertex)) == CGAL::COLLINEAR);
  };
  // Order of two piece starts along edge e (the pursuer sees the edge from its free side,
  // so along the edge its points turn counter-clockwise about q).
  auto before = [&](std::uint32_t e, std::size_t i, std::size_t j) {
    const VisibilityVertex &a = V.vertices[i], &b = V.vertices[j];
    if (a.kind == K::EnvironmentVertex && a.vertex == e) return true;
    if (b.kind == K::EnvironmentVertex && b.vertex == e) return false;
    if (a.kind == K::RayHit && b.kind == K::RayHit) {
      const auto o = CGAL::orientation(q, env.exact_vertex(a.vertex), env.exact_vertex(b.vertex));
      if (o != CGAL::COLLINEAR) return o == CGAL::LEFT_TURN;
    }
    return CGAL::compare_distance_to_point(env.exact_vertex(e), V.exact(i), V.exact(j)) == CGAL::SMALLER;
  };
  for (std::size_t r = 0; r < per_ring.size(); ++r) {
    auto& ps = per_ring[r];
    if (ps.empty()) continue;
    // Ring order: by edge, then along the edge (pieces of one edge run in its direction).
    std::sort(ps.begin(), ps.end(), [&](const Piece& a, const Piece& b) {
      if (a.edge != b.edge) return a.edge < b.edge;
      return a.index != b.index && before(a.edge, a.index, b.index);
    });
    for (std::size_t k = 0; k < ps.size(); ++k) {
      const Piece &p = ps[k], &q = ps[(k + 1) % ps.size()];
      const std::size_t end = (p.index + 1) % m;  // V vertex where piece p ends
      if (same_point(end, q.index)) continue;  // contiguous along the ring
      // An invisible stretch from the end of p to the start of q.
      const std::size_t after = p.index + 1 < m ? p.index + 1 : 0;  // V edge after p
      const std::size_t before = q.index == 0 ? m - 1 : q.index - 1;  // V edge before q
      if (free_index[after] == geometry::kNone || free_index[before] == geometry::kNone)
        throw std::logic_error("pursuit: an invisible stretch of the boundary not bounded by gaps in V" +
                               geometry::format_point(V.query));
      uf.join(free_index[after], free_index[before]);
    }
  }

  Shadows out;
  out.query = V.exact_query();
  for (std::size_t f = 0; f < free_edges.size(); ++f) {
    const std::size_t i = free_edges[f];
    out.gaps.push_back({V.edges[i].reflex, V.vertices[i], V.vertices[(i + 1) % m], uf.find(static_cast<std::uint32_t>(f))});
  }
  std::sort(out.gaps.begin(), out.gaps.end(), [](const Gap& a, const Gap& b) { return a.reflex < b.reflex; });
  for (std::size_t k = 1; k < out.gaps.size(); ++k)
    if (out.gaps[k].reflex == out.gaps[k - 1].reflex)
      throw std::logic_error("pursuit: two gaps at vertex " + std::to_string(out.gaps[k].reflex) + " in V" +
                             geometry::format_point(V.query));
  // Renumber components by their smallest gap vertex (gaps are sorted).
  std::vector<std::uint32_t> id(free_edges.size(), geometry::kNone);
  for (auto& g : out.gaps) {
    if (id[g.component] == geometry::kNone) id[g.component] = out.num_components++;
    g.component = id[g.component];
  }
  return out;
}

}  // namespace preimage::pursuit
