// SPDX-License-Identifier: Apache-2.0
// The generalized Voronoi diagram from Boost.Polygon's Voronoi diagram of segments.
//
// Steps: (1) snap every vertex to the grid 2^k with |coordinate| < 2^grid_bits grid steps and check
// exactly (segment sweep) that the snapped edges meet only at shared endpoints; (2) Boost's
// sweep on the int32 segments; (3) keep the primary edges whose two sites belong to different
// obstacles (rings joined by contacts), with their sites, clearance and a sampled polyline;
// (4) check the output (finite edges, endpoints equidistant to both sites and no obstacle
// nearer, every obstacle's GVD edges closed curves) and throw std::logic_error otherwise;
// (5) critical points of D along the GVD from the convex clearance of each edge.
#include <preimage/geometry/gvd.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/local_frame.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/segment_sweep.hpp>
#include <preimage/union_find.hpp>

#include <boost/polygon/voronoi_builder.hpp>
#include <boost/polygon/voronoi_diagram.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

namespace preimage::geometry {

namespace gvd_detail {

// A site in grid units (doubles holding integers): a point (a) or a segment (a, b).
struct ScaledSite {
  bool point = true;
  double ax = 0, ay = 0, bx = 0, by = 0;
};

struct XY {
  double x = 0, y = 0;
};

// Nearest point of the site to (px, py).
XY nearest_on(const ScaledSite& s, double px, double py) {
  if (s.point) return {s.ax, s.ay};
  const double dx = s.bx - s.ax, dy = s.by - s.ay;
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((px - s.ax) * dx + (py - s.ay) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return {s.ax + t * dx, s.ay + t * dy};
}

double distance_to(const ScaledSite& s, double px, double py) {
  const XY q = nearest_on(s, px, py);
  return std::hypot(px - q.x, py - q.y);
}

double segment_distance(const Point& p, const Segment& s) {
  const double ax = s.source().x(), ay = s.source().y(), bx = s.target().x(), by = s.target().y();
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p.x() - ax) * dx + (p.y() - ay) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x() - (ax + t * dx), p.y() - (ay + t * dy));
}

// How D changes moving from an end of an edge into it: +1 rises, -1 falls, 0 constant.
struct EdgeShape {
  int slope[2] = {0, 0};
  bool interior_min = false, plateau = false;
  XY min_point;      // the interior minimum (Interior saddles)
  XY min_nearest[2]; // its nearest points on the two sites
};

}  // namespace gvd_detail

GeneralizedVoronoiDiagram GeneralizedVoronoiDiagram::build(const Environment& env, const GvdOptions& options) {
  using namespace gvd_detail;
  // Far from the origin the snapping grid would be as coarse as the coordinates are large
  // (2^5 at 1e10): build the diagram in the local frame, then move it back. The canonical
  // frame (the box at 0 wherever that is exact), so the grid sits on the plan, not on the
  // origin, and a plan and its exact translates get one diagram, moved.
  if (const LocalFrame frame = LocalFrame::canonical(env); !frame.identity()) {
    GeneralizedVoronoiDiagram g = build(frame.to_local(env), options);
    g.to_input(frame, env);
    return g;
  }
  GeneralizedVoronoiDiagram g;
  const std::size_t n = env.num_vertices();

  // ---- obstacles: rings joined by contacts
  {
    UnionFind uf(env.num_rings());
    for (std::size_t v = 0; v < n; ++v) uf.join(static_cast<std::uint32_t>(env.ring_of(v)), static_cast<std::uint32_t>(env.ring_of(env.same_point_next(v))));
    std::vector<std::uint32_t> id_of_root(env.num_rings(), UINT32_MAX);
    g.ring_obstacle_.resize(env.num_rings());
    for (std::size_t r = 0; r < env.num_rings(); ++r) {
      const std::uint32_t root = uf.find(static_cast<std::uint32_t>(r));
      if (id_of_root[root] == UINT32_MAX) {
        id_of_root[root] = static_cast<std::uint32_t>(g.obstacle_rings_.size());
        g.obstacle_rings_.emplace_back();
      }
      g.ring_obstacle_[r] = id_of_root[root];
      g.obstacle_rings_[id_of_root[root]].push_back(static_cast<std::uint32_t>(r));
    }
  }
  g.edge_obstacle_.resize(n);
  g.next_.resize(n);
  for (std::size_t e = 0; e < n; ++e) g.next_[e] = static_cast<std::uint32_t>(env.next(e));
  g.segments_.reserve(n);
  for (std::size_t e = 0; e < n; ++e) {
    g.edge_obstacle_[e] = g.ring_obstacle_[env.ring_of(e)];
    g.segments_.push_back(env.edge(e));
  }

  // ---- snapping: |coordinate| < 2^grid_bits grid steps (int32 for Boost)
  double M = 0;
  for (const Point& p : env.vertices()) M = std::max({M, std::fabs(p.x()), std::fabs(p.y())});
  int e2 = 0;
  std::frexp(M, &e2);  // M < 2^e2
  if (options.grid_bits < 16 || options.grid_bits > 30)
    throw InputError("gvd: grid_bits must be in [16, 30], got " + std::to_string(options.grid_bits));
  g.resolution_exponent_ = e2 - options.grid_bits;
  g.resolution_ = std::ldexp(1.0, g.resolution_exponent_);
  const double res = g.resolution_;
  std::vector<std::int32_t> X(n), Y(n);
  g.snapped_.reserve(n);
  for (std::size_t v = 0; v < n; ++v) {
    X[v] = static_cast<std::int32_t>(std::llround(std::ldexp(env.vertex(v).x(), -g.resolution_exponent_)));
    Y[v] = static_cast<std::int32_t>(std::llround(std::ldexp(env.vertex(v).y(), -g.resolution_exponent_)));
    g.snapped_.emplace_back(std::ldexp(static_cast<double>(X[v]), g.resolution_exponent_), std::ldexp(static_cast<double>(Y[v]), g.resolution_exponent_));
  }
  const std::string grid_name = "the grid 2^" + std::to_string(g.resolution_exponent_) + " (" + format_number(res) + ")";
  auto edge_name = [&](std::size_t e) { return env.ring_name(env.ring_of(e)) + " edge " + std::to_string(env.input_edge_index(e)); };
  {
    // One point index per input point (contacts share theirs), so the sweep accepts exactly
    // the shared endpoints of the input and reports any new touching.
    std::vector<std::uint32_t> rep(n);
    for (std::size_t v = 0; v < n; ++v) {
      std::size_t m = v;
      for (std::size_t u = env.same_point_next(v); u != v; u = env.same_point_next(u)) m = std::min(m, u);
      rep[v] = static_cast<std::uint32_t>(m);
    }
    std::vector<IndexedSegment> segs(n);
    for (std::size_t e = 0; e < n; ++e) {
      segs[e] = {rep[e], rep[env.next(e)]};
      if (g.snapped_[e] == g.snapped_[env.next(e)])
        throw InputError("gvd: snapped to " + grid_name + ", " + edge_name(e) + " has length 0 (both ends at " + format_point(g.snapped_[e]) +
                         "): the input is finer than the resolution");
    }
    if (const auto c = find_segment_contact(g.snapped_, segs))
      throw InputError("gvd: snapped to " + grid_name + ", " + edge_name(c->first) + " and " + edge_name(c->second) +
                       " meet other than at a shared endpoint near " + format_point(c->near) + ": the input is finer than the resolution");
  }

  // ---- Boost.Polygon's Voronoi diagram of the segments (source index = edge id)
  boost::polygon::voronoi_builder<std::int32_t> builder;
  for (std::size_t e = 0; e < n; ++e) builder.insert_segment(X[e], Y[e], X[env.next(e)], Y[env.next(e)]);
  boost::polygon::voronoi_diagram<double> vd;
  builder.construct(&vd);

  auto site_of = [&](const boost::polygon::voronoi_diagram<double>::cell_type& c) {
    GvdSite s;
    const std::size_t idx = c.source_index();
    if (c.contains_segment()) {
      s.kind = GvdSite::Kind::Edge;
      s.index = static_cast<std::uint32_t>(idx);
    } else {
      s.kind = GvdSite::Kind::Vertex;
      s.index = static_cast<std::uint32_t>(c.source_category() == boost::polygon::SOURCE_CATEGORY_SEGMENT_START_POINT ? idx : env.next(idx));
    }
    s.obstacle = g.edge_obstacle_[s.index];  // a vertex has the obstacle of its out-edge
    return s;
  };
  auto scaled = [&](const GvdSite& s) {
    ScaledSite t;
    t.point = s.kind == GvdSite::Kind::Vertex;
    t.ax = X[s.index], t.ay = Y[s.index];
    if (!t.point) t.bx = X[env.next(s.index)], t.by = Y[env.next(s.index)];
    return t;
  };
  auto site_name = [&](const GvdSite& s) {
    return env.ring_name(env.ring_of(s.index)) + (s.kind == GvdSite::Kind::Edge ? " edge " + std::to_string(env.input_edge_index(s.index))
                                                                                : " vertex " + std::to_string(env.input_index(s.index)));
  };
  auto world = [&](double x, double y) { return Point(std::ldexp(x, g.resolution_exponent_), std::ldexp(y, g.resolution_exponent_)); };

  // max deviation of the sampled arcs, in grid units
  const CGAL::Bbox_2 box = env.bbox();
  const double extent = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  const double want_dev = options.max_deviation > 0 ? options.max_deviation : extent / 1000;
  g.max_deviation_ = want_dev;
  const double dev = want_dev / res;

  // ---- the shape of a Voronoi edge: its ends, their clearance, samples of a curved edge,
  // and how D runs along it (shared by the GVD and the medial axis)
  const auto& bverts = vd.vertices();
  using BoostEdge = boost::polygon::voronoi_diagram<double>::edge_type;
  constexpr double kEquidistance = 1.0;  // grid units
  struct EdgeGeometry {
    XY ends[2];
    double cl[2] = {0, 0};
    std::vector<XY> inner;  // samples strictly between the ends (curved edges)
    EdgeShape sh;
  };
  auto describe = [&](const BoostEdge& be, const GvdSite& s0, const GvdSite& s1, const ScaledSite& a, const ScaledSite& b) {
    EdgeGeometry G;
    EdgeShape& sh = G.sh;
    XY* ends = G.ends;
    const boost::polygon::voronoi_diagram<double>::vertex_type* bv[2] = {be.vertex0(), be.vertex1()};
    for (int k = 0; k < 2; ++k) {
      ends[k] = {bv[k]->x(), bv[k]->y()};
      const double da = distance_to(a, ends[k].x, ends[k].y), db = distance_to(b, ends[k].x, ends[k].y);
      if (!(std::fabs(da - db) <= kEquidistance))
        throw std::logic_error("gvd: Boost.Polygon's Voronoi vertex " + format_point(world(ends[k].x, ends[k].y)) + " is not equidistant to " +
                               site_name(s0) + " (" + format_number(da * res) + ") and " + site_name(s1) + " (" + format_number(db * res) + ")");
      G.cl[k] = std::min(da, db);
    }
    const double len = std::hypot(ends[1].x - ends[0].x, ends[1].y - ends[0].y);
    // Along the edge D is convex: it falls to its minimum at parameter t* and rises after.
    // With t0 < t1 the ends' parameters, slopes follow from where t* lies (within a grid step
    // of an end counts as at the end).
    auto slopes_from_min = [&](double t0, double t1, double tmin) {
      const double lo = std::min(t0, t1), hi = std::max(t0, t1);
      if (tmin > lo + 1 && tmin < hi - 1) {
        sh.interior_min = true;
        sh.slope[0] = sh.slope[1] = -1;
        return;
      }
      const bool min_at_0 = t0 < t1 ? tmin <= lo + 1 : tmin >= hi - 1;
      sh.slope[0] = min_at_0 ? 1 : -1;
      sh.slope[1] = -sh.slope[0];
    };
    if (a.point && b.point) {
      // bisector of two points: D = |X - a| is smallest at their midpoint
      const XY m{(a.ax + b.ax) / 2, (a.ay + b.ay) / 2};
      const double ux = len > 0 ? (ends[1].x - ends[0].x) / len : 0, uy = len > 0 ? (ends[1].y - ends[0].y) / len : 0;
      slopes_from_min(0, len, (m.x - ends[0].x) * ux + (m.y - ends[0].y) * uy);
      sh.min_point = m;
      sh.min_nearest[0] = {a.ax, a.ay}, sh.min_nearest[1] = {b.ax, b.ay};
    } else if (a.point != b.point) {
      // parabola: focus P, directrix the line of segment AB; frame u along AB from P's foot,
      // v the distance to the line: v = (u^2 + h^2) / 2h, D = v, smallest at the apex u = 0
      const ScaledSite& P = a.point ? a : b;
      const ScaledSite& S = a.point ? b : a;
      const double dx = S.bx - S.ax, dy = S.by - S.ay, L = std::hypot(dx, dy);
      const double ex = dx / L, ey = dy / L;
      double nx = -ey, ny = ex;
      double h = (P.ax - S.ax) * nx + (P.ay - S.ay) * ny;
      if (h < 0) nx = -nx, ny = -ny, h = -h;
      const double foot = (P.ax - S.ax) * ex + (P.ay - S.ay) * ey;
      auto u_of = [&](const XY& q) { return (q.x - S.ax) * ex + (q.y - S.ay) * ey - foot; };
      const double u0 = u_of(ends[0]), u1 = u_of(ends[1]);
      slopes_from_min(u0, u1, 0);
      const XY footp{S.ax + ex * foot, S.ay + ey * foot};
      sh.min_point = {footp.x + nx * h / 2, footp.y + ny * h / 2};
      sh.min_nearest[0] = {P.ax, P.ay}, sh.min_nearest[1] = footp;
      if (!a.point) std::swap(sh.min_nearest[0], sh.min_nearest[1]);
      if (be.is_curved() && h > 0) {
        const double step = std::sqrt(8 * h * dev);
        const double pieces_d = std::ceil(std::fabs(u1 - u0) / step);
        const std::size_t pieces = static_cast<std::size_t>(std::clamp(pieces_d, 1.0, 10000.0));
        const double du = (u1 - u0) / static_cast<double>(pieces);
        g.max_deviation_ = std::max(g.max_deviation_, du * du / (8 * h) * res);
        for (std::size_t k = 1; k < pieces; ++k) {
          const double u = u0 + du * static_cast<double>(k), v = (u * u + h * h) / (2 * h);
          G.inner.push_back({footp.x + ex * u + nx * v, footp.y + ey * u + ny * v});
        }
      }
    } else {
      // two segments: D is linear along their bisector, constant when they are parallel
      // (decided exactly on the integer coordinates)
      const std::int64_t c = static_cast<std::int64_t>(a.bx - a.ax) * static_cast<std::int64_t>(b.by - b.ay) -
                             static_cast<std::int64_t>(a.by - a.ay) * static_cast<std::int64_t>(b.bx - b.ax);
      if (c == 0) {
        sh.plateau = true;
      } else {
        const int s = G.cl[1] > G.cl[0] ? 1 : G.cl[1] < G.cl[0] ? -1 : 0;
        sh.slope[0] = s, sh.slope[1] = -s;
      }
      sh.min_point = {(ends[0].x + ends[1].x) / 2, (ends[0].y + ends[1].y) / 2};
      sh.min_nearest[0] = nearest_on(a, sh.min_point.x, sh.min_point.y);
      sh.min_nearest[1] = nearest_on(b, sh.min_point.x, sh.min_point.y);
    }
    return G;
  };

  // ---- keep the edges between different obstacles
  std::vector<std::uint32_t> vid(bverts.size(), UINT32_MAX);
  std::vector<EdgeShape> shapes;
  std::vector<std::array<ScaledSite, 2>> edge_sites;
  for (std::size_t i = 0; i < vd.edges().size(); i += 2) {
    const auto& be = vd.edges()[i];
    const GvdSite s0 = site_of(*be.cell()), s1 = site_of(*be.twin()->cell());
    if (s0.obstacle == s1.obstacle) continue;
    if (be.is_infinite())
      throw std::logic_error("gvd: Boost.Polygon returned an infinite Voronoi edge between " + site_name(s0) + " and " + site_name(s1) +
                             " (cf. boostorg/polygon #72)");
    if (!be.is_primary())
      throw std::logic_error("gvd: Boost.Polygon returned a secondary edge between " + site_name(s0) + " and " + site_name(s1) + " of different obstacles");
    const ScaledSite a = scaled(s0), b = scaled(s1);
    const EdgeGeometry G = describe(be, s0, s1, a, b);
    const EdgeShape& sh = G.sh;
    GvdEdge out;
    out.sites[0] = s0, out.sites[1] = s1;
    const boost::polygon::voronoi_diagram<double>::vertex_type* bv[2] = {be.vertex0(), be.vertex1()};
    for (int k = 0; k < 2; ++k) {
      const std::size_t bi = static_cast<std::size_t>(bv[k] - bverts.data());
      if (vid[bi] == UINT32_MAX) {
        vid[bi] = static_cast<std::uint32_t>(g.vertices_.size());
        g.vertices_.push_back({world(G.ends[k].x, G.ends[k].y), G.cl[k] * res, 0});
      }
      ++g.vertices_[vid[bi]].degree;
    }
    out.from = vid[static_cast<std::size_t>(bv[0] - bverts.data())];
    out.to = vid[static_cast<std::size_t>(bv[1] - bverts.data())];
    out.clearance_from = G.cl[0] * res, out.clearance_to = G.cl[1] * res;
    out.curved = be.is_curved();
    out.polyline.push_back(world(G.ends[0].x, G.ends[0].y));
    for (const XY& q : G.inner) out.polyline.push_back(world(q.x, q.y));
    out.polyline.push_back(world(G.ends[1].x, G.ends[1].y));
    out.min_clearance = std::min(out.clearance_from, out.clearance_to);
    if (sh.interior_min) out.min_clearance = std::min(out.min_clearance, distance_to(a, sh.min_point.x, sh.min_point.y) * res);
    g.edges_.push_back(std::move(out));
    shapes.push_back(sh);
    edge_sites.push_back({a, b});
  }

  // ---- the medial axis: every primary edge in free space, split at the minimum of D
  if (options.medial_axis) {
    std::vector<std::uint32_t> mvid(bverts.size(), UINT32_MAX);
    auto medial_vertex = [&](const boost::polygon::voronoi_diagram<double>::vertex_type* v, double cl) {
      const std::size_t bi = static_cast<std::size_t>(v - bverts.data());
      if (mvid[bi] == UINT32_MAX) {
        mvid[bi] = static_cast<std::uint32_t>(g.medial_vertices_.size());
        g.medial_vertices_.push_back({world(v->x(), v->y()), cl * res});
      }
      return mvid[bi];
    };
    // Per Boost half-edge kept: the first and the last sheet along its direction of travel.
    std::vector<std::uint32_t> first_sheet(vd.edges().size(), UINT32_MAX), last_sheet(vd.edges().size(), UINT32_MAX);
    auto half_index = [&](const BoostEdge* e) { return static_cast<std::size_t>(e - vd.edges().data()); };
    for (std::size_t i = 0; i < vd.edges().size(); i += 2) {
      const auto& be = vd.edges()[i];
      if (!be.is_primary() || be.is_infinite()) continue;
      const GvdSite s0 = site_of(*be.cell()), s1 = site_of(*be.twin()->cell());
      const ScaledSite a = scaled(s0), b = scaled(s1);
      const EdgeGeometry G = describe(be, s0, s1, a, b);
      std::vector<XY> pts;
      pts.push_back(G.ends[0]);
      pts.insert(pts.end(), G.inner.begin(), G.inner.end());
      pts.push_back(G.ends[1]);
      if (s0.obstacle == s1.obstacle) {
        // Inside free space or inside an obstacle (or outside the outer ring) as a whole:
        // one interior point decides, exactly, against the site (its nearest obstacle).
        const XY mid = pts.size() > 2 ? pts[pts.size() / 2] : XY{(pts[0].x + pts[1].x) / 2, (pts[0].y + pts[1].y) / 2};
        const Point m = world(mid.x, mid.y);
        bool free = false;
        if (s0.kind == GvdSite::Kind::Edge)
          free = CGAL::orientation(g.snapped_[s0.index], g.snapped_[env.next(s0.index)], m) == CGAL::LEFT_TURN;
        else if (s1.kind == GvdSite::Kind::Edge)
          free = CGAL::orientation(g.snapped_[s1.index], g.snapped_[env.next(s1.index)], m) == CGAL::LEFT_TURN;
        else
          free = distance_to(a, mid.x, mid.y) > 0 && in_free_wedge(env, s0.index, m);
        if (!free) continue;
      }
      // Split at the interior minimum of D (a saddle): D is then monotone or constant on each piece.
      std::vector<std::vector<XY>> pieces;
      if (G.sh.interior_min) {
        const XY mp = G.sh.min_point;
        const double ux = G.ends[1].x - G.ends[0].x, uy = G.ends[1].y - G.ends[0].y;
        const double tm = ux * (mp.x - G.ends[0].x) + uy * (mp.y - G.ends[0].y);
        std::vector<XY> p0{pts.front()}, p1;
        std::size_t k = 1;
        for (; k + 1 < pts.size() && ux * (pts[k].x - G.ends[0].x) + uy * (pts[k].y - G.ends[0].y) < tm; ++k) p0.push_back(pts[k]);
        p0.push_back(mp);
        p1.push_back(mp);
        for (; k < pts.size(); ++k) p1.push_back(pts[k]);
        pieces.push_back(std::move(p0));
        pieces.push_back(std::move(p1));
      } else {
        pieces.push_back(std::move(pts));
      }
      std::uint32_t prev_vertex = medial_vertex(be.vertex0(), G.cl[0]);
      const auto first_edge = static_cast<std::uint32_t>(g.medial_edges_.size());
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        MedialEdge me;
        me.sites[0] = s0, me.sites[1] = s1;
        me.plateau = G.sh.plateau;
        me.from = prev_vertex;
        if (p + 1 < pieces.size()) {
          me.to = static_cast<std::uint32_t>(g.medial_vertices_.size());
          g.medial_vertices_.push_back({world(pieces[p].back().x, pieces[p].back().y), distance_to(a, pieces[p].back().x, pieces[p].back().y) * res});
        } else {
          me.to = medial_vertex(be.vertex1(), G.cl[1]);
        }
        for (std::size_t k = 0; k < pieces[p].size(); ++k) {
          const XY& q = pieces[p][k];
          me.polyline.push_back(k == 0 ? g.medial_vertices_[me.from].p : k + 1 == pieces[p].size() ? g.medial_vertices_[me.to].p : world(q.x, q.y));
          me.clearance.push_back(k == 0 ? g.medial_vertices_[me.from].clearance
                                 : k + 1 == pieces[p].size() ? g.medial_vertices_[me.to].clearance
                                                             : std::min(distance_to(a, q.x, q.y), distance_to(b, q.x, q.y)) * res);
        }
        if (me.plateau) {
          const double c = (me.clearance.front() + me.clearance.back()) / 2;
          std::fill(me.clearance.begin(), me.clearance.end(), c);
        }
        prev_vertex = me.to;
        g.medial_edges_.push_back(std::move(me));
      }
      const auto last_edge = static_cast<std::uint32_t>(g.medial_edges_.size() - 1);
      for (std::uint32_t e = first_edge; e < last_edge; ++e) {
        g.medial_edges_[e].next_sheet[0] = 2 * (e + 1);       // along site 0 past the minimum
        g.medial_edges_[e + 1].next_sheet[1] = 2 * e + 1;     // along site 1, the other way
      }
      first_sheet[i] = 2 * first_edge, last_sheet[i] = 2 * last_edge;
      first_sheet[i + 1] = 2 * last_edge + 1, last_sheet[i + 1] = 2 * first_edge + 1;
    }
    // Across the flow line at the end of each half-edge: the next primary half-edge of the
    // same cell, or, past a secondary edge (the perpendicular at a segment's endpoint), the
    // next one of the neighbouring cell.
    for (std::size_t h = 0; h < vd.edges().size(); ++h) {
      if (last_sheet[h] == UINT32_MAX) continue;
      const BoostEdge* nh = vd.edges()[h].next();
      for (int guard = 0; guard < 4 && nh && !nh->is_primary(); ++guard) nh = nh->twin()->next();
      if (!nh || first_sheet[half_index(nh)] == UINT32_MAX) continue;
      const std::uint32_t s = last_sheet[h];
      g.medial_edges_[s / 2].next_sheet[s % 2] = first_sheet[half_index(nh)];
    }
    // Check: a sheet whose end lies off the obstacles continues into a sheet starting there.
    for (std::uint32_t e = 0; e < g.medial_edges_.size(); ++e)
      for (int s = 0; s < 2; ++s) {
        const MedialEdge& me = g.medial_edges_[e];
        const std::uint32_t end = s == 0 ? me.to : me.from;
        if (!(g.medial_vertices_[end].clearance > 2 * res)) continue;
        const std::uint32_t nx = me.next_sheet[s];
        if (nx == UINT32_MAX || (nx % 2 == 0 ? g.medial_edges_[nx / 2].from : g.medial_edges_[nx / 2].to) != end)
          throw std::logic_error("gvd: the medial axis sheet of " + site_name(me.sites[s]) + " ending at " + format_point(g.medial_vertices_[end].p) +
                                 " has no successor (Boost.Polygon's output is incomplete)");
      }
  }

  // ---- the grid for clearance()
  {
    const double w = std::max(box.xmax() - box.xmin(), 1e-300), h = std::max(box.ymax() - box.ymin(), 1e-300);
    const double cell = std::sqrt(w * h / static_cast<double>(std::max<std::size_t>(n, 1))) * 2;
    g.grid_cell_ = cell;
    g.grid_x0_ = box.xmin(), g.grid_y0_ = box.ymin();
    g.grid_nx_ = std::clamp<std::size_t>(static_cast<std::size_t>(w / cell) + 1, 1, 4096);
    g.grid_ny_ = std::clamp<std::size_t>(static_cast<std::size_t>(h / cell) + 1, 1, 4096);
    g.grid_cell_ = std::max(w / static_cast<double>(g.grid_nx_), h / static_cast<double>(g.grid_ny_)) * (1 + 1e-12);
    const std::size_t cells = g.grid_nx_ * g.grid_ny_;
    std::vector<std::uint32_t> count(cells + 1, 0);
    auto for_cells = [&](std::size_t e, auto&& f) {
      const Segment& s = g.segments_[e];
      auto ix = [&](double x) { return std::min<std::size_t>(g.grid_nx_ - 1, static_cast<std::size_t>(std::max(0.0, (x - g.grid_x0_) / g.grid_cell_))); };
      auto iy = [&](double y) { return std::min<std::size_t>(g.grid_ny_ - 1, static_cast<std::size_t>(std::max(0.0, (y - g.grid_y0_) / g.grid_cell_))); };
      const std::size_t x0 = ix(std::min(s.source().x(), s.target().x())), x1 = ix(std::max(s.source().x(), s.target().x()));
      const std::size_t y0 = iy(std::min(s.source().y(), s.target().y())), y1 = iy(std::max(s.source().y(), s.target().y()));
      for (std::size_t y = y0; y <= y1; ++y)
        for (std::size_t x = x0; x <= x1; ++x) f(y * g.grid_nx_ + x);
    };
    for (std::size_t e = 0; e < n; ++e) for_cells(e, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
    g.grid_start_ = count;
    g.grid_items_.resize(count[cells]);
    for (std::size_t e = 0; e < n; ++e) for_cells(e, [&](std::size_t c) { g.grid_items_[count[c]++] = static_cast<std::uint32_t>(e); });
  }

  // ---- checks of Boost's output
  for (const GvdVertex& v : g.vertices_) {
    const double d = g.clearance(v.p);
    if (!(std::fabs(d - v.clearance) <= 2 * res + 1e-12 * (M + v.clearance)))
      throw std::logic_error("gvd: Boost.Polygon's Voronoi vertex " + format_point(v.p) + " has clearance " + format_number(v.clearance) +
                             " to its sites but an obstacle lies at distance " + format_number(d) + " (a missing edge, cf. boostorg/polygon #43)");
  }
  if (g.num_obstacles() >= 2) {
    // Each obstacle's Voronoi region is bounded by closed curves of GVD edges: every vertex
    // has an even number of the obstacle's GVD edges, and every obstacle has some.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> parity;  // (obstacle, vertex) -> count
    std::vector<std::size_t> per_obstacle(g.num_obstacles(), 0);
    for (const GvdEdge& e : g.edges_)
      for (const GvdSite& s : e.sites) {
        ++per_obstacle[s.obstacle];
        ++parity[{s.obstacle, e.from}];
        ++parity[{s.obstacle, e.to}];
      }
    for (std::size_t o = 0; o < g.num_obstacles(); ++o)
      if (per_obstacle[o] == 0)
        throw std::logic_error("gvd: no GVD edge around " + env.ring_name(g.obstacle_rings_[o][0]) + " (Boost.Polygon's output is incomplete)");
    for (const auto& [key, count] : parity)
      if (count % 2)
        throw std::logic_error("gvd: the GVD edges around " + env.ring_name(g.obstacle_rings_[key.first][0]) + " end at " +
                               format_point(g.vertices_[key.second].p) + " (Boost.Polygon's output is incomplete, cf. boostorg/polygon #43)");
  }

  // ---- critical points of D along the GVD
  std::vector<std::vector<std::pair<std::uint32_t, int>>> incident(g.vertices_.size());  // (edge, end)
  for (std::uint32_t i = 0; i < g.edges_.size(); ++i) {
    incident[g.edges_[i].from].push_back({i, 0});
    incident[g.edges_[i].to].push_back({i, 1});
  }
  auto to_world = [&](const XY& q) { return world(q.x, q.y); };
  for (std::uint32_t i = 0; i < g.edges_.size(); ++i) {
    const EdgeShape& sh = shapes[i];
    if (sh.interior_min) {
      GvdCriticalPoint c;
      c.kind = GvdCriticalPoint::Kind::Interior;
      c.p = to_world(sh.min_point);
      c.clearance = g.edges_[i].min_clearance;
      c.edge = i;
      c.nearest[0] = to_world(sh.min_nearest[0]), c.nearest[1] = to_world(sh.min_nearest[1]);
      g.saddles_.push_back(c);
    }
  }
  // Plateaus: maximal runs of edges between parallel walls (D constant) joined at degree-2
  // vertices (a wall with collinear vertices splits one), D rising beyond both ends: the
  // saddle is the run's midpoint.
  std::vector<char> in_run(g.edges_.size(), 0);
  for (std::uint32_t i = 0; i < g.edges_.size(); ++i) {
    if (!shapes[i].plateau || in_run[i]) continue;
    in_run[i] = 1;
    // walk to one end of the run, then collect it from there in order
    std::uint32_t start = g.edges_[i].from, first = i;
    for (std::size_t guard = 0; guard <= g.edges_.size(); ++guard) {
      if (incident[start].size() != 2) break;
      const std::uint32_t j = incident[start][0].first == first ? incident[start][1].first : incident[start][0].first;
      if (!shapes[j].plateau || j == i) break;
      first = j;
      start = g.edges_[j].from == start ? g.edges_[j].to : g.edges_[j].from;
    }
    std::vector<std::uint32_t> run, chain{start};
    std::uint32_t at = start, e = first;
    for (std::size_t guard = 0; guard <= g.edges_.size(); ++guard) {
      run.push_back(e);
      in_run[e] = 1;
      at = g.edges_[e].from == at ? g.edges_[e].to : g.edges_[e].from;
      chain.push_back(at);
      if (incident[at].size() != 2) break;
      const std::uint32_t j = incident[at][0].first == e ? incident[at][1].first : incident[at][0].first;
      if (!shapes[j].plateau || j == first) break;
      e = j;
    }
    auto rises_beyond = [&](std::uint32_t v, std::uint32_t inner) {
      if (incident[v].size() != 2) return false;
      const auto& [j, k] = incident[v][0].first == inner ? incident[v][1] : incident[v][0];
      return !shapes[j].plateau && shapes[j].slope[k] == 1;
    };
    if (chain.front() == chain.back() || !rises_beyond(chain.front(), run.front()) || !rises_beyond(chain.back(), run.back())) continue;
    double total = 0;
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) total += std::hypot(g.vertices_[chain[k + 1]].p.x() - g.vertices_[chain[k]].p.x(), g.vertices_[chain[k + 1]].p.y() - g.vertices_[chain[k]].p.y());
    double left = total / 2;
    for (std::size_t k = 0; k < run.size(); ++k) {
      const Point& a = g.vertices_[chain[k]].p;
      const Point& b = g.vertices_[chain[k + 1]].p;
      const double len = std::hypot(b.x() - a.x(), b.y() - a.y());
      if (left > len && k + 1 < run.size()) {
        left -= len;
        continue;
      }
      const double t = len > 0 ? std::min(left / len, 1.0) : 0;
      GvdCriticalPoint c;
      c.kind = GvdCriticalPoint::Kind::Plateau;
      c.p = Point(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
      c.clearance = (g.edges_[run[k]].clearance_from + g.edges_[run[k]].clearance_to) / 2;
      c.edge = run[k];
      const double px = std::ldexp(c.p.x(), -g.resolution_exponent_), py = std::ldexp(c.p.y(), -g.resolution_exponent_);
      c.nearest[0] = to_world(nearest_on(edge_sites[run[k]][0], px, py));
      c.nearest[1] = to_world(nearest_on(edge_sites[run[k]][1], px, py));
      g.saddles_.push_back(c);
      break;
    }
  }
  for (std::uint32_t v = 0; v < g.vertices_.size(); ++v) {
    const auto& inc = incident[v];
    bool all_fall = !inc.empty(), all_rise = !inc.empty();
    for (const auto& [j, k] : inc) {
      all_fall = all_fall && shapes[j].slope[k] == -1;
      all_rise = all_rise && shapes[j].slope[k] == 1;
    }
    if (!all_fall && !(all_rise && inc.size() == 2)) continue;
    const double vx = std::ldexp(g.vertices_[v].p.x(), -g.resolution_exponent_), vy = std::ldexp(g.vertices_[v].p.y(), -g.resolution_exponent_);
    // the nearest points of the sites at v; the most nearly opposite pair of different obstacles
    std::vector<std::pair<XY, std::uint32_t>> near;
    for (const auto& [j, k] : inc)
      for (int s = 0; s < 2; ++s) near.push_back({nearest_on(edge_sites[j][s], vx, vy), g.edges_[j].sites[s].obstacle});
    double best = 3;
    std::size_t bi = 0, bj = 0;
    std::vector<double> angles;
    for (std::size_t p = 0; p < near.size(); ++p) {
      const double ax = vx - near[p].first.x, ay = vy - near[p].first.y, la = std::hypot(ax, ay);
      angles.push_back(std::atan2(ay, ax));
      for (std::size_t q = p + 1; q < near.size(); ++q) {
        if (near[p].second == near[q].second) continue;
        const double bx = vx - near[q].first.x, by = vy - near[q].first.y, lb = std::hypot(bx, by);
        const double cosine = la > 0 && lb > 0 ? (ax * bx + ay * by) / (la * lb) : 1;
        if (cosine < best) best = cosine, bi = p, bj = q;
      }
    }
    GvdCriticalPoint c;
    c.kind = GvdCriticalPoint::Kind::Vertex;
    c.p = g.vertices_[v].p;
    c.clearance = g.vertices_[v].clearance;
    c.vertex = v;
    c.nearest[0] = to_world(near[bi].first), c.nearest[1] = to_world(near[bj].first);
    if (all_fall) {
      g.maxima_.push_back(c);
    } else {
      // a minimum along the GVD is a saddle of D when D is critical there: the directions
      // from the nearest points do not fit in an open half-plane (largest gap <= pi)
      std::sort(angles.begin(), angles.end());
      double gap = angles.front() + 2 * std::numbers::pi - angles.back();
      for (std::size_t k = 1; k < angles.size(); ++k) gap = std::max(gap, angles[k] - angles[k - 1]);
      if (gap <= std::numbers::pi + 1e-9) g.saddles_.push_back(c);
    }
  }
  return g;
}

void GeneralizedVoronoiDiagram::to_input(const LocalFrame& frame, const Environment& env) {
  auto move = [&](Point& p) { p = frame.to_input(p); };
  for (GvdVertex& v : vertices_) move(v.p);
  for (GvdEdge& e : edges_)
    for (Point& p : e.polyline) move(p);
  for (auto* list : {&saddles_, &maxima_})
    for (GvdCriticalPoint& c : *list) move(c.p), move(c.nearest[0]), move(c.nearest[1]);
  for (MedialVertex& v : medial_vertices_) move(v.p);
  for (MedialEdge& e : medial_edges_)
    for (Point& p : e.polyline) move(p);
  for (Point& p : snapped_) move(p);
  for (std::size_t e = 0; e < segments_.size(); ++e) segments_[e] = env.edge(e);
  grid_x0_ += frame.dx(), grid_y0_ += frame.dy();
}

Point GeneralizedVoronoiDiagram::nearest_on_site(const GvdSite& s, const Point& p) const {
  const Point& a = snapped_[s.index];
  if (s.kind == GvdSite::Kind::Vertex) return a;
  const Point& b = snapped_[next_[s.index]];
  const double dx = b.x() - a.x(), dy = b.y() - a.y(), len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / len2, 0.0, 1.0) : 0.0;
  return {a.x() + t * dx, a.y() + t * dy};
}

double GeneralizedVoronoiDiagram::clearance_brute_force(const Point& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& s : segments_) best = std::min(best, gvd_detail::segment_distance(p, s));
  return best;
}

double GeneralizedVoronoiDiagram::distance_to_obstacle(const Point& p, std::size_t o) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < segments_.size(); ++e)
    if (edge_obstacle_[e] == o) best = std::min(best, gvd_detail::segment_distance(p, segments_[e]));
  return best;
}

double GeneralizedVoronoiDiagram::clearance(const Point& p) const {
  const double fx = (p.x() - grid_x0_) / grid_cell_, fy = (p.y() - grid_y0_) / grid_cell_;
  if (!(fx >= 0 && fy >= 0 && fx < static_cast<double>(grid_nx_) && fy < static_cast<double>(grid_ny_)) || grid_start_.empty())
    return clearance_brute_force(p);
  const auto cx = static_cast<std::ptrdiff_t>(fx), cy = static_cast<std::ptrdiff_t>(fy);
  const auto nx = static_cast<std::ptrdiff_t>(grid_nx_), ny = static_cast<std::ptrdiff_t>(grid_ny_);
  double best = std::numeric_limits<double>::infinity();
  for (std::ptrdiff_t r = 0;; ++r) {
    // cells at Chebyshev distance r from (cx, cy)
    for (std::ptrdiff_t y = cy - r; y <= cy + r; ++y) {
      if (y < 0 || y >= ny) continue;
      const std::ptrdiff_t step = (y == cy - r || y == cy + r) ? 1 : 2 * r;
      for (std::ptrdiff_t x = cx - r; x <= cx + r; x += std::max<std::ptrdiff_t>(step, 1)) {
        if (x < 0 || x >= nx) continue;
        const std::size_t c = static_cast<std::size_t>(y * nx + x);
        for (std::uint32_t k = grid_start_[c]; k < grid_start_[c + 1]; ++k)
          best = std::min(best, gvd_detail::segment_distance(p, segments_[grid_items_[k]]));
      }
    }
    // every cell beyond ring r is at least r cells away from p
    if (best <= static_cast<double>(r) * grid_cell_) return best;
    if (r > nx && r > ny) return best;
  }
}

std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::size_t>> GeneralizedVoronoiDiagram::obstacle_pairs() const {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> m;
  for (const GvdEdge& e : edges_) ++m[{std::min(e.sites[0].obstacle, e.sites[1].obstacle), std::max(e.sites[0].obstacle, e.sites[1].obstacle)}];
  return {m.begin(), m.end()};
}

}  // namespace preimage::geometry
