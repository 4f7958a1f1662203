// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/visibility.hpp>

#include <preimage/error.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

namespace preimage::geometry {

namespace {
ExactPoint exact_vertex(const Environment* environment, const ExactPoint& query, const VisibilityVertex& v) {
  switch (v.kind) {
    case VisibilityVertex::Kind::EnvironmentVertex: return environment->exact_vertex(v.vertex);
    case VisibilityVertex::Kind::Query: return query;
    case VisibilityVertex::Kind::RayHit: break;
  }
  // One lazy-exact construction: the two supporting lines meet in a single point
  // (the ray is not parallel to the edge it hits).
  const ExactKernel::Line_2 ray(query, environment->exact_vertex(v.vertex));
  const auto hit = CGAL::intersection(ray, environment->exact_edge_line(v.edge));
  return *boost::get<ExactPoint>(&*hit);
}

// Double rounding of a visibility vertex seen from o, for drawing only; decisions never read it.
// Inlined into compute's pass over the ray hits, so the divisions of consecutive hits overlap.
[[gnu::always_inline]] inline Point approx_vertex(const Environment& E, const Point& o, const VisibilityVertex& v) {
  switch (v.kind) {
    case VisibilityVertex::Kind::EnvironmentVertex: return E.vertex(v.vertex);
    case VisibilityVertex::Kind::Query: return o;
    case VisibilityVertex::Kind::RayHit: break;
  }
  const Point &w = E.vertex(v.vertex), &a = E.vertex(v.edge), &b = E.vertex(E.next(v.edge));
  const double dx = w.x() - o.x(), dy = w.y() - o.y(), ex = b.x() - a.x(), ey = b.y() - a.y();
  const double s = ((a.x() - o.x()) * ey - (a.y() - o.y()) * ex) / (dx * ey - dy * ex);
  return Point(o.x() + s * dx, o.y() + s * dy);
}
}  // namespace

ExactPoint VisibilityPolygon::exact_query() const { return constructed_query ? *constructed_query : to_exact(query); }

ExactPoint VisibilityPolygon::exact(std::size_t i) const {
  const auto& v = vertices[i];
  if (v.kind == VisibilityVertex::Kind::EnvironmentVertex) return environment->exact_vertex(v.vertex);
  return exact_vertex(environment, exact_query(), v);
}

ExactPoint exact_point(const Environment& env, const ExactPoint& query, const VisibilityVertex& v) {
  return exact_vertex(&env, query, v);
}

std::vector<ExactPoint> VisibilityPolygon::points() const {
  std::vector<ExactPoint> out;
  out.reserve(vertices.size());
  const ExactPoint q = exact_query();  // built once for all ray hits
  for (const auto& v : vertices) out.push_back(exact_vertex(environment, q, v));
  return out;
}

Point VisibilityPolygon::approx_point(std::size_t i) const {
  return abstract ? approx_vertex(*environment, query, vertices[i]) : vertices[i].approx;
}

double VisibilityPolygon::area() const {
  // Cross products about the viewpoint (terms about the origin lose a far plan's digits).
  double twice = 0;
  const std::size_t n = vertices.size();
  const double qx = query.x(), qy = query.y();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = approx_point(i), b = approx_point((i + 1) % n);
    twice += (a.x() - qx) * (b.y() - qy) - (b.x() - qx) * (a.y() - qy);
  }
  return twice / 2;
}

std::vector<ExactPoint> canonical_cycle(std::vector<ExactPoint> pts) {
  bool changed = true;
  while (changed && pts.size() >= 3) {
    changed = false;
    std::vector<ExactPoint> out;
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i < n; ++i) {
      const ExactPoint &a = pts[(i + n - 1) % n], &b = pts[i], &c = pts[(i + 1) % n];
      if (b == c || (a != b && orientation(a, b, c) == 0 && CGAL::collinear_are_ordered_along_line(a, b, c))) {
        changed = true;
        continue;
      }
      out.push_back(b);
    }
    pts.swap(out);
  }
  if (pts.empty()) return pts;
  auto first = std::min_element(pts.begin(), pts.end(), [](const ExactPoint& a, const ExactPoint& b) {
    return CGAL::compare_xy(a, b) == CGAL::SMALLER;
  });
  std::rotate(pts.begin(), first, pts.end());
  return pts;
}

// ---------------------------------------------------------------- preprocessing
namespace {
// Orientation of (p, a, b) with CGAL's own semi-static filter for Orientation_2
// (Static_filters_predicates/Orientation_2.h: the same differences, the same error bound
// and under/overflow guards), inlined here because the library call is not; whenever the
// double sign is not certain, CGAL::orientation decides (exact).
inline int vis_orient(const Point& p, const Point& a, const Point& b) {
  const double pax = a.x() - p.x(), pay = a.y() - p.y(), pbx = b.x() - p.x(), pby = b.y() - p.y();
  double maxx = std::max(std::abs(pax), std::abs(pbx)), maxy = std::max(std::abs(pay), std::abs(pby));
  if (maxx > maxy) std::swap(maxx, maxy);
  if (maxx >= 1e-146 && maxy < 1e153) {
    const double det = pax * pby - pay * pbx, eps = 8.8872057372592798e-16 * maxx * maxy;
    if (det > eps) return 1;
    if (det < -eps) return -1;
  }
  return orientation(p, a, b);
}
inline int vis_orient(const ExactPoint& p, const ExactPoint& a, const ExactPoint& b) { return orientation(p, a, b); }

// Exact: does the closed triangle V meet the closed box [x0, x1] x [y0, y1]? Separating
// axes of two convex sets: the box's (bounding boxes) and the triangle's edge normals (all
// four corners strictly right of a counter-clockwise edge). Corners are doubles, so every
// test is an exact comparison or orientation.
bool vis_triangle_meets_box(const Point* const V[3], double x0, double y0, double x1, double y1) {
  if (std::max({V[0]->x(), V[1]->x(), V[2]->x()}) < x0 || std::min({V[0]->x(), V[1]->x(), V[2]->x()}) > x1 ||
      std::max({V[0]->y(), V[1]->y(), V[2]->y()}) < y0 || std::min({V[0]->y(), V[1]->y(), V[2]->y()}) > y1)
    return false;
  const Point c[4] = {Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)};
  for (int e = 0; e < 3; ++e) {
    int right = 0;
    for (const Point& p : c) {
      if (vis_orient(*V[e], *V[(e + 1) % 3], p) >= 0) break;
      ++right;
    }
    if (right == 4) return false;
  }
  return true;
}
// Exact: is the closed box inside the open triangle (every corner strictly left of every edge)?
bool vis_box_inside_triangle(const Point* const V[3], double x0, double y0, double x1, double y1) {
  const Point c[4] = {Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)};
  for (int e = 0; e < 3; ++e)
    for (const Point& p : c)
      if (vis_orient(*V[e], *V[(e + 1) % 3], p) <= 0) return false;
  return true;
}
// Area of the triangle clipped to the box, in doubles (Sutherland-Hodgman): only orders a
// cell's list, never decides anything.
double vis_clipped_area(const Point* const V[3], double x0, double y0, double x1, double y1) {
  double px[10], py[10], qx[10], qy[10];
  int n = 3;
  for (int i = 0; i < 3; ++i) px[i] = V[i]->x(), py[i] = V[i]->y();
  for (int side = 0; side < 4 && n > 0; ++side) {
    auto value = [&](double x, double y) {  // >= 0 inside this side's half-plane
      switch (side) {
        case 0: return x - x0;
        case 1: return x1 - x;
        case 2: return y - y0;
        default: return y1 - y;
      }
    };
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const int k = (i + 1) % n;
      const double a = value(px[i], py[i]), b = value(px[k], py[k]);
      if (a >= 0) qx[m] = px[i], qy[m] = py[i], ++m;
      if ((a >= 0) != (b >= 0) && m < 10) {
        const double t = a / (a - b);
        qx[m] = px[i] + t * (px[k] - px[i]), qy[m] = py[i] + t * (py[k] - py[i]), ++m;
      }
    }
    n = std::min(m, 9);
    std::copy(qx, qx + n, px), std::copy(qy, qy + n, py);
  }
  double twice = 0;
  for (int i = 0; i < n; ++i) twice += px[i] * py[(i + 1) % n] - px[(i + 1) % n] * py[i];
  return std::abs(twice) / 2;
}
}  // namespace

VisibilityIndex::VisibilityIndex(const Environment& env) : env_(&env), tri_(env) {
  const auto& P = env.vertices();
  const auto& T = tri_.triangles();
  CGAL::Bbox_2 box = env.bbox();
  x0_ = box.xmin(), y0_ = box.ymin();
  {
    // |a - q| <= the box's extent in each coordinate for a vertex a and a query q in the box,
    // and rounding is monotone, so the computed differences are bounded by the rounded
    // extents dx, dy. CGAL's semi-static bound 8.8872057372592798e-16 * maxx * maxy grows
    // with maxx and maxy, so it holds with dx, dy in their place; 8.9e-16 leaves room for
    // the rounding of this product and for underflow in the determinant (extents kept in
    // CGAL's own safe range [1e-146, 1e153)).
    const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin();
    orient_eps_ = std::min(dx, dy) >= 1e-140 && std::max(dx, dy) < 1e150
                      ? 8.9e-16 * dx * dy
                      : std::numeric_limits<double>::infinity();
  }
  const double w = std::max(box.xmax() - box.xmin(), 1e-300), h = std::max(box.ymax() - box.ymin(), 1e-300);
  const double cells = std::max<double>(1.0, 2.0 * static_cast<double>(T.size()));
  const double aspect = w / h;
  gx_ = static_cast<std::uint32_t>(std::clamp(std::sqrt(cells * aspect), 1.0, 4096.0));
  gy_ = static_cast<std::uint32_t>(std::clamp(cells / gx_, 1.0, 4096.0));
  cw_ = w / gx_, ch_ = h / gy_;
  // Cell bounds consistent with cell_x / cell_y: xs[i] is the least double that cell_x maps
  // to i or beyond (cell_x is monotone), so every double point that cell_x, cell_y map to
  // (i, j) lies in the closed box [xs[i], xs[i+1]] x [ys[j], ys[j+1]] (clipped to the
  // environment's bounding box, which holds every triangle). Filing a triangle in every
  // cell whose box it meets (exactly) then makes the cell of any double point in free
  // space list the triangle holding it: no widening, no rounding to guard against.
  auto bounds = [](std::uint32_t g, double lo, double hi, auto&& index) {
    // Bisection over the doubles in their order (as 64-bit keys): 64 steps per bound.
    auto key = [](double x) {
      const auto u = std::bit_cast<std::uint64_t>(x);
      return u >> 63 ? ~u : u | (std::uint64_t(1) << 63);
    };
    auto value = [](std::uint64_t k) { return std::bit_cast<double>(k >> 63 ? k & ~(std::uint64_t(1) << 63) : ~k); };
    std::vector<double> b(g + 1);
    b[0] = lo, b[g] = hi;
    for (std::uint32_t i = 1; i < g; ++i) {
      std::uint64_t a = key(lo), c = key(hi);  // index(lo) = 0 < i <= g - 1 = index(hi)
      while (c - a > 1) {
        const std::uint64_t m = a + (c - a) / 2;
        (index(value(m)) >= i ? c : a) = m;
      }
      b[i] = value(c);  // the least double with index >= i
    }
    return b;
  };
  const std::vector<double> xs = bounds(gx_, box.xmin(), box.xmax(), [this](double x) { return cell_x(x); });
  const std::vector<double> ys = bounds(gy_, box.ymin(), box.ymax(), [this](double y) { return cell_y(y); });
  const std::size_t ncells = std::size_t(gx_) * gy_;

  // 1. Runs: the cells of a row that a triangle meets are consecutive (its part in the
  // row's band is convex), so each (triangle, row) is one run [first, last], its ends found
  // by exact triangle/box tests. Every cell of the grid is then known by its runs alone:
  // a long thin triangle costs two exact searches per row, not a test per cell it crosses.
  struct Run {
    std::uint32_t tri, row, first, last;
  };
  std::vector<Run> runs;
  runs.reserve(2 * T.size());
  for (std::uint32_t t = 0; t < T.size(); ++t) {
    const Point* const V[3] = {&P[T[t].v[0]], &P[T[t].v[1]], &P[T[t].v[2]]};
    const double xlo = std::min({V[0]->x(), V[1]->x(), V[2]->x()}), xhi = std::max({V[0]->x(), V[1]->x(), V[2]->x()});
    const double ylo = std::min({V[0]->y(), V[1]->y(), V[2]->y()}), yhi = std::max({V[0]->y(), V[1]->y(), V[2]->y()});
    // Cells whose closed boxes meet the bounding box (exact comparisons of doubles).
    std::uint32_t bi0 = cell_x(xlo), bi1 = cell_x(xhi), bj0 = cell_y(ylo), bj1 = cell_y(yhi);
    while (bi0 > 0 && xs[bi0] >= xlo) --bi0;
    while (bi1 + 1 < gx_ && xs[bi1 + 1] <= xhi) ++bi1;
    while (bj0 > 0 && ys[bj0] >= ylo) --bj0;
    while (bj1 + 1 < gy_ && ys[bj1 + 1] <= yhi) ++bj1;
    for (std::uint32_t j = bj0; j <= bj1; ++j) {
      // Guess the run from the x-extent of the triangle's part in the row in doubles, test
      // exactly, then extend while cells still meet it; scan the whole bounding box row if
      // the guess held none.
      const double sa = std::max(ylo, ys[j]), sb = std::min(yhi, ys[j + 1]);
      double exlo = std::numeric_limits<double>::infinity(), exhi = -exlo;
      for (int e = 0; e < 3; ++e) {
        const Point &p = *V[e], &q = *V[(e + 1) % 3];
        const double lo = std::max(sa, std::min(p.y(), q.y())), hi = std::min(sb, std::max(p.y(), q.y()));
        if (lo > hi) continue;
        for (double y : {lo, hi}) {
          const double x = p.y() == q.y() ? p.x() : p.x() + (q.x() - p.x()) * ((y - p.y()) / (q.y() - p.y()));
          exlo = std::min(exlo, x), exhi = std::max(exhi, x);
        }
        if (p.y() == q.y()) exlo = std::min(exlo, q.x()), exhi = std::max(exhi, q.x());
      }
      std::uint32_t g0 = bi0, g1 = bi1;
      if (exlo <= exhi) {
        g0 = std::clamp(cell_x(exlo), bi0, bi1), g1 = std::clamp(cell_x(exhi), bi0, bi1);
        g0 = g0 > bi0 ? g0 - 1 : g0, g1 = g1 < bi1 ? g1 + 1 : g1;
      }
      std::uint32_t first = kNone;
      for (std::uint32_t i = g0; i <= g1 && first == kNone; ++i)
        if (vis_triangle_meets_box(V, xs[i], ys[j], xs[i + 1], ys[j + 1])) first = i;
      for (std::uint32_t i = bi0; i <= bi1 && first == kNone; ++i)  // the guess held none
        if (vis_triangle_meets_box(V, xs[i], ys[j], xs[i + 1], ys[j + 1])) first = i;
      if (first == kNone) continue;
      while (first > bi0 && vis_triangle_meets_box(V, xs[first - 1], ys[j], xs[first], ys[j + 1])) --first;
      std::uint32_t last = std::max(first, g1);
      while (last > first && !vis_triangle_meets_box(V, xs[last], ys[j], xs[last + 1], ys[j + 1])) --last;
      while (last < bi1 && vis_triangle_meets_box(V, xs[last + 1], ys[j], xs[last + 2], ys[j + 1])) ++last;
      runs.push_back({t, j, first, last});
    }
  }

  // 2. Triangles per cell, from the runs (a difference array per row). A heavy cell
  // (more than kSlabMinTriangles) is a candidate for a slab.
  const bool slab_ids_fit = T.size() < kSlabCell;
  std::vector<std::uint32_t> count(ncells, 0);
  {
    std::vector<std::int64_t> diff(std::size_t(gx_ + 1) * gy_, 0);
    for (const Run& r : runs) ++diff[std::size_t(r.row) * (gx_ + 1) + r.first], --diff[std::size_t(r.row) * (gx_ + 1) + r.last + 1];
    for (std::uint32_t j = 0; j < gy_; ++j) {
      std::int64_t c = 0;
      for (std::uint32_t i = 0; i < gx_; ++i) count[std::size_t(j) * gx_ + i] = static_cast<std::uint32_t>(c += diff[std::size_t(j) * (gx_ + 1) + i]);
    }
  }
  std::vector<std::uint8_t> heavy(ncells, 0);
  bool any_heavy = false;
  for (std::size_t c = 0; c < ncells; ++c)
    if (slab_ids_fit && count[c] > kSlabMinTriangles) heavy[c] = 1, any_heavy = true;

  // 3. A light cell's entries, in place (the counts give each cell its slice), with their
  // overlap areas to sort by. Only a cell met by a single triangle can lie inside it (a
  // second closed triangle meeting a box inside an open triangle would overlap it), so only
  // those get the inside test, and only the others need areas. A heavy cell's triangles are
  // met again in the row sweeps below (runs sorted by row and first cell).
  struct Entry {
    std::uint32_t tri;
    float area;
  };
  std::vector<std::uint32_t> light_off(ncells + 1, 0);
  for (std::size_t c = 0; c < ncells; ++c) light_off[c + 1] = light_off[c] + (heavy[c] ? 0 : count[c]);
  std::vector<Entry> entries(light_off[ncells]);
  {
    std::vector<std::uint32_t> fill(light_off.begin(), light_off.end() - 1);
    for (const Run& r : runs) {
      const Point* const V[3] = {&P[T[r.tri].v[0]], &P[T[r.tri].v[1]], &P[T[r.tri].v[2]]};
      const std::uint32_t j = r.row, len = r.last - r.first + 1;
      // Long runs (thin triangles across many cells): one clipped area for the run, shared
      // out, instead of one per cell (the area only orders the lists).
      double shared = -1;
      for (std::uint32_t i = r.first; i <= r.last; ++i) {
        const std::size_t c = std::size_t(j) * gx_ + i;
        if (heavy[c]) continue;
        Entry& e = entries[fill[c]++];
        e.tri = r.tri, e.area = 0;
        if (count[c] == 1) {
          if (vis_box_inside_triangle(V, xs[i], ys[j], xs[i + 1], ys[j + 1])) e.tri |= kInsideCell;
        } else if (len > 4) {
          if (shared < 0) shared = vis_clipped_area(V, xs[r.first], ys[j], xs[r.last + 1], ys[j + 1]) / len;
          e.area = static_cast<float>(shared);
        } else {
          e.area = static_cast<float>(vis_clipped_area(V, xs[i], ys[j], xs[i + 1], ys[j + 1]));
        }
      }
    }
  }
  if (any_heavy) {  // by row, then first cell: two stable counting passes
    std::vector<Run> sorted(runs.size());
    auto pass = [&](std::vector<Run>& from, std::vector<Run>& to, std::uint32_t n, auto key) {
      std::vector<std::uint32_t> at(n + 1, 0);
      for (const Run& r : from) ++at[key(r) + 1];
      for (std::uint32_t k = 1; k <= n; ++k) at[k] += at[k - 1];
      for (const Run& r : from) to[at[key(r)]++] = r;
    };
    pass(runs, sorted, gx_, [](const Run& r) { return r.first; });
    pass(sorted, runs, gy_, [](const Run& r) { return r.row; });
  }

  // For the expansion: one step record per half-edge (HalfStep).
  steps_.resize(3 * T.size());
  for (std::uint32_t t = 0; t < T.size(); ++t)
    for (int s = 0; s < 3; ++s) {
      HalfStep& st = steps_[3 * t + s];
      const std::uint32_t u = T[t].nbr[s];
      if (u == kNone) {
        st = {kNone, T[t].v[s], T[t].v[(s + 1) % 3], T[t].edge[s], 0, 0};
        continue;
      }
      std::uint32_t j = 0;  // the slot of this edge in u, where it runs l -> r
      while (T[u].v[j] != T[t].v[(s + 1) % 3]) ++j;
      const std::uint32_t c = T[u].v[(j + 2) % 3];
      st = {c, 3 * u + (j + 1) % 3, 3 * u + (j + 2) % 3, kNone, P[c].x(), P[c].y()};
    }

  // 4. Slabs (see kSlabCell) for the heavy cells, by sweeps along the rows (edges crossing
  // cells from left to right) and the columns (bottom to top). Each triangle edge is one
  // record per line it crosses: the cells of that line it spans along the line (exact
  // comparisons of its end coordinates with the cell bounds: the query's shortcut relies
  // on it) and that it passes through rather than beside (in doubles: a wrong guess only
  // adds or omits an edge, which costs a fallback at query time, never a wrong answer).
  // One record per edge, from its left (after-bands) side unless that is not free space.
  std::vector<std::int32_t> slab_of(ncells, -1);
  std::vector<std::uint32_t> stash, stash_at(any_heavy ? ncells : 0, 0);  // heavy cells without a slab: their triangles
  if (any_heavy) {
    struct Rec {
      std::uint32_t line, a, b;  // cells a..b of the line
      std::uint32_t tri;
      std::uint8_t slot;
      bool reversed;
    };
    std::vector<Rec> recs[2];
    std::vector<std::uint32_t> crossing[2];  // per cell: edges crossing it, per orientation
    for (int o = 0; o < 2; ++o) {
      const bool vertical = o == 1;
      const std::uint32_t nlines = vertical ? gx_ : gy_, nalong = vertical ? gy_ : gx_;
      const std::vector<double>& ub = vertical ? ys : xs;  // cell bounds along the line
      const std::vector<double>& bb = vertical ? xs : ys;  // line bounds across
      auto cell_of = [&](std::uint32_t L, std::uint32_t i) { return vertical ? std::size_t(i) * gx_ + L : std::size_t(L) * gx_ + i; };
      // The cells that may take a slab of this orientation: heavy ones; for a vertical slab
      // only those that a horizontal one would not separate for half (see `want`). By line,
      // and by position along the lines (sorted lines).
      std::vector<std::uint8_t> line_heavy(nlines, 0);
      std::vector<std::uint32_t> at_off(nalong + 1, 0), at_lines;
      for (std::uint32_t i = 0; i < nalong; ++i) {
        for (std::uint32_t L = 0; L < nlines; ++L) {
          const std::size_t c = cell_of(L, i);
          if (heavy[c] && (!vertical || 2 * std::size_t(crossing[0][c]) < count[c])) line_heavy[L] = 1, at_lines.push_back(L);
        }
        at_off[i + 1] = static_cast<std::uint32_t>(at_lines.size());
      }
      auto u = [&](const Point& p) { return vertical ? p.y() : p.x(); };
      auto b = [&](const Point& p) { return vertical ? p.x() : p.y(); };
      auto cell_u = [&](double v) { return vertical ? cell_y(v) : cell_x(v); };
      auto cell_b = [&](double v) { return vertical ? cell_x(v) : cell_y(v); };
      std::vector<std::int64_t> diff(std::size_t(nalong + 1) * nlines, 0);
      auto record = [&](std::uint32_t L, std::uint32_t ra, std::uint32_t rb, std::uint32_t t, std::uint8_t s, bool reversed) {
        recs[o].push_back({L, ra, rb, t, s, reversed});
        ++diff[std::size_t(L) * (nalong + 1) + ra], --diff[std::size_t(L) * (nalong + 1) + rb + 1];
      };
      for (std::uint32_t t = 0; t < T.size() && !at_lines.empty(); ++t)
        for (std::uint8_t s = 0; s < 3; ++s) {
          const Point &pa = P[T[t].v[s]], &pb = P[T[t].v[(s + 1) % 3]];
          const bool reversed = u(pa) > u(pb);
          if (reversed && T[t].nbr[s] != kNone) continue;  // recorded from the other side
          const double umin = std::min(u(pa), u(pb)), umax = std::max(u(pa), u(pb));
          if (!(umin < umax)) continue;
          // Cells spanned along the line (exact): ub[i] >= umin and ub[i + 1] <= umax.
          std::uint32_t ea = cell_u(umin), eb = cell_u(umax);
          while (ea > 0 && ub[ea] >= umin) --ea;
          while (ea < nalong && ub[ea] < umin) ++ea;
          while (eb + 1 < nalong && ub[eb + 2] <= umax) ++eb;
          while (eb < nalong && ub[eb + 1] > umax) {
            if (eb == 0) { eb = kNone; break; }
            --eb;
          }
          if (eb == kNone || ea >= nalong || ea > eb) continue;
          const double bmin = std::min(b(pa), b(pb)), bmax = std::max(b(pa), b(pb));
          const std::uint32_t L0 = cell_b(bmin), L1 = cell_b(bmax);
          if (L1 - L0 <= eb - ea) {
            // Few lines: per line, the cells whose band the edge passes through (doubles).
            for (std::uint32_t L = L0; L <= L1; ++L) {
              if (!line_heavy[L]) continue;
              const double lo = std::max(bmin, bb[L]), hi = std::min(bmax, bb[L + 1]);
              if (lo > hi) continue;
              double ua = umin, ubb = umax;
              if (b(pa) != b(pb)) {
                const double k = (u(pb) - u(pa)) / (b(pb) - b(pa));
                ua = u(pa) + k * (lo - b(pa)), ubb = u(pa) + k * (hi - b(pa));
                if (ua > ubb) std::swap(ua, ubb);
              }
              const std::uint32_t ra = std::max(ea, cell_u(ua)), rb = std::min(eb, cell_u(ubb));
              if (ra <= rb) record(L, ra, rb, t, s, reversed);
            }
          } else {
            // Many lines (an edge nearly along them): per spanned position, the lines it
            // passes through there, only those with a cell of interest.
            const double k = (b(pb) - b(pa)) / (u(pb) - u(pa));
            for (std::uint32_t i = ea; i <= eb; ++i) {
              double ba = b(pa) + k * (ub[i] - u(pa)), bz = b(pa) + k * (ub[i + 1] - u(pa));
              if (ba > bz) std::swap(ba, bz);
              const std::uint32_t La = cell_b(std::max(ba, bmin)), Lb = cell_b(std::min(bz, bmax));
              const std::uint32_t* first = at_lines.data() + at_off[i];
              const std::uint32_t* last = at_lines.data() + at_off[i + 1];
              for (const std::uint32_t* l = std::lower_bound(first, last, La); l != last && *l <= Lb; ++l) record(*l, i, i, t, s, reversed);
            }
          }
        }
      crossing[o].assign(ncells, 0);
      for (std::uint32_t L = 0; L < nlines; ++L) {
        std::int64_t c = 0;
        for (std::uint32_t i = 0; i < nalong; ++i) {
          c += diff[std::size_t(L) * (nalong + 1) + i];
          crossing[o][cell_of(L, i)] = static_cast<std::uint32_t>(c);
        }
      }
      std::sort(recs[o].begin(), recs[o].end(), [](const Rec& p, const Rec& q) { return p.line != q.line ? p.line < q.line : p.a < q.a; });
    }
    // Per heavy cell: left to right unless the vertical slab separates more and the
    // horizontal one less than half the cell's triangles; fewer than 4 edges: no slab.
    std::vector<std::uint8_t> want(ncells, 0);  // 1 horizontal, 2 vertical
    for (std::size_t c = 0; c < ncells; ++c) {
      if (!heavy[c]) continue;
      const std::uint32_t H = crossing[0][c], V = crossing[1][c];
      const bool vertical = 2 * std::size_t(H) < count[c] && V > H;
      if ((vertical ? V : H) >= 4) want[c] = vertical ? 2 : 1;
    }
    struct Act {
      double ua, wa, slope;
      std::uint32_t tri, b;
      std::uint8_t slot;
      bool reversed;
      double at(double um) const { return wa + slope * (um - ua); }
    };
    // Slab edges are shared: consecutive cells of a line whose crossing edges differ only
    // at the two ends of their order across the line (a fan's edges ending or starting one
    // by one) take windows of one sorted run, a block, stored once. The block's guess keys
    // are taken at its first cell's middle (the slabs' `mid`), at most kBlockCells cells
    // from any of its cells, so the float guess stays as good as a cell's own.
    constexpr std::uint32_t kBlockCells = 32;
    std::vector<Act> buf, fresh, S;
    std::size_t ubeg = 0, uend = 0, lo = 0, hi = 0;
    double ref = 0;
    std::uint32_t ref_cell = 0;
    std::vector<std::uint32_t> block_slabs;  // slabs_ whose edge ranges are still positions in buf
    auto close_block = [&] {
      const std::size_t base = slab_edges_.size();
      for (std::size_t k = ubeg; k < uend; ++k) {
        const Act& e = buf[k];
        slab_edges_.push_back(SlabEdge{e.tri, e.slot, e.reversed, static_cast<float>(e.at(ref)), static_cast<float>(e.slope)});
      }
      for (const std::uint32_t sl : block_slabs) {
        slabs_[sl].edges = static_cast<std::uint32_t>(base + (slabs_[sl].edges - ubeg));
        slabs_[sl].edge_end = static_cast<std::uint32_t>(base + (slabs_[sl].edge_end - ubeg));
      }
      block_slabs.clear();
      ubeg = uend = lo = hi = 0;
    };
    auto open_block = [&](double um, std::uint32_t i) {  // a block holding S, sorted
      const std::size_t pad = S.size() + 16;
      buf.resize(S.size() + 2 * pad);
      std::copy(S.begin(), S.end(), buf.begin() + static_cast<std::ptrdiff_t>(pad));
      ubeg = lo = pad, uend = hi = pad + S.size();
      ref = um, ref_cell = i;
    };
    std::size_t reserve = 0;
    for (std::size_t c = 0; c < ncells; ++c)
      if (want[c]) reserve += crossing[want[c] - 1][c];
    slab_edges_.reserve(std::min<std::size_t>(reserve, 4 * T.size() + 1024));
    struct Tri {
      std::uint32_t tri, last;
    };
    std::vector<Tri> tris;  // the row sweep's triangles: runs reaching the current cell
    std::vector<std::uint32_t> mark(T.size(), 0), others, ends_at;
    std::uint32_t stamp = 0;
    std::size_t next_run = 0;
    for (int o = 0; o < 2; ++o) {
      const bool vertical = o == 1;
      const std::uint32_t nlines = vertical ? gx_ : gy_, nalong = vertical ? gy_ : gx_;
      const std::vector<double>& ub = vertical ? ys : xs;
      auto u = [&](const Point& p) { return vertical ? p.y() : p.x(); };
      auto w = [&](const Point& p) { return vertical ? -p.x() : p.y(); };
      std::size_t next = 0;
      const std::vector<Rec>& R = recs[o];
      for (std::uint32_t L = 0; L < nlines; ++L) {
        tris.clear();
        ends_at.assign(nalong, 0);
        std::size_t expired = 0, removed = 0;  // taken edges ending before the cell; no longer in the window
        std::uint32_t counted_upto = 0;
        while (next < R.size() && R[next].line < L) ++next;
        if (!vertical)
          while (next_run < runs.size() && runs[next_run].row < L) ++next_run;
        for (std::uint32_t i = 0; i < nalong; ++i) {
          const std::size_t c = vertical ? std::size_t(i) * gx_ + L : std::size_t(L) * gx_ + i;
          if (!heavy[c] || (vertical && want[c] != 2)) continue;
          // The cell's triangles: from the runs (rows), or kept by the row sweep (columns).
          const std::uint32_t* list = nullptr;
          std::size_t list_size = 0;
          if (!vertical) {
            std::size_t kept = 0;
            for (std::size_t k = 0; k < tris.size(); ++k)
              if (tris[k].last >= i) tris[kept++] = tris[k];
            tris.resize(kept);
            for (; next_run < runs.size() && runs[next_run].row == L && runs[next_run].first <= i; ++next_run)
              if (runs[next_run].last >= i) tris.push_back({runs[next_run].tri, runs[next_run].last});
            if (want[c] != 1) {  // no horizontal slab: keep the list for later
              stash_at[c] = static_cast<std::uint32_t>(stash.size());
              for (const Tri& t : tris) stash.push_back(t.tri);
              continue;
            }
          } else {
            list = stash.data() + stash_at[c], list_size = count[c];
          }
          const double ulo = ub[i], uhi = ub[i + 1], um = ulo / 2 + uhi / 2;
          // The edges crossing this cell: the window less the edges that ended, plus the
          // edges starting; in the block if those are at the window's ends, else in a new one.
          fresh.clear();
          for (; next < R.size() && R[next].line == L && R[next].a <= i; ++next) {
            const Rec& r = R[next];
            if (r.b < i) continue;
            const Point &pa = P[T[r.tri].v[r.slot]], &pb = P[T[r.tri].v[(r.slot + 1) % 3]];
            fresh.push_back({u(pa), w(pa), (w(pb) - w(pa)) / (u(pb) - u(pa)), r.tri, r.b, r.slot, r.reversed});
          }
          for (; counted_upto < i; ++counted_upto) expired += ends_at[counted_upto];
          for (const Act& f : fresh) ++ends_at[f.b];
          auto by_key = [um](const Act& p, const Act& q) { return p.at(um) < q.at(um); };
          std::sort(fresh.begin(), fresh.end(), by_key);
          std::size_t nl = lo, nh = hi, dropped = 0;
          while (nl < nh && buf[nl].b < i) ++nl, ++dropped;
          while (nh > nl && buf[nh - 1].b < i) --nh, ++dropped;
          bool ok = hi > lo && i - ref_cell <= kBlockCells && dropped == expired - removed && nl < nh;
          std::size_t below = 0, above = 0;
          if (ok && !fresh.empty()) {
            const double bottom = buf[nl].at(um), top = buf[nh - 1].at(um);
            while (below < fresh.size() && fresh[below].at(um) < bottom) ++below;
            while (above < fresh.size() - below && fresh[fresh.size() - 1 - above].at(um) > top) ++above;
            ok = below + above == fresh.size() && (below == 0 || (nl == ubeg && ubeg >= below)) &&
                 (above == 0 || (nh == uend && uend + above <= buf.size()));
          }
          if (ok) {
            removed += dropped;
            lo = nl, hi = nh;
            for (std::size_t k = below; k-- > 0;) buf[--ubeg] = fresh[k];
            for (std::size_t k = fresh.size() - above; k < fresh.size(); ++k) buf[uend++] = fresh[k];
            if (below) lo = ubeg;
            if (above) hi = uend;
          } else {
            S.clear();
            for (std::size_t k = lo; k < hi; ++k)
              if (buf[k].b >= i) S.push_back(buf[k]);
            removed += (hi - lo) - S.size();
            S.insert(S.end(), fresh.begin(), fresh.end());
            std::sort(S.begin(), S.end(), by_key);
            close_block();
            open_block(um, i);
          }
          // The cell's triangles with no edge in the slab.
          bool slab = hi - lo >= 4;
          if (slab) {
            if (++stamp == 0) std::fill(mark.begin(), mark.end(), 0), stamp = 1;
            for (std::size_t k = lo; k < hi; ++k) {
              mark[buf[k].tri] = stamp;
              if (const std::uint32_t nb = T[buf[k].tri].nbr[buf[k].slot]; nb != kNone) mark[nb] = stamp;
            }
            others.clear();
            if (!vertical) {
              for (const Tri& t : tris)
                if (mark[t.tri] != stamp) others.push_back(t.tri);
            } else {
              for (std::size_t k = 0; k < list_size; ++k)
                if (mark[list[k]] != stamp) others.push_back(list[k]);
            }
            slab = 2 * others.size() <= count[c];  // else mostly triangles the slab does not separate
          }
          if (!slab) {
            if (!vertical) {
              stash_at[c] = static_cast<std::uint32_t>(stash.size());
              for (const Tri& t : tris) stash.push_back(t.tri);
            }
            continue;
          }
          slab_of[c] = static_cast<std::int32_t>(slabs_.size());
          block_slabs.push_back(static_cast<std::uint32_t>(slabs_.size()));
          slabs_.push_back(Slab{static_cast<std::uint32_t>(lo), static_cast<std::uint32_t>(hi),
                                static_cast<std::uint32_t>(slab_others_.size()), static_cast<std::uint32_t>(slab_others_.size() + others.size()),
                                vertical, ulo, uhi, ref});
          slab_others_.insert(slab_others_.end(), others.begin(), others.end());
        }
        close_block();
      }
    }
  }

  // 5. Cell lists in cell order: a slab entry, or the triangles sorted by overlap area
  // (largest first; a heavy cell without a slab gets its areas here).
  cell_off_.assign(ncells + 1, 0);
  cell_tris_.clear();
  cell_tris_.reserve(entries.size() + slabs_.size());
  auto by_area = [](const Entry& a, const Entry& b) { return a.area != b.area ? a.area > b.area : a.tri < b.tri; };
  std::vector<Entry> own;
  for (std::size_t cell = 0; cell < ncells; ++cell) {
    if (slab_of[cell] >= 0) {
      cell_tris_.push_back(kSlabCell | static_cast<std::uint32_t>(slab_of[cell]));
    } else if (heavy[cell]) {
      const std::uint32_t i = static_cast<std::uint32_t>(cell % gx_), j = static_cast<std::uint32_t>(cell / gx_);
      own.clear();
      for (std::uint32_t k = stash_at[cell]; k < stash_at[cell] + count[cell]; ++k) {
        const std::uint32_t t = stash[k];
        const Point* const V[3] = {&P[T[t].v[0]], &P[T[t].v[1]], &P[T[t].v[2]]};
        own.push_back({t, static_cast<float>(vis_clipped_area(V, xs[i], ys[j], xs[i + 1], ys[j + 1]))});
      }
      std::sort(own.begin(), own.end(), by_area);
      for (const Entry& e : own) cell_tris_.push_back(e.tri);
    } else {
      Entry* const first = entries.data() + light_off[cell];
      Entry* const last = entries.data() + light_off[cell + 1];
      if (last - first > 1) std::sort(first, last, by_area);
      for (const Entry* e = first; e != last; ++e) cell_tris_.push_back(e->tri);
    }
    cell_off_[cell + 1] = static_cast<std::uint32_t>(cell_tris_.size());
  }
}

// Environment vertices in the query's number type: input points, or their lazy-exact twins
// for a constructed query (predicates then mix only like types).
namespace {
struct InputVertices {
  const Environment* env;
  const Point& operator()(std::uint32_t v) const { return env->vertex(v); }
};
struct ExactVertices {
  const Environment* env;
  const ExactPoint& operator()(std::uint32_t v) const { return env->exact_vertex(v); }
};
InputVertices vertices_for(const Environment* e, const Point*) { return {e}; }
ExactVertices vertices_for(const Environment* e, const ExactPoint*) { return {e}; }
ExactPoint exact_of(const Point& q) { return to_exact(q); }
const ExactPoint& exact_of(const ExactPoint& q) { return q; }
}  // namespace

template <class Q, class Count>
VisibilityIndex::Located VisibilityIndex::locate_triangle(const Q& q, const Point& approx, bool name_outside, Count count) const {
  const auto P = vertices_for(env_, &q);
  const auto& T = tri_.triangles();
  auto test = [&](std::uint32_t t) -> std::optional<Located> {
    const Triangle& tr = T[t];
    int o[3];
    for (int i = 0; i < 3; ++i) {
      o[i] = orientation(P(tr.v[i]), P(tr.v[(i + 1) % 3]), q);
      count();
      if (o[i] < 0) return std::nullopt;
    }
    for (int i = 0; i < 3; ++i)
      if (q == P(tr.v[i])) return Located{{Location::Kind::AtVertex, tr.v[i]}, t, i};
    for (int i = 0; i < 3; ++i)
      if (o[i] == 0) {
        if (tr.nbr[i] == kNone) return Located{{Location::Kind::OnEdge, tr.edge[i]}, t, i};
        return Located{{Location::Kind::Interior, 0}, t, i};  // on a diagonal: slot marks it
      }
    return Located{{Location::Kind::Interior, 0}, t, -1};
  };
  constexpr bool double_query = std::is_same_v<Q, Point>;
  const std::size_t c = std::size_t(cell_y(approx.y())) * gx_ + cell_x(approx.x());
  const std::uint32_t *k = cell_tris_.data() + cell_off_[c], *end = cell_tris_.data() + cell_off_[c + 1];
  if (k != end && (*k & kInsideCell)) {
    // q's cell box lies in the interior of one triangle: q does too, no test needed (only
    // for a double query, whose cell is its own; a constructed one may lie off its rounding's cell).
    if constexpr (double_query) return Located{{Location::Kind::Interior, 0}, *k & ~kInsideCell, -1};
  } else if (k != end && (*k & kSlabCell)) {
    const Slab& sl = slabs_[*k & ~kSlabCell];
    const SlabEdge* E = slab_edges_.data() + sl.edges;
    const std::size_t S = sl.edge_end - sl.edges;
    auto ends = [&](const SlabEdge& e, std::uint32_t& a, std::uint32_t& b) {
      a = T[e.tri].v[e.slot], b = T[e.tri].v[(e.slot + 1) % 3];
      if (e.reversed) std::swap(a, b);
    };
    auto left_tri = [&](const SlabEdge& e) { return e.reversed ? T[e.tri].nbr[e.slot] : e.tri; };
    auto right_tri = [&](const SlabEdge& e) { return e.reversed ? e.tri : T[e.tri].nbr[e.slot]; };
    auto try_tri = [&](std::uint32_t t) -> std::optional<Located> {
      if (t == kNone) return std::nullopt;
      return test(t);
    };
    if constexpr (double_query) {
      auto left_of = [&](const SlabEdge& e) {
        std::uint32_t a, b;
        ends(e, a, b);
        count();
        return orientation(P(a), P(b), q);
      };
      // The band: guessed in floats, verified exactly against its two edges; exact
      // binary search if that fails.
      const double along = sl.vertical ? q.y() : q.x(), across = sl.vertical ? -q.x() : q.y();
      const float du = static_cast<float>(along - sl.mid), kq = static_cast<float>(across);
      std::size_t lo = 0, hi = S;
      while (lo < hi) {
        const std::size_t m = (lo + hi) / 2;
        if (E[m].w_mid + E[m].slope * du < kq) lo = m + 1;
        else hi = m;
      }
      int below = lo > 0 ? left_of(E[lo - 1]) : 1, above = lo < S ? left_of(E[lo]) : -1;
      if (below <= 0 || above >= 0) {
        lo = 0, hi = S, below = 1, above = -1;
        while (lo < hi) {
          const std::size_t m = (lo + hi) / 2;
          const int o = left_of(E[m]);
          if (o > 0) lo = m + 1, below = o;
          else hi = m, above = o;
        }
      }
      if (above == 0) {  // on edge E[lo] (it crosses q's line across the cell): one of its sides
        if (auto r = try_tri(left_tri(E[lo]))) return *r;
        if (auto r = try_tri(right_tri(E[lo]))) return *r;
      } else if (lo > 0 && lo < S) {
        // Strictly between two edges of one triangle, strictly inside the cell's extent
        // along them (so both cross q's line across the cell at interior points): q lies
        // on the open chord of that triangle there, in its interior.
        const std::uint32_t t = left_tri(E[lo - 1]);
        if (t != kNone && t == right_tri(E[lo]) && along > sl.lo && along < sl.hi)
          return Located{{Location::Kind::Interior, 0}, t, -1};
        if (auto r = try_tri(t)) return *r;
        if (auto r = try_tri(right_tri(E[lo]))) return *r;
      } else if (lo == 0 && S > 0) {
        if (auto r = try_tri(right_tri(E[0]))) return *r;
      } else if (S > 0) {
        if (auto r = try_tri(left_tri(E[S - 1]))) return *r;
      }
    }
    // Every triangle of the cell: the others, then both sides of every slab edge.
    for (std::uint32_t i = sl.others; i < sl.others_end; ++i)
      if (auto r = test(slab_others_[i])) return *r;
    for (std::size_t i = 0; i < S; ++i) {
      if (auto r = try_tri(left_tri(E[i]))) return *r;
      if (auto r = try_tri(right_tri(E[i]))) return *r;
    }
    k = end;
  }
  for (; k != end; ++k)
    if (auto r = test(*k & ~kInsideCell)) return *r;
  if constexpr (!double_query) {
    // A constructed query need not lie in its rounding's cell: try every triangle (exact).
    for (std::uint32_t t = 0; t < T.size(); ++t)
      if (auto r = test(t)) return *r;
  }
  // Not in any triangle (the grid lists every triangle meeting each of its cells): classify
  // with the exact O(n) locator (outside or in a hole; for a constructed query its rounding
  // names where it lies) when asked to.
  if (!name_outside) return Located{{Location::Kind::Outside, 0}, kNone, -1};
  Location loc = geometry::locate(*env_, approx);
  if (loc.in_free_space()) loc = {Location::Kind::Outside, 0};
  if constexpr (double_query) loc = geometry::locate(*env_, q);
  return Located{loc, kNone, -1};
}

Location VisibilityIndex::locate(const Point& q) const { return locate_triangle(q, q).loc; }

bool VisibilityIndex::in_free_space(const Point& q) const { return locate_triangle(q, q, false).tri != kNone; }

std::size_t VisibilityIndex::locate_tests(const Point& q) const {
  std::size_t n = 0;
  locate_triangle(q, q, false, [&n] { ++n; });
  return n;
}

// ---------------------------------------------------------------- expansion
namespace {


// A point relative to the query: its coordinate differences, shared between tests.
struct Rel {
  double x = 0, y = 0;
  Rel() = default;
  Rel(const Point& a, const Point& q) : Rel(a.x(), a.y(), q) {}
  Rel(double a_x, double a_y, const Point& q) : x(a_x - q.x()), y(a_y - q.y()) {}
};
// orientation(q, a, b) given a - q and b - q, with the index's static filter bound eps
// (VisibilityIndex::orient_eps_): one product pair and two comparisons; CGAL decides the
// rare determinants within eps of zero.
inline int orient_rel(const Rel& a, const Rel& b, double eps, const Point& q, const Point& pa, const Point& pb) {
  const double det = a.x * b.y - a.y * b.x;
  if (det > eps) return 1;
  if (det < -eps) return -1;
  return orientation(q, pa, pb);
}

// Symbolic polygon vertex: exact points are constructed only once, at the end.
struct Sym {
  VisibilityVertex::Kind kind;
  std::uint32_t vertex, edge;
  bool operator==(const Sym&) const = default;
};

struct Piece {  // visible part of one boundary edge, between two cone rays
  std::uint32_t edge;
  std::uint32_t ray_r, ray_l;  // vertices defining the rays bounding it (kNone: through the query)
  Sym start, end;
};

// Work item: cross half-edge h (steps_[h]) inside the cone between rays q->R and q->L.
struct VisItem {
  std::uint32_t h;  // half-edge 3t + s
  std::uint32_t R, L;
};

// Per-thread scratch of compute: kept between queries, so a thread's queries stop
// allocating once these have grown to the largest polygon it has seen.
struct VisScratch {
  std::vector<Piece> pieces;
  std::vector<VisItem> stack;
};
VisScratch& vis_scratch() {
  thread_local VisScratch scratch;
  return scratch;
}

}  // namespace

// A polygon returned by value is computed into this thread's reused polygon and then
// copied out with exactly sized vectors: compute_at's working size (twice the piece count)
// would otherwise be allocated, and its pages touched, for every result.
namespace {
VisibilityPolygon& vis_result_scratch() {
  thread_local VisibilityPolygon scratch;
  return scratch;
}
}  // namespace

VisibilityPolygon VisibilityIndex::compute(const Point& q) const {
  VisibilityPolygon& scratch = vis_result_scratch();
  compute_at(q, q, scratch, true);
  return scratch;
}

void VisibilityIndex::compute(const Point& q, VisibilityPolygon& out) const { compute_at(q, q, out, true); }

void VisibilityIndex::compute_abstract(const Point& q, VisibilityPolygon& out) const { compute_at(q, q, out, false); }

VisibilityPolygon VisibilityIndex::compute_in_wedge(std::uint32_t v) const {
  if (v >= env_->num_vertices()) throw std::out_of_range("compute_in_wedge: no vertex " + std::to_string(v));
  VisibilityPolygon out;
  compute_at(env_->vertex(v), env_->vertex(v), out, true, v);
  return out;
}

VisibilityPolygon VisibilityIndex::compute(const ExactPoint& q) const {
  const auto& a = q.approx();
  VisibilityPolygon out;
  compute_at(q, Point(CGAL::to_double(a.x()), CGAL::to_double(a.y())), out, true);
  return out;
}

namespace {
// Process-wide pool of helper threads for compute_many, started on first use and kept:
// a batch of 500 queries lasts 0.5-2 ms on small maps, about what starting and joining
// threads per call cost. A helper that runs out of work polls the queue for 1 ms (yielding
// its core to anyone who wants it) before it sleeps on a condition variable: waking a
// sleeping thread on a virtual machine takes long enough to be a visible share of such a
// batch, and calls tend to come back to back (OpenMP runtimes poll for 200 ms). A batch
// is queued; each helper that takes it runs its chunks until none are left; the caller
// runs chunks too, then withdraws the batch from the queue (no helper can join after
// that) and waits for the helpers that joined to leave, so the batch (on the caller's
// stack) is never touched after compute_many returns. Several callers at once each queue
// their own batch; helpers serve the oldest.
class VisWorkerPool {
 public:
  struct Batch {
    // Runs chunks until the batch's counter is exhausted: a plain function and its context
    // (a std::function of the caller's lambda would allocate once per batch).
    void (*work)(void*) = nullptr;
    void* context = nullptr;
    std::size_t max_helpers = 0;
    std::size_t helpers = 0;     // joined and not yet left (guarded by the pool's mutex)
    std::condition_variable left;
  };

  static VisWorkerPool& instance() {
    static VisWorkerPool pool;
    return pool;
  }

  // Runs b.work on the calling thread and on up to b.max_helpers helpers; returns when all
  // of them have finished.
  void run(Batch& b) {
    {
      std::lock_guard<std::mutex> lock(m_);
      // Grow lazily to what callers have asked for (capped); never shrinks.
      while (workers_.size() < std::min<std::size_t>(b.max_helpers, kMaxWorkers))
        workers_.emplace_back([this] { serve(); });
      queue_.push_back(&b);
      queued_.fetch_add(1, std::memory_order_release);
    }
    if (b.max_helpers == 1) wake_.notify_one();
    else wake_.notify_all();
    b.work(b.context);
    std::unique_lock<std::mutex> lock(m_);
    withdraw(&b);
    b.left.wait(lock, [&] { return b.helpers == 0; });
  }

  ~VisWorkerPool() {
    {
      std::lock_guard<std::mutex> lock(m_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : workers_) t.join();
  }

 private:
  static constexpr std::size_t kMaxWorkers = 64;
  VisWorkerPool() = default;

  void withdraw(Batch* b) {  // under m_
    const auto it = std::find(queue_.begin(), queue_.end(), b);
    if (it != queue_.end()) queue_.erase(it), queued_.fetch_sub(1, std::memory_order_relaxed);
  }

  void serve() {
    std::unique_lock<std::mutex> lock(m_);
    while (true) {
      if (!stop_ && queue_.empty()) {  // poll before sleeping (see above)
        lock.unlock();
        const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(1);
        while (queued_.load(std::memory_order_acquire) == 0 && std::chrono::steady_clock::now() < until) std::this_thread::yield();
        lock.lock();
      }
      wake_.wait(lock, [&] { return stop_ || !queue_.empty(); });
      if (stop_) return;
      Batch* b = queue_.front();
      if (++b->helpers >= b->max_helpers) queue_.pop_front(), queued_.fetch_sub(1, std::memory_order_relaxed);  // enough helpers joined
      lock.unlock();
      b->work(b->context);
      lock.lock();
      withdraw(b);  // its work is exhausted: nobody else need join
      if (--b->helpers == 0) b->left.notify_all();
    }
  }

  std::mutex m_;
  std::condition_variable wake_;
  std::deque<Batch*> queue_;
  std::atomic<std::size_t> queued_{0};  // queue_.size(), for polling without the mutex
  std::vector<std::thread> workers_;
  bool stop_ = false;
};
}  // namespace

namespace {
// Runs one(i) for i in [0, count) on `threads` threads (0: one per hardware thread), the
// caller and the pool's helpers; rethrows the exception of the lowest failing i after all
// have ended.
template <class One>
void run_batch(std::size_t count, unsigned threads, One&& one) {
  std::size_t n = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  // Chunks small enough that the threads finish together (about 32 per thread: the last
  // chunk's time is what one thread may wait for the other), large enough that taking one
  // (an atomic add) is negligible next to its queries (each takes a microsecond or more).
  const std::size_t chunk = std::clamp<std::size_t>(count / (32 * n), 1, 16);
  n = std::max<std::size_t>(1, std::min(n, (count + chunk - 1) / chunk));
  std::atomic<std::size_t> next{0};
  std::mutex failed;
  std::size_t failed_at = count;
  std::exception_ptr error;
  auto work = [&] {
    for (std::size_t b; (b = next.fetch_add(chunk, std::memory_order_relaxed)) < count;) {
      for (std::size_t i = b; i < std::min(count, b + chunk); ++i) {
        try {
          one(i);
        } catch (...) {
          std::lock_guard<std::mutex> lock(failed);
          if (i < failed_at) failed_at = i, error = std::current_exception();
        }
      }
    }
  };
  if (n == 1) {
    work();
  } else {
    VisWorkerPool::Batch batch;
    batch.work = [](void* w) { (*static_cast<decltype(work)*>(w))(); };
    batch.context = &work;
    batch.max_helpers = n - 1;
    VisWorkerPool::instance().run(batch);
  }
  if (error) std::rethrow_exception(error);
}
}  // namespace

std::vector<VisibilityPolygon> VisibilityIndex::compute_many(std::span<const Point> queries, unsigned threads,
                                                             bool abstract) const {
  std::vector<VisibilityPolygon> out(queries.size());
  run_batch(queries.size(), threads, [&](std::size_t i) {
    VisibilityPolygon& scratch = vis_result_scratch();
    compute_at(queries[i], queries[i], scratch, !abstract);
    out[i] = scratch;  // exactly sized
  });
  return out;
}

void VisibilityIndex::compute_many(std::span<const Point> queries, std::vector<VisibilityPolygon>& out,
                                   unsigned threads, bool abstract) const {
  out.resize(queries.size());
  run_batch(queries.size(), threads, [&](std::size_t i) { compute_at(queries[i], queries[i], out[i], !abstract); });
}

template <class Q>
void VisibilityIndex::compute_at(const Q& q, const Point& approx, VisibilityPolygon& out, bool coordinates,
                                 std::uint32_t only_wedge) const {
  const Located where = only_wedge == kNone
                            ? locate_triangle(q, approx)
                            : Located{{Location::Kind::AtVertex, only_wedge}, tri_.boundary_slot(only_wedge).first, 0};
  if (!where.loc.in_free_space())
    throw InputError(std::string("visibility: query point ")
                         .append(format_point(approx))
                         .append(" is not in free space: it lies ")
                         .append(where.loc.kind == Location::Kind::InHole ? "inside " : "outside ")
                         .append(env_->ring_name(where.loc.kind == Location::Kind::InHole ? where.loc.index + 1 : 0)));
  const auto& P = env_->vertices();
  const auto Pq = vertices_for(env_, &q);  // vertices in the query's type, for predicates
  const auto& T = tri_.triangles();
  const Environment& E = *env_;

  auto sym_vertex = [](std::uint32_t v) { return Sym{VisibilityVertex::Kind::EnvironmentVertex, v, kNone}; };
  const Sym sym_query{VisibilityVertex::Kind::Query, kNone, kNone};

  // This thread's scratch, moved into locals for the query (the hot loop then keeps the
  // vectors' pointers in registers across predicate calls) and handed back at the end.
  struct Borrow {
    VisScratch& home;
    std::vector<Piece> pieces;
    std::vector<VisItem> stack;
    explicit Borrow(VisScratch& h) : home(h), pieces(std::move(h.pieces)), stack(std::move(h.stack)) {
      pieces.clear();
    }
    ~Borrow() { home.pieces = std::move(pieces), home.stack = std::move(stack); }
    Borrow(const Borrow&) = delete;
    Borrow& operator=(const Borrow&) = delete;
  } borrow(vis_scratch());
  std::vector<Piece>& pieces = borrow.pieces;
  // The work stack as a bare array over the scratch vector's storage: a push is a store and
  // an increment (growth, rare, out of the loop's way); vector::push_back was left out of
  // line here and cost a call per step.
  std::vector<VisItem>& stack_store = borrow.stack;
  if (stack_store.size() < 64) stack_store.resize(64);
  VisItem* stack = stack_store.data();
  std::size_t top = 0;
  auto push = [&](VisItem item) {
    if (top == stack_store.size()) [[unlikely]] {
      stack_store.resize(2 * top);
      stack = stack_store.data();
    }
    stack[top++] = item;
  };
  const HalfStep* const S = steps_.data();
  const double eps = orient_eps_;
  // Does the end x of a boundary edge lie on the cone ray q -> a (a - q is ad)?
  auto on_ray = [&](std::uint32_t a, const Rel& ad, std::uint32_t x) __attribute__((always_inline)) {
    if constexpr (std::is_same_v<Q, Point>) return orient_rel(ad, Rel(P[x], q), eps, q, P[a], P[x]) == 0;
    else return vis_orient(q, Pq(a), Pq(x)) == 0;
  };
  auto run = [&](std::uint32_t t0, int s0, std::uint32_t R0, std::uint32_t L0) {
    push({3 * t0 + static_cast<std::uint32_t>(s0), R0, L0});
    while (top > 0) {
      VisItem it = stack[--top];
      Rel rd, ld;  // R - q and L - q (double queries)
      if constexpr (std::is_same_v<Q, Point>) rd = Rel(P[it.R], q), ld = Rel(P[it.L], q);
      // Follow one cone across triangles; a split pushes its left part and goes on with
      // the right one (the order of the pieces is that of a plain stack).
      while (true) {
        const HalfStep& st = S[it.h];
        const std::uint32_t c = st.c;
        if (c == kNone) {  // boundary edge (r, l): emit the visible piece of it
          // Written field by field into the list: a piece composed on the stack and copied
          // was reloaded wider than it was stored, stalling store forwarding (profiled).
          const std::uint32_t e = st.edge, r = st.right, l = st.left;
          Piece& pc = pieces.emplace_back();
          pc.edge = e, pc.ray_r = it.R, pc.ray_l = it.L;
          if (it.R == r || on_ray(it.R, rd, r)) {
            pc.start.kind = VisibilityVertex::Kind::EnvironmentVertex, pc.start.vertex = r, pc.start.edge = kNone;
          } else {
            pc.start.kind = VisibilityVertex::Kind::RayHit, pc.start.vertex = it.R, pc.start.edge = e;
          }
          if (it.L == l || on_ray(it.L, ld, l)) {
            pc.end.kind = VisibilityVertex::Kind::EnvironmentVertex, pc.end.vertex = l, pc.end.edge = kNone;
          } else {
            pc.end.kind = VisibilityVertex::Kind::RayHit, pc.end.vertex = it.L, pc.end.edge = e;
          }
          break;
        }
        // Across the diagonal into the neighbour, whose apex c lies beyond it.
        if constexpr (std::is_same_v<Q, Point>) {
          // vis_orient(q, R, c) and vis_orient(q, L, c) with the differences from q shared
          // (c's computed once, R's and L's kept while the cone is followed).
          const Rel cd(st.cx, st.cy, q);
          if (orient_rel(rd, cd, eps, q, P[it.R], P[c]) <= 0) {
            it.h = st.left;
          } else if (orient_rel(ld, cd, eps, q, P[it.L], P[c]) >= 0) {
            it.h = st.right;
          } else {  // c splits the cone; right part first (counter-clockwise output)
            push({st.left, c, it.L});
            it = {st.right, it.R, c};
            ld = cd;
          }
        } else if (vis_orient(q, Pq(it.R), Pq(c)) <= 0) {
          it.h = st.left;
        } else if (vis_orient(q, Pq(it.L), Pq(c)) >= 0) {
          it.h = st.right;
        } else {
          push({st.left, c, it.L});
          it = {st.right, it.R, c};
        }
      }
    }
  };

  out.environment = env_;
  out.query = approx;
  if constexpr (std::is_same_v<Q, Point>) out.constructed_query.reset();
  else out.constructed_query = q;
  out.location = where.loc;
  out.abstract = !coordinates;
  out.vertices.clear();
  out.edges.clear();
  const Triangle& t0 = T[where.tri];
  switch (where.loc.kind) {
    case Location::Kind::Interior:
      if (where.slot < 0) {
        for (int i = 0; i < 3; ++i) run(where.tri, i, t0.v[i], t0.v[(i + 1) % 3]);
      } else {  // on a diagonal: expand the two other edges of both triangles
        const int s = where.slot;
        const std::uint32_t u = t0.nbr[s];
        int j = 0;
        while (T[u].nbr[j] != where.tri || T[u].v[j] != t0.v[(s + 1) % 3]) ++j;
        for (int k : {(s + 1) % 3, (s + 2) % 3}) run(where.tri, k, t0.v[k], t0.v[(k + 1) % 3]);
        for (int k : {(j + 1) % 3, (j + 2) % 3}) run(u, k, T[u].v[k], T[u].v[(k + 1) % 3]);
      }
      break;
    case Location::Kind::OnEdge: {  // q inside boundary edge (a, b) of t0
      const int s = where.slot;
      const std::uint32_t a = t0.v[s], b = t0.v[(s + 1) % 3];
      pieces.push_back({t0.edge[s], kNone, b, sym_query, sym_vertex(b)});
      for (int k : {(s + 1) % 3, (s + 2) % 3}) run(where.tri, k, t0.v[k], t0.v[(k + 1) % 3]);
      pieces.push_back({t0.edge[s], a, kNone, sym_vertex(a), sym_query});
      break;
    }
    case Location::Kind::AtVertex: {
      // The fan of triangles around v inside its free wedge; at a contact, every wedge there
      // in counter-clockwise order (wedge_end(v) starts the next one), so V(q) is their
      // union, a weakly simple polygon through q once per wedge. The point is named by one
      // id throughout so the wedges' pieces join without a gap.
      const std::uint32_t v0 = static_cast<std::uint32_t>(where.loc.index);
      std::uint32_t v = v0;
      do {
        const std::uint32_t w = static_cast<std::uint32_t>(E.next(v));
        const std::uint32_t pv = static_cast<std::uint32_t>(E.prev(E.wedge_end(v)));
        pieces.push_back({v, kNone, w, sym_vertex(v0), sym_vertex(w)});
        auto [t, s] = tri_.boundary_slot(v);  // slot s = (v, w)
        while (true) {
          const Triangle& tr = T[t];
          const int opp = (s + 1) % 3;  // edge opposite v
          run(t, opp, tr.v[opp], tr.v[(opp + 1) % 3]);
          const int back = (s + 2) % 3;  // edge (x, v): continue counter-clockwise around v
          if (tr.nbr[back] == kNone) break;
          const std::uint32_t u = tr.nbr[back];
          int k = 0;
          while (T[u].v[k] != v) ++k;
          t = u, s = static_cast<std::uint8_t>(k);
        }
        pieces.push_back({pv, pv, kNone, sym_vertex(pv), sym_vertex(v0)});
        v = static_cast<std::uint32_t>(E.wedge_end(v));
      } while (v != v0 && only_wedge == kNone);
      break;
    }
    default: break;
  }

  // Merge consecutive pieces of one edge that continue each other (in place).
  {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      if (kept > 0 && pieces[kept - 1].edge == pieces[k].edge && pieces[kept - 1].end == pieces[k].start) {
        pieces[kept - 1].end = pieces[k].end, pieces[kept - 1].ray_l = pieces[k].ray_l;
      } else {
        if (kept != k) pieces[kept] = pieces[k];  // merges are rare: most pieces stay put
        ++kept;
      }
    }
    pieces.resize(kept);
    while (pieces.size() > 1 && pieces.back().edge == pieces.front().edge && pieces.back().end == pieces.front().start) {
      pieces.front().start = pieces.back().start, pieces.front().ray_r = pieces.back().ray_r;
      pieces.pop_back();
    }
  }

  const Point no_coordinates(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
  auto realise = [&](const Sym& sv) -> VisibilityVertex {
    VisibilityVertex v{sv.kind, sv.vertex, sv.edge, no_coordinates};
    if (coordinates) v.approx = sv.kind == VisibilityVertex::Kind::EnvironmentVertex ? P[sv.vertex] : approx_vertex(E, approx, v);
    return v;
  };
  // Output records are written field by field in place (as the pieces above: a record
  // composed on the stack and copied stalled store forwarding).
  // A ray hit's coordinates wait for a pass of their own after the loop: each needs a
  // division, which stalled every emission here (profiled); in their own loop the
  // divisions of consecutive hits overlap.
  // The output is sized for its largest case (a gap after every piece) and written through
  // plain pointers, then cut to what was written: emplace_back reloaded and stored the
  // vectors' ends around every record (profiled, 8% of a query on comb-120).
  const std::size_t m = pieces.size();
  out.vertices.resize(2 * m);
  out.edges.resize(2 * m);
  VisibilityVertex* const vout = out.vertices.data();
  VisibilityEdge* const eout = out.edges.data();
  std::size_t nv = 0, ne = 0;
  auto emit_vertex = [&](const Sym& sv) __attribute__((always_inline)) {
    VisibilityVertex& v = vout[nv++];
    v.kind = sv.kind, v.vertex = sv.vertex, v.edge = sv.edge;
    v.approx = !coordinates ? no_coordinates : sv.kind == VisibilityVertex::Kind::EnvironmentVertex ? P[sv.vertex] : approx;
  };
  auto emit_edge = [&](VisibilityEdge::Kind kind, std::uint32_t edge, std::uint32_t reflex, bool left) {
    VisibilityEdge& d = eout[ne++];
    d.kind = kind, d.edge = edge, d.reflex = reflex, d.occluder_on_left = left;
  };
  for (std::size_t k = 0; k < m; ++k) {
    const Piece& pc = pieces[k];
    emit_vertex(pc.start);
    emit_edge(VisibilityEdge::Kind::Solid, pc.edge, kNone, false);
    const Sym &X = pc.end, &Y = pieces[k + 1 == m ? 0 : k + 1].start;  // not % m: a 64-bit division per piece (profiled)
    if (X == Y) continue;
    // A gap along the shared cone ray q -> c between the two hits X (end of this piece)
    // and Y (start of the next).
    emit_vertex(X);
    const bool both_vertices = X.kind == VisibilityVertex::Kind::EnvironmentVertex &&
                               Y.kind == VisibilityVertex::Kind::EnvironmentVertex;
    if (both_vertices) {  // the ray may run along an edge (ids at a contact name one wedge: compare points)
      if (const std::size_t e = E.edge_between(X.vertex, Y.vertex); e != SIZE_MAX) {
        emit_edge(VisibilityEdge::Kind::Solid, static_cast<std::uint32_t>(e), kNone, false);
        continue;
      }
      if (const std::size_t e = E.edge_between(Y.vertex, X.vertex); e != SIZE_MAX) {
        emit_edge(VisibilityEdge::Kind::Solid, static_cast<std::uint32_t>(e), kNone, false);
        continue;
      }
    }
    // Usually one end is c itself, the occluder, nearer to q; otherwise compare exactly.
    bool outward;
    if (X == sym_vertex(pc.ray_l)) {
      outward = true;
    } else if (Y == sym_vertex(pc.ray_l)) {
      outward = false;
    } else {
      const ExactPoint eq = exact_of(q);
      outward = CGAL::compare_distance_to_point(eq, exact_vertex(env_, eq, vout[nv - 1]),
                                                exact_vertex(env_, eq, realise(Y))) == CGAL::SMALLER;
    }
    emit_edge(VisibilityEdge::Kind::Free, kNone, pc.ray_l, !outward);
  }
  out.vertices.resize(nv);
  out.edges.resize(ne);
  if (coordinates)
    for (VisibilityVertex& v : out.vertices)
      if (v.kind == VisibilityVertex::Kind::RayHit) v.approx = approx_vertex(E, approx, v);
}

// ---------------------------------------------------------------- walks along a line
// A straight walk along the line from a through b, through the triangles it crosses. Every
// vertex of the triangulation is an environment vertex, so the walk meets three situations:
//   - it crosses the interior of a triangle edge: a diagonal is crossed, a boundary edge
//     ends the walk (the line would leave free space);
//   - it passes through a vertex w: it may go on only if the direction a -> b lies in the
//     closed free wedge at w (the fan of triangles around w), possibly along an edge;
//   - (segment walks) b lies in the closed triangle it is in: b is reached.
// Every test is an orientation or dot-product sign on a, b and environment vertices (a
// direction at a vertex w on the line is that of a -> b), so every decision is exact.
// The walk starts at a (start == kNone) or at vertex `start` on the line; it calls
// on_vertex(w) for every vertex it passes through after the start. Returns true when b is
// reached (segment walks), false when the line leaves free space.
template <class OnVertex>
bool VisibilityIndex::walk(const Point& a, const Point& b, std::uint32_t start, bool to_b, OnVertex&& on_vertex) const {
  const auto& P = env_->vertices();
  const auto& T = tri_.triangles();

  auto inside = [&](std::uint32_t t) {  // b in the closed triangle t
    if (!to_b) return false;
    const Triangle& tr = T[t];
    for (int i = 0; i < 3; ++i)
      if (orientation(P[tr.v[i]], P[tr.v[(i + 1) % 3]], b) < 0) return false;
    return true;
  };
  // Is b between w and x on the line (so reached before x)?
  auto within = [&](const Point& w, const Point& x) { return to_b && CGAL::collinear_are_ordered_along_line(w, b, x); };

  enum class Step { Reached, Blocked, Walk, Pivot };
  std::uint32_t t = kNone, pivot = kNone;
  int entry = -1;
  // Enter the neighbour of u across edge slot `s` (the line crosses that edge's interior).
  auto cross = [&](std::uint32_t u, int s) -> Step {
    const std::uint32_t nb = T[u].nbr[s];
    if (nb == kNone) return Step::Blocked;
    const std::uint32_t x = T[u].v[s];
    int j = 0;
    while (T[nb].v[(j + 1) % 3] != x) ++j;  // in nb the shared edge runs the other way
    t = nb, entry = j;
    return Step::Walk;
  };
  // Leave vertex w (on the line) in direction a -> b: the fan triangle of w whose closed
  // wedge holds it. For x off the line, orientation(w, x, w + (b - a)) = -orientation(a, b, x).
  // At a contact the point has one fan per free wedge: try each (ids linked by
  // same_point_next); a direction in none of them enters a ring's material.
  auto turn_at = [&](std::uint32_t w0) -> Step {
    const Point& W = P[w0];
    std::uint32_t w = w0;
    do {
      auto [u, s] = tri_.boundary_slot(w);  // triangle with edge (w, next(w)) at slot s
      while (true) {
        const Triangle& tr = T[u];
        const int sa = (s + 1) % 3, sb = (s + 2) % 3;
        const std::uint32_t x = tr.v[sa], y = tr.v[sb];  // counter-clockwise around w: x then y
        const int ox = -orientation(a, b, P[x]), oy = -orientation(a, b, P[y]);
        for (std::uint32_t e : {x, y}) {
          if ((e == x ? ox : oy) == 0 && dot_sign(W, P[e], a, b) > 0) {  // along edge w -> e
            if (within(W, P[e])) return Step::Reached;
            on_vertex(e);
            pivot = e;
            return Step::Pivot;
          }
        }
        if (ox > 0 && oy < 0) {  // strictly inside the wedge: through triangle u
          if (inside(u)) return Step::Reached;
          return cross(u, sa);  // edge (x, y) is slot sa
        }
        if (tr.nbr[sb] == kNone) break;  // last triangle of the fan: outside this free wedge
        const std::uint32_t nu = tr.nbr[sb];
        int k = 0;
        while (T[nu].v[k] != w) ++k;
        u = nu, s = k;
      }
      w = static_cast<std::uint32_t>(env_->same_point_next(w));
    } while (w != w0);
    return Step::Blocked;
  };

  Step step = Step::Blocked;
  if (start != kNone) {
    step = turn_at(start);
  } else {
    const Located where = locate_triangle(a, a);
    if (!where.loc.in_free_space()) return false;
    if (to_b && a == b) return true;
    const Triangle& t0 = T[where.tri];
    switch (where.loc.kind) {
      case Location::Kind::AtVertex:
        step = turn_at(static_cast<std::uint32_t>(where.loc.index));
        break;
      case Location::Kind::OnEdge:
      case Location::Kind::Interior: {
        if (where.slot >= 0) {  // a inside edge `slot` of t0: a boundary edge or a diagonal
          const int s = where.slot;
          const std::uint32_t u0 = t0.v[s], u1 = t0.v[(s + 1) % 3];
          const int o = orientation(P[u0], P[u1], b);
          if (o == 0) {  // along the edge's line, towards one of its ends
            const std::uint32_t toward = dot_sign(a, P[u1], a, b) > 0 ? u1 : u0;
            if (within(a, P[toward])) return true;
            on_vertex(toward);
            step = turn_at(toward);
          } else if (o > 0) {
            t = where.tri, entry = s, step = Step::Walk;
          } else {
            if (t0.nbr[s] == kNone) return false;  // behind a boundary edge
            const std::uint32_t u = t0.nbr[s];
            int j = 0;
            while (T[u].v[(j + 1) % 3] != u0) ++j;
            t = u, entry = j, step = Step::Walk;
          }
          break;
        }
        // a strictly inside t0: leave through the edge or vertex the line meets.
        if (inside(where.tri)) return true;
        for (int i = 0; i < 3; ++i) {
          const std::uint32_t vi = t0.v[i], vj = t0.v[(i + 1) % 3];
          const int oi = orientation(a, b, P[vi]);
          if (oi == 0 && dot_sign(a, P[vi], a, b) > 0) {
            on_vertex(vi);
            pivot = vi, step = Step::Pivot;
            break;
          }
          if (oi < 0 && orientation(a, b, P[vj]) > 0) {
            step = cross(where.tri, i);
            break;
          }
        }
        break;
      }
      default:
        return false;
    }
  }

  for (std::size_t guard = 0; guard <= 4 * T.size() + 8; ++guard) {
    if (step == Step::Reached) return true;
    if (step == Step::Blocked) return false;
    if (step == Step::Pivot) {
      step = turn_at(pivot);
      continue;
    }
    // Walk: in t, entered across slot `entry` (its interior).
    const Triangle& tr = T[t];
    if (inside(t)) return true;
    const std::uint32_t x = tr.v[entry], c = tr.v[(entry + 2) % 3];
    const int oc = orientation(a, b, P[c]);
    if (oc == 0) {  // through the far vertex (b is beyond it: not inside t)
      on_vertex(c);
      pivot = c, step = Step::Pivot;
      continue;
    }
    // Exit through the edge joining c to whichever end of the entry edge lies across the line.
    step = oc == orientation(a, b, P[x]) ? cross(t, (entry + 1) % 3) : cross(t, (entry + 2) % 3);
  }
  throw std::logic_error("visibility: the walk from " + format_point(a) + " towards " + format_point(b) + " did not end");
}

bool VisibilityIndex::visible(const Point& p, const Point& q) const {
  return walk(p, q, kNone, true, [](std::uint32_t) {});
}

bool VisibilityIndex::visible_from_vertex(std::uint32_t v, const Point& q) const {
  const Point& p = env_->vertex(v);
  if (p == q) return true;
  return walk(p, q, v, true, [](std::uint32_t) {});  // a q outside free space is never reached
}

std::vector<std::uint32_t> VisibilityIndex::visible_vertices(const Point& q) const {
  const VisibilityPolygon vis = compute(q);
  std::vector<std::uint32_t> out;
  for (const auto& v : vis.vertices)
    if (v.kind == VisibilityVertex::Kind::EnvironmentVertex) out.push_back(v.vertex);
  // Vertices the expansion does not list: those lying on a ray from q through a listed
  // vertex c, beyond c (on a gap edge, or at the tip of a needle that V(q) regularises
  // away). Walk each such ray exactly from c.
  const std::size_t listed = out.size();
  for (std::size_t i = 0; i < listed; ++i) {
    const std::uint32_t c = out[i];
    if (env_->vertex(c) == q) continue;
    walk(q, env_->vertex(c), c, false, [&](std::uint32_t w) { out.push_back(w); });
  }
  // A contact point is listed under one id per wedge seen; seeing the point is seeing every
  // ring's vertex there (a shortest path may bend there around any of them).
  if (env_->has_contacts())
    for (std::size_t i = 0, m = out.size(); i < m; ++i)
      for (std::size_t w = env_->same_point_next(out[i]); w != out[i]; w = env_->same_point_next(w))
        out.push_back(static_cast<std::uint32_t>(w));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace preimage::geometry
