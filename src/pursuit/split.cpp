// SPDX-License-Identifier: Apache-2.0
// The constructive O(log n) strategy of 6.3 (see split.hpp).
#include <preimage/pursuit/split.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/triangulation.hpp>
#include <preimage/geometry/visibility.hpp>

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
      : env_(env), T_(env), index_(env), start_(start), search_regions_(search_regions) {
    const auto& tris = T_.triangles();
    centre_.resize(tris.size());
    for (std::size_t t = 0; t < tris.size(); ++t) {
      const Point &a = env.vertex(tris[t].v[0]), &b = env.vertex(tris[t].v[1]), &c = env.vertex(tris[t].v[2]);
      centre_[t] = Point((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
      if (!strictly_in(t, centre_[t])) throw std::logic_error("pursuit: a triangle's centroid is not inside it");
      const auto ra = env.ring_of(tris[t].v[0]), rb = env.ring_of(tris[t].v[1]), rc = env.ring_of(tris[t].v[2]);
      if (ra != rb && rb != rc && ra != rc) ++res_.trichromatic;
    }
    by_x_.resize(env.num_vertices());
    for (std::uint32_t v = 0; v < by_x_.size(); ++v) by_x_[v] = v;
    std::sort(by_x_.begin(), by_x_.end(), [&](auto a, auto b) { return env.vertex(a).x() < env.vertex(b).x(); });
    start_tri_ = containing(start);
    in_.assign(T_.size(), 0);
  }

  SplitResult run() {
    std::vector<std::uint32_t> all(T_.size());
    for (std::uint32_t t = 0; t < all.size(); ++t) all[t] = t;
    res_.plan.paths.clear();
    clear(all);
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

  // Pursuer p walks to `to` (strictly inside triangle `tri`) through the dual graph (a
  // breadth-first path: with holes the graph has cycles).
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
      while (j > i + 1 && !index_.visible(way[i], way[j])) --j;
      shortened.push_back(way[j]);
      i = j;
    }
    for (std::size_t w = 1; w < shortened.size(); ++w)
      for (std::size_t q = 0; q < res_.plan.paths.size(); ++q)
        res_.plan.paths[q].push_back(q == p ? shortened[w] : res_.plan.paths[q].back());
    where_[p] = tri;
  }

  // Marks `region` in in_ (cleared by the caller's Mark going out of scope).
  struct Mark {
    std::vector<char>& in;
    const std::vector<std::uint32_t>& region;
    Mark(std::vector<char>& in_, const std::vector<std::uint32_t>& r) : in(in_), region(r) {
      for (auto t : region) in[t] = 1;
    }
    ~Mark() {
      for (auto t : region) in[t] = 0;
    }
  };

  // The boundary of `region`'s union: edges (a, b) of its triangles whose far side is a
  // wall or a triangle outside it.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> outline(const std::vector<std::uint32_t>& region,
                                                              const std::vector<char>& in) const {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (auto t : region)
      for (int i = 0; i < 3; ++i) {
        const auto& tr = T_.triangles()[t];
        if (tr.nbr[i] == kNone || !in[tr.nbr[i]]) out.push_back({tr.v[i], tr.v[(i + 1) % 3]});
      }
    return out;
  }

  // A double point strictly inside the kernel of the union of `region`'s triangles (none
  // when the region has a hole: no point sees around it).
  std::optional<Point> kernel_of(const std::vector<std::uint32_t>& region, const std::vector<char>& in) const {
    std::vector<std::pair<Point, Point>> edges;
    CGAL::Bbox_2 box;
    for (auto [a, b] : outline(region, in)) {
      box += env_.vertex(a).bbox();
      edges.push_back({env_.vertex(a), env_.vertex(b)});
    }
    return kernel_point(edges, box);
  }

  // Cycle rank of the region's dual graph: the number of holes its union surrounds
  // (0: simply connected, up to points where it touches itself).
  std::size_t cycle_rank(const std::vector<std::uint32_t>& region, const std::vector<char>& in) const {
    std::size_t inner = 0;
    for (auto t : region)
      for (auto n : T_.triangles()[t].nbr)
        if (n != kNone && in[n]) ++inner;
    return inner / 2 + 1 - region.size();
  }

  // The union of a simply connected region's triangles as an environment of its own, or
  // nullopt where it touches itself at a vertex (no simple ring).
  std::optional<geometry::Environment> sub_environment(const std::vector<std::uint32_t>& region, const std::vector<char>& in) const {
    std::vector<std::uint32_t> next(env_.num_vertices(), kNone);
    std::uint32_t first = kNone;
    std::size_t count = 0;
    for (auto [a, b] : outline(region, in)) {
      if (next[a] != kNone) return std::nullopt;
      next[a] = b, first = a, ++count;
    }
    geometry::Ring ring;
    for (std::uint32_t v = first;;) {
      ring.push_back(env_.vertex(v));
      v = next[v];
      if (v == first || v == kNone || ring.size() > count) break;
    }
    if (ring.size() != count) return std::nullopt;
    try {
      return geometry::Environment::make(std::move(ring), {});
    } catch (const InputError&) {
      return std::nullopt;  // e.g. two corners at one point (a contact of the whole environment)
    }
  }

  // One pursuer clears the region on its own (exhaustive search in the region alone: the
  // guards keep evaders from crossing its chords), if it can within a budget.
  std::optional<Plan> one_pursuer_plan(const std::vector<std::uint32_t>& region, const std::vector<char>& in) const {
    if (!search_regions_ || region.size() > 400 || cycle_rank(region, in) > 0) return std::nullopt;
    const auto sub = sub_environment(region, in);
    if (!sub) return std::nullopt;
    const auto cells = ConservativeCells::build(*sub);
    const auto r = search(cells, 1, {std::nullopt, 200'000, false});
    if (r.outcome != SearchResult::Outcome::Plan) return std::nullopt;
    return r.plan;
  }

  // Is segment ab (an edge of the triangulation) wholly in V(g)? Both ends are seen and
  // no environment vertex but a and b lies in the closed triangle g a b: then no obstacle
  // enters it (one would have to cross a free segment), so the closed triangle lies in
  // free space and g sees every point of ab within it. (A vertex on ga does not do: an
  // obstacle may lie along ga and reach across to gb, hiding what is behind it.)
  bool seen_edge(const Point& g, const std::vector<char>& vis, std::uint32_t a, std::uint32_t b) const {
    if (!vis[a] || !vis[b]) return false;
    const Point &pa = env_.vertex(a), &pb = env_.vertex(b);
    const int o = orientation(g, pa, pb);
    if (o == 0) return true;
    const double lo = std::min({g.x(), pa.x(), pb.x()}), hi = std::max({g.x(), pa.x(), pb.x()});
    auto it = std::lower_bound(by_x_.begin(), by_x_.end(), lo, [&](std::uint32_t v, double x) { return env_.vertex(v).x() < x; });
    for (; it != by_x_.end() && env_.vertex(*it).x() <= hi; ++it) {
      if (*it == a || *it == b) continue;
      const Point& v = env_.vertex(*it);
      if (orientation(g, pa, v) != -o && orientation(pa, pb, v) != -o && orientation(pb, g, v) != -o) return false;
    }
    return true;
  }

  // A static guard standing at the centre of triangle `guard`: the triangles it sees
  // wholly drop out of the region, and the rest falls apart into parts no evader can
  // leave unseen (joined only across edges the guard does not see wholly).
  struct GuardSplit {
    std::uint32_t guard = kNone;
    std::vector<std::vector<std::uint32_t>> parts;
    std::size_t max_rank = 0, max_size = 0;
  };
  GuardSplit split_by_guard(const std::vector<std::uint32_t>& region, const std::vector<char>& in, std::uint32_t guard) {
    const auto& tris = T_.triangles();
    const Point& g = centre_[guard];
    vis_.assign(env_.num_vertices(), 0);
    for (auto v : index_.visible_vertices(g)) vis_[v] = 1;
    // Per triangle of the region, which of its edges the guard sees wholly (an edge shared
    // by two of the region's triangles is decided once).
    for (std::size_t k = 0; k < region.size(); ++k) local_[region[k]] = static_cast<std::uint32_t>(k);
    std::vector<std::array<char, 3>> seen(region.size());
    std::vector<char> whole(region.size());
    for (std::size_t k = 0; k < region.size(); ++k) {
      const auto& tr = tris[region[k]];
      for (int i = 0; i < 3; ++i) {
        const auto n = tr.nbr[i];
        if (n != kNone && in[n] && local_[n] < k) {
          int j = 0;
          while (tris[n].nbr[j] != region[k]) ++j;
          seen[k][i] = seen[local_[n]][j];
        } else {
          seen[k][i] = seen_edge(g, vis_, tr.v[i], tr.v[(i + 1) % 3]);
        }
      }
      whole[k] = seen[k][0] && seen[k][1] && seen[k][2];
    }
    std::vector<std::uint32_t> up(region.size());
    for (std::uint32_t k = 0; k < up.size(); ++k) up[k] = k;
    auto find = [&](std::uint32_t x) {
      while (up[x] != x) x = up[x] = up[up[x]];
      return x;
    };
    for (std::size_t k = 0; k < region.size(); ++k) {
      if (whole[k]) continue;
      for (int i = 0; i < 3; ++i) {
        const auto n = tris[region[k]].nbr[i];
        if (n == kNone || !in[n] || seen[k][i] || whole[local_[n]]) continue;
        up[find(static_cast<std::uint32_t>(k))] = find(local_[n]);
      }
    }
    GuardSplit out;
    out.guard = guard;
    std::vector<std::uint32_t> part_of(region.size(), kNone);
    for (std::size_t k = 0; k < region.size(); ++k) {
      if (whole[k]) continue;
      const auto r = find(static_cast<std::uint32_t>(k));
      if (part_of[r] == kNone) part_of[r] = static_cast<std::uint32_t>(out.parts.size()), out.parts.emplace_back();
      out.parts[part_of[r]].push_back(region[k]);
    }
    for (auto& part : out.parts) {
      for (auto t : part) part_in_[t] = 1;
      out.max_rank = std::max(out.max_rank, cycle_rank(part, part_in_));
      out.max_size = std::max(out.max_size, part.size());
      for (auto t : part) part_in_[t] = 0;
    }
    return out;
  }

  // The guard that leaves the fewest holes in any part, then the smallest largest part
  // (balanced splits keep the nesting of guards logarithmic). Trichromatic triangles
  // (corners on three different rings, 6.3) are where a guard cuts between holes; every
  // triangle of the region is a candidate, so a region around a single hole, which has
  // none, is cut too.
  GuardSplit best_guard(const std::vector<std::uint32_t>& region, const std::vector<char>& in) {
    const std::size_t step = std::max<std::size_t>(1, region.size() / 400);
    GuardSplit best;
    for (std::size_t k = 0; k < region.size(); k += step) {
      GuardSplit s = split_by_guard(region, in, region[k]);
      if (best.guard == kNone || std::tie(s.max_rank, s.max_size) < std::tie(best.max_rank, best.max_size)) best = std::move(s);
    }
    return best;
  }

  // How one region is cleared, decided before anyone moves: a pursuer standing at a kernel
  // point, one pursuer walking its own plan, or a guard splitting it. `entry` is where the
  // pursuer who starts on it goes first, `exit` where it is free again (a split's is its
  // guard's post: the parts' pursuers leave from inside it).
  struct Clearing {
    std::optional<Point> kernel;
    std::optional<Plan> plan;
    GuardSplit split;
    Point entry, exit;
    std::size_t parts = 1;  // parts this clearing clears (a standing point may see several)
  };
  Clearing prepare(const std::vector<std::uint32_t>& region) {
    Clearing c;
    const Mark mark(in_, region);  // in_ holds exactly this region while it is examined
    c.kernel = kernel_of(region, in_);
    if (!c.kernel && region.size() == 1) throw std::logic_error("pursuit: a triangle with an empty kernel");
    if (!c.kernel) c.plan = one_pursuer_plan(region, in_);
    if (!c.kernel && !c.plan) c.split = best_guard(region, in_);
    if (c.kernel) c.entry = c.exit = *c.kernel;
    else if (c.plan) c.entry = c.plan->paths[0].front(), c.exit = c.plan->paths[0].back();
    else c.entry = c.exit = centre_[c.split.guard];
    return c;
  }

  // The order the parts of a split are cleared in does not matter for correctness (the
  // guard sees every edge between two parts), only for the length walked between them,
  // which was most of a plan on house plans (parts in triangle order). A nearest-neighbour
  // tour from `from`, improved by 2-opt, on straight-line distances from one part's exit
  // to the next one's entry.
  static std::vector<std::size_t> tour(const std::vector<Clearing>& parts, const Point& from) {
    const std::size_t n = parts.size();
    auto d = [](const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); };
    std::vector<std::size_t> order;
    std::vector<char> used(n, 0);
    Point at = from;
    for (std::size_t step = 0; step < n; ++step) {
      std::size_t best = n;
      for (std::size_t i = 0; i < n; ++i)
        if (!used[i] && (best == n || d(at, parts[i].entry) < d(at, parts[best].entry))) best = i;
      used[best] = 1, order.push_back(best), at = parts[best].exit;
    }
    // 2-opt reverses a stretch; with entry != exit a reversed part is walked differently,
    // so only runs of parts whose entry is their exit are reversed. Inside such a run the
    // legs keep their lengths; only the two at its ends change (O(1) per candidate).
    auto sym = [&](std::size_t k) { return parts[order[k]].entry == parts[order[k]].exit; };
    for (int pass = 0; pass < 50; ++pass) {
      bool better = false;
      for (std::size_t i = 0; i + 1 < n; ++i) {
        if (!sym(i)) continue;
        const Point& before = i == 0 ? from : parts[order[i - 1]].exit;
        const Point& first = parts[order[i]].entry;
        for (std::size_t j = i + 1; j < n && sym(j); ++j) {
          const Point& last = parts[order[j]].entry;
          const double after_old = j + 1 < n ? d(last, parts[order[j + 1]].entry) : 0;
          const double after_new = j + 1 < n ? d(first, parts[order[j + 1]].entry) : 0;
          if (d(before, last) + after_new < d(before, first) + after_old - 1e-9) {
            std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i), order.begin() + static_cast<std::ptrdiff_t>(j) + 1);
            better = true;
            break;  // the run starting at i changed: its first part is another now
          }
        }
      }
      if (!better) break;
    }
    return order;
  }

  // Where the next pursuer take() hands out stands now.
  Point next_free() const {
    for (std::uint32_t p = 0; p < busy_.size(); ++p)
      if (!busy_[p]) return res_.plan.paths[p].back();
    return start_;
  }

  // A pursuer standing at a part's kernel point also clears every other part it sees
  // wholly (each triangle's three edges seen, the test of split_by_guard: the part is then
  // inside V). Along a wall drawn as a staircase of 1 cm steps every step was a part of one
  // triangle of its own, walked to one at a time (house 1451: 70 of its 86 parts). Greedy
  // set cover over the kernel points: the point that clears most parts not yet cleared.
  std::vector<Clearing> stand_where_many_are_seen(std::vector<Clearing> parts,
                                                   const std::vector<std::vector<std::uint32_t>>& tris_of) {
    const auto& tris = T_.triangles();
    const std::size_t n = parts.size();
    std::vector<std::vector<std::size_t>> sees(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!parts[i].kernel) continue;
      const Point& x = *parts[i].kernel;
      vis_.assign(env_.num_vertices(), 0);
      for (auto v : index_.visible_vertices(x)) vis_[v] = 1;
      for (std::size_t j = 0; j < n; ++j) {
        bool whole = true;
        for (std::size_t k = 0; k < tris_of[j].size() && whole && j != i; ++k)
          for (int e = 0; e < 3 && whole; ++e) whole = seen_edge(x, vis_, tris[tris_of[j][k]].v[e], tris[tris_of[j][k]].v[(e + 1) % 3]);
        if (whole) sees[i].push_back(j);
      }
    }
    std::vector<char> cleared(n, 0);
    std::vector<Clearing> out;
    for (;;) {
      std::size_t best = n, most = 0;
      for (std::size_t i = 0; i < n; ++i) {
        std::size_t m = 0;
        for (auto j : sees[i]) m += !cleared[j];
        if (m > most) best = i, most = m;
      }
      if (best == n) break;
      Clearing g;
      g.kernel = parts[best].kernel, g.entry = g.exit = *g.kernel, g.parts = most;
      for (auto j : sees[best]) cleared[j] = 1;
      out.push_back(std::move(g));
    }
    for (std::size_t j = 0; j < n; ++j)
      if (!cleared[j]) out.push_back(std::move(parts[j]));
    return out;
  }

  void clear(const std::vector<std::uint32_t>& region) { execute(prepare(region)); }

  void execute(Clearing c) {
    if (c.kernel) {
      // The kernel point may lie on a diagonal between two of the region's triangles.
      const std::uint32_t p = take();
      travel(p, containing(*c.kernel), *c.kernel);
      busy_[p] = 0;
      res_.regions += c.parts;
      ++res_.stops;
      return;
    }
    if (c.plan) {
      const std::uint32_t p = take();
      const auto& path = c.plan->paths[0];
      travel(p, containing(path[0]), path[0]);
      for (std::size_t i = 1; i < path.size(); ++i)
        for (std::size_t q = 0; q < res_.plan.paths.size(); ++q) res_.plan.paths[q].push_back(q == p ? path[i] : res_.plan.paths[q].back());
      where_[p] = containing(path.back());
      busy_[p] = 0;
      ++res_.regions;
      ++res_.stops;
      return;
    }
    const std::uint32_t guard = take();
    travel(guard, c.split.guard, centre_[c.split.guard]);
    ++res_.guards;
    res_.guard_points.push_back(centre_[c.split.guard]);
    if (c.split.parts.empty()) ++res_.regions;  // the guard sees the whole region
    std::vector<Clearing> parts;
    for (auto& part : c.split.parts) parts.push_back(prepare(part));
    parts = stand_where_many_are_seen(std::move(parts), c.split.parts);
    c.split.parts.clear();
    for (std::size_t i : tour(parts, next_free())) execute(std::move(parts[i]));
    busy_[guard] = 0;
  }

  const geometry::Environment& env_;
  geometry::Triangulation T_;
  geometry::VisibilityIndex index_;
  Point start_;
  bool search_regions_;
  std::uint32_t start_tri_ = 0;
  std::vector<Point> centre_;
  std::vector<std::uint32_t> by_x_;
  std::vector<char> in_, vis_, part_in_ = std::vector<char>(T_.size(), 0);
  std::vector<std::uint32_t> local_ = std::vector<std::uint32_t>(T_.size(), kNone);
  std::vector<char> busy_;
  std::vector<std::uint32_t> where_;
  SplitResult res_;
};

}  // namespace

SplitResult split_strategy(const geometry::Environment& env, const std::optional<Point>& start, bool search_regions) {
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
