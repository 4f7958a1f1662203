// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/shortest_path_map.hpp>

#include <preimage/error.hpp>
#include <preimage/parallel_for.hpp>

#include <algorithm>
#include <cmath>
#include <queue>
#include <string>
#include <thread>

namespace preimage::geometry {

namespace {

double spm_length(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

unsigned spm_threads(unsigned threads, std::size_t work) {
  if (work < 64) return 1;
  if (threads == 0) threads = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
  return threads;
}

}  // namespace

ShortestPathMap::ShortestPathMap(const VisibilityGraph& graph, const Point& source, unsigned threads)
    : graph_(&graph), source_(source) {
  const VisibilityIndex& index = graph.index();
  const Environment& env = graph.environment();
  if (!index.in_free_space(source)) {
    std::string msg("shortest path map: the source ");
    msg.append(format_point(source)).append(" is not in free space");
    throw InputError(msg);
  }
  const auto& reflex = graph.reflex_vertices();
  const double inf = std::numeric_limits<double>::infinity();
  dist_.assign(env.num_vertices(), inf);
  pred_.assign(env.num_vertices(), kNone);

  // Out-lists: for reflex u, the reflex vertices w it sees with segment uw tangent at u
  // (the graph's lists, shared with its transits' searches: one visibility query per vertex).
  std::vector<std::uint32_t> slot(env.num_vertices(), kNone);
  for (std::size_t k = 0; k < reflex.size(); ++k) slot[reflex[k]] = static_cast<std::uint32_t>(k);
  parallel_for(reflex.size(), spm_threads(threads, reflex.size()), [&](std::size_t k) { graph.tangent_out(reflex[k]); });
  out_off_.assign(reflex.size() + 1, 0);
  for (std::size_t k = 0; k < reflex.size(); ++k) {
    const std::uint32_t u = reflex[k];
    for (std::uint32_t w : graph.tangent_out(u))
      if (env.vertex(w) != env.vertex(u)) out_.push_back(w);
    out_off_[k + 1] = static_cast<std::uint32_t>(out_.size());
  }
  slot_ = std::move(slot);
  const auto& slot_ref = slot_;

  struct Item {
    double d;
    std::uint32_t v;
    bool operator>(const Item& o) const { return d > o.d || (d == o.d && v > o.v); }
  };
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  for (std::uint32_t w : index.visible_vertices(source))
    if (slot_ref[w] != kNone) {
      const double d = spm_length(source, env.vertex(w));
      if (d < dist_[w]) dist_[w] = d, pred_[w] = kSource, open.push({d, w});
    }
  std::vector<char> done(env.num_vertices(), 0);
  while (!open.empty()) {
    const Item it = open.top();
    open.pop();
    if (done[it.v]) continue;
    done[it.v] = 1, ++reached_, max_dist_ = std::max(max_dist_, it.d);
    const Point& U = env.vertex(it.v);
    for (std::uint32_t k = out_off_[slot_ref[it.v]]; k < out_off_[slot_ref[it.v] + 1]; ++k) {
      const std::uint32_t w = out_[k];
      ++edges_;
      const double d = it.d + spm_length(U, env.vertex(w));
      if (d < dist_[w]) dist_[w] = d, pred_[w] = it.v, open.push({d, w});
    }
  }
}

ShortestPathMap::Query ShortestPathMap::query(const Point& p) const {
  Query q;
  const VisibilityIndex& index = graph_->index();
  if (!index.in_free_space(p)) return q;
  const Environment& env = graph_->environment();
  if (index.visible(source_, p)) q.distance = spm_length(source_, p), q.root = kSource;
  for (std::uint32_t v : index.visible_vertices(p)) {
    if (pred_[v] == kNone || !tangent_at(env, v, p)) continue;
    const double d = dist_[v] + spm_length(env.vertex(v), p);
    if (d < q.distance) q.distance = d, q.root = v;
  }
  return q;
}

Point ShortestPathMap::root_point(std::uint32_t root) const { return root == kSource ? source_ : environment().vertex(root); }

std::vector<Point> ShortestPathMap::path_to(const Point& p) const {
  const Query q = query(p);
  std::vector<Point> out;
  if (q.root == kNone) return out;
  out.push_back(p);
  for (std::uint32_t r = q.root; r != kSource; r = pred_[r]) out.push_back(environment().vertex(r));
  out.push_back(source_);
  std::reverse(out.begin(), out.end());
  return out;
}

bool ShortestPathMap::extends(std::uint32_t v) const {
  const Environment& env = environment();
  const std::uint32_t u = pred_[v];
  if (u == kNone) return false;
  const Point& U = root_point(u);
  const Point& V = env.vertex(v);
  if (U == V) return false;
  // The extension enters free space iff the obstacle's wedge at v (between its two
  // neighbours, < 180 degrees at a reflex vertex) lies on one side of the line UV and the
  // ray beyond V does not run along one of v's edges.
  const Point& A = env.vertex(env.prev(v));
  const Point& B = env.vertex(env.next(v));
  const int oa = orientation(U, V, A), ob = orientation(U, V, B);
  if (oa * ob < 0) return false;                          // the ray enters the obstacle at v
  if (oa == 0 && dot_sign(U, V, V, A) > 0) return false;  // runs along edge v-prev(v)
  if (ob == 0 && dot_sign(U, V, V, B) > 0) return false;  // runs along edge v-next(v)
  return true;
}

std::size_t ShortestPathMap::num_extensions() const {
  std::size_t n = 0;
  for (std::uint32_t v : graph_->reflex_vertices()) n += extends(v);
  return n;
}

std::vector<ShortestPathMap::Extension> ShortestPathMap::extensions(double tolerance, unsigned threads) const {
  const Environment& env = environment();
  const auto& reflex = graph_->reflex_vertices();
  // Exact part (lazy-exact points are not shared between threads): which bends, and the hits.
  std::vector<Extension> result;
  for (std::uint32_t v : reflex) {
    if (!extends(v)) continue;
    const std::uint32_t u = pred_[v];
    const Point& U = root_point(u);
    const ExactPoint eu = to_exact(U), ev = env.exact_vertex(v);
    const auto hit = shoot_ray(env, ev, ev - eu);
    if (!hit) continue;  // cannot happen in a bounded environment
    result.push_back({v, u, hit->point, hit->edge, to_double(hit->point), false, kNone});
  }
  // Collisions on the extensions, in double: one query each, a bisection for those that collide.
  parallel_for(result.size(), spm_threads(threads, result.size()), [&](std::size_t k) {
    Extension& e = result[k];
    const std::uint32_t v = e.vertex;
    const Point& V = env.vertex(v);
    // h through v along the extension: D(v) + |v x|. The true h is 1-Lipschitz, so
    // h(x) - (D(v) + |vx|) is non-increasing from 0 along it: find where it drops below.
    const Point H = e.end;
    const double len = spm_length(V, H);
    auto at = [&](double t) { return Point(V.x() + t * (H.x() - V.x()), V.y() + t * (H.y() - V.y())); };
    auto shorter = [&](double t, std::uint32_t* who) {
      const Point x = at(t);
      const Query q = query(x);
      if (q.root == kNone) return false;  // rounded off the boundary: nothing decided there
      const double f = dist_[v] + spm_length(V, x);
      if (who) *who = q.root;
      return q.distance < f - 1e-9 * std::max(1.0, f);
    };
    const double t_end = 1 - 1e-9;
    if (len > 0 && shorter(t_end, nullptr)) {
      double lo = 0, hi = t_end;
      const double eps = std::max(tolerance, 1e-15);
      while (hi - lo > eps) {
        const double mid = (lo + hi) / 2;
        (shorter(mid, nullptr) ? hi : lo) = mid;
      }
      std::uint32_t who = kNone;
      shorter(hi, &who);
      e.end = at(lo), e.collides = true, e.collider = who;
    }
  });
  return result;
}

std::vector<ShortestPathMap::Collision> ShortestPathMap::collisions() const {
  const Environment& env = environment();
  // Is predecessor(v) -> v -> x locally shortest: a turn at v (if any) towards the obstacle,
  // whose neighbours of v then lie on that side of both segments (exact orientations)?
  auto taut = [&](std::uint32_t v, const Point& x) {
    const Point& P = root_point(pred_[v]);
    const Point& V = env.vertex(v);
    const int s = orientation(P, V, x);
    if (s == 0 || P == V) return true;
    for (const std::size_t n : {env.prev(v), env.next(v)}) {
      const Point& N = env.vertex(n);
      if (orientation(P, V, N) * s < 0 || orientation(V, x, N) * s < 0) return false;
    }
    return true;
  };
  const auto& reflex = graph_->reflex_vertices();
  std::vector<Collision> result;
  for (std::size_t k = 0; k < reflex.size(); ++k) {
    const std::uint32_t a = reflex[k];
    if (pred_[a] == kNone) continue;
    const Point& A = env.vertex(a);
    for (std::uint32_t j = out_off_[k]; j < out_off_[k + 1]; ++j) {
      const std::uint32_t b = out_[j];
      if (b < a || pred_[b] == kNone) continue;  // each pair once (the segment is tangent at a here)
      const Point& B = env.vertex(b);
      if (!tangent_at(env, b, A)) continue;
      const double ab = spm_length(A, B), da = dist_[a], db = dist_[b];
      if (!(std::fabs(da - db) < ab * (1 - 1e-9))) continue;  // one front reaches the other's root first
      const double t = (ab + db - da) / 2 / ab;
      const Point x(A.x() + t * (B.x() - A.x()), A.y() + t * (B.y() - A.y()));
      const double h = da + t * ab;
      if (!taut(a, x) || !taut(b, x)) continue;  // x cannot be reached through both: no query
      const Query q = query(x);
      if (q.root == kNone || q.distance < h - 1e-9 * std::max(1.0, h)) continue;  // a third root is shorter there
      result.push_back({x, a, b, h});
    }
  }
  std::sort(result.begin(), result.end(), [](const Collision& l, const Collision& r) { return l.a != r.a ? l.a < r.a : l.b < r.b; });
  return result;
}

ShortestPathMap::Samples ShortestPathMap::sample(std::size_t columns, unsigned threads) const {
  Samples s;
  const auto box = environment().bbox();
  const double w = box.xmax() - box.xmin(), h = box.ymax() - box.ymin();
  s.columns = std::max<std::size_t>(columns, 2);
  s.step = w / static_cast<double>(s.columns - 1);
  if (!(s.step > 0)) s.step = 1;
  s.rows = static_cast<std::size_t>(std::floor(h / s.step)) + 1;
  s.x0 = box.xmin(), s.y0 = box.ymin();
  s.values.resize(s.columns * s.rows);
  // h(p) is the least D(r) + |rp| over the roots r that see p: every such sum is the length
  // of a path in free space, and p's own root gives h(p). So each root's visibility polygon
  // (one per reached reflex vertex and the source: O(n) polygons instead of a visibility
  // query per sample, which was most of the wave front's time, issue 49) is scan-converted
  // onto the grid, keeping the least sum per sample. Rows cut the polygon's edges in double,
  // so whether a sample is in free space is decided by the exact in_free_space test (O(1)),
  // and one in free space that no span covered (rounding at an edge) gets a full query.
  std::vector<std::uint32_t> roots{kSource};
  for (std::uint32_t v : graph_->reflex_vertices())
    if (pred_[v] != kNone) roots.push_back(v);
  // Nearest roots first: the samples' values are then close to final early, and a farther
  // root is rejected by comparing squares, without a square root.
  std::stable_sort(roots.begin() + 1, roots.end(), [&](std::uint32_t a, std::uint32_t b) { return dist_[a] < dist_[b]; });
  const unsigned t = spm_threads(threads, roots.size());
  const std::size_t n = s.values.size();
  std::vector<std::vector<Query>> best(t, std::vector<Query>(n));
  parallel_for(t, t, [&](std::size_t th) {
    VisibilityPolygon V;
    std::vector<std::vector<double>> cuts;
    auto& out = best[th];
    for (std::size_t k = th; k < roots.size(); k += t) {
      const std::uint32_t r = roots[k];
      const Point R = root_point(r);
      const double d0 = r == kSource ? 0.0 : dist_[r];
      graph_->index().compute(R, V);
      const std::size_t m = V.vertices.size();
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (const auto& x : V.vertices) lo = std::min(lo, x.approx.y()), hi = std::max(hi, x.approx.y());
      const std::ptrdiff_t j0 = std::max<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(std::ceil((lo - s.y0) / s.step)));
      const std::ptrdiff_t j1 = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(s.rows) - 1, static_cast<std::ptrdiff_t>(std::floor((hi - s.y0) / s.step)));
      if (j1 < j0) continue;
      cuts.assign(static_cast<std::size_t>(j1 - j0 + 1), {});
      for (std::size_t e = 0; e < m; ++e) {
        const Point &a = V.vertices[e].approx, &b = V.vertices[(e + 1) % m].approx;
        if (a.y() == b.y()) continue;
        const Point &p = a.y() < b.y() ? a : b, &q = a.y() < b.y() ? b : a;
        // Rows with p.y <= y < q.y (half open: a vertex shared by two edges counts once).
        std::ptrdiff_t ja = std::max<std::ptrdiff_t>(j0, static_cast<std::ptrdiff_t>(std::ceil((p.y() - s.y0) / s.step)));
        while (ja > j0 && s.y0 + s.step * static_cast<double>(ja - 1) >= p.y()) --ja;
        for (std::ptrdiff_t j = ja; j <= j1; ++j) {
          const double y = s.y0 + s.step * static_cast<double>(j);
          if (y < p.y()) continue;
          if (y >= q.y()) break;
          cuts[static_cast<std::size_t>(j - j0)].push_back(p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
        }
      }
      for (std::ptrdiff_t j = j0; j <= j1; ++j) {
        auto& xs = cuts[static_cast<std::size_t>(j - j0)];
        std::sort(xs.begin(), xs.end());
        const double y = s.y0 + s.step * static_cast<double>(j), dy2 = (y - R.y()) * (y - R.y());
        for (std::size_t c = 0; c + 1 < xs.size(); c += 2) {
          const double xa = xs[c], xb = xs[c + 1];
          const std::ptrdiff_t ia = std::max<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(std::ceil((xa - s.x0) / s.step)));
          const std::ptrdiff_t ib = std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(s.columns) - 1, static_cast<std::ptrdiff_t>(std::floor((xb - s.x0) / s.step)));
          for (std::ptrdiff_t i = ia; i <= ib; ++i) {
            const double x = s.x0 + s.step * static_cast<double>(i);
            const std::size_t at = static_cast<std::size_t>(j) * s.columns + static_cast<std::size_t>(i);
            const double slack = out[at].distance - d0, d2 = (x - R.x()) * (x - R.x()) + dy2;
            if (!(slack > 0) || d2 >= slack * slack) continue;  // (infinite slack passes)
            const double f = d0 + std::sqrt(d2);  // hypot's overflow care was a sixth of the time
            if (f < out[at].distance) out[at] = {f, r};
          }
        }
      }
    }
  });
  parallel_for(s.rows, spm_threads(threads, n), [&](std::size_t j) {
    for (std::size_t i = 0; i < s.columns; ++i) {
      const std::size_t at = j * s.columns + i;
      Query q;
      for (std::size_t th = 0; th < t; ++th)
        if (best[th][at].distance < q.distance) q = best[th][at];
      const Point p = s.point(i, j);
      if (!graph_->index().in_free_space(p)) s.values[at] = {};
      else s.values[at] = q.root != kNone ? q : query(p);
    }
  });
  return s;
}

}  // namespace preimage::geometry
