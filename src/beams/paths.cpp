// SPDX-License-Identifier: Apache-2.0
#include <preimage/beams/paths.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/error.hpp>

#include <algorithm>
#include <deque>
#include <optional>
#include <random>
#include <stdexcept>

namespace preimage::beams {
namespace {

using geometry::ExactFT;
using EVector = geometry::ExactKernel::Vector_2;
using ESegment = geometry::ExactKernel::Segment_2;

ExactFT cross(const EVector& u, const EVector& v) { return u.x() * v.y() - u.y() * v.x(); }

// y of the non-vertical segment ab at abscissa x.
ExactFT y_at(const ExactPoint& a, const ExactPoint& b, const ExactFT& x) {
  return a.y() + (x - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
}

}  // namespace

// ---------------------------------------------------------------- tracing
Trace trace_path(const BeamArrangement& A, std::span<const ExactPoint> path) {
  if (path.empty()) throw InputError("path: empty");
  const auto& env = A.environment();
  const auto& H = A.half_edges();
  const auto& V = A.vertices();
  auto at = [](std::size_t k) { return "path point " + std::to_string(k); };
  Trace T;
  auto r0 = A.locate(path[0]);
  if (!r0) throw InputError(at(0) + " " + geometry::format_point(geometry::to_double(path[0])) + " is not strictly inside a region");
  T.regions.push_back(*r0);
  for (std::size_t k = 1; k < path.size(); ++k) {
    const ExactPoint &a = path[k - 1], &b = path[k];
    const std::string seg = "path segment " + std::to_string(k - 1) + "-" + std::to_string(k);
    const ESegment ab(a, b);
    for (std::size_t e = 0; e < env.num_vertices(); ++e)
      if (CGAL::do_intersect(ab, ESegment(env.exact_vertex(e), env.exact_vertex(env.next(e)))))
        throw InputError(seg + " touches the boundary");
    for (auto& l : A.landmarks())
      if (CGAL::do_intersect(ab, geometry::to_exact(l))) throw InputError(seg + " passes through a landmark");
    struct Hit { ExactFT s; std::uint32_t half_edge; Symbol y; ExactPoint at; };
    std::vector<Hit> hits;
    for (std::uint32_t i = 0; i < A.beams().size(); ++i) {
      const BeamGeometry& bg = A.beams()[i];
      const int o1 = geometry::orientation(bg.from, bg.to, a), o2 = geometry::orientation(bg.from, bg.to, b);
      if (o1 * o2 > 0) continue;
      const int o3 = geometry::orientation(a, b, bg.from), o4 = geometry::orientation(a, b, bg.to);
      if (o3 * o4 > 0) continue;
      if (o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0) {
        // Collinear with the beam's line yet apart from the beam is fine.
        if (!CGAL::do_intersect(ab, ESegment(bg.from, bg.to))) continue;
        throw InputError(seg + " touches beam " + std::to_string(i) + " without crossing it");
      }
      const EVector d = b - a, e = bg.to - bg.from;
      const ExactFT s = cross(bg.from - a, e) / cross(d, e);
      const ExactPoint X = a + s * d;
      // The beam piece holding X (its even half-edge runs from -> to, region on the left).
      std::uint32_t piece = kNone;
      const auto [first, last] = A.beam_pieces(i);
      for (std::uint32_t h = first; h < last && piece == kNone; h += 2) {
        if (X == V[H[h].origin] || X == V[H[h].target]) throw InputError(seg + " passes through a crossing of beams");
        if (CGAL::collinear_are_strictly_ordered_along_line(V[H[h].origin], X, V[H[h].target])) piece = h;
      }
      // From the right of from->to (o1 < 0) to the left: positive; entering the even half-edge's face.
      const bool positive = o1 < 0;
      const Symbol y = positive || !bg.directed ? Alphabet::positive(bg.label) : Alphabet::negative(bg.label);
      hits.push_back({s, positive ? piece : piece + 1, y, X});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& p, const Hit& q) { return p.s < q.s; });
    for (std::size_t j = 1; j < hits.size(); ++j)
      if (hits[j].s == hits[j - 1].s) throw InputError(seg + " passes through a crossing of beams");
    for (const Hit& h : hits) {
      if (A.region_of(BeamArrangement::twin(h.half_edge)) != T.regions.back())
        throw std::logic_error("trace_path: crossing does not leave the current region");
      T.word.push_back(h.y);
      T.regions.push_back(A.region_of(h.half_edge));
      T.crossings.push_back(h.at);
    }
  }
  auto rk = A.locate(path.back());
  if (!rk || *rk != T.regions.back())
    throw InputError(at(path.size() - 1) + " " + geometry::format_point(geometry::to_double(path.back())) +
                     " is not strictly inside a region");
  return T;
}

// ---------------------------------------------------------------- simulation
Simulation simulate(const BeamArrangement& A, std::uint64_t seed, std::size_t steps,
                    const std::function<void(std::size_t)>& progress) {
  std::mt19937_64 rng(seed);
  const CGAL::Bbox_2 box = A.environment().bbox();
  std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax());
  const double reach = 0.35 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  std::uniform_real_distribution<double> angle(0, 2 * 3.14159265358979), len(0.05 * reach, reach);
  Simulation sim;
  for (int tries = 0; sim.path.empty(); ++tries) {
    if (tries > 100000) throw std::runtime_error("simulate: no point strictly inside a region found");
    const ExactPoint p = geometry::random_point<ExactPoint>(rng, ux, uy);
    if (A.locate(p)) sim.path.push_back(p);
  }
  sim.trace = trace_path(A, sim.path);
  for (std::size_t k = 0; k < steps; ++k) {
    const geometry::Point c = geometry::to_double(sim.path.back());
    for (int tries = 0;; ++tries) {
      if (tries > 10000) return sim;  // boxed in: stop early rather than loop
      const double th = angle(rng), l = len(rng);
      const ExactPoint q(c.x() + l * std::cos(th), c.y() + l * std::sin(th));
      const ExactPoint seg[2] = {sim.path.back(), q};
      try {
        Trace t = trace_path(A, seg);  // rejects degenerate contacts; resample then
        sim.path.push_back(q);
        sim.trace.word.insert(sim.trace.word.end(), t.word.begin(), t.word.end());
        sim.trace.regions.insert(sim.trace.regions.end(), t.regions.begin() + 1, t.regions.end());
        sim.trace.crossings.insert(sim.trace.crossings.end(), t.crossings.begin(), t.crossings.end());
        if (progress) progress(k + 1);
        break;
      } catch (const InputError&) {
      }
    }
  }
  return sim;
}

// ---------------------------------------------------------------- routing inside a region
std::vector<ExactPoint> route_in_region(const BeamArrangement& A, std::uint32_t r, const ExactPoint& p, const ExactPoint& q) {
  const auto& H = A.half_edges();
  const auto& V = A.vertices();
  const auto hs = A.region_half_edges(r);
  auto clear = [&](const ExactPoint& a, const ExactPoint& b) {
    const ESegment s(a, b);
    for (std::uint32_t h : hs)
      if (CGAL::do_intersect(s, ESegment(V[H[h].origin], V[H[h].target]))) return false;
    return true;
  };
  if (p == q) return {p};
  if (clear(p, q)) return {p, q};

  // Vertical slabs between consecutive vertex abscissae; in each slab the region is a
  // stack of open trapezoids between consecutive half-edges (face above a left-to-right
  // half-edge, below a right-to-left one). Trapezoids are convex, so a path through
  // their sample points and points on shared walls stays inside.
  std::vector<ExactFT> X;
  for (std::uint32_t h : hs) X.push_back(V[H[h].origin].x());
  std::sort(X.begin(), X.end());
  X.erase(std::unique(X.begin(), X.end()), X.end());
  struct Cell { std::size_t slab; std::uint32_t lo, hi; ExactPoint mid; };
  std::vector<Cell> cells;
  std::vector<std::size_t> slab_begin{0};
  for (std::size_t i = 0; i + 1 < X.size(); ++i) {
    const ExactFT xm = (X[i] + X[i + 1]) / 2;
    struct Cut { ExactFT y; bool opens; std::uint32_t h; };
    std::vector<Cut> cuts;
    for (std::uint32_t h : hs) {
      const ExactPoint &a = V[H[h].origin], &b = V[H[h].target];
      if (a.x() == b.x()) continue;
      const ExactFT lo = CGAL::min(a.x(), b.x()), hi = CGAL::max(a.x(), b.x());
      if (lo <= X[i] && hi >= X[i + 1]) cuts.push_back({y_at(a, b, xm), a.x() < b.x(), h});
    }
    std::sort(cuts.begin(), cuts.end(), [](const Cut& u, const Cut& v) { return u.y < v.y || (u.y == v.y && !u.opens && v.opens); });
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
      if (cuts[k].opens && !cuts[k + 1].opens)
        cells.push_back({i, cuts[k].h, cuts[k + 1].h, ExactPoint(xm, (cuts[k].y + cuts[k + 1].y) / 2)});
    slab_begin.push_back(cells.size());
  }
  auto eval = [&](std::uint32_t h, const ExactFT& x) { return y_at(V[H[h].origin], V[H[h].target], x); };
  // A point strictly inside a cell (or on its wall, away from the boundary): its cell.
  auto cell_of = [&](const ExactPoint& z) -> std::size_t {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const Cell& C = cells[c];
      if (z.x() < X[C.slab] || z.x() > X[C.slab + 1]) continue;
      if (eval(C.lo, z.x()) < z.y() && z.y() < eval(C.hi, z.x())) return c;
    }
    throw std::logic_error("route_in_region: point not in any cell");
  };
  // Walls: neighbouring cells share an open interval on x = X[i] not blocked by the
  // region's own vertices or vertical edges there.
  std::vector<std::vector<std::pair<std::size_t, ExactPoint>>> adj(cells.size());
  for (std::size_t i = 1; i + 1 < X.size(); ++i) {
    std::vector<ExactFT> block;
    std::vector<std::pair<ExactFT, ExactFT>> vertical;
    for (std::uint32_t h : hs) {
      const ExactPoint &a = V[H[h].origin], &b = V[H[h].target];
      if (a.x() == X[i]) block.push_back(a.y());
      if (a.x() == X[i] && b.x() == X[i]) vertical.push_back({CGAL::min(a.y(), b.y()), CGAL::max(a.y(), b.y())});
    }
    std::sort(block.begin(), block.end());
    for (std::size_t l = slab_begin[i - 1]; l < slab_begin[i]; ++l)
      for (std::size_t rr = slab_begin[i]; rr < slab_begin[i + 1]; ++rr) {
        const ExactFT lo = CGAL::max(eval(cells[l].lo, X[i]), eval(cells[rr].lo, X[i]));
        const ExactFT hi = CGAL::min(eval(cells[l].hi, X[i]), eval(cells[rr].hi, X[i]));
        if (!(lo < hi)) continue;
        std::vector<ExactFT> cuts{lo};
        for (auto& y : block)
          if (lo < y && y < hi) cuts.push_back(y);
        cuts.push_back(hi);
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
          const ExactFT y = (cuts[k] + cuts[k + 1]) / 2;
          bool covered = false;
          for (auto& [v0, v1] : vertical) covered = covered || (v0 <= y && y <= v1);
          if (covered) continue;
          const ExactPoint w(X[i], y);
          adj[l].push_back({rr, w});
          adj[rr].push_back({l, w});
          break;
        }
      }
  }
  const std::size_t cp = cell_of(p), cq = cell_of(q);
  std::vector<std::size_t> from(cells.size(), SIZE_MAX);
  std::vector<ExactPoint> via(cells.size());
  std::deque<std::size_t> queue{cp};
  from[cp] = cp;
  while (!queue.empty() && from[cq] == SIZE_MAX) {
    const std::size_t c = queue.front();
    queue.pop_front();
    for (auto& [d, w] : adj[c])
      if (from[d] == SIZE_MAX) from[d] = c, via[d] = w, queue.push_back(d);
  }
  if (from[cq] == SIZE_MAX) throw std::logic_error("route_in_region: region not connected");
  std::vector<ExactPoint> back{q};
  for (std::size_t c = cq; c != cp; c = from[c]) back.push_back(cells[c].mid), back.push_back(via[c]);
  back.push_back(cells[cp].mid);
  back.push_back(p);
  std::reverse(back.begin(), back.end());
  return back;
}

// ---------------------------------------------------------------- sample paths
namespace {

// A point strictly inside the face of half-edge h, on the normal through the midpoint
// m of h: halfway to the first boundary point of that face along the normal.
ExactPoint portal(const BeamArrangement& A, std::uint32_t h, const ExactPoint& m) {
  const auto& H = A.half_edges();
  const auto& V = A.vertices();
  const EVector d = V[H[h].target] - V[H[h].origin];
  const EVector n(-d.y(), d.x());  // left normal: into the face of h
  std::optional<ExactFT> best;
  for (std::uint32_t g : A.region_half_edges(A.region_of(h))) {
    if (g == h || g == BeamArrangement::twin(h)) continue;
    const ExactPoint &a = V[H[g].origin], &b = V[H[g].target];
    const EVector e = b - a, w = a - m;
    const ExactFT den = cross(n, e);
    std::vector<ExactFT> ts;
    if (den == 0) {
      if (cross(w, n) == 0) ts = {(w * n) / (n * n), ((b - m) * n) / (n * n)};
    } else {
      const ExactFT s = cross(w, n) / den;
      if (s >= 0 && s <= 1) ts.push_back(cross(w, e) / den);
    }
    for (auto& t : ts)
      if (t > 0 && (!best || t < *best)) best = t;
  }
  return m + (*best / 2) * n;
}

// Appends a crossing of half-edge h's piece, from path.back() (strictly inside the
// region behind h) to a point strictly inside h's face.
void append_crossing(const BeamArrangement& A, std::uint32_t h, std::vector<ExactPoint>& path) {
  const auto& H = A.half_edges();
  const auto& V = A.vertices();
  const ExactPoint m = CGAL::midpoint(V[H[h].origin], V[H[h].target]);
  const ExactPoint out = portal(A, BeamArrangement::twin(h), m), in = portal(A, h, m);
  const auto part = route_in_region(A, A.region_of(BeamArrangement::twin(h)), path.back(), out);
  path.insert(path.end(), part.begin() + 1, part.end());
  // out, m and in lie on the normal through m: one segment crossing the beam at m.
  path.push_back(in);
}

void append_route(const BeamArrangement& A, std::uint32_t r, const ExactPoint& to, std::vector<ExactPoint>& path) {
  const auto part = route_in_region(A, r, path.back(), to);
  path.insert(path.end(), part.begin() + 1, part.end());
}

}  // namespace

std::vector<ExactPoint> crossing_path(const BeamArrangement& A, std::uint32_t h) {
  std::vector<ExactPoint> path{A.regions()[A.region_of(BeamArrangement::twin(h))].sample};
  append_crossing(A, h, path);
  append_route(A, A.region_of(h), A.regions()[A.region_of(h)].sample, path);
  return path;
}

std::vector<ExactPoint> free_path(const BeamArrangement& A, const ExactPoint& p, const ExactPoint& q) {
  auto where = [&](const ExactPoint& x, const char* what) {
    auto r = A.locate(x);
    if (!r) throw InputError(std::string(what) + " " + geometry::format_point(geometry::to_double(x)) + " is not strictly inside a region");
    return *r;
  };
  const std::uint32_t rp = where(p, "path end"), rq = where(q, "path end");
  // Breadth-first over G's crossings (any label): fewest beam crossings.
  std::vector<std::uint32_t> via(A.num_regions(), kNone);
  std::vector<char> seen(A.num_regions(), 0);
  std::deque<std::uint32_t> queue{rp};
  seen[rp] = 1;
  const auto& E = A.edges();
  while (!queue.empty() && !seen[rq]) {
    const std::uint32_t r = queue.front();
    queue.pop_front();
    auto it = std::lower_bound(E.begin(), E.end(), r, [](const Crossing& c, std::uint32_t v) { return c.from < v; });
    for (; it != E.end() && it->from == r; ++it)
      if (!seen[it->to]) seen[it->to] = 1, via[it->to] = it->half_edge, queue.push_back(it->to);
  }
  if (!seen[rq]) throw std::logic_error("free_path: free space is not connected through G");
  std::vector<std::uint32_t> steps;
  for (std::uint32_t r = rq; r != rp; r = A.region_of(BeamArrangement::twin(via[r]))) steps.push_back(via[r]);
  std::reverse(steps.begin(), steps.end());
  std::vector<ExactPoint> path{p};
  for (std::uint32_t h : steps) append_crossing(A, h, path);
  append_route(A, rq, q, path);
  return path;
}

std::vector<ExactPoint> sample_path(const BeamArrangement& A, std::span<const std::uint32_t> regions,
                                    std::span<const Symbol> word) {
  if (regions.size() != word.size() + 1) throw std::invalid_argument("sample_path: need one more region than observations");
  std::vector<ExactPoint> path{A.regions()[regions[0]].sample};
  for (std::size_t i = 0; i < word.size(); ++i) {
    const Crossing* c = A.find_edge(regions[i], word[i], regions[i + 1]);
    if (!c) throw std::invalid_argument("sample_path: step " + std::to_string(i + 1) + " is not an edge of G");
    append_crossing(A, c->half_edge, path);  // c's half-edge has the region entered as its face
    append_route(A, regions[i + 1], A.regions()[regions[i + 1]].sample, path);
  }
  return path;
}

}  // namespace preimage::beams
