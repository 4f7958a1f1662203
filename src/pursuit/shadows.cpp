// SPDX-License-Identifier: Apache-2.0
// Shadow components from the visibility polygon: the visible pieces of each boundary ring
// in ring order; between two consecutive pieces lies an invisible stretch, which joins
// the gap leaving the first piece to the gap entering the second (their shadows are one
// region bounded by both gaps and the stretch).
#include <preimage/pursuit/shadows.hpp>

#include <preimage/geometry/segment_arrangement.hpp>

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
    if (gaps[i].reflex != o.gaps[i].reflex || gaps[i].component != o.gaps[i].component || gaps[i].pinch != o.gaps[i].pinch)
      return false;
  return true;
}

Shadows shadows_of(const geometry::VisibilityPolygon& V, std::span<const std::uint32_t> edge_pieces) {
  const geometry::Environment& env = *V.environment;
  const std::size_t m = V.edges.size(), n = env.num_vertices();
  const bool contacts = env.has_contacts();
  using K = VisibilityVertex::Kind;
  const ExactPoint& q = V.exact_query();
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
  // Union-find nodes: the free edges, then (with contacts) one per vertex id at a contact:
  // the hidden part near the point of the wedge starting at that id.
  std::vector<std::uint32_t> wedge_node;
  std::uint32_t nodes = static_cast<std::uint32_t>(free_edges.size());
  if (contacts) {
    wedge_node.assign(n, geometry::kNone);
    for (std::size_t v = 0; v < n; ++v)
      if (env.is_contact(v)) wedge_node[v] = nodes++;
  }
  UnionFind uf(nodes);
  // Contact points q sees, and the wedge it sees into there (kAll: q stands at the point).
  constexpr std::uint32_t kAll = geometry::kNone - 1;
  std::vector<std::uint32_t> seen_from;  // per id: kNone (point hidden), the wedge, or kAll
  if (contacts) {
    seen_from.assign(n, geometry::kNone);
    auto mark_point = [&](std::size_t v, std::uint32_t wedge) {
      for (std::size_t w = v;;) {
        seen_from[w] = wedge;
        w = env.same_point_next(w);
        if (w == v) break;
      }
    };
    if (V.location.kind == geometry::Location::Kind::AtVertex && env.is_contact(V.location.index))
      mark_point(V.location.index, kAll);
    for (const auto& x : V.vertices)
      if (x.kind == K::EnvironmentVertex && env.is_contact(x.vertex) && seen_from[x.vertex] == geometry::kNone) {
        const std::size_t w = geometry::wedge_toward(env, x.vertex, q);
        if (w == SIZE_MAX) throw std::logic_error("pursuit: V" + geometry::format_point(V.query) + " sees a contact from material");
        mark_point(x.vertex, static_cast<std::uint32_t>(w));
      }
  }
  // A gap's name: its occluding vertex, at a contact the wedge q sees into (whose hidden
  // part near the point is the gap's region).
  std::vector<std::uint32_t> gap_name(free_edges.size());
  for (std::size_t f = 0; f < free_edges.size(); ++f) {
    std::uint32_t r = V.edges[free_edges[f]].reflex;
    if (contacts && env.is_contact(r)) {
      r = seen_from[r];
      if (r == geometry::kNone || r == kAll)
        throw std::logic_error("pursuit: a gap at a contact not seen in V" + geometry::format_point(V.query));
      uf.join(static_cast<std::uint32_t>(f), wedge_node[r]);
    }
    gap_name[f] = r;
  }

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
  auto same_point = [&](std::size_t i, std::size_t j) {
    const VisibilityVertex &a = V.vertices[i], &b = V.vertices[j];
    if (a.kind == K::Query || b.kind == K::Query) return V.exact(i) == V.exact(j);
    if (a.kind != b.kind) return false;
    if (a.kind == K::EnvironmentVertex) return a.vertex == b.vertex || env.vertex(a.vertex) == env.vertex(b.vertex);
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
  // A hidden stretch of a ring that passes a contact point is two pieces there: one ending
  // in the wedge before the ring's vertex x, one starting in the wedge after it. (Whether
  // the evader passes the point is decided for the point below, not by the ring.)
  auto through_contact = [&](std::uint32_t& cur, std::size_t x) {
    if (!env.is_contact(x)) return;
    uf.join(cur, wedge_node[env.wedge_start(x)]);
    cur = wedge_node[x];
  };
  auto at_contact = [&](std::size_t i) { return contacts && V.vertices[i].kind == K::EnvironmentVertex && env.is_contact(V.vertices[i].vertex); };
  for (std::size_t r = 0; r < per_ring.size(); ++r) {
    auto& ps = per_ring[r];
    if (ps.empty()) {
      // A ring q sees nothing of: its stretches between the contacts on it, all around.
      if (contacts) {
        std::uint32_t cur = geometry::kNone, first = geometry::kNone;
        for (std::size_t x = env.ring_begin(r); x < env.ring_end(r); ++x)
          if (env.is_contact(x)) {
            if (cur == geometry::kNone) first = static_cast<std::uint32_t>(x), cur = wedge_node[x];
            else through_contact(cur, x);
          }
        if (cur != geometry::kNone) uf.join(cur, wedge_node[env.wedge_start(first)]);
      }
      continue;
    }
    // Ring order: by edge, then along the edge (pieces of one edge run in its direction).
    std::sort(ps.begin(), ps.end(), [&](const Piece& a, const Piece& b) {
      if (a.edge != b.edge) return a.edge < b.edge;
      return a.index != b.index && before(a.edge, a.index, b.index);
    });
    for (std::size_t k = 0; k < ps.size(); ++k) {
      const Piece &p = ps[k], &nx = ps[(k + 1) % ps.size()];
      const std::size_t end = (p.index + 1) % m;  // V vertex where piece p ends
      if (same_point(end, nx.index)) continue;  // contiguous along the ring
      // An invisible stretch from the end of p to the start of nx. An end at a contact
      // point, where V goes on along another ring, lies in the wedge the ring enters there.
      const std::size_t after = p.index + 1 < m ? p.index + 1 : 0;  // V edge after p
      const std::size_t before_nx = nx.index == 0 ? m - 1 : nx.index - 1;  // V edge before nx
      const bool from_contact = at_contact(end), to_contact = at_contact(nx.index);
      const std::uint32_t a = from_contact ? wedge_node[env.next(p.edge)] : free_index[after];
      const std::uint32_t b = to_contact ? wedge_node[env.wedge_start(nx.edge)] : free_index[before_nx];
      if (a == geometry::kNone || b == geometry::kNone)
        throw std::logic_error("pursuit: an invisible stretch of the boundary not bounded by gaps in V" +
                               geometry::format_point(V.query));
      std::uint32_t cur = a;
      if (contacts) {
        // Ring vertices strictly inside the stretch.
        const std::size_t size = env.ring_size(r), base = env.ring_begin(r);
        const std::size_t first = V.vertices[end].kind == K::EnvironmentVertex ? env.next(env.next(p.edge)) : env.next(p.edge);
        const std::size_t stop = V.vertices[nx.index].kind == K::EnvironmentVertex ? nx.edge : env.next(nx.edge);
        std::size_t count = (stop + size - first) % size;
        // Both ends inside one edge with nx before p along it (only the last piece in ring
        // order, when every piece lies on that edge): the stretch is the rest of the ring.
        if (count == 0 && k + 1 == ps.size() && nx.edge == p.edge) count = size;
        for (std::size_t x = first, c = 0; c < count; ++c, x = x + 1 == base + size ? base : x + 1) through_contact(cur, x);
      }
      uf.join(cur, b);
    }
  }
  if (contacts) {
    // The evader passes through a hidden contact point: every wedge there is one region.
    for (std::size_t v = 0; v < n; ++v)
      if (env.is_contact(v) && seen_from[v] == geometry::kNone) uf.join(wedge_node[v], wedge_node[env.same_point_next(v)]);
    // A piece of free space (between contact points) q sees nothing of is one hidden
    // region: its wedges are joined through open space, not only along rings.
    if (edge_pieces.size() != n) throw std::logic_error("pursuit: the shadows of a map with contacts need its pieces of free space");
    std::vector<std::uint32_t> rep(n, geometry::kNone);  // per piece: a wedge node, or kAll when seen
    for (std::size_t i = 0; i < m; ++i)
      if (V.edges[i].kind == VisibilityEdge::Kind::Solid) rep[edge_pieces[V.edges[i].edge]] = kAll;
    for (std::size_t v = 0; v < n; ++v) {
      if (!env.is_contact(v)) continue;
      std::uint32_t& r = rep[edge_pieces[v]];  // wedge v lies on edge v's free side
      if (r == kAll) continue;
      if (r == geometry::kNone) r = wedge_node[v];
      else uf.join(r, wedge_node[v]);
    }
    // In the piece q sees into, every hidden region has a gap. A cluster of touching rings
    // q sees nothing of is not joined to it along any ring, though: find the region beside
    // each hidden wedge there in the arrangement of V's free edges, and join its gap.
    std::vector<char> has_gap(nodes, 0);
    for (std::uint32_t f = 0; f < free_edges.size(); ++f) has_gap[uf.find(f)] = 1;
    std::vector<std::uint32_t> loose;
    for (std::uint32_t v = 0; v < n; ++v)
      if (env.is_contact(v) && rep[edge_pieces[v]] == kAll && seen_from[v] != kAll && seen_from[v] != v &&
          !has_gap[uf.find(wedge_node[v])])
        loose.push_back(v);
    if (!loose.empty()) {
      auto end_of = [&](std::size_t i) -> geometry::SegmentEnd {
        const auto& x = V.vertices[i];
        if (x.kind == K::EnvironmentVertex) return {geometry::SegmentEnd::Kind::AtVertex, x.vertex};
        if (x.kind == K::RayHit) return {geometry::SegmentEnd::Kind::OnEdge, x.edge};
        throw std::logic_error("pursuit: a gap ends at the pursuer in V" + geometry::format_point(V.query));
      };
      std::vector<geometry::ArrangementSegment> segs;
      for (std::size_t i : free_edges) {
        const std::size_t j = (i + 1) % m;
        std::optional<std::pair<geometry::Point, geometry::Point>> carrier;
        if (!V.constructed_query) carrier = std::make_pair(V.query, env.vertex(V.edges[i].reflex));
        ExactPoint a = V.exact(i), b = V.exact(j);
        geometry::SegmentEnd ea = end_of(i), eb = end_of(j);
        segs.push_back({std::move(a), std::move(b), ea, eb, carrier});
      }
      const auto A = geometry::SegmentArrangement::build(env, std::move(segs), {}, nullptr, true);
      for (std::uint32_t v : loose)
        for (std::uint32_t h : A.region_half_edges(A.region_of(A.first_piece(v))))
          if (const std::uint32_t f = A.half_edges()[h].segment; f != geometry::kNone) {
            uf.join(wedge_node[v], f);  // segment f is free edge f
            break;
          }
    }
  }

  Shadows out;
  out.query = q;
  for (std::size_t f = 0; f < free_edges.size(); ++f) {
    const std::size_t i = free_edges[f];
    // A pursuer standing at a contact point looks along a wall through the next point: V
    // has a free edge of no length there, bounding no region (the checker drops it too).
    if (contacts && V.location.kind == geometry::Location::Kind::AtVertex && V.exact(i) == V.exact((i + 1) % m)) continue;
    out.gaps.push_back({gap_name[f], V.vertices[i], V.vertices[(i + 1) % m], uf.find(static_cast<std::uint32_t>(f))});
  }
  // Pinches: wedges at a contact point other than the one q sees into, or all of them at
  // a hidden point.
  if (contacts)
    for (std::uint32_t v = 0; v < n; ++v) {
      if (!env.is_contact(v) || seen_from[v] == kAll || seen_from[v] == v) continue;
      const VisibilityVertex at{K::EnvironmentVertex, v, geometry::kNone, env.vertex(v)};
      out.gaps.push_back({v, at, at, uf.find(wedge_node[v]), true});
    }
  std::sort(out.gaps.begin(), out.gaps.end(), [](const Gap& a, const Gap& b) { return a.reflex < b.reflex; });
  for (std::size_t k = 1; k < out.gaps.size(); ++k)
    if (out.gaps[k].reflex == out.gaps[k - 1].reflex)
      throw std::logic_error("pursuit: two gaps at vertex " + std::to_string(out.gaps[k].reflex) + " in V" +
                             geometry::format_point(V.query));
  // Renumber components by their smallest gap vertex (gaps are sorted).
  std::vector<std::uint32_t> id(nodes, geometry::kNone);
  for (auto& g : out.gaps) {
    if (id[g.component] == geometry::kNone) id[g.component] = out.num_components++;
    g.component = id[g.component];
  }
  return out;
}

}  // namespace preimage::pursuit
