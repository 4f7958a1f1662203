// SPDX-License-Identifier: Apache-2.0
// The constructive O(log n) strategy of 6.3 (see split.hpp).
#include <preimage/pursuit/split.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/triangulation.hpp>

#include <CGAL/Intersections_2/Line_2_Line_2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace preimage::pursuit {

using geometry::ExactKernel;
using geometry::orientation;
using Line = ExactKernel::Line_2;

namespace {

// A point of the kernel of the region left of every directed edge, strictly inside it,
// in doubles; nullopt if the kernel has no interior (or none representable). The kernel
// is clipped from a box one half-plane at a time; its vertices are always intersections
// of two input lines, so no construction builds on another.
std::optional<Point> kernel_point(const std::vector<std::pair<Point, Point>>& edges, const CGAL::Bbox_2& box) {
  const double m = 1 + std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  const Point c0(box.xmin() - m, box.ymin() - m), c1(box.xmax() + m, box.ymin() - m), c2(box.xmax() + m, box.ymax() + m),
      c3(box.xmin() - m, box.ymax() + m);
  auto line = [](const Point& a, const Point& b) { return Line(geometry::to_exact(a), geometry::to_exact(b)); };
  std::vector<Line> poly{line(c0, c1), line(c1, c2), line(c2, c3), line(c3, c0)};
  auto vertex = [&](std::size_t k) {  // start of edge k: previous line meets line k
    const auto hit = CGAL::intersection(poly[(k + poly.size() - 1) % poly.size()], poly[k]);
    const ExactPoint* p = hit ? boost::get<ExactPoint>(&*hit) : nullptr;
    if (!p) throw std::logic_error("pursuit: kernel edges do not meet");
    return *p;
  };
  for (const auto& [a, b] : edges) {
    const Line H = line(a, b);
    bool skip = false;
    for (const Line& L : poly) {
      if (L == H) skip = true;
      if (L == H.opposite()) return std::nullopt;  // a slab of width zero
    }
    if (skip) continue;
    const std::size_t n = poly.size();
    std::vector<int> side(n);
    for (std::size_t k = 0; k < n; ++k) side[k] = CGAL::orientation(geometry::to_exact(a), geometry::to_exact(b), vertex(k));
    std::vector<Line> out;
    bool any_in = false;
    // Edge k runs from vertex k to vertex k + 1 along poly[k]; where it leaves the closed
    // half-plane, H closes the polygon (at the vertex itself when that lies on H).
    for (std::size_t k = 0; k < n; ++k) {
      const int s = side[k], e = side[(k + 1) % n];
      if (s >= 0) any_in = true;
      if (s >= 0 && e >= 0) out.push_back(poly[k]);
      else if (s > 0 && e < 0) out.push_back(poly[k]), out.push_back(H);
      else if (s == 0 && e < 0) out.push_back(H);
      else if (s < 0 && e > 0) out.push_back(poly[k]);
    }
    if (!any_in) return std::nullopt;
    poly.swap(out);
    if (poly.size() < 3) return std::nullopt;
  }
  double sx = 0, sy = 0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const auto p = geometry::to_double(vertex(k));
    sx += p.x(), sy += p.y();
  }
  const Point cand(sx / poly.size(), sy / poly.size());
  for (const auto& [a, b] : edges)
    if (orientation(a, b, cand) <= 0) return std::nullopt;
  return cand;
}

class Splitter {
 public:
  Splitter(const geometry::Environment& env, const Point& start, bool search_regions)
      : env_(env), T_(env), start_(start), search_regions_(search_regions) {
    const auto& tris = T_.triangles();
    centre_.resize(tris.size());
    for (std::size_t t = 0; t < tris.size(); ++t) {
      const Point &a = env.vertex(tris[t].v[0]), &b = env.vertex(tris[t].v[1]), &c = env.vertex(tris[t].v[2]);
      centre_[t] = Point((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
      if (!strictly_in(t, centre_[t])) throw std::logic_error("pursuit: a triangle's centroid is not inside it");
    }
    start_tri_ = containing(start);
  }

  SplitResult run() {
    std::vector<std::uint32_t> all(T_.size());
    for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
    res_.plan.paths.clear();
    clear(all, 0);
    for (std::size_t p = 0; p < res_.plan.paths.size(); ++p)
      for (std::size_t i = 0; i + 1 < res_.plan.paths[p].size(); ++i) {
        const Point &a = res_.plan.paths[p][i], &b = res_.plan.paths[p][i + 1];
        if (a != b && !geometry::visible(env_, a, b))
          throw std::logic_error("pursuit: split-strategy segment " + std::to_string(i) + " of pursuer " + std::to_string(p) +
                                 " leaves free space");
        res_.plan.length += std::hypot(a.x() - b.x(), a.y() - b.y());
      }
    res_.pursuers = res_.plan.paths.size();
    return res_;
  }

 private:
  bool strictly_in(std::size_t t, const Point& p) const {
    const auto& tr = T_.triangles()[t];
    for (int i = 0; i < 3; ++i)
      if (orientation(env_.vertex(tr.v[i]), env_.vertex(tr.v[(i + 1) % 3]), p) <= 0) return false;
    return true;
  }
  std::uint32_t containing(const Point& p) const {
    for (std::uint32_t t = 0; t < T_.size(); ++t) {
      const auto& tr = T_.triangles()[t];
      bool in = true;
      for (int i = 0; i < 3 && in; ++i) in = orientation(env_.vertex(tr.v[i]), env_.vertex(tr.v[(i + 1) % 3]), p) >= 0;
      if (in) return t;
    }
    throw std::logic_error("pursuit: a free-space point in no triangle");
  }

  // A pursuer that is not guarding: an idle one, else a new one (it waited at the start).
  std::uint32_t take() {
    for (std::uint32_t p = 0; p < busy_.size(); ++p)
      if (!busy_[p]) return busy_[p] = 1, p;
    const std::size_t waypoints = res_.plan.paths.empty() ? 1 : res_.plan.paths[0].size();
    res_.plan.paths.emplace_back(waypoints, start_);
    busy_.push_back(1);
    where_.push_back(start_tri_);
    return static_cast<std::uint32_t>(busy_.size() - 1);
  }

  // Pursuer p walks to `to` (strictly inside triangle `tri`), through the dual tree.
  void travel(std::uint32_t p, std::uint32_t tri, const Point& to) {
    const auto& tris = T_.triangles();
    std::vector<std::uint32_t> from(T_.size(), kNone), queue{where_[p]};
    from[where_[p]] = where_[p];
    for (std::size_t q = 0; q < queue.size() && from[tri] == kNone; ++q)
      for (std::uint32_t n : tris[queue[q]].nbr)
        if (n != kNone && from[n] == kNone) from[n] = queue[q], queue.push_back(n);
    std::vector<std::uint32_t> chain{tri};
    while (chain.back() != where_[p]) chain.push_back(from[chain.back()]);
    std::reverse(chain.begin(), chain.end());
    std::vector<Point> way{res_.plan.paths[p].back()};
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const auto& tr = tris[chain[i]];
      int s = 0;
      while (tr.nbr[s] != chain[i + 1]) ++s;
      const Point &a = env_.vertex(tr.v[s]), &b = env_.vertex(tr.v[(s + 1) % 3]);
      const Point mid((a.x() + b.x()) / 2, (a.y() + b.y()) / 2);
      bool ok = false;
      for (double eps : {1e-3, 1e-2, 0.1, 0.3}) {
        const Point &c1 = centre_[chain[i]], &c2 = centre_[chain[i + 1]];
        const Point p1(mid.x() + eps * (c1.x() - mid.x()), mid.y() + eps * (c1.y() - mid.y()));
        const Point p2(mid.x() + eps * (c2.x() - mid.x()), mid.y() + eps * (c2.y() - mid.y()));
        if (!strictly_in(chain[i], p1) || !strictly_in(chain[i + 1], p2)) continue;
        if (orientation(p1, p2, a) * orientation(p1, p2, b) >= 0) continue;  // must cross the diagonal itself
        way.push_back(p1), way.push_back(p2), ok = true;
        break;
      }
      if (!ok) way.push_back(centre_[chain[i]]), way.push_back(centre_[chain[i + 1]]);
    }
    way.push_back(to);
    // Shortcut where a straight segment stays in free space (exact test).
    std::vector<Point> shortened{way[0]};
    for (std::size_t i = 0; i + 1 < way.size();) {
      std::size_t j = std::min(way.size() - 1, i + 24);
      while (j > i + 1 && !geometry::visible(env_, way[i], way[j])) --j;
      shortened.push_back(way[j]);
      i = j;
    }
    for (std::size_t w = 1; w < shortened.size(); ++w)
      for (std::size_t q = 0; q < res_.plan.paths.size(); ++q)
        res_.plan.paths[q].push_back(q == p ? shortened[w] : res_.plan.paths[q].back());
    where_[p] = tri;
  }

  // A double point strictly inside the kernel of the union of `region`'s triangles.
  std::optional<Point> kernel_of(const std::vector<std::uint32_t>& region) const {
    const auto& tris = T_.triangles();
    std::vector<char> in(T_.size(), 0);
    for (auto t : region) in[t] = 1;
    std::vector<std::pair<Point, Point>> edges;
    CGAL::Bbox_2 box;
    for (auto t : region)
      for (int i = 0; i < 3; ++i) {
        box += env_.vertex(tris[t].v[i]).bbox();
        if (tris[t].nbr[i] == kNone || !in[tris[t].nbr[i]]) edges.push_back({env_.vertex(tris[t].v[i]), env_.vertex(tris[t].v[(i + 1) % 3])});
      }
    return kernel_point(edges, box);
  }
  bool star_shaped(const std::vector<std::uint32_t>& region) const { return kernel_of(region).has_value(); }

  // The union of `region`'s triangles as an environment of its own (a simple polygon: a
  // subtree of the dual tree of a simple polygon's triangulation).
  geometry::Environment sub_environment(const std::vector<std::uint32_t>& region) const {
    const auto& tris = T_.triangles();
    std::vector<char> in(T_.size(), 0);
    for (auto t : region) in[t] = 1;
    std::vector<std::uint32_t> next(env_.num_vertices(), kNone);
    std::uint32_t first = kNone;
    for (auto t : region)
      for (int i = 0; i < 3; ++i)
        if (tris[t].nbr[i] == kNone || !in[tris[t].nbr[i]]) next[tris[t].v[i]] = tris[t].v[(i + 1) % 3], first = tris[t].v[i];
    geometry::Ring ring;
    for (std::uint32_t v = first;;) {
      ring.push_back(env_.vertex(v));
      v = next[v];
      if (v == first) break;
    }
    return geometry::Environment::make(std::move(ring), {});
  }

  // One pursuer clears the region on its own (exhaustive search in the region alone: the
  // guards keep evaders from crossing its chords), if it can within a budget.
  std::optional<Plan> one_pursuer_plan(const std::vector<std::uint32_t>& region) const {
    if (!search_regions_ || region.size() > 400) return std::nullopt;
    const auto cells = ConservativeCells::build(sub_environment(region));
    const auto r = search(cells, 1, {std::nullopt, 200'000, false});
    if (r.outcome != SearchResult::Outcome::Plan) return std::nullopt;
    return r.plan;
  }

  void clear(const std::vector<std::uint32_t>& region, std::size_t depth) {
    const auto& tris = T_.triangles();
    std::vector<char> in(T_.size(), 0);
    for (auto t : region) in[t] = 1;
    if (auto k = kernel_of(region)) {
      for (auto t : region)
        if (strictly_in(t, *k)) {
          const std::uint32_t p = take();
          travel(p, t, *k);
          busy_[p] = 0;
          ++res_.regions;
          return;
        }
    }
    if (region.size() == 1) throw std::logic_error("pursuit: a triangle with an empty kernel");
    if (auto plan = one_pursuer_plan(region)) {
      const std::uint32_t p = take();
      const auto& path = plan->paths[0];
      travel(p, containing(path[0]), path[0]);
      for (std::size_t i = 1; i < path.size(); ++i)
        for (std::size_t q = 0; q < res_.plan.paths.size(); ++q) res_.plan.paths[q].push_back(q == p ? path[i] : res_.plan.paths[q].back());
      where_[p] = containing(path.back());
      busy_[p] = 0;
      ++res_.regions;
      return;
    }
    // Split at a dual edge: among the most balanced (each side keeps a large share of the
    // triangles, so the depth stays logarithmic) prefer one leaving star-shaped sides.
    std::vector<std::uint32_t> parent(T_.size(), kNone), order{region[0]}, size(T_.size(), 1);
    parent[region[0]] = region[0];
    for (std::size_t q = 0; q < order.size(); ++q)
      for (std::uint32_t n : tris[order[q]].nbr)
        if (n != kNone && in[n] && parent[n] == kNone) parent[n] = order[q], order.push_back(n);
    for (std::size_t q = order.size(); q-- > 1;) size[parent[order[q]]] += size[order[q]];
    auto split_at = [&](std::uint32_t child, std::vector<std::uint32_t>& sub, std::vector<std::uint32_t>& rest) {
      std::vector<char> in_sub(T_.size(), 0);
      std::vector<std::uint32_t> stack{child};
      while (!stack.empty()) {
        const auto t = stack.back();
        stack.pop_back();
        in_sub[t] = 1, sub.push_back(t);
        for (std::uint32_t n : tris[t].nbr)
          if (n != kNone && in[n] && parent[n] == t) stack.push_back(n);
      }
      for (auto t : region)
        if (!in_sub[t]) rest.push_back(t);
    };
    std::vector<std::pair<std::size_t, std::uint32_t>> cands;  // (smaller side, child)
    for (std::size_t q = 1; q < order.size(); ++q)
      cands.push_back({std::min<std::size_t>(size[order[q]], region.size() - size[order[q]]), order[q]});
    std::sort(cands.begin(), cands.end(), [](auto& a, auto& b) { return a.first > b.first || (a.first == b.first && a.second < b.second); });
    if (cands.size() > 12) cands.resize(12);
    std::uint32_t best = cands[0].second;
    int best_bad = 3;
    for (auto [small, child] : cands) {
      if (small * 4 < cands[0].first * 3) break;  // keep the split balanced
      std::vector<std::uint32_t> a, b;
      split_at(child, a, b);
      const int bad = !star_shaped(a) + !star_shaped(b);
      if (bad < best_bad) best_bad = bad, best = child;
      if (bad == 0) break;
    }
    std::vector<std::uint32_t> sub, rest;
    split_at(best, sub, rest);
    // The guard stands inside the triangle on the chord's far side and sees the whole chord.
    const std::uint32_t guard = take(), post = parent[best];
    travel(guard, post, centre_[post]);
    ++res_.guards;
    clear(sub, depth + 1);
    clear(rest, depth + 1);
    busy_[guard] = 0;
  }

  const geometry::Environment& env_;
  geometry::Triangulation T_;
  Point start_;
  bool search_regions_;
  std::uint32_t start_tri_ = 0;
  std::vector<Point> centre_;
  std::vector<char> busy_;
  std::vector<std::uint32_t> where_;
  SplitResult res_;
};

}  // namespace

SplitResult split_strategy(const geometry::Environment& env, const std::optional<Point>& start, bool search_regions) {
  if (env.num_holes() > 0)
    throw InputError("pursuit: the split strategy needs simply connected free space (this environment has " +
                     std::to_string(env.num_holes()) + " obstacle(s); the O(sqrt(h) + log n) construction is not implemented)");
  Point s;
  if (start) {
    const auto loc = geometry::locate(env, *start);
    if (!loc.in_free_space())
      throw InputError("--start " + geometry::format_point(*start) + " is not in free space (it is " + geometry::to_string(loc.kind) + ")");
    s = *start;
  } else {
    const geometry::Triangulation T(env);
    const auto& tr = T.triangles()[0];
    const Point &a = env.vertex(tr.v[0]), &b = env.vertex(tr.v[1]), &c = env.vertex(tr.v[2]);
    s = Point((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
  }
  return Splitter(env, s, search_regions).run();
}

}  // namespace preimage::pursuit
