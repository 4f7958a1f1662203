// SPDX-License-Identifier: Apache-2.0
// The contamination checker (see checker.hpp). Between two sampled moments t1, t2 it
// overlays the free edges of both moments (shared segment arrangement): every face of
// the overlay lies in one face of each moment's own subdivision, so "a shadow region at
// t2 meets the contaminated set at t1" becomes "some face of the overlay is in both".
// Visibility of a face is decided by an exact point-in-polygon test of its sample point
// against each V; nothing here knows about gaps, cells or labels. The steps are geometry
// alone, so path segments are built on several threads (`StepSummary`) and the
// contamination is carried through them in order on the calling thread (`Contamination`).
#include <preimage/pursuit/checker.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/segment_arrangement.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/union_find.hpp>

#include "checker_internal.hpp"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

namespace preimage::pursuit {

using geometry::Environment;
using geometry::ExactFT;
using geometry::ExactKernel;
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

namespace detail {

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

}  // namespace detail

namespace {

using namespace detail;

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
// `sensor`: the range polygon's corners around the origin (CheckOptions::range), or empty.
Moment take(const Environment& env, const geometry::VisibilityIndex& vis, std::size_t waypoint, double fraction,
            std::vector<ExactPoint> at, bool exact, const std::vector<Point>& sensor, const Moment* like = nullptr) {
  Moment m{waypoint, fraction, std::move(at), {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
  if (env.has_contacts()) m.contact_seen.assign(env.num_vertices(), 0);
  auto see = [&](std::size_t v) {
    if (!env.has_contacts() || !env.is_contact(v)) return;
    if (!sensor.empty() && !in_convex(m.sensor.back(), m.sensor_boxes.back(), env.exact_vertex(static_cast<std::uint32_t>(v)))) return;
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
      if (!sensor.empty()) {
        m.sensor.push_back(like->sensor[l]);
        m.sensor_boxes.push_back(like->sensor_boxes[l]);
        m.sensor_points.push_back(like->sensor_points[l]);
      }
      continue;
    }
    if (!sensor.empty()) {
      m.sensor.emplace_back();
      m.sensor_boxes.emplace_back();
      m.sensor_points.emplace_back();
      for (const Point& c : sensor) {
        m.sensor.back().push_back(e + ExactKernel::Vector_2(c.x(), c.y()));
        m.sensor_boxes.back() += m.sensor.back().back().bbox();
      }
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
    if (!sensor.empty()) add_sensor_pieces(env, m.sensor.back(), m);
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
    if (CGAL::do_overlap(box, m.boxes[l]) && (m.sensor.empty() || in_convex(m.sensor[l], m.sensor_boxes[l], p)) && in_v(m.loops[l], p))
      return false;
  return true;
}

double face_area(const geometry::SegmentArrangement& A, std::size_t r) {
  double twice = 0;
  for (std::uint32_t h : A.region_half_edges(r)) {
    const Point &a = A.approx_vertices()[A.half_edges()[h].origin], &b = A.approx_vertices()[A.half_edges()[h].target];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return twice / 2;
}

constexpr std::uint32_t kNoClass = std::numeric_limits<std::uint32_t>::max();

// What a step from one moment to the next says about contamination, computed from the
// geometry alone so that steps can be built on several threads and the contamination
// carried through them afterwards, in order (`Contamination::advance`).
//
// The overlay's faces are grouped two ways: by the earlier moment's own subdivision (its
// "classes": joined across the later moment's free edges only) and by the later one's (its
// regions). Both groupings are intrinsic to their moment, so the regions of the later moment
// here are the classes of the same moment in the next step's overlay, where each is found
// by its stretch key (or by locating a point inside it) to carry its contamination over
// (`from_prev`).
struct StepSummary {
  std::size_t waypoint = 0;
  double fraction = 0;
  Point at0;               // the first pursuer, for "cleared at"
  bool initial = false;    // no earlier moment: every shadow region is contaminated
  bool one_to_one = true;  // every shadow region of each moment meets exactly one of the other
  // Classes of the earlier moment: hidden from every pursuer then.
  std::vector<char> hidden1;
  // The previous step's regions, each mapped to the class holding it here (kNoClass when
  // it was not located). Empty at the first step of a segment, whose previous step another
  // thread built: then the overlay is kept to locate them in.
  std::vector<std::uint32_t> from_prev;
  std::shared_ptr<const geometry::SegmentArrangement> overlay;
  std::vector<std::uint32_t> class_of_face;
  // Regions of the later moment hidden from everybody: a point strictly inside each (its
  // first face's sample), and their faces in the overlay's order.
  std::vector<ExactPoint> region_sample;
  std::vector<std::uint64_t> region_key;  // the smallest stretch key on each region's boundary
  struct Face {
    std::uint32_t region, cls;
    double area;  // from the vertices' intervals: for reports, decided by nothing
    ExactPoint sample;
  };
  std::vector<Face> faces;
  // At a waypoint drawn as a frame: the pursuers, their V and every hidden face's rings.
  bool frame = false;
  std::vector<Point> pursuers;
  std::vector<std::vector<Point>> visible;
  std::vector<std::vector<std::vector<Point>>> face_rings;
};

// A stretch of a moment's free edge, and one side of it: free edge i (its index in the
// moment), between its c-th and (c+1)-th meeting with other free edges of the same moment,
// left or right. The face of the moment's own subdivision beside the stretch is the same
// in the two overlays the moment is part of (with the moment before and the one after), so
// the key names that face in both without locating a point: every face of a moment's
// subdivision has one of its free edges on its boundary unless nobody's view is cut.
using StretchKey = std::uint64_t;
constexpr StretchKey kNoKey = std::numeric_limits<StretchKey>::max();
StretchKey stretch_key(std::uint32_t free_index, std::uint32_t meetings, bool right) {
  return (static_cast<StretchKey>(free_index) << 32) | (static_cast<StretchKey>(meetings) << 1) | (right ? 1 : 0);
}

// For every piece of the arrangement's segments that are free edges of one moment
// (`index`: the segment's index in that moment's free list, or kNoClass), calls
// visit(key, region on that side).
template <class Visit>
void stretches(const geometry::SegmentArrangement& A, const std::vector<std::uint32_t>& index, Visit&& visit) {
  const auto& H = A.half_edges();
  for (std::uint32_t s = 0; s < index.size(); ++s) {
    if (index[s] == kNoClass) continue;
    const auto [first, last] = A.segment_pieces(s);
    std::uint32_t meetings = 0;
    for (std::uint32_t h = first; h < last; h += 2) {
      if (h != first)
        for (std::uint32_t o : A.outgoing(H[h].origin)) {
          const std::uint32_t t = H[o].segment;
          if (t != geometry::kNone && t != s && index[t] != kNoClass) {
            ++meetings;
            break;
          }
        }
      visit(stretch_key(index[s], meetings, false), A.region_of(h));
      visit(stretch_key(index[s], meetings, true), A.region_of(h + 1));
    }
  }
}

// One step from `prev` (none at the first moment) to `next`. `before`: the previous step
// when this thread built it, to map its regions here.
StepSummary summarise(const Environment& env, const Moment* prev, const Moment& next, const StepSummary* before, bool frame,
                      bool locate_regions, bool limited) {
  // Overlay: both moments' free edges, equal ones merged.
  struct Item {
    FreeSeg s;
    bool in_prev;
    std::uint32_t index;  // in its moment's free list
  };
  std::vector<Item> items;
  if (prev)
    for (std::uint32_t i = 0; i < prev->free.size(); ++i) items.push_back({prev->free[i], true, i});
  for (std::uint32_t i = 0; i < next.free.size(); ++i) items.push_back({next.free[i], false, i});
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
  std::vector<std::uint32_t> prev_index, next_index;  // the segment's (smallest) index in each moment's list
  for (auto& it : items) {
    if (segs.empty() || cmp(segs.back().from, it.s.a) != CGAL::EQUAL || cmp(segs.back().to, it.s.b) != CGAL::EQUAL) {
      segs.push_back({it.s.a, it.s.b, it.s.ea, it.s.eb, it.s.carrier});
      of_prev.push_back(0), of_next.push_back(0);
      prev_index.push_back(kNoClass), next_index.push_back(kNoClass);
    }
    (it.in_prev ? of_prev : of_next).back() = 1;
    auto& index = (it.in_prev ? prev_index : next_index).back();
    index = std::min(index, it.index);
  }
  // Sensor corners in free space: isolated points, one per location (a waiting pursuer's
  // are the same in both moments).
  std::vector<ExactPoint> points;
  for (const auto& g : segs)
    for (const auto* e : {&g.from_end, &g.to_end})
      if (e->kind == geometry::SegmentEnd::Kind::AtPoint) points.push_back(e == &g.from_end ? g.from : g.to);
  if (!points.empty()) {
    auto less = [&](const ExactPoint& a, const ExactPoint& b) { return cmp(a, b) == CGAL::SMALLER; };
    std::sort(points.begin(), points.end(), less);
    points.erase(std::unique(points.begin(), points.end(), [&](const ExactPoint& a, const ExactPoint& b) { return cmp(a, b) == CGAL::EQUAL; }),
                 points.end());
    for (auto& g : segs)
      for (auto* e : {&g.from_end, &g.to_end})
        if (e->kind == geometry::SegmentEnd::Kind::AtPoint)
          e->index = static_cast<std::uint32_t>(std::lower_bound(points.begin(), points.end(), e == &g.from_end ? g.from : g.to, less) - points.begin());
  }
  auto A = std::make_shared<geometry::SegmentArrangement>(geometry::SegmentArrangement::build(env, std::move(segs), points, nullptr, true));
  const auto& H = A->half_edges();
  const std::size_t nr = A->num_regions();
  // Faces of each moment's own subdivision: join across the other moment's edges only.
  UnionFind f1(nr), f2(nr);
  for (std::uint32_t h = 0; h < H.size(); h += 2) {
    const std::uint32_t s = H[h].segment;
    if (s == geometry::kNone) continue;
    if (A->region_of(h) == geometry::kNone || A->region_of(h + 1) == geometry::kNone)
      throw std::logic_error("pursuit checker: a free edge outside free space near " +
                             geometry::format_point(A->approx_vertices()[H[h].origin]) + " (segment " +
                             geometry::format_point(geometry::to_double(A->segments()[s].from)) + " - " +
                             geometry::format_point(geometry::to_double(A->segments()[s].to)) + ", pursuer at " +
                             geometry::format_point(next.at[0]) + ")");
    if (!of_prev[s]) f1.join(A->region_of(h), A->region_of(h + 1));
    if (!of_next[s]) f2.join(A->region_of(h), A->region_of(h + 1));
  }
  // The faces meet at a contact point only there (the arrangement glues the rings): the
  // evader passes through it while nobody sees it.
  if (env.has_contacts())
    for (std::uint32_t v = 0; v < env.num_vertices(); ++v) {
      if (!env.is_contact(v)) continue;
      const std::uint32_t a = A->region_of(A->first_piece(v)), b = A->region_of(A->first_piece(env.same_point_next(v)));
      if (prev && !prev->contact_seen[v]) f1.join(a, b);
      if (!next.contact_seen[v]) f2.join(a, b);
    }
  // With a limited range a moment's own segment can have both sides hidden from everybody
  // (a sensor edge outside another pursuer's view, a free edge beyond range): it separates
  // nothing, so the faces on its sides are one shadow. (Unlimited, every free edge has V on
  // one side.)
  if (limited) {
    auto join_hidden = [&](UnionFind& f, const Moment& m, const std::vector<char>& own) {
      std::vector<signed char> root_hidden(nr, -1);
      std::vector<char> face_hidden(nr, 0);
      for (std::uint32_t r = 0; r < nr; ++r) {
        const std::uint32_t root = f.find(r);
        if (root_hidden[root] < 0) root_hidden[root] = hidden(m, A->sample(root)) ? 1 : 0;
        face_hidden[r] = static_cast<char>(root_hidden[root]);
      }
      for (std::uint32_t h = 0; h < H.size(); h += 2) {
        const std::uint32_t s = H[h].segment;
        if (s == geometry::kNone || !own[s]) continue;
        const std::uint32_t a = A->region_of(h), b = A->region_of(h + 1);
        if (face_hidden[a] && face_hidden[b]) f.join(a, b);
      }
    };
    if (prev) join_hidden(f1, *prev, of_prev);
    join_hidden(f2, next, of_next);
  }
  StepSummary out;
  out.waypoint = next.waypoint, out.fraction = next.fraction, out.at0 = next.at[0];
  out.initial = prev == nullptr;
  // Classes of the earlier moment, numbered in face order, and whether each is hidden.
  std::vector<std::uint32_t> cls(nr, kNoClass);
  std::uint32_t classes = 0;
  for (std::uint32_t r = 0; r < nr; ++r) {
    const std::uint32_t root = f1.find(r);
    if (cls[root] == kNoClass) {
      cls[root] = classes++;
      if (prev) out.hidden1.push_back(hidden(*prev, A->sample(root)));
    }
    cls[r] = cls[root];
  }
  // Regions of the later moment hidden from everybody, numbered in face order.
  std::vector<char> hidden2(nr, 0), seen(nr, 0);
  std::vector<std::uint32_t> region(nr, kNoClass);
  for (std::uint32_t r = 0; r < nr; ++r) {
    const std::uint32_t root = f2.find(r);
    if (!seen[root]) seen[root] = 1, hidden2[root] = hidden(next, A->sample(root));
    if (!hidden2[root]) continue;
    if (region[root] == kNoClass) region[root] = static_cast<std::uint32_t>(out.region_sample.size()), out.region_sample.push_back(A->sample(r));
    out.faces.push_back({region[root], cls[r], face_area(*A, r), A->sample(r)});
    if (frame) {
      std::vector<std::vector<Point>> rings;
      for (std::uint32_t h0 : A->region_cycles(r)) {
        rings.emplace_back();
        for (std::uint32_t h = h0;;) {
          rings.back().push_back(A->approx_vertices()[H[h].origin]);
          h = H[h].next;
          if (h == h0) break;
        }
      }
      out.face_rings.push_back(std::move(rings));
    }
  }
  if (prev) {
    // Which shadow regions of the two moments meet (through a face hidden at both).
    std::vector<long> partner1(classes, -1), partner2(out.region_sample.size(), -1);
    auto pair = [&](std::vector<long>& slot, std::uint32_t a, std::uint32_t b) {
      if (slot[a] == -1) slot[a] = b;
      else if (slot[a] != static_cast<long>(b)) out.one_to_one = false;
    };
    for (const auto& f : out.faces)
      if (out.hidden1[f.cls]) pair(partner1, f.cls, f.region), pair(partner2, f.region, f.cls);
    for (std::uint32_t c = 0; c < classes; ++c)
      if (out.hidden1[c] && partner1[c] == -1) out.one_to_one = false;
    for (long p : partner2)
      if (p == -1) out.one_to_one = false;
  }
  // Each hidden region's smallest stretch key, for the next step to find it by.
  out.region_key.assign(out.region_sample.size(), kNoKey);
  stretches(*A, next_index, [&](StretchKey key, std::uint32_t r) {
    if (r == geometry::kNone) return;
    const std::uint32_t root = f2.find(r);
    if (hidden2[root]) out.region_key[region[root]] = std::min(out.region_key[region[root]], key);
  });
  if (before) {
    // The previous step's regions are classes here: found by their keys, or else located.
    std::vector<std::pair<StretchKey, std::uint32_t>> keyed;
    stretches(*A, prev_index, [&](StretchKey key, std::uint32_t r) {
      if (r != geometry::kNone) keyed.emplace_back(key, cls[r]);
    });
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t i = 0; i < before->region_sample.size(); ++i) {
      const StretchKey key = before->region_key[i];
      const auto it = std::lower_bound(keyed.begin(), keyed.end(), std::make_pair(key, std::uint32_t{0}));
      if (!locate_regions && key != kNoKey && it != keyed.end() && it->first == key) {
        out.from_prev.push_back(it->second);
      } else {
        const auto r = A->locate_closed(before->region_sample[i]);
        out.from_prev.push_back(r ? cls[*r] : kNoClass);
      }
    }
  } else if (prev) {
    out.overlay = std::move(A);
    out.class_of_face = std::move(cls);
  }
  if (frame) {
    out.frame = true;
    out.pursuers = next.at;
    for (std::size_t l = 0; l < next.loops.size(); ++l) {
      out.visible.emplace_back();
      for (auto& p : next.loops[l]) out.visible.back().push_back(geometry::to_double(p));
      // With a range: V clipped by the sensor polygon, in doubles (a drawing, deciding nothing).
      if (!next.sensor.empty())
        for (std::size_t i = 0; i < next.sensor[l].size() && !out.visible.back().empty(); ++i) {
          const Point a = geometry::to_double(next.sensor[l][i]), b = geometry::to_double(next.sensor[l][(i + 1) % next.sensor[l].size()]);
          auto side = [&](const Point& x) { return (b.x() - a.x()) * (x.y() - a.y()) - (b.y() - a.y()) * (x.x() - a.x()); };
          const auto in = std::move(out.visible.back());
          auto& kept = out.visible.back();
          kept.clear();
          for (std::size_t k = 0; k < in.size(); ++k) {
            const Point &x = in[k], &y = in[(k + 1) % in.size()];
            const double sx = side(x), sy = side(y);
            if (sx >= 0) kept.push_back(x);
            if ((sx >= 0) != (sy >= 0)) {
              const double t = sx / (sx - sy);
              kept.emplace_back(x.x() + t * (y.x() - x.x()), x.y() + t * (y.y() - x.y()));
            }
          }
        }
    }
  }
  return out;
}

// The contaminated regions, carried from step to step.
struct Contamination {
  std::vector<char> region;  // per region of the last step: contaminated
  const StepSummary* last = nullptr;
  std::vector<ExactPoint> last_samples;  // its region samples (the summary is freed)
  double area = 0;
  std::vector<std::vector<std::vector<Point>>> polygons;  // contaminated faces (at a frame)
  std::optional<ExactPoint> recontaminated_at;
  std::size_t count() const { return static_cast<std::size_t>(std::count(region.begin(), region.end(), 1)); }

  // A shadow region of the later moment is contaminated iff it meets a contaminated class
  // (region) of the earlier one; a class hidden then but clean whose face it shares with a
  // contaminated region is recontaminated.
  void advance(const StepSummary& S) {
    std::vector<char> cont1(S.hidden1.size(), 0);
    if (!S.initial) {
      for (std::size_t i = 0; i < region.size(); ++i) {
        if (!region[i]) continue;
        std::uint32_t c = kNoClass;
        if (!S.from_prev.empty()) {
          c = S.from_prev[i];
        } else if (const auto r = S.overlay->locate_closed(last_samples[i])) {
          c = S.class_of_face[*r];
        }
        if (c != kNoClass) cont1[c] = 1;
      }
    }
    std::vector<char> next(S.region_sample.size(), 0);
    for (const auto& f : S.faces)
      if (S.initial || cont1[f.cls]) next[f.region] = 1;
    area = 0;
    polygons.clear();
    recontaminated_at.reset();
    for (std::size_t k = 0; k < S.faces.size(); ++k) {
      const auto& f = S.faces[k];
      if (!next[f.region]) continue;
      area += f.area;
      if (S.frame) polygons.push_back(S.face_rings[k]);
      if (!S.initial && !recontaminated_at && S.hidden1[f.cls] && !cont1[f.cls]) recontaminated_at = f.sample;
    }
    region = std::move(next);
    last_samples = S.region_sample;
  }
};

CheckResult check(const Environment& env, const ExactPaths& paths, const CheckOptions& options, bool exact) {
  const geometry::VisibilityIndex vis(env);
  const std::size_t k = paths.size(), steps = paths[0].size();
  const std::vector<Point> sensor = options.range != 0 ? range_sensor(options.range, options.range_sides) : std::vector<Point>{};
  const bool limited = !sensor.empty();
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
  auto wanted = [&](std::size_t waypoint) {
    return std::find(options.frames.begin(), options.frames.end(), waypoint) != options.frames.end();
  };

  // Segment j of the paths (waypoint j to j + 1), from the moment at waypoint j: its steps,
  // built without the contamination (and the first moment's, for segment 0). Every thread
  // gets its own copy of the paths' lazy points.
  auto segment = [&](const Environment& E, const geometry::VisibilityIndex& VI, const ExactPaths& P, std::size_t j) {
    std::vector<StepSummary> out;
    auto at_time = [&](std::size_t i, const ExactFT& f) {
      std::vector<ExactPoint> at;
      for (auto& p : P) {
        const ExactPoint &a = p[i], &b = p[std::min(i + 1, steps - 1)];
        at.push_back(f == 0 || a == b ? a : a + f * (b - a));
      }
      return at;
    };
    Moment prev = take(E, VI, j, 0, at_time(j, 0), exact, sensor);
    const StepSummary* before = nullptr;  // the last step, when built here
    if (j == 0) {
      out.push_back(summarise(E, nullptr, prev, nullptr, wanted(0), options.locate_regions, limited));
      before = &out.back();
    }
    auto commit = [&](Moment next, StepSummary S) {
      out.push_back(std::move(S));
      before = &out.back();
      prev = std::move(next);
    };
    // Along segment j from fraction f0 (the previous moment) to f1: a step whose shadow
    // regions do not meet one to one is halved, up to kRefine times. Within an interval
    // without events each region only deforms, and once the step is short against the
    // gaps between regions a region meets nothing but its own continuation; over a long
    // step "meets" can also pair a region with another one that slid into the place it
    // held (a window onto a wall, its view sliding along the wall), which read a cleared
    // region as contaminated (found on a wall-following pursuer's plan).
    std::vector<ExactFT> events;  // the event fractions of the segment (one mover)
    std::function<void(const ExactFT&, const ExactFT&, int)> along = [&](const ExactFT& f0, const ExactFT& f1, int depth) {
      const bool end = f1 >= 1;
      Moment next = take(E, VI, end ? j + 1 : j, end ? 0 : CGAL::to_double(f1), end ? at_time(j + 1, 0) : at_time(j, f1), exact, sensor, &prev);
      const bool frame = next.fraction == 0 && wanted(next.waypoint);
      StepSummary S = summarise(E, &prev, next, before, frame, options.locate_regions, limited);
      if (S.one_to_one || depth >= kRefine) return commit(std::move(next), std::move(S));
      // A step across one event (a region appearing, vanishing, splitting or merging there) is
      // never one to one: bisecting it went 24 levels deep towards the event, two steps per
      // level, which was most of the samples on office plans. The step across the event is
      // cut to the length those levels would reach at once, centred on it, and only the
      // event-free steps beside it are halved further if they slide.
      const auto in_lo = std::upper_bound(events.begin(), events.end(), f0);
      const auto in_hi = std::lower_bound(events.begin(), events.end(), f1);
      if (in_hi - in_lo == 1) {
        const ExactFT& e = *in_lo;
        const ExactFT half = (f1 - f0) * ExactFT(std::ldexp(1.0, depth - kRefine - 1));
        const ExactFT a = e - half > f0 ? e - half : (f0 + e) / 2, b = e + half < f1 ? e + half : (e + f1) / 2;
        along(f0, a, depth + 1);
        along(a, b, kRefine);
        along(b, f1, depth + 1);
        return;
      }
      const ExactFT mid = (f0 + f1) / 2;
      along(f0, mid, depth + 1);
      along(mid, f1, depth + 1);
    };
    std::vector<std::size_t> moving;
    for (std::size_t l = 0; l < k; ++l)
      if (P[l][j] != P[l][j + 1]) moving.push_back(l);
    if (moving.empty()) {
      if (wanted(j + 1)) {
        Moment next = take(E, VI, j + 1, 0, at_time(j + 1, 0), exact, sensor, &prev);
        StepSummary S = summarise(E, &prev, next, before, true, options.locate_regions, limited);
        commit(std::move(next), std::move(S));
      }
      return out;
    }
    const bool whole = options.every_critical_line;
    for (std::size_t l : moving) {
      const ExactPoint &a = P[l][j], &b = P[l][j + 1];
      for (const CriticalLine& L : lines) ray_crossings(a, b, E.exact_vertex(L.u), E.exact_vertex(L.w), L.from_u, L.from_w, whole, events);
      if (moving.size() != 1) continue;
      for (std::size_t s = 0; s < k; ++s) {
        if (s == l) continue;
        // A waiting pursuer's V: a ray of the mover's V grazing u ends at a wall point z of
        // it. An environment vertex z is on a static line already when u sees it (and the
        // ray cannot reach it otherwise): only the constructed wall points count.
        for (auto& z : whole ? prev.loops[s] : prev.ray_hits[s])
          for (std::uint32_t u : reflex)
            if (whole || tangent_at(E, u, z)) ray_crossings(a, b, E.exact_vertex(u), z, true, false, whole, events);
      }
    }
    if (limited) {
      RangeEvents re;
      for (std::size_t l : moving)
        range_events(E, P[l][j], P[l][j + 1], sensor, options.range, reflex, moving.size() == 1 ? &prev : nullptr, l, re);
      events.insert(events.end(), re.cuts.begin(), re.cuts.end());
      std::sort(events.begin(), events.end());
      separate_range_events(re, events, j);
    }
    std::sort(events.begin(), events.end());
    events.erase(std::unique(events.begin(), events.end()), events.end());
    // Sample fractions: one between every two events (within an interval the shadows only
    // deform); uniform refinement when several pursuers move together.
    std::vector<ExactFT> fr;
    std::vector<ExactFT> cuts{0};
    cuts.insert(cuts.end(), events.begin(), events.end());
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
      along(last, f, moving.size() == 1 ? 0 : kRefine);
      last = f;
    }
    return out;
  };

  // The contamination, carried through the steps in order as segments come in.
  CheckResult res;
  Contamination cont;
  bool any_contaminated = false;
  auto consume = [&](std::vector<StepSummary>& seg) {
    for (StepSummary& S : seg) {
      cont.advance(S);
      ++res.moments;
      const bool now = cont.count() > 0;
      if (S.frame) {
        CheckFrame f;
        f.waypoint = S.waypoint;
        f.pursuers = S.pursuers;
        f.visible = std::move(S.visible);
        f.contaminated = cont.polygons;
        f.regions = cont.count();
        res.frames.push_back(std::move(f));
      }
      if (S.initial) {
        if (!now) res.cleared_at = CheckResult::Moment{0, 0, S.at0};
      } else {
        if (cont.recontaminated_at && !res.first_recontamination)
          res.first_recontamination = CheckResult::Moment{S.waypoint, S.fraction, geometry::to_double_canonical(*cont.recontaminated_at)};
        if (!now && any_contaminated && !res.cleared_at) res.cleared_at = CheckResult::Moment{S.waypoint, S.fraction, S.at0};
      }
      any_contaminated = now;
    }
    seg.clear();
    seg.shrink_to_fit();
  };
  const std::size_t segments = steps - 1;
  if (segments == 0) {
    // One waypoint: the first moment only.
    ExactPaths P = paths;
    std::vector<StepSummary> seg;
    seg.push_back(summarise(env, nullptr, take(env, vis, 0, 0, [&] {
      std::vector<ExactPoint> at;
      for (auto& p : P) at.push_back(p[0]);
      return at;
    }(), exact, sensor), nullptr, wanted(0), options.locate_regions, limited));
    consume(seg);
  } else {
    // Segments are built on `threads` threads, at most `window` ahead of the one whose
    // contamination is being carried (each holds its steps' faces until then).
    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    const unsigned threads = static_cast<unsigned>(std::min<std::size_t>(options.threads ? options.threads : hw, segments));
    const std::size_t window = 64 * static_cast<std::size_t>(threads);
    std::vector<std::vector<StepSummary>> built(segments);
    std::vector<char> ready(segments, 0);
    std::size_t next_segment = 0, consumed = 0;
    bool failed = false;
    std::exception_ptr error;
    std::mutex m;
    std::condition_variable cv;
    auto work = [&] {
      try {
        // Every thread builds its own environment, index and paths: lazy exact points shared
        // between threads have their reference counts bumped by every copy (an arrangement
        // copies its environment), and two threads doing so on one cache line cost CPU.
        ExactPaths P;
        std::optional<Environment> own;
        {
          const std::lock_guard<std::mutex> lock(m);
          for (auto& p : paths) {
            P.emplace_back();
            for (auto& q : p) P.back().emplace_back(ExactFT(q.x().exact()), ExactFT(q.y().exact()));
          }
          std::vector<geometry::Ring> holes;
          for (std::size_t r = 1; r < env.num_rings(); ++r) holes.push_back(env.ring(r));
          own = Environment::make(env.ring(0), std::move(holes));
        }
        if (own->vertices() != env.vertices()) throw std::logic_error("pursuit checker: a copy of the environment renumbered its vertices");
        const geometry::VisibilityIndex own_vis(*own);
        while (true) {
          std::size_t j;
          {
            std::unique_lock<std::mutex> lock(m);
            cv.wait(lock, [&] { return failed || next_segment >= segments || next_segment < consumed + window; });
            if (failed || next_segment >= segments) return;
            j = next_segment++;
          }
          auto seg = segment(*own, own_vis, P, j);
          {
            const std::lock_guard<std::mutex> lock(m);
            built[j] = std::move(seg);
            ready[j] = 1;
          }
          cv.notify_all();
        }
      } catch (...) {
        {
          const std::lock_guard<std::mutex> lock(m);
          if (!error) error = std::current_exception();
          failed = true;
        }
        cv.notify_all();
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
    std::exception_ptr consumer_error;
    try {
      for (std::size_t j = 0; j < segments; ++j) {
        std::vector<StepSummary> seg;
        {
          std::unique_lock<std::mutex> lock(m);
          cv.wait(lock, [&] { return failed || ready[j]; });
          if (failed) break;
          seg = std::move(built[j]);
        }
        consume(seg);
        {
          const std::lock_guard<std::mutex> lock(m);
          consumed = j + 1;
        }
        cv.notify_all();
      }
    } catch (...) {
      consumer_error = std::current_exception();
      const std::lock_guard<std::mutex> lock(m);
      failed = true;  // the threads stop at their next segment
    }
    cv.notify_all();
    for (auto& th : pool) th.join();
    if (consumer_error) std::rethrow_exception(consumer_error);
    if (error) std::rethrow_exception(error);
  }
  res.cleared = cont.count() == 0;
  for (std::size_t i = 0; i < cont.region.size(); ++i)
    if (cont.region[i])
      res.contaminated_exact.push_back(cont.last_samples[i]), res.contaminated_at_end.push_back(geometry::to_double_canonical(cont.last_samples[i]));
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
