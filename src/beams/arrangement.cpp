// SPDX-License-Identifier: Apache-2.0
// Building the subdivision (see arrangement.hpp). Steps:
//   1. each beam resolved to an exact segment with its end attachments (boundary
//      edge, environment vertex, landmark), validated against the environment;
//   2. pairwise beam crossings by orientation tests (constructions only for real
//      crossings), sorted along each beam by their exact points;
//   3. half-edges for boundary pieces and beam pieces, sorted counter-clockwise
//      around each vertex; next() = the clockwise neighbour of the twin;
//   4. boundary cycles traced and classified at their lexicographically smallest
//      vertex; each inner cycle hangs in the face hit by a leftward ray;
//   5. free faces become regions with a sample point; beam pieces become G's edges.
// Hot loops use predicates on stored points and build few lazy-exact constructions:
// every construction is a DAG node kept alive as long as the arrangement.
#include <preimage/beams/arrangement.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>

#include <CGAL/Intersections_2/Line_2_Line_2.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <stdexcept>
#include <tuple>

namespace preimage::beams {
namespace {

using geometry::Environment;
using geometry::ExactFT;
using geometry::Point;
using EVector = geometry::ExactKernel::Vector_2;

int orient(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) { return geometry::orientation(a, b, c); }

std::string where(const ExactPoint& p) { return geometry::format_point(geometry::to_double(p)); }

// Where a beam end is attached.
struct End {
  enum Kind { OnEdge, AtVertex, AtLandmark } kind;
  std::uint32_t index;
  ExactPoint p;
};

}  // namespace

class ArrangementBuilder {
 public:
  ArrangementBuilder(BeamArrangement& A, const scene::Scene& s) : A(A), S(s) {}
  void run();

 private:
  std::string name(std::size_t i) const {
    return "$.beams[" + std::to_string(i) + "] ('" + S.beams[i].label + "')";
  }
  [[noreturn]] void fail(std::size_t i, const std::string& what) const { throw InputError(name(i) + ": " + what); }
  void make_box();
  std::uint32_t obstacle_of(const End& e) const {
    if (e.kind == End::AtLandmark) return e.index;
    const std::size_t ring = A.env_.ring_of(e.index);  // edge e starts at vertex e
    return ring == 0 ? kOuter : static_cast<std::uint32_t>(ring - 1);
  }
  End boundary_end(std::size_t i, const Point& p, const char* which);
  End shot_end(std::size_t i, const ExactPoint& origin, const EVector& dir);
  void check_leaves(std::size_t i, const End& e, const ExactPoint& toward);
  void check_interior(std::size_t i, const End& a, const End& b);
  void resolve_beams();
  void find_crossings();
  void build_half_edges();
  void link();
  void faces();
  void regions_and_graph();
  std::optional<Point> double_sample(std::span<const std::uint32_t> face, const std::vector<Point>& approx_v) const;
  bool strictly_inside(std::span<const std::uint32_t> face, const ExactPoint& s) const;
  ExactPoint exact_sample(std::span<const std::uint32_t> face) const;

  BeamArrangement& A;
  const scene::Scene& S;
  std::vector<End> from_, to_;
  struct X {
    std::uint32_t vertex;
    std::uint32_t other;
  };
  std::vector<std::vector<X>> along_;  // crossings on each beam
  std::vector<std::uint32_t> landmark_vertex_;
  std::vector<std::uint32_t> end_vertex_from_, end_vertex_to_;
  std::vector<std::uint32_t> cycle_of_;
  std::vector<std::uint32_t> face_he_;  // a half-edge of each face's outer cycle
  std::uint32_t unbounded_face_ = kNone;
};

// ---------------------------------------------------------------- 1. beams as segments
void ArrangementBuilder::make_box() {
  // The unbounded plane with point landmarks: a box strictly containing every
  // landmark, every beam's defining points and every crossing of the beams' carriers.
  std::vector<ExactPoint> pts;
  for (auto& l : S.landmarks) pts.push_back(geometry::to_exact(l.at));
  struct Carrier { ExactPoint p; EVector d; bool lo_inf, hi_inf; };
  std::vector<Carrier> c;
  for (auto& b : S.beams) {
    pts.push_back(geometry::to_exact(b.from));
    pts.push_back(geometry::to_exact(b.to));
    c.push_back({geometry::to_exact(b.from), geometry::to_exact(b.to) - geometry::to_exact(b.from),
                 b.shape == scene::Beam::Shape::Line, b.shape != scene::Beam::Shape::Segment});
  }
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j) {
      const ExactFT den = c[i].d.x() * c[j].d.y() - c[i].d.y() * c[j].d.x();
      if (den == 0) continue;
      const EVector w = c[j].p - c[i].p;
      const ExactFT t = (w.x() * c[j].d.y() - w.y() * c[j].d.x()) / den;
      const ExactFT u = (w.x() * c[i].d.y() - w.y() * c[i].d.x()) / den;
      auto in = [](const ExactFT& t, const Carrier& k) { return (k.lo_inf || t >= 0) && (k.hi_inf || t <= 1); };
      if (in(t, c[i]) && in(u, c[j])) pts.push_back(c[i].p + t * c[i].d);
    }
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Point q = geometry::to_double(pts[k]);
    if (k == 0 || q.x() < x0) x0 = q.x();
    if (k == 0 || q.x() > x1) x1 = q.x();
    if (k == 0 || q.y() < y0) y0 = q.y();
    if (k == 0 || q.y() > y1) y1 = q.y();
  }
  double margin = std::max({1.0, 0.1 * (x1 - x0), 0.1 * (y1 - y0)});
  for (;; margin *= 2) {
    const double bx0 = x0 - margin, bx1 = x1 + margin, by0 = y0 - margin, by1 = y1 + margin;
    bool inside = true;
    for (auto& q : pts) inside = inside && q.x() > bx0 && q.x() < bx1 && q.y() > by0 && q.y() < by1;
    if (!inside) continue;
    A.env_ = Environment::make({Point(bx0, by0), Point(bx1, by0), Point(bx1, by1), Point(bx0, by1)}, {}, "box");
    return;
  }
}

End ArrangementBuilder::boundary_end(std::size_t i, const Point& p, const char* which) {
  const auto loc = geometry::locate(A.env_, p);
  if (loc.kind == geometry::Location::Kind::OnEdge) return {End::OnEdge, static_cast<std::uint32_t>(loc.index), geometry::to_exact(p)};
  if (loc.kind == geometry::Location::Kind::AtVertex) return {End::AtVertex, static_cast<std::uint32_t>(loc.index), geometry::to_exact(p)};
  std::string what = loc.kind == geometry::Location::Kind::Interior ? "in free space"
                     : loc.kind == geometry::Location::Kind::InHole ? "inside " + A.env_.ring_name(loc.index + 1)
                                                                     : "outside the boundary";
  fail(i, std::string(which) + " " + geometry::format_point(p) + " is not on the boundary (it is " + what + ")");
}

End ArrangementBuilder::shot_end(std::size_t i, const ExactPoint& origin, const EVector& dir) {
  auto hit = geometry::shoot_ray(A.env_, origin, dir);
  if (!hit) fail(i, "the beam leaves the environment");  // cannot happen from closed free space
  if (hit->along_edge) fail(i, "the beam runs along edge " + std::to_string(A.env_.input_edge_index(hit->edge)) + " of " +
                               A.env_.ring_name(A.env_.ring_of(hit->edge)));
  if (hit->vertex) return {End::AtVertex, static_cast<std::uint32_t>(*hit->vertex), A.env_.exact_vertex(*hit->vertex)};
  return {End::OnEdge, static_cast<std::uint32_t>(hit->edge), hit->point};
}

// The beam must leave its boundary end strictly into free space.
void ArrangementBuilder::check_leaves(std::size_t i, const End& e, const ExactPoint& q) {
  const Environment& E = A.env_;
  bool ok;
  if (e.kind == End::OnEdge) {
    ok = orient(E.exact_vertex(e.index), E.exact_vertex(E.next(e.index)), q) > 0;
  } else if (e.kind == End::AtVertex) {
    const std::size_t v = e.index;
    const int l1 = orient(E.exact_vertex(E.prev(v)), E.exact_vertex(v), q), l2 = orient(E.exact_vertex(v), E.exact_vertex(E.next(v)), q);
    ok = E.turn(v) > 0 ? (l1 > 0 && l2 > 0) : E.turn(v) < 0 ? (l1 > 0 || l2 > 0) : l1 > 0;
  } else {
    return;
  }
  if (!ok) fail(i, "the beam does not enter free space at " + where(e.p));
}

// The open segment between two ends must not meet the boundary.
void ArrangementBuilder::check_interior(std::size_t i, const End& a, const End& b) {
  const Environment& E = A.env_;
  for (std::size_t e = 0; e < E.num_vertices(); ++e) {
    const ExactPoint &s = E.exact_vertex(e), &t = E.exact_vertex(E.next(e));
    const int o1 = orient(a.p, b.p, s), o2 = orient(a.p, b.p, t);
    if (o1 * o2 > 0) continue;
    const int o3 = orient(s, t, a.p), o4 = orient(s, t, b.p);
    if (o3 * o4 > 0) continue;
    // The closed segments meet. Fine only at a beam end lying on this edge, with the
    // rest of the beam off the edge's line.
    const bool a_on = o3 == 0 && (a.kind == End::OnEdge ? a.index == e : (a.index == e || a.index == E.next(e)));
    const bool b_on = o4 == 0 && (b.kind == End::OnEdge ? b.index == e : (b.index == e || b.index == E.next(e)));
    if ((a_on && o4 != 0) || (b_on && o3 != 0)) continue;
    if (o1 == 0 && o2 == 0 && !a_on && !b_on) {
      // Collinear but possibly disjoint.
      auto between = [](const ExactPoint& p, const ExactPoint& q, const ExactPoint& r) {
        return CGAL::collinear_are_ordered_along_line(p, r, q);
      };
      if (!between(a.p, b.p, s) && !between(a.p, b.p, t) && !between(s, t, a.p)) continue;
    }
    fail(i, "the beam touches edge " + std::to_string(E.input_edge_index(e)) + " of " + E.ring_name(E.ring_of(e)) +
                " (a beam's interior must lie in free space)");
  }
}

void ArrangementBuilder::resolve_beams() {
  const std::size_t m = S.beams.size();
  from_.resize(m);
  to_.resize(m);
  auto landmark_at = [&](std::size_t i, const Point& p, const char* which) -> End {
    for (std::size_t l = 0; l < S.landmarks.size(); ++l)
      if (S.landmarks[l].at == p) return {End::AtLandmark, static_cast<std::uint32_t>(l), geometry::to_exact(p)};
    fail(i, std::string(which) + " " + geometry::format_point(p) + " is not a landmark (in a scene without an environment, " +
                "segments join landmarks and rays start at one)");
  };
  for (std::size_t i = 0; i < m; ++i) {
    const scene::Beam& b = S.beams[i];
    const ExactPoint p = geometry::to_exact(b.from), q = geometry::to_exact(b.to);
    using Shape = scene::Beam::Shape;
    if (b.shape == Shape::Line) {
      const auto loc = geometry::locate(A.env_, b.from);
      if (loc.kind != geometry::Location::Kind::Interior)
        fail(i, "a line beam's \"from\" point " + geometry::format_point(b.from) + " must lie in open free space");
      from_[i] = shot_end(i, p, p - q);
      to_[i] = shot_end(i, p, q - p);
    } else if (A.unbounded_) {
      from_[i] = landmark_at(i, b.from, "from");
      to_[i] = b.shape == Shape::Segment ? landmark_at(i, b.to, "to") : shot_end(i, p, q - p);
    } else {
      from_[i] = boundary_end(i, b.from, "from");
      check_leaves(i, from_[i], q);
      if (b.shape == Shape::Ray) {
        to_[i] = shot_end(i, p, q - p);
      } else {
        to_[i] = boundary_end(i, b.to, "to");
        check_leaves(i, to_[i], p);
        check_interior(i, from_[i], to_[i]);
      }
    }
    BeamGeometry g{0, b.directed, b.shape, from_[i].p, to_[i].p};
    g.unbounded_from = A.unbounded_ && b.shape == Shape::Line;
    g.unbounded_to = A.unbounded_ && b.shape != Shape::Segment;
    g.from_obstacle = obstacle_of(from_[i]);
    g.to_obstacle = obstacle_of(to_[i]);
    if (!A.alphabet_.add(b.label, b.directed, &g.label))
      fail(i, "label '" + b.label + "' is shared by directed and undirected beams");
    // A beam must not pass through a landmark other than its own ends.
    for (std::size_t l = 0; l < A.landmarks_.size(); ++l) {
      const ExactPoint L = geometry::to_exact(A.landmarks_[l]);
      if (orient(g.from, g.to, L) == 0 && CGAL::collinear_are_strictly_ordered_along_line(g.from, L, g.to))
        fail(i, "the beam passes through landmark '" + S.landmarks[l].label + "'");
    }
    A.beams_.push_back(std::move(g));
  }
}

// ---------------------------------------------------------------- 2. crossings
void ArrangementBuilder::find_crossings() {
  const std::size_t m = A.beams_.size();
  along_.assign(m, {});
  std::vector<CGAL::Bbox_2> box(m);
  std::vector<geometry::ExactKernel::Line_2> carrier;
  for (std::size_t i = 0; i < m; ++i) {
    box[i] = A.beams_[i].from.bbox() + A.beams_[i].to.bbox();
    carrier.emplace_back(geometry::to_exact(S.beams[i].from), geometry::to_exact(S.beams[i].to));
  }
  // Sort by left end of the box so each beam meets only candidates overlapping in x.
  std::vector<std::uint32_t> order(m);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return box[a].xmin() < box[b].xmin(); });
  for (std::size_t oi = 0; oi < m; ++oi) {
    const std::uint32_t i = order[oi];
    const ExactPoint &P = A.beams_[i].from, &Q = A.beams_[i].to;
    for (std::size_t oj = oi + 1; oj < m && box[order[oj]].xmin() <= box[i].xmax(); ++oj) {
      const std::uint32_t j = order[oj];
      if (box[j].ymin() > box[i].ymax() || box[j].ymax() < box[i].ymin()) continue;
      const ExactPoint &R = A.beams_[j].from, &T = A.beams_[j].to;
      const int o1 = orient(P, Q, R), o2 = orient(P, Q, T);
      if (o1 * o2 > 0) continue;
      const int o3 = orient(R, T, P), o4 = orient(R, T, Q);
      if (o3 * o4 > 0) continue;
      const std::uint32_t a = std::min(i, j), b = std::max(i, j);
      if (o1 == 0 && o2 == 0) {
        // Collinear: they may only share an end point, pointing away from each other.
        const bool overlap = CGAL::collinear_are_strictly_ordered_along_line(P, R, Q) ||
                             CGAL::collinear_are_strictly_ordered_along_line(P, T, Q) ||
                             CGAL::collinear_are_strictly_ordered_along_line(R, P, T) ||
                             CGAL::collinear_are_strictly_ordered_along_line(R, Q, T) || (P == R && Q == T) ||
                             (P == T && Q == R);
        if (overlap) fail(b, "the beam overlaps " + name(a));
        continue;
      }
      if (o1 * o2 < 0 && o3 * o4 < 0) {
        // One lazy node for the line pair and one for the point (the carriers are
        // leaves built from the input doubles), instead of a DAG per parameter.
        const auto hit = CGAL::intersection(carrier[i], carrier[j]);
        const std::uint32_t v = static_cast<std::uint32_t>(A.vertices_.size());
        A.vertices_.push_back(*boost::get<ExactPoint>(&*hit));
        along_[i].push_back({v, j});
        along_[j].push_back({v, i});
        ++A.crossings_;
        continue;
      }
      // They touch at an end: fine when it is a shared end, otherwise one beam ends on the other.
      auto shared = [&](const ExactPoint& x) { return x == P || x == Q; };
      if ((o1 == 0 && !shared(R)) || (o2 == 0 && !shared(T))) fail(j, "the beam ends on " + name(i));
      if ((o3 == 0 && !(P == R || P == T)) || (o4 == 0 && !(Q == R || Q == T))) fail(i, "the beam ends on " + name(j));
    }
  }
  // Crossings in order along each beam: all lie on its carrier, so the lexicographic
  // order of the points (reversed when the beam runs right to left) is the order.
  for (std::size_t i = 0; i < m; ++i) {
    auto& xs = along_[i];
    const bool forward = CGAL::compare_xy(A.beams_[i].from, A.beams_[i].to) == CGAL::SMALLER;
    const auto before = forward ? CGAL::SMALLER : CGAL::LARGER;
    std::sort(xs.begin(), xs.end(), [&](const X& a, const X& b) {
      return a.vertex != b.vertex && CGAL::compare_xy(A.vertices_[a.vertex], A.vertices_[b.vertex]) == before;
    });
    for (std::size_t k = 1; k < xs.size(); ++k)
      if (A.vertices_[xs[k].vertex] == A.vertices_[xs[k - 1].vertex])
        fail(i, "the beam meets " + name(xs[k - 1].other) + " and " + name(xs[k].other) + " at one point " +
                    where(A.vertices_[xs[k].vertex]) + " (beams must cross in pairs)");
  }
}

// ---------------------------------------------------------------- 3. half-edges
void ArrangementBuilder::build_half_edges() {
  const Environment& E = A.env_;
  // Beam ends strictly inside boundary edges, grouped per edge and sorted along it.
  struct Att { std::uint32_t edge; ExactPoint p; std::uint32_t beam; bool to; };
  std::vector<Att> att;
  landmark_vertex_.assign(S.landmarks.size(), kNone);
  end_vertex_from_.assign(A.beams_.size(), kNone);
  end_vertex_to_.assign(A.beams_.size(), kNone);
  for (std::uint32_t i = 0; i < A.beams_.size(); ++i)
    for (const bool to : {false, true}) {
      const End& e = to ? to_[i] : from_[i];
      std::uint32_t& slot = to ? end_vertex_to_[i] : end_vertex_from_[i];
      if (e.kind == End::AtVertex) slot = e.index;
      else if (e.kind == End::AtLandmark) {
        if (landmark_vertex_[e.index] == kNone) {
          landmark_vertex_[e.index] = static_cast<std::uint32_t>(A.vertices_.size());
          A.vertices_.push_back(e.p);
        }
        slot = landmark_vertex_[e.index];
      } else {
        att.push_back({e.index, e.p, i, to});
      }
    }
  std::sort(att.begin(), att.end(), [&](const Att& a, const Att& b) {
    if (a.edge != b.edge) return a.edge < b.edge;
    const bool forward = geometry::lex_less_xy(E.vertex(a.edge), E.vertex(E.next(a.edge)));
    const auto c = CGAL::compare_xy(a.p, b.p);
    return forward ? c == CGAL::SMALLER : c == CGAL::LARGER;
  });
  std::vector<std::vector<std::uint32_t>> on_edge(E.num_vertices());
  for (std::size_t k = 0; k < att.size(); ++k) {
    std::uint32_t v;
    if (k > 0 && att[k - 1].edge == att[k].edge && att[k - 1].p == att[k].p) {
      v = static_cast<std::uint32_t>(A.vertices_.size() - 1);  // beams sharing an end
    } else {
      v = static_cast<std::uint32_t>(A.vertices_.size());
      A.vertices_.push_back(att[k].p);
      on_edge[att[k].edge].push_back(v);
    }
    (att[k].to ? end_vertex_to_ : end_vertex_from_)[att[k].beam] = v;
  }
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t beam) {
    A.half_edges_.push_back({a, b, kNone, kNone, beam});
    A.half_edges_.push_back({b, a, kNone, kNone, beam});
  };
  // Boundary pieces: the even half-edge runs in ring direction (free space on its left).
  for (std::uint32_t e = 0; e < E.num_vertices(); ++e) {
    std::uint32_t prev = e;
    for (std::uint32_t v : on_edge[e]) add(prev, v, kNone), prev = v;
    add(prev, static_cast<std::uint32_t>(E.next(e)), kNone);
  }
  // Beam pieces: the even half-edge runs from -> to.
  for (std::uint32_t i = 0; i < A.beams_.size(); ++i) {
    A.beam_he_.push_back(static_cast<std::uint32_t>(A.half_edges_.size()));
    std::uint32_t prev = end_vertex_from_[i];
    for (const X& x : along_[i]) add(prev, x.vertex, i), prev = x.vertex;
    add(prev, end_vertex_to_[i], i);
  }
  A.beam_he_.push_back(static_cast<std::uint32_t>(A.half_edges_.size()));
}

void ArrangementBuilder::link() {
  auto& H = A.half_edges_;
  const std::size_t nv = A.vertices_.size();
  A.out_begin_.assign(nv + 1, 0);
  for (auto& h : H) ++A.out_begin_[h.origin + 1];
  for (std::size_t v = 0; v < nv; ++v) A.out_begin_[v + 1] += A.out_begin_[v];
  A.out_.assign(H.size(), 0);
  std::vector<std::uint32_t> fill(A.out_begin_.begin(), A.out_begin_.end() - 1);
  for (std::uint32_t h = 0; h < H.size(); ++h) A.out_[fill[H[h].origin]++] = h;
  for (std::size_t v = 0; v < nv; ++v) {
    auto b = A.out_.begin() + A.out_begin_[v], e = A.out_.begin() + A.out_begin_[v + 1];
    const ExactPoint& c = A.vertices_[v];
    std::sort(b, e, [&](std::uint32_t x, std::uint32_t y) { return geometry::ccw_less(c, A.vertices_[H[x].target], A.vertices_[H[y].target]); });
    const std::size_t d = e - b;
    // Face on the left: arriving along twin(h_i), leave along the clockwise neighbour h_{i-1}.
    for (std::size_t i = 0; i < d; ++i) H[BeamArrangement::twin(b[i])].next = b[(i + d - 1) % d];
  }
}

// ---------------------------------------------------------------- 4. faces
void ArrangementBuilder::faces() {
  auto& H = A.half_edges_;
  const auto& V = A.vertices_;
  cycle_of_.assign(H.size(), kNone);
  std::vector<std::uint32_t> cycle_min;     // lexicographically smallest vertex
  std::vector<std::uint32_t> cycle_first;   // a half-edge of the cycle
  std::vector<char> outer;
  for (std::uint32_t h0 = 0; h0 < H.size(); ++h0) {
    if (cycle_of_[h0] != kNone) continue;
    const std::uint32_t c = static_cast<std::uint32_t>(cycle_first.size());
    std::uint32_t vmin = H[h0].origin;
    for (std::uint32_t h = h0; cycle_of_[h] == kNone; h = H[h].next) {
      cycle_of_[h] = c;
      // Distinct vertices are distinct points: never compare a lazy point with itself
      // (an exact tie would force the slow exact evaluation).
      if (H[h].origin != vmin && CGAL::compare_xy(V[H[h].origin], V[vmin]) == CGAL::SMALLER) vmin = H[h].origin;
    }
    // Outer (a bounded face inside it) iff at every visit of vmin the face's wedge
    // stays in the right half-plane, i.e. does not contain the direction west.
    bool is_outer = true;
    for (std::uint32_t h = h0;;) {
      if (H[h].target == vmin) {
        const std::uint32_t a = H[h].origin, b = H[H[h].next].target;
        if (a == b || orient(V[vmin], V[b], V[a]) <= 0) is_outer = false;
      }
      h = H[h].next;
      if (h == h0) break;
    }
    cycle_min.push_back(vmin);
    cycle_first.push_back(h0);
    outer.push_back(is_outer);
  }
  const std::size_t nc = cycle_first.size();
  std::vector<std::uint32_t> face(nc, kNone), parent(nc, kNone);
  std::vector<CGAL::Bbox_2> box(V.size());
  for (std::size_t v = 0; v < V.size(); ++v) box[v] = V[v].bbox();
  for (std::uint32_t c = 0; c < nc; ++c)
    if (outer[c]) face[c] = static_cast<std::uint32_t>(face_he_.size()), face_he_.push_back(cycle_first[c]);
  unbounded_face_ = static_cast<std::uint32_t>(face_he_.size());
  // Inner cycles: shoot a ray west from the cycle's leftmost vertex; the first edge hit
  // belongs to a cycle of the enclosing face (its leftmost vertex is further west).
  for (std::uint32_t c = 0; c < nc; ++c) {
    if (outer[c]) continue;
    const ExactPoint& v = V[cycle_min[c]];
    std::uint32_t best_he = kNone;
    std::optional<ExactFT> best_x;
    double best_lo = -HUGE_VAL;  // lower bound of the best hit so far (interval filter only)
    auto offer = [&](const ExactFT& x, std::uint32_t he) {
      if (!best_x || x > *best_x) best_x = x, best_he = he, best_lo = CGAL::to_interval(x).first;
    };
    auto last_out = [&](std::uint32_t w) { return A.out_[A.out_begin_[w + 1] - 1]; };  // wedge holding east
    const CGAL::Bbox_2& vb = box[cycle_min[c]];
    for (std::uint32_t h = 0; h < H.size(); h += 2) {
      // Interval pre-filter: skip edges certainly above, below, right of v, or left of the best hit.
      const CGAL::Bbox_2 &ba = box[H[h].origin], &bb = box[H[h].target];
      if ((ba.ymin() > vb.ymax() && bb.ymin() > vb.ymax()) || (ba.ymax() < vb.ymin() && bb.ymax() < vb.ymin()) ||
          (ba.xmin() > vb.xmax() && bb.xmin() > vb.xmax()) || (ba.xmax() < best_lo && bb.xmax() < best_lo))
        continue;
      const ExactPoint &a = V[H[h].origin], &b = V[H[h].target];
      if (H[h].origin == cycle_min[c] || H[h].target == cycle_min[c]) continue;
      const bool ay = a.y() == v.y(), by = b.y() == v.y();
      if (ay || by) {
        if (ay && a.x() < v.x() && (!by || a.x() > b.x())) offer(a.x(), last_out(H[h].origin));
        else if (by && b.x() < v.x()) offer(b.x(), last_out(H[h].target));
        continue;
      }
      if ((a.y() < v.y()) == (b.y() < v.y())) continue;
      if (a.x() > v.x() && b.x() > v.x()) continue;
      if (best_x && a.x() < *best_x && b.x() < *best_x) continue;
      const ExactFT x = a.x() + (v.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (x < v.x()) offer(x, a.y() > b.y() ? h : h + 1);  // the downward half-edge faces east
    }
    parent[c] = best_he == kNone ? kNone : cycle_of_[best_he];
  }
  auto resolve = [&](std::uint32_t c) {
    std::vector<std::uint32_t> chain;
    while (face[c] == kNone && parent[c] != kNone) chain.push_back(c), c = parent[c];
    const std::uint32_t f = face[c] == kNone ? unbounded_face_ : face[c];
    for (auto x : chain) face[x] = f;
    face[c] = f;
    return f;
  };
  for (std::uint32_t c = 0; c < nc; ++c) resolve(c);
  for (std::uint32_t h = 0; h < H.size(); ++h) H[h].face = face[cycle_of_[h]];
}

// ---------------------------------------------------------------- 5. regions and G
// Sample points. The face lies left of each of its half-edges; from the midpoint of its
// widest (in x) half-edge go up (edge running right) or down (running left) to the
// nearest other edge of the face over that abscissa, and take the middle.
std::optional<Point> ArrangementBuilder::double_sample(std::span<const std::uint32_t> face,
                                                       const std::vector<Point>& approx_v) const {
  const auto& H = A.half_edges_;
  std::uint32_t base = kNone;
  double width = 0;
  for (std::uint32_t h : face) {
    const double w = std::abs(approx_v[H[h].target].x() - approx_v[H[h].origin].x());
    if (w > width) width = w, base = h;
  }
  if (base == kNone) return std::nullopt;
  const Point &a = approx_v[H[base].origin], &b = approx_v[H[base].target];
  const double mx = (a.x() + b.x()) / 2, my = (a.y() + b.y()) / 2;
  const bool up = a.x() < b.x();
  double best = up ? HUGE_VAL : -HUGE_VAL;
  for (std::uint32_t h : face) {
    if (h == base) continue;
    const Point &p = approx_v[H[h].origin], &q = approx_v[H[h].target];
    const Point &lo = p.x() < q.x() ? p : q, &hi = p.x() < q.x() ? q : p;
    if (mx < lo.x() || mx > hi.x()) continue;
    const double y = lo.x() == hi.x() ? (up ? std::min(p.y(), q.y()) : std::max(p.y(), q.y()))
                                      : lo.y() + (mx - lo.x()) * (hi.y() - lo.y()) / (hi.x() - lo.x());
    if (up ? (y > my && y < best) : (y < my && y > best)) best = y;
  }
  if (!std::isfinite(best)) return std::nullopt;
  return Point(mx, (my + best) / 2);
}

// Exactly: s is on no edge of the face, and an upward ray from s crosses the face's
// boundary an odd number of times (half-open rule in x; an edge with the face on both
// sides is met twice and cancels).
bool ArrangementBuilder::strictly_inside(std::span<const std::uint32_t> face, const ExactPoint& s) const {
  const auto& H = A.half_edges_;
  const auto& V = A.vertices_;
  bool inside = false;
  for (std::uint32_t h : face) {
    const ExactPoint &p = V[H[h].origin], &q = V[H[h].target];
    const auto cp = CGAL::compare_x(p, s), cq = CGAL::compare_x(q, s);
    if (cp == cq && cp != CGAL::EQUAL) continue;  // entirely left or right of s
    const int o = orient(p, q, s);
    if (o == 0) {
      if (CGAL::collinear_are_ordered_along_line(p, s, q)) return false;
      continue;
    }
    if ((cp == CGAL::LARGER) == (cq == CGAL::LARGER)) continue;
    // One end at or left of s, the other right of it: s is below the edge iff it is
    // right of the edge directed left to right.
    if ((cp == CGAL::LARGER ? -o : o) < 0) inside = !inside;
  }
  return inside;
}

ExactPoint ArrangementBuilder::exact_sample(std::span<const std::uint32_t> face) const {
  const auto& H = A.half_edges_;
  const auto& V = A.vertices_;
  std::uint32_t base = kNone;
  double width = -1;
  for (std::uint32_t h : face) {
    const double w = std::abs(CGAL::to_double(V[H[h].target].x()) - CGAL::to_double(V[H[h].origin].x()));
    if (CGAL::compare_x(V[H[h].target], V[H[h].origin]) != CGAL::EQUAL && w > width) width = w, base = h;
  }
  const ExactPoint &a = V[H[base].origin], &b = V[H[base].target];
  const ExactPoint m = CGAL::midpoint(a, b);
  const bool up = a.x() < b.x();
  const CGAL::Bbox_2 mb = m.bbox();
  std::optional<ExactFT> best;
  for (std::uint32_t h : face) {
    if (h == base) continue;
    const CGAL::Bbox_2 bp = V[H[h].origin].bbox(), bq = V[H[h].target].bbox();
    if ((bp.xmax() < mb.xmin() && bq.xmax() < mb.xmin()) || (bp.xmin() > mb.xmax() && bq.xmin() > mb.xmax())) continue;
    if (up ? (bp.ymax() < mb.ymin() && bq.ymax() < mb.ymin()) : (bp.ymin() > mb.ymax() && bq.ymin() > mb.ymax())) continue;
    const ExactPoint &p = V[H[h].origin], &q = V[H[h].target];
    const ExactPoint &lo = p.x() < q.x() ? p : q, &hi = p.x() < q.x() ? q : p;
    if (m.x() < lo.x() || m.x() > hi.x()) continue;
    ExactFT y;
    if (lo.x() == hi.x()) y = up ? CGAL::min(p.y(), q.y()) : CGAL::max(p.y(), q.y());
    else y = lo.y() + (m.x() - lo.x()) * (hi.y() - lo.y()) / (hi.x() - lo.x());
    if (up ? y > m.y() : y < m.y())
      if (!best || (up ? y < *best : y > *best)) best = y;
  }
  return ExactPoint(m.x(), (m.y() + *best) / 2);
}

void ArrangementBuilder::regions_and_graph() {
  const auto& H = A.half_edges_;
  const auto& V = A.vertices_;
  const std::size_t nf = face_he_.size() + 1;
  // Free faces: their outer cycle runs along beams or along the boundary in ring direction.
  std::vector<std::uint32_t> region(nf, kNone);
  std::vector<std::uint32_t> free_faces;
  for (std::uint32_t f = 0; f + 1 < nf; ++f) {
    const HalfEdge& h = H[face_he_[f]];
    if (h.beam != kNone || face_he_[f] % 2 == 0) free_faces.push_back(f);
  }
  // Half-edges per face (CSR).
  std::vector<std::uint32_t> begin(nf + 1, 0), he(H.size());
  for (auto& h : H) ++begin[h.face + 1];
  for (std::size_t f = 0; f < nf; ++f) begin[f + 1] += begin[f];
  {
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for (std::uint32_t h = 0; h < H.size(); ++h) he[fill[H[h].face]++] = h;
  }
  // Vertex coordinates rounded from their intervals (reading x() or y() of a lazy point
  // would build DAG nodes that live as long as the arrangement).
  std::vector<Point> approx_v(V.size());
  for (std::size_t v = 0; v < V.size(); ++v) {
    const auto& a = V[v].approx();
    approx_v[v] = Point(CGAL::to_double(a.x()), CGAL::to_double(a.y()));
  }
  std::vector<ExactPoint> sample(nf);
  std::vector<Point> sample_approx(nf);
  for (std::uint32_t f : free_faces) {
    const auto hs = std::span<const std::uint32_t>(he).subspan(begin[f], begin[f + 1] - begin[f]);
    // A point computed in doubles is kept when exact predicates confirm it lies strictly
    // inside the face; the exact construction is the fallback for slivers.
    if (auto p = double_sample(hs, approx_v); p && strictly_inside(hs, geometry::to_exact(*p))) {
      sample[f] = geometry::to_exact(*p);
      sample_approx[f] = *p;
    } else {
      sample[f] = exact_sample(hs);
      sample_approx[f] = geometry::to_double(sample[f]);
    }
  }
  // Regions numbered by sample point, left to right (then bottom to top). This order is
  // only a naming convention, so rounded coordinates (ties by face) decide it: no exact
  // evaluation is forced when two samples share an abscissa.
  std::vector<std::pair<double, double>> approx(nf);
  for (std::uint32_t f : free_faces) approx[f] = {sample_approx[f].x(), sample_approx[f].y()};
  std::sort(free_faces.begin(), free_faces.end(), [&](auto x, auto y) { return std::tie(approx[x], x) < std::tie(approx[y], y); });
  A.face_region_.assign(nf, kNone);
  A.region_he_begin_.assign(1, 0);
  for (std::uint32_t r = 0; r < free_faces.size(); ++r) {
    const std::uint32_t f = free_faces[r];
    A.face_region_[f] = r;
    Region R{sample[f], {}};
    std::vector<std::uint32_t> cyc;
    for (std::uint32_t k = begin[f]; k < begin[f + 1]; ++k) {
      A.region_he_.push_back(he[k]);
      cyc.push_back(cycle_of_[he[k]]);
    }
    // One half-edge per cycle, the outer cycle first.
    R.cycles.push_back(face_he_[f]);
    std::sort(cyc.begin(), cyc.end());
    cyc.erase(std::unique(cyc.begin(), cyc.end()), cyc.end());
    for (std::uint32_t c : cyc)
      if (c != cycle_of_[face_he_[f]])
        for (std::uint32_t k = begin[f]; k < begin[f + 1]; ++k)
          if (cycle_of_[he[k]] == c) {
            R.cycles.push_back(he[k]);
            break;
          }
    A.regions_.push_back(std::move(R));
    A.region_he_begin_.push_back(static_cast<std::uint32_t>(A.region_he_.size()));
  }
  // G: crossing a beam piece from its right (odd half-edge's face) to its left (even's).
  std::vector<Crossing> edges;
  std::vector<filter::Transition> tr;
  for (std::uint32_t h = 0; h < H.size(); h += 2) {
    if (H[h].beam == kNone) continue;
    const BeamGeometry& b = A.beams_[H[h].beam];
    const std::uint32_t L = A.region_of(h), R = A.region_of(h + 1);
    if (L == kNone || R == kNone) throw std::logic_error("beam piece outside free space");
    const Symbol pos = Alphabet::positive(b.label), neg = b.directed ? Alphabet::negative(b.label) : pos;
    edges.push_back({R, L, pos, h});
    edges.push_back({L, R, neg, h + 1});
  }
  std::sort(edges.begin(), edges.end(), [](const Crossing& a, const Crossing& b) {
    return std::tie(a.from, a.symbol, a.to, a.half_edge) < std::tie(b.from, b.symbol, b.to, b.half_edge);
  });
  // The multigraph keeps every piece; the transition relation keeps one transition per
  // (from, symbol, to), or region sequences would be counted once per parallel piece.
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Crossing& e = edges[i];
    if (i == 0 || e.from != edges[i - 1].from || e.symbol != edges[i - 1].symbol || e.to != edges[i - 1].to)
      tr.push_back({e.from, e.symbol, e.to});
  }
  A.edges_ = std::move(edges);
  A.graph_ = filter::TransitionSystem(A.regions_.size(), A.alphabet_.num_symbols(), std::move(tr));
}

void ArrangementBuilder::run() {
  A.unbounded_ = !S.environment;
  if (A.unbounded_) {
    for (auto& l : S.landmarks) A.landmarks_.push_back(l.at), A.landmark_labels_.push_back(l.label);
    make_box();
  } else {
    A.env_ = *S.environment;
  }
  A.vertices_.clear();
  for (std::size_t v = 0; v < A.env_.num_vertices(); ++v) A.vertices_.push_back(A.env_.exact_vertex(v));
  resolve_beams();
  find_crossings();
  build_half_edges();
  A.vertex_obstacle_.assign(A.vertices_.size(), kNone);  // crossings stay kNone
  for (std::size_t v = 0; v < A.env_.num_vertices(); ++v) {
    const std::size_t ring = A.env_.ring_of(v);
    A.vertex_obstacle_[v] = ring == 0 ? kOuter : static_cast<std::uint32_t>(ring - 1);
  }
  for (std::size_t i = 0; i < A.beams_.size(); ++i) {
    A.vertex_obstacle_[end_vertex_from_[i]] = A.beams_[i].from_obstacle;
    A.vertex_obstacle_[end_vertex_to_[i]] = A.beams_[i].to_obstacle;
  }
  link();
  faces();
  regions_and_graph();
}

BeamArrangement BeamArrangement::build(const scene::Scene& scene) {
  BeamArrangement A;
  ArrangementBuilder(A, scene).run();
  return A;
}

std::string BeamArrangement::obstacle_name(std::uint32_t o) const {
  std::string s = std::string("o").append(std::to_string(o + 1)).append(" (");
  if (unbounded_) return s.append("landmark '").append(landmark_labels_[o]).append("')");
  return s.append(env_.ring_name(o + 1)).append(")");
}

ExactPoint BeamArrangement::obstacle_point(std::uint32_t o) const {
  if (unbounded_) return geometry::to_exact(landmarks_[o]);
  return env_.exact_vertex(env_.ring_begin(o + 1));
}

const Crossing* BeamArrangement::find_edge(std::uint32_t from, Symbol y, std::uint32_t to) const {
  auto it = std::lower_bound(edges_.begin(), edges_.end(), std::tie(from, y, to), [](const Crossing& c, const auto& k) {
    return std::tie(c.from, c.symbol, c.to) < k;
  });
  return it != edges_.end() && it->from == from && it->symbol == y && it->to == to ? &*it : nullptr;
}

BeamArrangement::Piece BeamArrangement::piece(std::uint32_t h) const {
  const std::uint32_t beam = half_edges_[h].beam;
  if (beam == kNone) throw std::invalid_argument("BeamArrangement::piece: half-edge " + std::to_string(h) + " is not on a beam");
  return {beam, ((h & ~1u) - beam_he_[beam]) / 2};
}

std::optional<std::uint32_t> BeamArrangement::locate(const ExactPoint& p) const {
  // Straight up from p: the lowest edge above decides the face (face below a
  // right-to-left half-edge); at a vertex, the wedge holding the direction south.
  const auto& H = half_edges_;
  const auto& V = vertices_;
  std::optional<ExactFT> best;
  std::uint32_t best_he = kNone;
  auto at_vertex = [&](std::uint32_t w) {
    const ExactPoint south(V[w].x(), V[w].y() - 1);
    const std::uint32_t b = out_begin_[w], e = out_begin_[w + 1];
    std::uint32_t pick = out_[e - 1];
    for (std::uint32_t k = b; k < e; ++k)
      if (geometry::ccw_less(V[w], V[H[out_[k]].target], south)) pick = out_[k];
    return pick;
  };
  auto offer = [&](const ExactFT& y, std::uint32_t he) {
    if (!best || y < *best) best = y, best_he = he;
  };
  for (std::uint32_t h = 0; h < H.size(); h += 2) {
    const ExactPoint &a = V[H[h].origin], &b = V[H[h].target];
    if (a.x() < p.x() && b.x() < p.x()) continue;
    if (a.x() > p.x() && b.x() > p.x()) continue;
    if (orient(a, b, p) == 0 && CGAL::collinear_are_ordered_along_line(a, p, b)) return std::nullopt;
    if (a.x() == p.x() || b.x() == p.x()) {
      // Vertical edge or an end on the vertical line: the lowest such end above p.
      for (std::uint32_t w : {H[h].origin, H[h].target})
        if (V[w].x() == p.x() && V[w].y() > p.y()) offer(V[w].y(), at_vertex(w));
      continue;
    }
    const ExactFT y = a.y() + (p.x() - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
    if (y > p.y()) offer(y, a.x() > b.x() ? h : h + 1);
  }
  if (best_he == kNone) return std::nullopt;
  const std::uint32_t r = region_of(best_he);
  if (r == kNone) return std::nullopt;
  return r;
}

}  // namespace preimage::beams
