// SPDX-License-Identifier: Apache-2.0
// Building the subdivision (see segment_arrangement.hpp). Steps:
//   1. pairwise crossings by orientation tests (constructions only for real crossings),
//      sorted along each segment by their exact points; equal points on one segment are
//      one vertex (several segments through a point);
//   2. half-edges for boundary pieces and segment pieces, sorted counter-clockwise
//      around each vertex; next() = the clockwise neighbour of the twin;
//   3. boundary cycles traced and classified at their lexicographically smallest
//      vertex; each inner cycle hangs in the face hit by a leftward ray;
//   4. free faces become regions with a sample point.
// Hot loops use predicates on stored points and build few lazy-exact constructions:
// every construction is a DAG node kept alive as long as the arrangement.
#include <preimage/geometry/segment_arrangement.hpp>

#include <preimage/union_find.hpp>

#include <CGAL/Intersections_2/Line_2_Line_2.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace preimage::geometry {
namespace {

int orient(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) { return orientation(a, b, c); }

// Exactly: s is on no edge of the face, and an upward ray from s crosses the face's
// boundary an odd number of times (half-open rule in x; an edge with the face on both
// sides is met twice and cancels).
bool strictly_inside_face(const std::vector<ArrangementHalfEdge>& H, const std::vector<ExactPoint>& V,
                          std::span<const std::uint32_t> face, const ExactPoint& s) {
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

}  // namespace

class SegmentArrangementBuilder {
 public:
  SegmentArrangementBuilder(SegmentArrangement& A, const std::vector<ExactPoint>& points, const ArrangementPolicy* policy,
                            bool glue)
      : A(A), points_(points), policy_(policy), glue_(glue) {}
  void run();

 private:
  void find_crossings();
  void build_half_edges();
  void link();
  void faces();
  void regions();
  std::optional<Point> double_sample(std::span<const std::uint32_t> face) const;
  ExactPoint exact_sample(std::span<const std::uint32_t> face) const;

  SegmentArrangement& A;
  const std::vector<ExactPoint>& points_;
  const ArrangementPolicy* policy_;
  bool glue_;
  // The vertex an environment vertex's edges start from: itself, or with glue_ the
  // smallest id at its point.
  std::uint32_t glued(std::size_t v) const {
    if (!glue_) return static_cast<std::uint32_t>(v);
    std::size_t best = v;
    for (std::size_t w = A.env_.same_point_next(v); w != v; w = A.env_.same_point_next(w)) best = std::min(best, w);
    return static_cast<std::uint32_t>(best);
  }
  struct X {
    std::uint32_t vertex;
    std::uint32_t other;
  };
  std::vector<std::vector<X>> along_;  // crossings on each segment
  std::vector<std::uint32_t> cycle_of_;
  std::vector<std::uint32_t> face_he_;  // a half-edge of each face's outer cycle
  std::uint32_t unbounded_face_ = kNone;
};

// ---------------------------------------------------------------- 1. crossings
void SegmentArrangementBuilder::find_crossings() {
  const auto& S = A.segments_;
  const std::size_t m = S.size();
  along_.assign(m, {});
  std::vector<CGAL::Bbox_2> box(m);
  std::vector<ExactKernel::Line_2> carrier;
  carrier.reserve(m);
  for (std::size_t i = 0; i < m; ++i) {
    box[i] = S[i].from.bbox() + S[i].to.bbox();
    if (S[i].carrier) carrier.emplace_back(to_exact(S[i].carrier->first), to_exact(S[i].carrier->second));
    else carrier.emplace_back(S[i].from, S[i].to);
  }
  auto contact = [&](std::size_t i, std::size_t j, SegmentContactKind kind) {
    if (policy_) policy_->contact(i, j, kind);
    throw std::logic_error("segment arrangement: segments " + std::to_string(i) + " and " + std::to_string(j) +
                           " touch without crossing");
  };
  // Sort by left end of the box so each segment meets only candidates overlapping in x.
  std::vector<std::uint32_t> order(m);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return box[a].xmin() < box[b].xmin(); });
  for (std::size_t oi = 0; oi < m; ++oi) {
    const std::uint32_t i = order[oi];
    const ExactPoint &P = S[i].from, &Q = S[i].to;
    for (std::size_t oj = oi + 1; oj < m && box[order[oj]].xmin() <= box[i].xmax(); ++oj) {
      const std::uint32_t j = order[oj];
      if (box[j].ymin() > box[i].ymax() || box[j].ymax() < box[i].ymin()) continue;
      const ExactPoint &R = S[j].from, &T = S[j].to;
      const int o1 = orient(P, Q, R), o2 = orient(P, Q, T);
      if (o1 * o2 > 0) continue;
      const int o3 = orient(R, T, P), o4 = orient(R, T, Q);
      if (o3 * o4 > 0) continue;
      if (o1 == 0 && o2 == 0) {
        // Collinear: they may only share an end point, pointing away from each other.
        const bool overlap = CGAL::collinear_are_strictly_ordered_along_line(P, R, Q) ||
                             CGAL::collinear_are_strictly_ordered_along_line(P, T, Q) ||
                             CGAL::collinear_are_strictly_ordered_along_line(R, P, T) ||
                             CGAL::collinear_are_strictly_ordered_along_line(R, Q, T) || (P == R && Q == T) ||
                             (P == T && Q == R);
        if (overlap) contact(std::min(i, j), std::max(i, j), SegmentContactKind::Overlap);
        continue;
      }
      if (o1 * o2 < 0 && o3 * o4 < 0) {
        // One lazy node for the line pair and one for the point, instead of a DAG per parameter.
        const auto hit = CGAL::intersection(carrier[i], carrier[j]);
        const std::uint32_t v = static_cast<std::uint32_t>(A.vertices_.size());
        A.vertices_.push_back(*boost::get<ExactPoint>(&*hit));
        along_[i].push_back({v, j});
        along_[j].push_back({v, i});
        continue;
      }
      // They touch at an end: fine when it is a shared end, otherwise one ends on the other.
      auto shared = [&](const ExactPoint& x) { return x == P || x == Q; };
      if ((o1 == 0 && !shared(R)) || (o2 == 0 && !shared(T))) contact(j, i, SegmentContactKind::FirstEndsOnSecond);
      if ((o3 == 0 && !(P == R || P == T)) || (o4 == 0 && !(Q == R || Q == T))) contact(i, j, SegmentContactKind::FirstEndsOnSecond);
    }
  }
  // Crossings in order along each segment: all lie on its carrier, so the lexicographic
  // order of the points (reversed when the segment runs right to left) is the order.
  // Equal points are one vertex, whatever the number of segments through it.
  UnionFind same(A.vertices_.size());
  for (std::size_t i = 0; i < m; ++i) {
    auto& xs = along_[i];
    const bool forward = CGAL::compare_xy(S[i].from, S[i].to) == CGAL::SMALLER;
    const auto before = forward ? CGAL::SMALLER : CGAL::LARGER;
    std::sort(xs.begin(), xs.end(), [&](const X& a, const X& b) {
      return a.vertex != b.vertex && CGAL::compare_xy(A.vertices_[a.vertex], A.vertices_[b.vertex]) == before;
    });
    for (std::size_t k = 1; k < xs.size(); ++k)
      if (A.vertices_[xs[k].vertex] == A.vertices_[xs[k - 1].vertex]) {
        if (policy_) policy_->multiple(i, xs[k - 1].other, xs[k].other, A.vertices_[xs[k].vertex]);
        same.join(xs[k].vertex, xs[k - 1].vertex);
      }
  }
  // Renumber: environment vertices keep their ids; each crossing point gets the id of the
  // first of its copies, in creation order (pairs crossing once keep their numbering).
  const std::uint32_t nv = static_cast<std::uint32_t>(A.env_.num_vertices());
  std::vector<std::uint32_t> id(A.vertices_.size(), kNone);
  std::vector<ExactPoint> kept(A.vertices_.begin(), A.vertices_.begin() + nv);
  for (std::uint32_t v = 0; v < nv; ++v) id[v] = v;
  for (std::uint32_t v = nv; v < A.vertices_.size(); ++v) {
    const std::uint32_t root = static_cast<std::uint32_t>(same.find(v));
    if (id[root] == kNone) id[root] = static_cast<std::uint32_t>(kept.size()), kept.push_back(A.vertices_[v]);
    id[v] = id[root];
  }
  A.crossings_ = kept.size() - nv;
  A.vertices_.swap(kept);
  for (auto& xs : along_) {
    for (auto& x : xs) x.vertex = id[x.vertex];
    xs.erase(std::unique(xs.begin(), xs.end(), [](const X& a, const X& b) { return a.vertex == b.vertex; }), xs.end());
  }
}

// ---------------------------------------------------------------- 2. half-edges
void SegmentArrangementBuilder::build_half_edges() {
  const Environment& E = A.env_;
  const auto& S = A.segments_;
  // Segment ends strictly inside boundary edges, grouped per edge and sorted along it.
  struct Att { std::uint32_t edge; ExactPoint p; std::uint32_t slot; };
  std::vector<Att> att;
  std::vector<std::uint32_t> point_vertex(points_.size(), kNone);
  A.end_vertex_.assign(2 * S.size(), kNone);
  for (std::uint32_t i = 0; i < S.size(); ++i)
    for (const bool to : {false, true}) {
      const SegmentEnd& e = to ? S[i].to_end : S[i].from_end;
      const ExactPoint& p = to ? S[i].to : S[i].from;
      std::uint32_t& slot = A.end_vertex_[2 * i + (to ? 1 : 0)];
      if (e.kind == SegmentEnd::Kind::AtVertex) {
        slot = glued(e.index);
      } else if (e.kind == SegmentEnd::Kind::AtPoint) {
        if (point_vertex[e.index] == kNone) {
          point_vertex[e.index] = static_cast<std::uint32_t>(A.vertices_.size());
          A.vertices_.push_back(points_[e.index]);
        }
        slot = point_vertex[e.index];
      } else {
        att.push_back({e.index, p, 2 * i + (to ? 1 : 0)});
      }
    }
  std::sort(att.begin(), att.end(), [&](const Att& a, const Att& b) {
    if (a.edge != b.edge) return a.edge < b.edge;
    const bool forward = lex_less_xy(E.vertex(a.edge), E.vertex(E.next(a.edge)));
    const auto c = CGAL::compare_xy(a.p, b.p);
    return forward ? c == CGAL::SMALLER : c == CGAL::LARGER;
  });
  std::vector<std::vector<std::uint32_t>> on_edge(E.num_vertices());
  for (std::size_t k = 0; k < att.size(); ++k) {
    std::uint32_t v;
    if (k > 0 && att[k - 1].edge == att[k].edge && att[k - 1].p == att[k].p) {
      v = static_cast<std::uint32_t>(A.vertices_.size() - 1);  // segments sharing an end
    } else {
      v = static_cast<std::uint32_t>(A.vertices_.size());
      A.vertices_.push_back(att[k].p);
      on_edge[att[k].edge].push_back(v);
    }
    A.end_vertex_[att[k].slot] = v;
  }
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t seg) {
    A.half_edges_.push_back({a, b, kNone, kNone, seg});
    A.half_edges_.push_back({b, a, kNone, kNone, seg});
  };
  // Boundary pieces: the even half-edge runs in ring direction (free space on its left).
  A.edge_he_.assign(E.num_vertices(), kNone);
  for (std::uint32_t e = 0; e < E.num_vertices(); ++e) {
    A.edge_he_[e] = static_cast<std::uint32_t>(A.half_edges_.size());
    std::uint32_t prev = glued(e);
    for (std::uint32_t v : on_edge[e]) add(prev, v, kNone), prev = v;
    add(prev, glued(E.next(e)), kNone);
  }
  // Segment pieces: the even half-edge runs from -> to.
  for (std::uint32_t i = 0; i < S.size(); ++i) {
    A.seg_he_.push_back(static_cast<std::uint32_t>(A.half_edges_.size()));
    std::uint32_t prev = A.end_vertex_[2 * i];
    for (const X& x : along_[i]) add(prev, x.vertex, i), prev = x.vertex;
    add(prev, A.end_vertex_[2 * i + 1], i);
  }
  A.seg_he_.push_back(static_cast<std::uint32_t>(A.half_edges_.size()));
}

void SegmentArrangementBuilder::link() {
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
    std::sort(b, e, [&](std::uint32_t x, std::uint32_t y) { return ccw_less(c, A.vertices_[H[x].target], A.vertices_[H[y].target]); });
    const std::size_t d = e - b;
    // Face on the left: arriving along twin(h_i), leave along the clockwise neighbour h_{i-1}.
    for (std::size_t i = 0; i < d; ++i) H[SegmentArrangement::twin(b[i])].next = b[(i + d - 1) % d];
  }
}

// ---------------------------------------------------------------- 3. faces
void SegmentArrangementBuilder::faces() {
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

// ---------------------------------------------------------------- 4. regions
// Sample points. The face lies left of each of its half-edges; from the midpoint of its
// widest (in x) half-edge go up (edge running right) or down (running left) to the
// nearest other edge of the face over that abscissa, and take the middle.
std::optional<Point> SegmentArrangementBuilder::double_sample(std::span<const std::uint32_t> face) const {
  const auto& H = A.half_edges_;
  const auto& approx_v = A.approx_;
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

ExactPoint SegmentArrangementBuilder::exact_sample(std::span<const std::uint32_t> face) const {
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

void SegmentArrangementBuilder::regions() {
  const auto& H = A.half_edges_;
  const std::size_t nf = face_he_.size() + 1;
  // Free faces: their outer cycle runs along segments or along the boundary in ring direction.
  std::vector<std::uint32_t> free_faces;
  for (std::uint32_t f = 0; f + 1 < nf; ++f) {
    const ArrangementHalfEdge& h = H[face_he_[f]];
    if (h.segment != kNone || face_he_[f] % 2 == 0) free_faces.push_back(f);
  }
  // Half-edges per face (CSR).
  std::vector<std::uint32_t> begin(nf + 1, 0), he(H.size());
  for (auto& h : H) ++begin[h.face + 1];
  for (std::size_t f = 0; f < nf; ++f) begin[f + 1] += begin[f];
  {
    std::vector<std::uint32_t> fill(begin.begin(), begin.end() - 1);
    for (std::uint32_t h = 0; h < H.size(); ++h) he[fill[H[h].face]++] = h;
  }
  std::vector<ExactPoint> sample(nf);
  std::vector<Point> sample_approx(nf);
  for (std::uint32_t f : free_faces) {
    const auto hs = std::span<const std::uint32_t>(he).subspan(begin[f], begin[f + 1] - begin[f]);
    // A point computed in doubles is kept when exact predicates confirm it lies strictly
    // inside the face; the exact construction is the fallback for slivers.
    if (auto p = double_sample(hs); p && strictly_inside_face(A.half_edges_, A.vertices_, hs, to_exact(*p))) {
      sample[f] = to_exact(*p);
      sample_approx[f] = *p;
    } else {
      sample[f] = exact_sample(hs);
      sample_approx[f] = to_double(sample[f]);
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
    A.sample_.push_back(sample[f]);
    std::vector<std::uint32_t> cyc;
    for (std::uint32_t k = begin[f]; k < begin[f + 1]; ++k) {
      A.region_he_.push_back(he[k]);
      cyc.push_back(cycle_of_[he[k]]);
    }
    // One half-edge per cycle, the outer cycle first.
    std::vector<std::uint32_t> cycles{face_he_[f]};
    std::sort(cyc.begin(), cyc.end());
    cyc.erase(std::unique(cyc.begin(), cyc.end()), cyc.end());
    for (std::uint32_t c : cyc)
      if (c != cycle_of_[face_he_[f]])
        for (std::uint32_t k = begin[f]; k < begin[f + 1]; ++k)
          if (cycle_of_[he[k]] == c) {
            cycles.push_back(he[k]);
            break;
          }
    A.cycles_.push_back(std::move(cycles));
    A.region_he_begin_.push_back(static_cast<std::uint32_t>(A.region_he_.size()));
  }
}

void SegmentArrangementBuilder::run() {
  A.vertices_.clear();
  for (std::size_t v = 0; v < A.env_.num_vertices(); ++v) A.vertices_.push_back(A.env_.exact_vertex(v));
  find_crossings();
  build_half_edges();
  // Vertex coordinates rounded from their intervals (reading x() or y() of a lazy point
  // would build DAG nodes that live as long as the arrangement).
  A.approx_.resize(A.vertices_.size());
  for (std::size_t v = 0; v < A.vertices_.size(); ++v) {
    const auto& a = A.vertices_[v].approx();
    A.approx_[v] = Point(CGAL::to_double(a.x()), CGAL::to_double(a.y()));
  }
  A.xlo_.resize(A.vertices_.size()), A.xhi_.resize(A.vertices_.size());
  for (std::size_t v = 0; v < A.vertices_.size(); ++v) {
    const auto x = A.vertices_[v].approx().x();
    A.xlo_[v] = x.inf(), A.xhi_[v] = x.sup();
  }
  link();
  faces();
  regions();
}

SegmentArrangement SegmentArrangement::build(Environment env, std::vector<ArrangementSegment> segments,
                                             const std::vector<ExactPoint>& points, const ArrangementPolicy* policy,
                                             bool glue_contacts) {
  SegmentArrangement A;
  A.env_ = std::move(env);
  A.segments_ = std::move(segments);
  SegmentArrangementBuilder(A, points, policy, glue_contacts && A.env_.has_contacts()).run();
  return A;
}

bool SegmentArrangement::strictly_inside(std::size_t r, const ExactPoint& s) const {
  return strictly_inside_face(half_edges_, vertices_, region_half_edges(r), s);
}

std::optional<std::uint32_t> SegmentArrangement::locate(const ExactPoint& p, bool closed) const {
  // Straight up from p: the lowest edge above decides the face (face below a
  // right-to-left half-edge); at a vertex, the wedge holding the direction south.
  const auto& H = half_edges_;
  const auto& V = vertices_;
  auto at_vertex = [&](std::uint32_t w) {
    const ExactPoint south(V[w].x(), V[w].y() - 1);
    const std::uint32_t b = out_begin_[w], e = out_begin_[w + 1];
    std::uint32_t pick = out_[e - 1];
    for (std::uint32_t k = b; k < e; ++k)
      if (ccw_less(V[w], V[H[out_[k]].target], south)) pick = out_[k];
    return pick;
  };
  // Heights above p are compared on intervals first (built from the coordinates' own
  // intervals, no lazy construction: constructing every crossing's exact height was most of
  // the checker's point location), and exactly only where two intervals overlap.
  using I = CGAL::Interval_nt<true>;
  auto interval = [](const CGAL::Interval_nt<false>& x) { return I(x.inf(), x.sup()); };
  const I px = interval(p.approx().x()), py = interval(p.approx().y());
  struct Candidate {
    std::uint32_t a = kNone, b = kNone;  // the edge's ends, or a = the vertex and b = kNone
    std::uint32_t he = kNone;
    I y;
  };
  auto exact_y = [&](const Candidate& c) -> ExactFT {
    if (c.b == kNone) return V[c.a].y();
    const ExactPoint &a = V[c.a], &b = V[c.b];
    return a.y() + (p.x() - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
  };
  std::optional<Candidate> best;
  std::optional<ExactFT> best_exact;
  auto offer = [&](const Candidate& c) {
    if (best) {
      if (c.y.inf() > best->y.sup()) return;
      if (!(c.y.sup() < best->y.inf())) {
        if (!best_exact) best_exact = exact_y(*best);
        ExactFT e = exact_y(c);
        if (!(e < *best_exact)) return;
        best = c, best_exact = std::move(e);
        return;
      }
    }
    best = c, best_exact.reset();
  };
  // Edges whose x-range misses p's are dropped on the coordinates' intervals (no exact
  // number is built: reading x() of a lazy point allocates, and doing that for every edge
  // was 58 % of the pursuit checker's time on an office floor); the rest compare exactly.
  const double plo = px.inf(), phi = px.sup();
  for (std::uint32_t h = 0; h < H.size(); h += 2) {
    const std::uint32_t ia = H[h].origin, ib = H[h].target;
    if (xhi_[ia] < plo && xhi_[ib] < plo) continue;
    if (xlo_[ia] > phi && xlo_[ib] > phi) continue;
    const ExactPoint &a = V[ia], &b = V[ib];
    const auto ca = CGAL::compare_x(a, p), cb = CGAL::compare_x(b, p);
    if (ca == CGAL::SMALLER && cb == CGAL::SMALLER) continue;
    if (ca == CGAL::LARGER && cb == CGAL::LARGER) continue;
    if (orient(a, b, p) == 0 && CGAL::collinear_are_ordered_along_line(a, p, b)) {
      if (!closed || H[h].segment == kNone) return std::nullopt;
      const std::uint32_t r = region_of(h);
      return r != kNone ? std::optional<std::uint32_t>(r) : std::nullopt;
    }
    if (ca == CGAL::EQUAL || cb == CGAL::EQUAL) {
      // Vertical edge or an end on the vertical line: the lowest such end above p.
      for (std::uint32_t w : {ia, ib})
        if (CGAL::compare_x(V[w], p) == CGAL::EQUAL && CGAL::compare_y(V[w], p) == CGAL::LARGER)
          offer({w, kNone, at_vertex(w), interval(V[w].approx().y())});
      continue;
    }
    // The edge's height at p.x: above p exactly when p lies below the edge (p is not on it).
    const I ax = interval(a.approx().x()), ay = interval(a.approx().y());
    const I bx = interval(b.approx().x()), by = interval(b.approx().y());
    const Candidate c{ia, ib, a.x() > b.x() ? h : h + 1, ay + (px - ax) * (by - ay) / (bx - ax)};
    const bool above = c.y.inf() > py.sup() ? true : c.y.sup() < py.inf() ? false : exact_y(c) > p.y();
    if (above) offer(c);
  }
  if (!best) return std::nullopt;
  const std::uint32_t r = region_of(best->he);
  if (r == kNone) return std::nullopt;
  return r;
}

}  // namespace preimage::geometry
