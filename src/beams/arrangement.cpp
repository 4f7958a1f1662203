// SPDX-License-Identifier: Apache-2.0
// Building the subdivision (see arrangement.hpp). Steps:
//   1. each beam resolved to an exact segment with its end attachments (boundary
//      edge, environment vertex, landmark), validated against the environment;
//   2. the segments handed to geometry::SegmentArrangement, whose contact hooks reject
//      beams that overlap, end on another beam or meet two others at one point;
//   3. beam pieces become G's edges.
#include <preimage/beams/arrangement.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
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
  void subdivide();
  void graph();

  BeamArrangement& A;
  const scene::Scene& S;
  std::vector<End> from_, to_;
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
    ok = geometry::orientation(E.exact_vertex(e.index), E.exact_vertex(E.next(e.index)), q) > 0;
  } else if (e.kind == End::AtVertex) {
    const std::size_t v = e.index;
    const int l1 = geometry::orientation(E.exact_vertex(E.prev(v)), E.exact_vertex(v), q), l2 = geometry::orientation(E.exact_vertex(v), E.exact_vertex(E.next(v)), q);
    ok = E.turn(v) > 0 ? (l1 > 0 && l2 > 0) : E.turn(v) < 0 ? (l1 > 0 || l2 > 0) : l1 > 0;
  } else {
    return;
  }
  if (!ok) fail(i, "the beam does not enter free space at " + geometry::format_point(e.p));
}

// The open segment between two ends must not meet the boundary.
void ArrangementBuilder::check_interior(std::size_t i, const End& a, const End& b) {
  const Environment& E = A.env_;
  for (std::size_t e = 0; e < E.num_vertices(); ++e) {
    const ExactPoint &s = E.exact_vertex(e), &t = E.exact_vertex(E.next(e));
    const int o1 = geometry::orientation(a.p, b.p, s), o2 = geometry::orientation(a.p, b.p, t);
    if (o1 * o2 > 0) continue;
    const int o3 = geometry::orientation(s, t, a.p), o4 = geometry::orientation(s, t, b.p);
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
      if (geometry::orientation(g.from, g.to, L) == 0 && CGAL::collinear_are_strictly_ordered_along_line(g.from, L, g.to))
        fail(i, "the beam passes through landmark '" + S.landmarks[l].label + "'");
    }
    A.beams_.push_back(std::move(g));
  }
}

// ---------------------------------------------------------------- 2. the subdivision
namespace {
// Beams must cross in pairs and may not touch otherwise (section 2): the shared
// arrangement's contact hooks throw the beam's own message.
struct BeamContacts final : geometry::ArrangementPolicy {
  std::function<void(std::size_t, const std::string&)> fail;
  std::function<std::string(std::size_t)> name;
  void contact(std::size_t i, std::size_t j, geometry::SegmentContactKind kind) const override {
    if (kind == geometry::SegmentContactKind::Overlap) fail(j, "the beam overlaps " + name(i));
    fail(i, "the beam ends on " + name(j));
  }
  void multiple(std::size_t i, std::size_t a, std::size_t b, const ExactPoint& p) const override {
    fail(i, "the beam meets " + name(a) + " and " + name(b) + " at one point " + geometry::format_point(p) + " (beams must cross in pairs)");
  }
};
}  // namespace

void ArrangementBuilder::subdivide() {
  std::vector<geometry::ArrangementSegment> segs;
  auto end_of = [](const End& e) {
    using K = geometry::SegmentEnd::Kind;
    return geometry::SegmentEnd{e.kind == End::OnEdge ? K::OnEdge : e.kind == End::AtVertex ? K::AtVertex : K::AtPoint, e.index};
  };
  for (std::size_t i = 0; i < A.beams_.size(); ++i)
    segs.push_back({A.beams_[i].from, A.beams_[i].to, end_of(from_[i]), end_of(to_[i]),
                    std::make_pair(S.beams[i].from, S.beams[i].to)});
  std::vector<ExactPoint> points;
  for (auto& l : S.landmarks) points.push_back(geometry::to_exact(l.at));
  BeamContacts contacts;
  contacts.fail = [this](std::size_t i, const std::string& what) { fail(i, what); };
  contacts.name = [this](std::size_t i) { return name(i); };
  A.arr_ = geometry::SegmentArrangement::build(A.env_, std::move(segs), points, &contacts);
  const auto& H = A.arr_.half_edges();
  A.half_edges_.clear();
  A.half_edges_.reserve(H.size());
  for (auto& h : H) A.half_edges_.push_back({h.origin, h.target, h.next, h.face, h.segment});
  A.regions_.clear();
  for (std::size_t r = 0; r < A.arr_.num_regions(); ++r) A.regions_.push_back({A.arr_.sample(r), A.arr_.region_cycles(r)});
}

// ---------------------------------------------------------------- 3. G
void ArrangementBuilder::graph() {
  const auto& H = A.half_edges_;
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
  resolve_beams();
  subdivide();
  A.vertex_obstacle_.assign(A.arr_.vertices().size(), kNone);  // crossings stay kNone
  for (std::size_t v = 0; v < A.env_.num_vertices(); ++v) {
    const std::size_t ring = A.env_.ring_of(v);
    A.vertex_obstacle_[v] = ring == 0 ? kOuter : static_cast<std::uint32_t>(ring - 1);
  }
  for (std::size_t i = 0; i < A.beams_.size(); ++i) {
    A.vertex_obstacle_[A.arr_.from_vertex(i)] = A.beams_[i].from_obstacle;
    A.vertex_obstacle_[A.arr_.to_vertex(i)] = A.beams_[i].to_obstacle;
  }
  graph();
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
  return {beam, ((h & ~1u) - arr_.segment_pieces(beam).first) / 2};
}

}  // namespace preimage::beams
