// SPDX-License-Identifier: Apache-2.0
// The contamination checker (see checker.hpp). Between two sampled moments t1, t2 it
// overlays the free edges of both moments (shared segment arrangement): every face of
// the overlay lies in one face of each moment's own subdivision, so "a shadow region at
// t2 meets the contaminated set at t1" becomes "some face of the overlay is in both".
// Visibility of a face is decided by an exact point-in-polygon test of its sample point
// against each V; nothing here knows about gaps, cells or labels.
#include <preimage/pursuit/checker.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/segment_arrangement.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/union_find.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>

namespace preimage::pursuit {

using geometry::Environment;
using geometry::ExactFT;
using geometry::ExactPoint;
using geometry::Point;

void validate_paths(const Environment& env, const ExactPaths& paths) {
  if (paths.empty()) throw InputError("path: no pursuer");
  for (std::size_t l = 0; l < paths.size(); ++l) {
    if (paths[l].empty()) throw InputError("path: pursuer " + std::to_string(l + 1) + " has no points");
    if (paths[l].size() != paths[0].size())
      throw InputError("path: pursuer " + std::to_string(l + 1) + " has " + std::to_string(paths[l].size()) +
                       " points, pursuer 1 has " + std::to_string(paths[0].size()) +
                       " (pursuers pass their waypoints together: repeat a point to wait)");
    for (std::size_t i = 0; i < paths[l].size(); ++i) {
      const auto loc = geometry::locate(env, paths[l][i]);
      const auto at = [&](std::size_t k) { return geometry::format_point(geometry::to_double(paths[l][k])); };
      if (!loc.in_free_space())
        throw InputError("path: pursuer " + std::to_string(l + 1) + " point " + std::to_string(i) + " " + at(i) +
                         " is not in free space (" + geometry::to_string(loc.kind) + ")");
      if (i > 0 && !geometry::visible(env, paths[l][i - 1], paths[l][i]))
        throw InputError("path: pursuer " + std::to_string(l + 1) + " segment " + std::to_string(i - 1) + " from " +
                         at(i - 1) + " to " + at(i) + " leaves free space");
    }
  }
}

ExactPaths to_exact(const Paths& paths) {
  ExactPaths out;
  for (auto& p : paths) {
    out.emplace_back();
    for (auto& q : p) out.back().push_back(geometry::to_exact(q));
  }
  return out;
}

Paths to_double(const ExactPaths& paths) {
  Paths out;
  for (auto& p : paths) {
    out.emplace_back();
    for (auto& q : p) out.back().push_back(geometry::to_double(q));
  }
  return out;
}

void validate_paths(const Environment& env, const Paths& paths) { validate_paths(env, to_exact(paths)); }

namespace {

// A free edge of some V, split at environment vertices it grazes.
struct FreeSeg {
  ExactPoint a, b;
  geometry::SegmentEnd ea, eb;
  std::optional<std::pair<Point, Point>> carrier;  // input doubles on its line, when the pursuer is one
};

struct Moment {
  std::size_t waypoint;
  double fraction;
  std::vector<ExactPoint> at_exact;
  std::vector<Point> at;  // rounded
  std::vector<std::vector<ExactPoint>> loops;  // V of each pursuer, exact
  std::vector<CGAL::Bbox_2> boxes;  // per pursuer, V's box (a point outside it is not in V)
  std::vector<std::vector<ExactPoint>> ray_hits;  // per pursuer, V's constructed vertices (ends of free edges on walls)
  std::vector<FreeSeg> free;
  std::vector<std::size_t> free_begin;  // pursuer l's free edges: free[free_begin[l] .. free_begin[l + 1])
  std::vector<char> contact_seen;  // per vertex id at a contact: some pursuer sees the point
};

geometry::SegmentEnd end_of(const geometry::VisibilityPolygon& V, std::size_t i) {
  const auto& v = V.vertices[i];
  using K = geometry::VisibilityVertex::Kind;
  if (v.kind == K::EnvironmentVertex) return {geometry::SegmentEnd::Kind::AtVertex, v.vertex};
  if (v.kind == K::RayHit) return {geometry::SegmentEnd::Kind::OnEdge, v.edge};
  // The pursuer itself, on the boundary.
  if (V.location.kind == geometry::Location::Kind::AtVertex)
    return {geometry::SegmentEnd::Kind::AtVertex, static_cast<std::uint32_t>(V.location.index)};
  return {geometry::SegmentEnd::Kind::OnEdge, static_cast<std::uint32_t>(V.location.index)};
}

// V of every pursuer at one moment. With `exact`, V is computed at the exact positions
// (constructed points, e.g. on edges); otherwise at their double rounding, which is how
// double input paths are sampled (a rounded sample stays within its event interval).
// A pursuer standing where it stood at `like` (a waiting guard) keeps its V from there
// (without contacts, whose bookkeeping is per moment): two of three pursuers' Vs were
// recomputed at every sample of office 848's plan.
Moment take(const Environment& env, const geometry::VisibilityIndex& vis, std::size_t waypoint, double fraction,
            std::vector<ExactPoint> at, bool exact, const Moment* like = nullptr) {
  Moment m{waypoint, fraction, std::move(at), {}, {}, {}, {}, {}, {}, {}};
  if (env.has_contacts()) m.contact_seen.assign(env.num_vertices(), 0);
  auto see = [&](std::size_t v) {
    if (!env.has_contacts() || !env.is_contact(v)) return;
    for (std::size_t w = v;;) {
      m.contact_seen[w] = 1;
      w = env.same_point_next(w);
      if (w == v) break;
    }
  };
  for (std::size_t l = 0; l < m.at_exact.size(); ++l) {
    const ExactPoint& e = m.at_exact[l];
    // Where V is taken on a double path: rounded from the exact sample, so that it does not
    // depend on what was computed before (see to_double_canonical).
    const Point q = geometry::to_double_canonical(e);
    m.at.push_back(q);
    m.free_begin.push_back(m.free.size());
    if (like && !env.has_contacts() && like->at_exact.size() == m.at_exact.size() && like->at_exact[l] == e) {
      m.loops.push_back(like->loops[l]);
      m.boxes.push_back(like->boxes[l]);
      m.ray_hits.push_back(like->ray_hits[l]);
      m.free.insert(m.free.end(), like->free.begin() + static_cast<std::ptrdiff_t>(like->free_begin[l]),
                    like->free.begin() + static_cast<std::ptrdiff_t>(like->free_begin[l + 1]));
      continue;
    }
    // A sample of a double path on a sloping wall may round into the obstacle: take V at
    // the exact sample then (V's free edges then have no double carrier).
    const bool at_exact = exact || !vis.in_free_space(q);
    const auto V = at_exact ? vis.compute(e) : vis.compute(q);
    m.loops.push_back(V.points());
    m.boxes.emplace_back();
    for (const ExactPoint& x : m.loops.back()) m.boxes.back() += x.bbox();
    m.ray_hits.emplace_back();
    for (std::size_t i = 0; i < V.vertices.size(); ++i)
      if (V.vertices[i].kind == geometry::VisibilityVertex::Kind::RayHit) m.ray_hits.back().push_back(m.loops.back()[i]);
    for (const auto& x : V.vertices)
      if (x.kind == geometry::VisibilityVertex::Kind::EnvironmentVertex) see(x.vertex);
    if (V.location.kind == geometry::Location::Kind::AtVertex) see(V.location.index);
    const std::size_t n = V.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (V.edges[i].kind != geometry::VisibilityEdge::Kind::Free) continue;
      const ExactPoint A = m.loops.back()[i], B = m.loops.back()[(i + 1) % n];
      // Environment vertices strictly inside the free edge (a degenerate position).
      std::vector<std::pair<ExactPoint, std::uint32_t>> cuts;
      const CGAL::Bbox_2 box = A.bbox() + B.bbox();
      for (std::uint32_t v = 0; v < env.num_vertices(); ++v) {
        const Point& p = env.vertex(v);
        if (p.x() < box.xmin() || p.x() > box.xmax() || p.y() < box.ymin() || p.y() > box.ymax()) continue;
        const ExactPoint& e = env.exact_vertex(v);
        if (geometry::orientation(A, B, e) == 0 && CGAL::collinear_are_strictly_ordered_along_line(A, e, B))
          cuts.push_back({e, v}), see(v);
      }
      std::sort(cuts.begin(), cuts.end(), [&](auto& x, auto& y) {
        return CGAL::compare_distance_to_point(A, x.first, y.first) == CGAL::SMALLER;
      });
      ExactPoint from = A;
      geometry::SegmentEnd from_end = end_of(V, i);
      const Point carrier_q = env.vertex(V.edges[i].reflex);
      // Pieces between consecutive contacts; a piece running along an edge (the pursuer in
      // line with it) lies on the boundary and separates nothing.
      auto add = [&](const ExactPoint& to, geometry::SegmentEnd to_end) {
        using K = geometry::SegmentEnd::Kind;
        const bool along = from_end.kind == K::AtVertex && to_end.kind == K::AtVertex &&
                           (env.edge_between(from_end.index, to_end.index) != SIZE_MAX ||
                            env.edge_between(to_end.index, from_end.index) != SIZE_MAX);
        std::optional<std::pair<Point, Point>> carrier;
        if (!at_exact) carrier = std::make_pair(q, carrier_q);
        // A free edge of no length: V passing from one ring to another at a contact point
        // the pursuer's line of sight runs into along a wall (the pursuer at a vertex).
        const bool empty = from_end.kind == K::AtVertex && to_end.kind == K::AtVertex &&
                           env.vertex(from_end.index) == env.vertex(to_end.index);
        if (!along && !empty) m.free.push_back({from, to, from_end, to_end, carrier});
        from = to, from_end = to_end;
      };
      for (auto& [p, v] : cuts) add(p, {geometry::SegmentEnd::Kind::AtVertex, v});
      add(B, end_of(V, (i + 1) % n));
    }
  }
  m.free_begin.push_back(m.free.size());
  return m;
}

// Halvings of a step whose regions do not meet one to one (one moving pursuer).
constexpr int kRefine = 24;

bool in_v(const std::vector<ExactPoint>& loop, const ExactPoint& p) { return geometry::winding_number(loop, p) != 0; }

bool hidden(const Moment& m, const ExactPoint& p) {
  const CGAL::Bbox_2 box = p.bbox();
  for (std::size_t l = 0; l < m.loops.size(); ++l)
    if (CGAL::do_overlap(box, m.boxes[l]) && in_v(m.loops[l], p)) return false;
  return true;
}

// The contaminated set after a moment: one witness point per face of each contaminated region.
struct Contamination {
  std::vector<ExactPoint> witnesses;
  std::vector<Point> regions;  // one point per contaminated region
  std::vector<ExactPoint> exact_regions;
  double area = 0;
  bool recontaminated = false;
  Point recontaminated_at;
  std::vector<std::vector<std::vector<Point>>> polygons;  // contaminated faces as rings (when asked)
  /// Every shadow region of the previous moment meets exactly one of this moment and vice
  /// versa: the step followed each region (the only correspondence without an event).
  bool one_to_one = true;
};

double face_area(const geometry::SegmentArrangement& A, std::size_t r) {
  double twice = 0;
  for (std::uint32_t h : A.region_half_edges(r)) {
    const Point &a = A.approx_vertices()[A.half_edges()[h].origin], &b = A.approx_vertices()[A.half_edges()[h].target];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return twice / 2;
}

// One step from `prev` (contamination `cont`, or everything hidden if null) to `next`.
Contamination step(const Environment& env, const Moment* prev, const Contamination* cont, const Moment& next,
                   bool polygons = false) {
  // Overlay: both moments' free edges, equal ones merged.
  struct Item {
    FreeSeg s;
    bool in_prev;
  };
  std::vector<Item> items;
  if (prev)
    for (auto& f : prev->free) items.push_back({f, true});
  for (auto& f : next.free) items.push_back({f, false});
  // A waiting pursuer's free edges are the same lazy points in both moments (take reuses
  // its V): compare the handles first, as equal constructed points cannot be told apart by
  // their intervals and went to exact arithmetic through an exception every time.
  auto cmp = [](const ExactPoint& a, const ExactPoint& b) { return CGAL::identical(a, b) ? CGAL::EQUAL : CGAL::compare_xy(a, b); };
  for (auto& it : items)
    if (cmp(it.s.a, it.s.b) == CGAL::LARGER) std::swap(it.s.a, it.s.b), std::swap(it.s.ea, it.s.eb);
  std::sort(items.begin(), items.end(), [&](const Item& x, const Item& y) {
    const auto c = cmp(x.s.a, y.s.a);
    if (c != CGAL::EQUAL) return c == CGAL::SMALLER;
    return cmp(x.s.b, y.s.b) == CGAL::SMALLER;
  });
  std::vector<geometry::ArrangementSegment> segs;
  std::vector<char> of_prev, of_next;
  for (auto& it : items) {
    if (segs.empty() || cmp(segs.back().from, it.s.a) != CGAL::EQUAL || cmp(segs.back().to, it.s.b) != CGAL::EQUAL) {
      segs.push_back({it.s.a, it.s.b, it.s.ea, it.s.eb, it.s.carrier});
      of_prev.push_back(0), of_next.push_back(0);
    }
    (it.in_prev ? of_prev : of_next).back() = 1;
  }
  const auto A = geometry::SegmentArrangement::build(env, std::move(segs), {}, nullptr, true);
  const auto& H = A.half_edges();
  const std::size_t nr = A.num_regions();
  // Faces of each moment's own subdivision: join across the other moment's edges only.
  UnionFind f1(nr), f2(nr);
  for (std::uint32_t h = 0; h < H.size(); h += 2) {
    const std::uint32_t s = H[h].segment;
    if (s == geometry::kNone) continue;
    if (A.region_of(h) == geometry::kNone || A.region_of(h + 1) == geometry::kNone)
      throw std::logic_error("pursuit checker: a free edge outside free space near " +
                             geometry::format_point(A.approx_vertices()[H[h].origin]) + " (segment " +
                             geometry::format_point(geometry::to_double(A.segments()[s].from)) + " - " +
                             geometry::format_point(geometry::to_double(A.segments()[s].to)) + ", pursuer at " +
                             geometry::format_point(next.at[0]) + ")");
    if (!of_prev[s]) f1.join(A.region_of(h), A.region_of(h + 1));
    if (!of_next[s]) f2.join(A.region_of(h), A.region_of(h + 1));
  }
  // The faces meet at a contact point only there (the arrangement glues the rings): the
  // evader passes through it while nobody sees it.
  if (env.has_contacts())
    for (std::uint32_t v = 0; v < env.num_vertices(); ++v) {
      if (!env.is_contact(v)) continue;
      const std::uint32_t a = A.region_of(A.first_piece(v)), b = A.region_of(A.first_piece(env.same_point_next(v)));
      if (prev && !prev->contact_seen[v]) f1.join(a, b);
      if (!next.contact_seen[v]) f2.join(a, b);
    }
  // Contaminated faces of the previous moment: those holding a witness.
  std::vector<char> cont1(nr, 0), clear_shadow1(nr, 0);
  if (cont) {
    for (auto& w : cont->witnesses)
      if (auto r = A.locate_closed(w)) cont1[f1.find(*r)] = 1;
    for (std::uint32_t r = 0; r < nr; ++r) {
      const std::uint32_t root = f1.find(r);
      if (root == r && !cont1[root] && hidden(*prev, A.sample(r))) clear_shadow1[root] = 1;
    }
  }
  // Regions of the next moment hidden from everybody, and whether they meet the old set.
  std::vector<char> hidden2(nr, 0), cont2(nr, 0), seen(nr, 0);
  Contamination out;
  for (std::uint32_t r = 0; r < nr; ++r) {
    const std::uint32_t root = f2.find(r);
    if (!seen[root]) seen[root] = 1, hidden2[root] = hidden(next, A.sample(root));
  }
  for (std::uint32_t r = 0; r < nr; ++r) {
    const std::uint32_t root = f2.find(r);
    if (hidden2[root] && (!cont || cont1[f1.find(r)])) cont2[root] = 1;
  }
  if (prev) {
    // Which shadow regions of the two moments meet (through a face hidden at both).
    std::vector<char> hidden1(nr, 0), seen1(nr, 0);
    std::vector<long> partner1(nr, -1), partner2(nr, -1);
    for (std::uint32_t r = 0; r < nr; ++r) {
      const std::uint32_t root = f1.find(r);
      if (!seen1[root]) seen1[root] = 1, hidden1[root] = hidden(*prev, A.sample(root));
    }
    auto pair = [&](std::vector<long>& slot, std::uint32_t a, std::uint32_t b) {
      if (slot[a] == -1) slot[a] = b;
      else if (slot[a] != static_cast<long>(b)) out.one_to_one = false;
    };
    for (std::uint32_t r = 0; r < nr; ++r) {
      const std::uint32_t a = f1.find(r), b = f2.find(r);
      if (hidden1[a] && hidden2[b]) pair(partner1, a, b), pair(partner2, b, a);
    }
    for (std::uint32_t r = 0; r < nr; ++r) {
      if (f1.find(r) == r && hidden1[r] && partner1[r] == -1) out.one_to_one = false;
      if (f2.find(r) == r && hidden2[r] && partner2[r] == -1) out.one_to_one = false;
    }
  }
  std::vector<char> reported(nr, 0);
  for (std::uint32_t r = 0; r < nr; ++r) {
    const std::uint32_t root = f2.find(r);
    if (!cont2[root]) continue;
    out.witnesses.push_back(A.sample(r));
    out.area += face_area(A, r);
    if (polygons) {
      std::vector<std::vector<Point>> rings;
      for (std::uint32_t h0 : A.region_cycles(r)) {
        rings.emplace_back();
        for (std::uint32_t h = h0;;) {
          rings.back().push_back(A.approx_vertices()[H[h].origin]);
          h = H[h].next;
          if (h == h0) break;
        }
      }
      out.polygons.push_back(std::move(rings));
    }
    if (!reported[root]) {
      reported[root] = 1;
      out.regions.push_back(geometry::to_double(A.sample(r)));
      out.exact_regions.push_back(A.sample(r));
    }
    if (cont && clear_shadow1[f1.find(r)] && !out.recontaminated)
      out.recontaminated = true, out.recontaminated_at = geometry::to_double(A.sample(r));
  }
  return out;
}

// Is the line through reflex vertex u and point z tangent to the obstacle at u (u's
// neighbours not strictly on opposite sides of it)? Only then can a ray graze u along it.
bool tangent_at(const Environment& env, std::uint32_t u, const ExactPoint& z) {
  const ExactPoint& U = env.exact_vertex(u);
  const int sp = geometry::orientation(U, z, env.exact_vertex(static_cast<std::uint32_t>(env.prev(u))));
  const int sn = geometry::orientation(U, z, env.exact_vertex(static_cast<std::uint32_t>(env.next(u))));
  return sp * sn >= 0;
}

// The parameter in (0, 1) where segment a -> b crosses the line through p and q, if it does.
std::optional<ExactFT> crossing(const ExactPoint& ea, const ExactPoint& eb, const ExactPoint& p, const ExactPoint& q) {
  const int sa = geometry::orientation(p, q, ea), sb = geometry::orientation(p, q, eb);
  if (sa * sb >= 0) return std::nullopt;
  const auto d = q - p;
  const ExactFT ca = d.x() * (ea.y() - p.y()) - d.y() * (ea.x() - p.x());
  const ExactFT cb = d.x() * (eb.y() - p.y()) - d.y() * (eb.x() - p.x());
  return ca / (ca - cb);
}

// Where a pursuer moving on a -> b has an event on the line through p and q (4.3's critical
// rays): only on the ray from p away from q when p is a tangent reflex vertex (from_p),
// there a ray of V from the pursuer grazes p and ends at q, or the one from q away from p
// (from_q). Between p and q, or past a vertex that is not tangent, V keeps its structure,
// so a crossing there is no event: most of a corridor's lines on office floors were such.
// With `whole_line` every crossing counts (the sampling before, kept as a reference).
void ray_crossings(const ExactPoint& ea, const ExactPoint& eb, const ExactPoint& p, const ExactPoint& q, bool from_p, bool from_q,
                   bool whole_line, std::vector<ExactFT>& out) {
  if (!whole_line && !from_p && !from_q) return;
  const auto t = crossing(ea, eb, p, q);
  if (!t) return;
  if (whole_line) return out.push_back(*t);
  const auto d = q - p;
  const ExactFT along = (ea + *t * (eb - ea) - p) * d;  // < 0: beyond p; > |d|^2: beyond q
  if ((from_p && along < 0) || (from_q && along > d.squared_length())) out.push_back(*t);
}

CheckResult check(const Environment& env, const ExactPaths& paths, const CheckOptions& options, bool exact) {
  const geometry::VisibilityIndex vis(env);
  const std::size_t k = paths.size(), steps = paths[0].size();
  // Lines through a reflex vertex and a vertex it sees: where one pursuer's V changes.
  std::vector<std::uint32_t> reflex;
  for (std::uint32_t v = 0; v < env.num_vertices(); ++v)
    if (env.is_reflex(v)) reflex.push_back(v);
  struct CriticalLine {
    std::uint32_t u, w;
    bool from_u, from_w;  // its critical rays: past u away from w, past w away from u
  };
  std::vector<CriticalLine> lines;
  for (std::uint32_t u : reflex)
    for (std::uint32_t w = 0; w < env.num_vertices(); ++w)
      if (w != u && (!env.is_reflex(w) || w > u) && geometry::visible(env, env.vertex(u), env.vertex(w))) {
        const bool from_u = options.every_critical_line || tangent_at(env, u, env.exact_vertex(w));
        const bool from_w = options.every_critical_line || (env.is_reflex(w) && tangent_at(env, w, env.exact_vertex(u)));
        if (from_u || from_w) lines.push_back({u, w, from_u, from_w});
      }

  CheckResult res;
  auto at_time = [&](std::size_t j, const ExactFT& f) {
    std::vector<ExactPoint> at;
    for (auto& p : paths) {
      const ExactPoint &a = p[j], &b = p[std::min(j + 1, steps - 1)];
      at.push_back(f == 0 || a == b ? a : a + f * (b - a));
    }
    return at;
  };
  auto wanted = [&](std::size_t waypoint) {
    return std::find(options.frames.begin(), options.frames.end(), waypoint) != options.frames.end();
  };
  auto record = [&](const Moment& m, const Contamination& c) {
    CheckFrame f;
    f.waypoint = m.waypoint;
    f.pursuers = m.at;
    for (auto& loop : m.loops) {
      f.visible.emplace_back();
      for (auto& p : loop) f.visible.back().push_back(geometry::to_double(p));
    }
    f.contaminated = c.polygons;
    f.regions = c.regions.size();
    res.frames.push_back(std::move(f));
  };
  Moment prev = take(env, vis, 0, 0, at_time(0, 0), exact);
  Contamination cont = step(env, nullptr, nullptr, prev, wanted(0));
  if (wanted(0)) record(prev, cont);
  res.moments = 1;
  auto commit = [&](Moment next, Contamination c, bool frame) {
    if (frame) record(next, c);
    ++res.moments;
    if (c.recontaminated && !res.first_recontamination)
      res.first_recontamination = CheckResult::Moment{next.waypoint, next.fraction, c.recontaminated_at};
    if (c.regions.empty() && !cont.regions.empty() && !res.cleared_at)
      res.cleared_at = CheckResult::Moment{next.waypoint, next.fraction, next.at[0]};
    prev = std::move(next);
    cont = std::move(c);
  };
  auto advance = [&](Moment next) {
    const bool frame = next.fraction == 0 && wanted(next.waypoint);
    commit(next, step(env, &prev, &cont, next, frame), frame);
  };
  // Along segment j from fraction f0 (the previous moment) to f1: a step whose shadow
  // regions do not meet one to one is halved, up to kRefine times. Within an interval
  // without events each region only deforms, and once the step is short against the
  // gaps between regions a region meets nothing but its own continuation; over a long
  // step "meets" can also pair a region with another one that slid into the place it
  // held (a window onto a wall, its view sliding along the wall), which read a cleared
  // region as contaminated (found on a wall-following pursuer's plan).
  std::vector<ExactFT> events_now;  // the event fractions of the segment being sampled (one mover)
  std::function<void(std::size_t, const ExactFT&, const ExactFT&, int)> along = [&](std::size_t j, const ExactFT& f0,
                                                                                   const ExactFT& f1, int depth) {
    const bool end = f1 >= 1;
    Moment next =
        take(env, vis, end ? j + 1 : j, end ? 0 : CGAL::to_double(f1), end ? at_time(j + 1, 0) : at_time(j, f1), exact, &prev);
    const bool frame = next.fraction == 0 && wanted(next.waypoint);
    Contamination c = step(env, &prev, &cont, next, frame);
    if (c.one_to_one || depth >= kRefine) return commit(std::move(next), std::move(c), frame);
    // A step across one event (a region appearing, vanishing, splitting or merging there) is
    // never one to one: bisecting it went 24 levels deep towards the event, two steps per
    // level, which was most of the samples on office plans. The step across the event is
    // cut to the length those levels would reach at once, centred on it, and only the
    // event-free steps beside it are halved further if they slide.
    const auto in_lo = std::upper_bound(events_now.begin(), events_now.end(), f0);
    const auto in_hi = std::lower_bound(events_now.begin(), events_now.end(), f1);
    if (in_hi - in_lo == 1) {
      const ExactFT& e = *in_lo;
      const ExactFT half = (f1 - f0) * ExactFT(std::ldexp(1.0, depth - kRefine - 1));
      const ExactFT a = e - half > f0 ? e - half : (f0 + e) / 2, b = e + half < f1 ? e + half : (e + f1) / 2;
      along(j, f0, a, depth + 1);
      along(j, a, b, kRefine);
      along(j, b, f1, depth + 1);
      return;
    }
    const ExactFT mid = (f0 + f1) / 2;
    along(j, f0, mid, depth + 1);
    along(j, mid, f1, depth + 1);
  };
  if (cont.regions.empty()) res.cleared_at = CheckResult::Moment{0, 0, prev.at[0]};
  for (std::size_t j = 0; j + 1 < steps; ++j) {
    std::vector<std::size_t> moving;
    for (std::size_t l = 0; l < k; ++l)
      if (paths[l][j] != paths[l][j + 1]) moving.push_back(l);
    if (moving.empty()) {
      if (wanted(j + 1)) advance(take(env, vis, j + 1, 0, at_time(j + 1, 0), exact, &prev));
      continue;
    }
    const bool whole = options.every_critical_line;
    std::vector<ExactFT>& ev = events_now;
    ev.clear();
    for (std::size_t l : moving) {
      const ExactPoint &a = paths[l][j], &b = paths[l][j + 1];
      for (const CriticalLine& L : lines) ray_crossings(a, b, env.exact_vertex(L.u), env.exact_vertex(L.w), L.from_u, L.from_w, whole, ev);
      if (moving.size() != 1) continue;
      for (std::size_t s = 0; s < k; ++s) {
        if (s == l) continue;
        // A waiting pursuer's V: a ray of the mover's V grazing u ends at a wall point z of
        // it. An environment vertex z is on a static line already when u sees it (and the
        // ray cannot reach it otherwise): only the constructed wall points count.
        for (auto& z : whole ? prev.loops[s] : prev.ray_hits[s])
          for (std::uint32_t u : reflex)
            if (whole || tangent_at(env, u, z)) ray_crossings(a, b, env.exact_vertex(u), z, true, false, whole, ev);
      }
    }
    std::sort(ev.begin(), ev.end());
    ev.erase(std::unique(ev.begin(), ev.end()), ev.end());
    // Sample fractions: one between every two events (within an interval the shadows only
    // deform); uniform refinement when several pursuers move together.
    std::vector<ExactFT> fr;
    std::vector<ExactFT> cuts{0};
    cuts.insert(cuts.end(), ev.begin(), ev.end());
    cuts.push_back(1);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) fr.push_back((cuts[i] + cuts[i + 1]) / 2);
    if (moving.size() > 1)
      for (std::size_t s = 1; s < options.substeps; ++s) fr.push_back(ExactFT(double(s) / options.substeps));
    fr.push_back(1);
    std::sort(fr.begin(), fr.end());
    fr.erase(std::unique(fr.begin(), fr.end()), fr.end());
    ExactFT last = 0;
    for (const ExactFT& f : fr) {
      if (f <= 0) continue;
      along(j, last, f, moving.size() == 1 ? 0 : kRefine);
      last = f;
    }
  }
  res.cleared = cont.regions.empty();
  res.contaminated_at_end = cont.regions;
  res.contaminated_exact = cont.exact_regions;
  res.contaminated_area = cont.area;
  return res;
}

}  // namespace

CheckResult check_paths(const Environment& env, const Paths& paths, const CheckOptions& options) {
  validate_paths(env, paths);
  return check(env, to_exact(paths), options, false);
}

CheckResult check_exact_paths(const Environment& env, const ExactPaths& paths, const CheckOptions& options) {
  validate_paths(env, paths);
  return check(env, paths, options, true);
}

}  // namespace preimage::pursuit
