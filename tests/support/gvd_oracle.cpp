// SPDX-License-Identifier: Apache-2.0
#include "gvd_oracle.hpp"

#include <preimage/union_find.hpp>

#include <CGAL/Segment_Delaunay_graph_2.h>
#include <CGAL/Segment_Delaunay_graph_filtered_traits_2.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace preimage::testing {

namespace {

using SdgKernel = CGAL::Simple_cartesian<double>;
using SdgTraits = CGAL::Segment_Delaunay_graph_filtered_traits_without_intersections_2<SdgKernel, CGAL::Field_with_sqrt_tag>;
using Sdg = CGAL::Segment_Delaunay_graph_2<SdgTraits>;

}  // namespace

std::size_t cgal_segment_delaunay_graph_size(const std::vector<geometry::Point>& points,
                                             const std::vector<std::pair<std::size_t, std::size_t>>& segments) {
  std::vector<SdgKernel::Point_2> pts;
  pts.reserve(points.size());
  for (const auto& p : points) pts.emplace_back(p.x(), p.y());
  Sdg sdg;
  sdg.insert_segments(pts, segments.begin(), segments.end());
  return sdg.number_of_vertices();
}

std::vector<PlainGvdEdge> cgal_gvd_edges(const geometry::Environment& env, const std::vector<geometry::Point>& points,
                                         const std::vector<std::uint32_t>& ring_obstacle) {
  // one point per distinct location (contacts share theirs)
  std::map<std::pair<double, double>, std::size_t> index;
  std::vector<SdgKernel::Point_2> pts;
  std::vector<std::uint32_t> point_obstacle;
  std::vector<std::size_t> id(env.num_vertices());
  for (std::size_t v = 0; v < env.num_vertices(); ++v) {
    const auto key = std::make_pair(points[v].x(), points[v].y());
    auto [it, fresh] = index.emplace(key, pts.size());
    if (fresh) {
      pts.emplace_back(key.first, key.second);
      point_obstacle.push_back(ring_obstacle[env.ring_of(v)]);
    } else if (point_obstacle[it->second] != ring_obstacle[env.ring_of(v)]) {
      throw std::logic_error("oracle: one point in two obstacles");
    }
    id[v] = it->second;
  }
  std::vector<std::pair<std::size_t, std::size_t>> segs;
  for (std::size_t e = 0; e < env.num_vertices(); ++e) segs.emplace_back(id[e], id[env.next(e)]);
  Sdg sdg;
  sdg.insert_segments(pts, segs.begin(), segs.end());
  auto obstacle_of = [&](const Sdg::Site_2& s) {
    const SdgKernel::Point_2 p = s.is_point() ? s.point() : s.segment().source();
    const auto it = index.find({p.x(), p.y()});
    if (it == index.end()) throw std::logic_error("oracle: a site that is not an input point");
    return point_obstacle[it->second];
  };
  std::vector<PlainGvdEdge> out;
  for (auto e = sdg.finite_edges_begin(); e != sdg.finite_edges_end(); ++e) {
    const auto f = e->first;
    const int i = e->second;
    const auto u = f->vertex(sdg.ccw(i)), w = f->vertex(sdg.cw(i));
    const std::uint32_t ou = obstacle_of(u->site()), ow = obstacle_of(w->site());
    if (ou == ow) continue;
    const auto g = f->neighbor(i);
    if (sdg.is_infinite(f) || sdg.is_infinite(g)) throw std::logic_error("oracle: an infinite GVD edge");
    const auto a = sdg.primal(f), b = sdg.primal(g);
    out.push_back({geometry::Point(a.x(), a.y()), geometry::Point(b.x(), b.y()), {ou, ow}});
  }
  return out;
}

GvdTopology gvd_topology(const std::vector<PlainGvdEdge>& edges, double merge) {
  GvdTopology t;
  // cluster the end points: a sweep by x joins points within `merge` (both coordinates)
  std::vector<geometry::Point> ends;
  for (const auto& e : edges) ends.push_back(e.a), ends.push_back(e.b);
  std::vector<std::uint32_t> order(ends.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto i, auto j) { return ends[i].x() < ends[j].x(); });
  UnionFind uf(ends.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = i + 1; j < order.size() && ends[order[j]].x() - ends[order[i]].x() <= merge; ++j)
      if (std::fabs(ends[order[j]].y() - ends[order[i]].y()) <= merge) uf.join(order[i], order[j]);
  std::vector<std::uint32_t> node(ends.size(), UINT32_MAX), root_node(ends.size(), UINT32_MAX);
  for (std::uint32_t i = 0; i < ends.size(); ++i) {
    const auto r = uf.find(i);
    if (root_node[r] == UINT32_MAX) root_node[r] = static_cast<std::uint32_t>(t.nodes.size()), t.nodes.push_back(ends[i]);
    node[i] = root_node[r];
  }
  t.degree.assign(t.nodes.size(), 0);
  std::vector<std::vector<std::uint32_t>> inc(t.nodes.size());
  std::vector<std::uint32_t> kept;
  for (std::uint32_t k = 0; k < edges.size(); ++k) {
    const auto a = node[2 * k], b = node[2 * k + 1];
    if (a == b) continue;  // zero length
    kept.push_back(k);
    ++t.degree[a], ++t.degree[b];
    inc[a].push_back(k), inc[b].push_back(k);
  }
  auto pair_of = [&](std::uint32_t k) {
    return std::make_pair(std::min(edges[k].obstacle[0], edges[k].obstacle[1]), std::max(edges[k].obstacle[0], edges[k].obstacle[1]));
  };
  std::vector<char> used(edges.size(), 0);
  auto walk = [&](std::uint32_t start_node, std::uint32_t k) {
    const auto pr = pair_of(k);
    std::uint32_t at = start_node;
    for (;;) {
      used[k] = 1;
      if (pair_of(k) != pr) t.problem = "a degree-2 node joins different obstacle pairs";
      at = node[2 * k] == at ? node[2 * k + 1] : node[2 * k];
      if (t.degree[at] != 2) break;
      const std::uint32_t next = inc[at][0] == k ? inc[at][1] : inc[at][0];
      if (used[next]) break;  // closed cycle
      k = next;
    }
    ++t.chains[pr];
  };
  for (std::uint32_t v = 0; v < t.nodes.size(); ++v)
    if (t.degree[v] != 2)
      for (auto k : inc[v])
        if (!used[k]) walk(v, k);
  for (auto k : kept)
    if (!used[k]) walk(node[2 * k], k);  // cycles of degree-2 nodes
  return t;
}

std::string match_nodes(const GvdTopology& a, const GvdTopology& b, double tol, std::uint32_t min_degree) {
  std::vector<std::uint32_t> bs;
  for (std::uint32_t j = 0; j < b.nodes.size(); ++j)
    if (b.degree[j] >= min_degree) bs.push_back(j);
  std::sort(bs.begin(), bs.end(), [&](auto i, auto j) { return b.nodes[i].x() < b.nodes[j].x(); });
  std::vector<char> taken(b.nodes.size(), 0);
  std::size_t na = 0;
  for (std::uint32_t i = 0; i < a.nodes.size(); ++i) {
    if (a.degree[i] < min_degree) continue;
    ++na;
    const auto& p = a.nodes[i];
    auto lo = std::lower_bound(bs.begin(), bs.end(), p.x() - tol, [&](std::uint32_t j, double x) { return b.nodes[j].x() < x; });
    std::uint32_t found = UINT32_MAX;
    for (auto it = lo; it != bs.end() && b.nodes[*it].x() <= p.x() + tol; ++it)
      if (!taken[*it] && std::fabs(b.nodes[*it].y() - p.y()) <= tol && b.degree[*it] == a.degree[i]) {
        found = *it;
        break;
      }
    if (found == UINT32_MAX)
      return "node (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ") of degree " + std::to_string(a.degree[i]) + " has no match";
    taken[found] = 1;
  }
  if (na != bs.size()) return std::to_string(na) + " nodes against " + std::to_string(bs.size());
  return "";
}

}  // namespace preimage::testing
