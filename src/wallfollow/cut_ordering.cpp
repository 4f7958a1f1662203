// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>

#include <algorithm>
#include <cmath>

namespace preimage::wallfollow {

using geometry::ExactPoint;

namespace {
std::string name(const CutPoint& p) {
  const char* k = p.kind == CutPoint::Kind::Vertex ? "v" : p.kind == CutPoint::Kind::Left ? "l" : "r";
  return std::string(k).append(std::to_string(p.vertex + 1));
}
}  // namespace

Cut shoot_cut(const geometry::Environment& env, std::uint32_t v, bool left) {
  // Straight on past v in the direction of the edge just traversed (III.A, JUMP).
  const ExactPoint& at = env.exact_vertex(v);
  const auto d = at - env.exact_vertex(left ? env.next(v) : env.prev(v));
  const auto hit = geometry::shoot_ray(env, at, d);
  const std::string cut = name({left ? CutPoint::Kind::Left : CutPoint::Kind::Right, v});
  if (!hit) throw std::logic_error("cut " + cut + " leaves the environment");
  if (hit->vertex || hit->along_edge)
    throw InputError(std::string("cut ").append(cut).append(" from vertex ").append(std::to_string(env.input_index(v)))
                         .append(" meets vertex ").append(std::to_string(env.input_index(hit->vertex ? *hit->vertex : hit->edge)))
                         .append(" (three collinear vertices: no general position)"));
  return {v, left, hit->point, static_cast<std::uint32_t>(hit->edge)};
}

TrueCuts true_cut_ordering(const geometry::Environment& env) {
  TrueCuts T;
  const std::size_t n = env.num_vertices();
  T.ordering.n = n;
  T.ordering.reflex.resize(n);
  std::vector<std::vector<std::uint32_t>> on_edge(n);
  for (std::uint32_t v = 0; v < n; ++v) {
    T.ordering.reflex[v] = env.is_reflex(v);
    if (!env.is_reflex(v)) continue;
    for (bool left : {true, false}) {
      T.cuts.push_back(shoot_cut(env, v, left));
      on_edge[T.cuts.back().edge].push_back(static_cast<std::uint32_t>(T.cuts.size() - 1));
    }
  }
  auto point_of = [&](const Cut& c) { return CutPoint{c.left ? CutPoint::Kind::Left : CutPoint::Kind::Right, c.vertex}; };
  for (std::uint32_t e = 0; e < n; ++e) {
    T.ordering.points.push_back({CutPoint::Kind::Vertex, e});
    auto& xs = on_edge[e];
    const ExactPoint& start = env.exact_vertex(e);
    std::sort(xs.begin(), xs.end(), [&](auto a, auto b) {
      return a != b && CGAL::has_smaller_distance_to_point(start, T.cuts[a].end, T.cuts[b].end);
    });
    for (std::size_t k = 0; k < xs.size(); ++k) {
      if (k > 0 && T.cuts[xs[k]].end == T.cuts[xs[k - 1]].end)
        throw InputError("cuts " + name(point_of(T.cuts[xs[k - 1]])) + " and " + name(point_of(T.cuts[xs[k]])) +
                         " end at the same boundary point " + geometry::format_point(geometry::to_double(T.cuts[xs[k]].end)) +
                         " (the cut ordering needs distinct cut endpoints, V.A)");
      T.ordering.points.push_back(point_of(T.cuts[xs[k]]));
    }
  }
  return T;
}

CutOrdering CutOrdering::relabelled(std::size_t first) const {
  CutOrdering o;
  o.n = n;
  o.reflex.resize(n);
  for (std::size_t v = 0; v < n; ++v) o.reflex[v] = reflex[(v + first) % n];
  const auto start = std::find(points.begin(), points.end(), CutPoint{CutPoint::Kind::Vertex, static_cast<std::uint32_t>(first)});
  const std::size_t s = static_cast<std::size_t>(start - points.begin());
  o.points.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    CutPoint p = points[(s + k) % points.size()];
    p.vertex = static_cast<std::uint32_t>((p.vertex + n - first) % n);
    o.points.push_back(p);
  }
  return o;
}

CutOrdering CutOrdering::canonical() const {
  CutOrdering best = relabelled(0);
  for (std::size_t f = 1; f < n; ++f) {
    CutOrdering c = relabelled(f);
    if (c.points < best.points) best = std::move(c);
  }
  return best;
}

std::string CutOrdering::str() const {
  std::string s = "(";
  for (std::size_t k = 0; k < points.size(); ++k) s.append(k ? ", " : "").append(name(points[k]));
  return s + ")";
}

std::vector<CutChord> chords(const CutOrdering& o) {
  std::vector<std::size_t> at_vertex(o.n);
  for (std::size_t k = 0; k < o.points.size(); ++k)
    if (o.points[k].kind == CutPoint::Kind::Vertex) at_vertex[o.points[k].vertex] = k;
  std::vector<CutChord> out;
  for (std::size_t k = 0; k < o.points.size(); ++k)
    if (o.points[k].kind != CutPoint::Kind::Vertex) {
      const std::uint32_t v = o.points[k].vertex;
      out.push_back({{CutPoint::Kind::Vertex, v}, o.points[k], at_vertex[v], k});
    }
  return out;
}

bool chords_cross(const CutChord& a, const CutChord& b) {
  if (a.at_from == b.at_from || a.at_from == b.at_to || a.at_to == b.at_from || a.at_to == b.at_to) return false;
  const std::size_t lo = std::min(a.at_from, a.at_to), hi = std::max(a.at_from, a.at_to);
  auto inside = [&](std::size_t k) { return lo < k && k < hi; };
  return inside(b.at_from) != inside(b.at_to);
}

std::vector<std::string> reflex_chain_violations(const CutOrdering& o) {
  std::vector<std::string> out;
  const std::size_t n = o.n;
  // Maximal chains: runs of reflex vertices, cyclically. chain[v] = first vertex of v's chain.
  std::vector<long> chain(n, -1);
  std::size_t s = 0;
  while (s < n && o.reflex[s]) ++s;
  if (s == n) return out;  // no convex vertex: not a polygon; nothing to say
  for (std::size_t k = 1; k <= n; ++k) {
    const std::size_t v = (s + k) % n;
    if (!o.reflex[v]) continue;
    const std::size_t p = (v + n - 1) % n;
    chain[v] = o.reflex[p] ? chain[p] : static_cast<long>(v);
  }
  // Edge e lies between vertices of one chain when both of its ends are in that chain.
  std::size_t edge = 0;
  for (const CutPoint& p : o.points) {
    if (p.kind == CutPoint::Kind::Vertex) {
      edge = p.vertex;
      continue;
    }
    const std::size_t b = (edge + 1) % n;
    if (chain[edge] >= 0 && chain[edge] == chain[b] && chain[p.vertex] == chain[edge])
      out.push_back(name(p) + " lies between v" + std::to_string(edge + 1) + " and v" + std::to_string(b + 1) +
                    ", inside the reflex chain of v" + std::to_string(p.vertex + 1) + " (not realizable)");
  }
  return out;
}

render::SvgCanvas cut_diagram(const CutOrdering& o, const std::string& title) {
  using geometry::Point;
  render::SvgCanvas c(CGAL::Bbox_2(-1.35, -1.35, 1.35, 1.35), 560);
  const std::size_t N = o.points.size();
  auto at = [&](std::size_t k) {
    const double a = M_PI / 2 + 2 * M_PI * static_cast<double>(k) / static_cast<double>(N);
    return Point(std::cos(a), std::sin(a));
  };
  std::vector<Point> circle;
  for (int k = 0; k <= 180; ++k) circle.emplace_back(std::cos(k * M_PI / 90), std::sin(k * M_PI / 90));
  c.polyline(circle, {"none", "#999", 1.0, 1.0, ""}, "boundary of E (counter-clockwise from the top)");
  const render::Style left{"none", "#1a73e8", 1.2, 0.8, ""}, right{"none", "#d93025", 1.2, 0.8, ""};
  for (const auto& ch : chords(o))
    c.segment(at(ch.at_from), at(ch.at_to), ch.to.kind == CutPoint::Kind::Left ? left : right,
              name(ch.from) + " - " + name(ch.to));
  const bool labels = N <= 80;
  for (std::size_t k = 0; k < N; ++k) {
    const CutPoint& p = o.points[k];
    const bool vertex = p.kind == CutPoint::Kind::Vertex;
    const std::string colour = !vertex ? (p.kind == CutPoint::Kind::Left ? "#1a73e8" : "#d93025") : o.reflex[p.vertex] ? "#222" : "#fff";
    c.point(at(k), vertex ? 4 : 3, {colour, "#222", 1.0, 1.0, ""}, name(p));
    if (labels) c.label(Point(1.16 * at(k).x() - 0.05, 1.16 * at(k).y() - 0.03), name(p), 11);
  }
  c.legend("left cut v_i - l_i", left);
  c.legend("right cut v_i - r_i", right);
  c.legend("reflex vertex (filled), convex vertex (open)", {"#222", "#222", 1.0, 1.0, ""});
  if (!title.empty()) c.label(Point(-1.3, 1.28), title, 13);
  return c;
}

render::SvgCanvas cuts_figure(const geometry::Environment& env, const TrueCuts& T) {
  using geometry::Point;
  render::SvgCanvas c(env.bbox(), 560);
  c.environment(env);
  const render::Style left{"none", "#1a73e8", 1.5, 0.9, "5 3"}, right{"none", "#d93025", 1.5, 0.9, "5 3"};
  const bool labels = env.num_vertices() <= 60;
  for (const Cut& k : T.cuts) {
    const Point a = env.vertex(k.vertex), b = geometry::to_double(k.end);
    const std::string id = name({k.left ? CutPoint::Kind::Left : CutPoint::Kind::Right, k.vertex});
    c.segment(a, b, k.left ? left : right, std::string("cut ").append(id));
    c.point(b, 3, {k.left ? "#1a73e8" : "#d93025", "#222", 1.0, 1.0, ""}, id);
    if (labels) c.label(b, id, 11, k.left ? "#1a73e8" : "#d93025");
  }
  for (std::size_t v = 0; v < env.num_vertices() && labels; ++v) c.label(env.vertex(v), std::string("v").append(std::to_string(v + 1)), 12);
  c.legend("left cut (after LFOLLOW) to l_i", left);
  c.legend("right cut (after RFOLLOW) to r_i", right);
  return c;
}

}  // namespace preimage::wallfollow
