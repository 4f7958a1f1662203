// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/visibility.hpp>

#include <preimage/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

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
}  // namespace

ExactPoint VisibilityPolygon::exact(std::size_t i) const { return exact_vertex(environment, exact_query, vertices[i]); }

ExactPoint exact_point(const Environment& env, const ExactPoint& query, const VisibilityVertex& v) {
  return exact_vertex(&env, query, v);
}

std::vector<ExactPoint> VisibilityPolygon::points() const {
  std::vector<ExactPoint> out;
  out.reserve(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) out.push_back(exact(i));
  return out;
}

double VisibilityPolygon::area() const {
  double twice = 0;
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point &a = vertices[i].approx, &b = vertices[(i + 1) % n].approx;
    twice += a.x() * b.y() - b.x() * a.y();
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
VisibilityIndex::VisibilityIndex(const Environment& env) : env_(&env), tri_(env) {
  const auto& P = env.vertices();
  const auto& T = tri_.triangles();
  CGAL::Bbox_2 box = env.bbox();
  x0_ = box.xmin(), y0_ = box.ymin();
  const double w = std::max(box.xmax() - box.xmin(), 1e-300), h = std::max(box.ymax() - box.ymin(), 1e-300);
  const double cells = std::max<double>(1.0, static_cast<double>(T.size()));
  const double aspect = w / h;
  gx_ = static_cast<std::uint32_t>(std::clamp(std::sqrt(cells * aspect), 1.0, 4096.0));
  gy_ = static_cast<std::uint32_t>(std::clamp(cells / gx_, 1.0, 4096.0));
  cw_ = w / gx_, ch_ = h / gy_;
  auto cx = [&](double x) { return std::min<std::uint32_t>(gx_ - 1, static_cast<std::uint32_t>(std::max(0.0, (x - x0_) / cw_))); };
  auto cy = [&](double y) { return std::min<std::uint32_t>(gy_ - 1, static_cast<std::uint32_t>(std::max(0.0, (y - y0_) / ch_))); };
  // Two passes (count, fill) into a CSR layout. A triangle goes into the cells its rows
  // cross, not its whole bounding box (long thin triangles, as a circle's or a square with
  // collinear sides has, made the boxes' cells gigabytes). Rows and cells are widened by
  // one on each side so rounding in a cell index can never lose a triangle; the
  // containment test itself is exact.
  cell_off_.assign(std::size_t(gx_) * gy_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      for (std::size_t i = 1; i < cell_off_.size(); ++i) cell_off_[i] += cell_off_[i - 1];
      cell_tris_.resize(cell_off_.back());
      fill.assign(cell_off_.begin(), cell_off_.end() - 1);
    }
    for (std::uint32_t t = 0; t < T.size(); ++t) {
      const Point* V[3] = {&P[T[t].v[0]], &P[T[t].v[1]], &P[T[t].v[2]]};
      const double ylo = std::min({V[0]->y(), V[1]->y(), V[2]->y()}), yhi = std::max({V[0]->y(), V[1]->y(), V[2]->y()});
      std::uint32_t j0 = cy(ylo), j1 = cy(yhi);
      j0 = j0 ? j0 - 1 : 0, j1 = std::min(gy_ - 1, j1 + 1);
      for (std::uint32_t j = j0; j <= j1; ++j) {
        // x-extent of the triangle within rows j - 1 .. j + 1 (a slab three rows tall).
        const double sa = std::max(ylo, y0_ + (static_cast<double>(j) - 1) * ch_);
        const double sb = std::min(yhi, y0_ + (static_cast<double>(j) + 2) * ch_);
        double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo;
        for (int e = 0; e < 3; ++e) {
          const Point &p = *V[e], &q = *V[(e + 1) % 3];
          const double lo = std::max(sa, std::min(p.y(), q.y())), hi = std::min(sb, std::max(p.y(), q.y()));
          if (lo > hi) continue;
          for (double y : {lo, hi}) {
            const double x = p.y() == q.y() ? p.x() : p.x() + (q.x() - p.x()) * ((y - p.y()) / (q.y() - p.y()));
            xlo = std::min(xlo, x), xhi = std::max(xhi, x);
          }
          if (p.y() == q.y()) xlo = std::min(xlo, q.x()), xhi = std::max(xhi, q.x());
        }
        if (!(xlo <= xhi)) continue;
        std::uint32_t i0 = cx(xlo), i1 = cx(xhi);
        i0 = i0 ? i0 - 1 : 0, i1 = std::min(gx_ - 1, i1 + 1);
        for (std::uint32_t i = i0; i <= i1; ++i) {
          const std::size_t c = std::size_t(j) * gx_ + i;
          if (pass == 0) ++cell_off_[c + 1];
          else cell_tris_[fill[c]++] = t;
        }
      }
    }
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
  const double fx = (approx.x() - x0_) / cw_, fy = (approx.y() - y0_) / ch_;
  if (fx >= -1 && fy >= -1 && fx <= gx_ + 1 && fy <= gy_ + 1) {
    std::uint32_t i = std::min<std::uint32_t>(gx_ - 1, static_cast<std::uint32_t>(std::max(0.0, fx)));
    std::uint32_t j = std::min<std::uint32_t>(gy_ - 1, static_cast<std::uint32_t>(std::max(0.0, fy)));
    std::size_t c = std::size_t(j) * gx_ + i;
    for (auto k = cell_off_[c]; k < cell_off_[c + 1]; ++k)
      if (auto r = test(cell_tris_[k])) return *r;
  }
  // Not in any triangle (the grid lists every triangle meeting each of its cells): classify
  // with the exact O(n) locator (outside or in a hole; for a constructed query its rounding
  // names where it lies) when asked to.
  if (!name_outside) return Located{{Location::Kind::Outside, 0}, kNone, -1};
  Location loc = geometry::locate(*env_, approx);
  if (loc.in_free_space()) loc = {Location::Kind::Outside, 0};
  if constexpr (std::is_same_v<Q, Point>) loc = geometry::locate(*env_, q);
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

}  // namespace

VisibilityPolygon VisibilityIndex::compute(const Point& q) const { return compute_at(q, q); }

VisibilityPolygon VisibilityIndex::compute(const ExactPoint& q) const {
  const auto& a = q.approx();
  return compute_at(q, Point(CGAL::to_double(a.x()), CGAL::to_double(a.y())));
}

template <class Q>
VisibilityPolygon VisibilityIndex::compute_at(const Q& q, const Point& approx) const {
  const Located where = locate_triangle(q, approx);
  if (!where.loc.in_free_space())
    throw InputError("visibility: query point " + format_point(approx) + " is not in free space: it lies " +
                     (where.loc.kind == Location::Kind::InHole ? "inside " + env_->ring_name(where.loc.index + 1)
                                                               : "outside " + env_->ring_name(0)));
  const auto& P = env_->vertices();
  const auto Pq = vertices_for(env_, &q);  // vertices in the query's type, for predicates
  const auto& T = tri_.triangles();
  const Environment& E = *env_;

  auto sym_vertex = [](std::uint32_t v) { return Sym{VisibilityVertex::Kind::EnvironmentVertex, v, kNone}; };
  auto sym_hit = [](std::uint32_t through, std::uint32_t e) { return Sym{VisibilityVertex::Kind::RayHit, through, e}; };
  const Sym sym_query{VisibilityVertex::Kind::Query, kNone, kNone};

  std::vector<Piece> pieces;
  // Work item: cross edge `slot` of triangle `t` inside the cone between rays q->R and q->L.
  struct Item { std::uint32_t t; int slot; std::uint32_t R, L; };
  std::vector<Item> stack;
  auto run = [&](std::uint32_t t0, int s0, std::uint32_t R0, std::uint32_t L0) {
    stack.push_back({t0, s0, R0, L0});
    while (!stack.empty()) {
      Item it = stack.back();
      stack.pop_back();
      const Triangle& tr = T[it.t];
      const std::uint32_t r = tr.v[it.slot], l = tr.v[(it.slot + 1) % 3];
      if (tr.nbr[it.slot] == kNone) {  // boundary: emit the visible piece of this edge
        const std::uint32_t e = tr.edge[it.slot];
        Piece pc{e, it.R, it.L, {}, {}};
        pc.start = (it.R == r || orientation(q, Pq(it.R), Pq(r)) == 0) ? sym_vertex(r) : sym_hit(it.R, e);
        pc.end = (it.L == l || orientation(q, Pq(it.L), Pq(l)) == 0) ? sym_vertex(l) : sym_hit(it.L, e);
        pieces.push_back(pc);
        continue;
      }
      const std::uint32_t u = tr.nbr[it.slot];
      const Triangle& nt = T[u];
      int j = 0;
      while (nt.v[j] != l) ++j;  // entry edge in u runs l -> r
      const std::uint32_t c = nt.v[(j + 2) % 3];
      const int right_slot = (j + 1) % 3, left_slot = (j + 2) % 3;  // (r, c) and (c, l)
      const int cr = orientation(q, Pq(it.R), Pq(c));
      const int cl = orientation(q, Pq(it.L), Pq(c));
      if (cr <= 0) {
        stack.push_back({u, left_slot, it.R, it.L});
      } else if (cl >= 0) {
        stack.push_back({u, right_slot, it.R, it.L});
      } else {  // c splits the cone; right part first (counter-clockwise output)
        stack.push_back({u, left_slot, c, it.L});
        stack.push_back({u, right_slot, it.R, c});
      }
    }
  };

  VisibilityPolygon out;
  out.environment = env_;
  out.query = approx;
  out.exact_query = exact_of(q);
  out.location = where.loc;
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
    case Location::Kind::AtVertex: {  // fan of triangles around v inside the free wedge
      const std::uint32_t v = static_cast<std::uint32_t>(where.loc.index);
      const std::uint32_t w = static_cast<std::uint32_t>(E.next(v)), pv = static_cast<std::uint32_t>(E.prev(v));
      pieces.push_back({v, kNone, w, sym_vertex(v), sym_vertex(w)});
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
      pieces.push_back({pv, pv, kNone, sym_vertex(pv), sym_vertex(v)});
      break;
    }
    default: break;
  }

  // Merge consecutive pieces of one edge that continue each other.
  {
    std::vector<Piece> merged;
    for (auto& pc : pieces) {
      if (!merged.empty() && merged.back().edge == pc.edge && merged.back().end == pc.start) {
        merged.back().end = pc.end, merged.back().ray_l = pc.ray_l;
      } else {
        merged.push_back(pc);
      }
    }
    while (merged.size() > 1 && merged.back().edge == merged.front().edge && merged.back().end == merged.front().start) {
      merged.front().start = merged.back().start, merged.front().ray_r = merged.back().ray_r;
      merged.pop_back();
    }
    pieces.swap(merged);
  }

  auto realise = [&](const Sym& sv) -> VisibilityVertex {
    switch (sv.kind) {
      case VisibilityVertex::Kind::EnvironmentVertex: return {sv.kind, sv.vertex, kNone, P[sv.vertex]};
      case VisibilityVertex::Kind::Query: return {sv.kind, kNone, kNone, approx};
      case VisibilityVertex::Kind::RayHit: break;
    }
    // Double rounding of the hit, for drawing only; decisions never read it.
    const Point &w = P[sv.vertex], &a = P[sv.edge], &b = P[E.next(sv.edge)];
    const Point& o = approx;
    const double dx = w.x() - o.x(), dy = w.y() - o.y(), ex = b.x() - a.x(), ey = b.y() - a.y();
    const double s = ((a.x() - o.x()) * ey - (a.y() - o.y()) * ex) / (dx * ey - dy * ex);
    return {sv.kind, sv.vertex, sv.edge, Point(o.x() + s * dx, o.y() + s * dy)};
  };
  const std::size_t m = pieces.size();
  out.vertices.reserve(2 * m);
  out.edges.reserve(2 * m);
  std::vector<VisibilityVertex> starts;
  starts.reserve(m);
  for (const Piece& pc : pieces) starts.push_back(realise(pc.start));
  for (std::size_t k = 0; k < m; ++k) {
    const Piece& pc = pieces[k];
    out.vertices.push_back(starts[k]);
    out.edges.push_back({VisibilityEdge::Kind::Solid, pc.edge, kNone, false});
    if (pc.end == pieces[(k + 1) % m].start) continue;
    // A gap along the shared cone ray q -> c between the two hits X (end of this piece)
    // and Y (start of the next).
    out.vertices.push_back(realise(pc.end));
    const Sym &X = pc.end, &Y = pieces[(k + 1) % m].start;
    const bool both_vertices = X.kind == VisibilityVertex::Kind::EnvironmentVertex &&
                               Y.kind == VisibilityVertex::Kind::EnvironmentVertex;
    if (both_vertices && E.next(X.vertex) == Y.vertex) {  // the ray runs along an edge
      out.edges.push_back({VisibilityEdge::Kind::Solid, X.vertex, kNone, false});
      continue;
    }
    if (both_vertices && E.next(Y.vertex) == X.vertex) {
      out.edges.push_back({VisibilityEdge::Kind::Solid, Y.vertex, kNone, false});
      continue;
    }
    // Usually one end is c itself, the occluder, nearer to q; otherwise compare exactly.
    bool outward;
    if (X == sym_vertex(pc.ray_l)) outward = true;
    else if (Y == sym_vertex(pc.ray_l)) outward = false;
    else outward = CGAL::compare_distance_to_point(out.exact_query, exact_vertex(env_, out.exact_query, out.vertices.back()),
                                                   exact_vertex(env_, out.exact_query, starts[(k + 1) % m])) == CGAL::SMALLER;
    out.edges.push_back({VisibilityEdge::Kind::Free, kNone, pc.ray_l, !outward});
  }
  return out;
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
  auto turn_at = [&](std::uint32_t w) -> Step {
    const Point& W = P[w];
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
      if (tr.nbr[sb] == kNone) return Step::Blocked;  // last triangle of the fan: outside the free wedge
      const std::uint32_t nu = tr.nbr[sb];
      int k = 0;
      while (T[nu].v[k] != w) ++k;
      u = nu, s = k;
    }
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
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace preimage::geometry
