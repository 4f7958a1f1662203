// SPDX-License-Identifier: Apache-2.0
// Building the conservative cells: critical segments -> shared segment arrangement ->
// one double sample strictly inside each (convex) cell -> V(sample) and its shadows ->
// exact transitions and crossing points on every boundary.
#include <preimage/pursuit/cells.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/geometry/visibility.hpp>

#include <cmath>
#include <stdexcept>

namespace preimage::pursuit {

using geometry::orientation;

namespace {

// Half-edges of region r's outer cycle, in order.
std::vector<std::uint32_t> outer_cycle(const geometry::SegmentArrangement& A, std::size_t r) {
  std::vector<std::uint32_t> out;
  const std::uint32_t h0 = A.region_cycles(r)[0];
  for (std::uint32_t h = h0;;) {
    out.push_back(h);
    h = A.half_edges()[h].next;
    if (h == h0) break;
  }
  return out;
}

}  // namespace

bool ConservativeCells::in_closed_cell(std::size_t c, const ExactPoint& p) const {
  const auto& A = *arr_;
  for (std::uint32_t h : A.region_half_edges(c)) {
    const auto& e = A.half_edges()[h];
    if (orientation(A.vertices()[e.origin], A.vertices()[e.target], p) < 0) return false;
  }
  return true;
}

Shadows ConservativeCells::shadows_at(const Point& p) const { return shadows_of(vis_->compute(p), pieces_); }

std::optional<std::uint32_t> ConservativeCells::locate(const Point& p) const {
  const ExactPoint q = geometry::to_exact(p);
  if (auto r = arr_->locate(q)) return *r;
  for (std::uint32_t c = 0; c < cells_.size(); ++c)
    if (in_closed_cell(c, q)) return c;
  return std::nullopt;
}

std::optional<std::vector<ConservativeCells::Crossing>> ConservativeCells::walk(const Point& p, const Point& q) const {
  const auto& A = *arr_;
  const auto& H = A.half_edges();
  const auto& V = A.vertices();
  const ExactPoint ep = geometry::to_exact(p), eq = geometry::to_exact(q);
  auto c = A.locate(ep);
  if (!c || !A.locate(eq)) return std::nullopt;
  std::vector<Crossing> out;
  for (std::size_t guard = 0; guard <= boundaries_.size() + 1; ++guard) {
    if (A.strictly_inside(*c, eq)) return out;
    // The convex cell is left by the half-edge whose origin is right of p -> q and whose
    // target is left of it.
    std::uint32_t exit = kNone;
    for (std::uint32_t h : A.region_half_edges(*c)) {
      const int oa = orientation(ep, eq, V[H[h].origin]), ob = orientation(ep, eq, V[H[h].target]);
      if (oa == 0 || ob == 0) {
        // A vertex of the convex cell ahead on the line is where the segment leaves it.
        const ExactPoint& w = oa == 0 ? V[H[h].origin] : V[H[h].target];
        if (CGAL::angle(w, ep, eq) == CGAL::ACUTE) return std::nullopt;
        continue;
      }
      if (oa < 0 && ob > 0) exit = h;
    }
    if (exit == kNone) return std::nullopt;
    // q beyond the exit edge (it is not inside this cell)?
    if (orientation(V[H[exit].origin], V[H[exit].target], eq) >= 0) return std::nullopt;
    const std::uint32_t b = boundary_of_[exit];
    if (b == kNone) return std::nullopt;  // leaves free space
    const CellBoundary& B = boundaries_[b];
    const bool rightward = *c == B.left;
    out.push_back({b, rightward});
    c = rightward ? B.right : B.left;
  }
  throw std::logic_error("pursuit: a walk through the cells does not end");
}

ConservativeCells ConservativeCells::build(const Environment& env) {
  ConservativeCells C;
  for (std::size_t v = 0; v < env.num_vertices(); ++v) C.reflex_ += is_reflex_wedge(env, v);
  C.critical_ = critical_segments(env);
  std::vector<geometry::ArrangementSegment> segs;
  segs.reserve(C.critical_.size());
  for (const auto& s : C.critical_)
    segs.push_back({s.from, s.to, {geometry::SegmentEnd::Kind::AtVertex, s.origin}, s.end,
                    std::make_pair(env.vertex(s.partner), env.vertex(s.origin))});
  C.arr_ = std::make_shared<geometry::SegmentArrangement>(geometry::SegmentArrangement::build(env, std::move(segs), {}, nullptr, true));
  const auto& A = *C.arr_;
  const auto& H = A.half_edges();
  const auto& V = A.vertices();
  const auto& P = A.approx_vertices();
  C.vis_ = std::make_shared<geometry::VisibilityIndex>(A.environment());
  C.pieces_ = C.vis_->triangulation().edge_pieces();

  // Cells: convex (every corner is a convex vertex, a hit, a crossing, or a sector of a
  // reflex vertex cut by its two extension rays), sampled at a double point inside.
  const std::size_t n = A.num_regions();
  C.cells_.resize(n);
  C.adjacent_.resize(n);
  for (std::size_t r = 0; r < n; ++r) {
    const auto cyc = outer_cycle(A, r);
    if (A.region_cycles(r).size() != 1) throw std::logic_error("pursuit: a conservative cell with a hole");
    Cell& cell = C.cells_[r];
    for (std::size_t k = 0; k < cyc.size(); ++k) {
      const auto& e = H[cyc[k]];
      const auto& f = H[cyc[(k + 1) % cyc.size()]];
      if (orientation(V[e.origin], V[e.target], V[f.target]) < 0)
        throw std::logic_error("pursuit: conservative cell " + std::to_string(r) + " is not convex");
      cell.polygon.push_back(P[e.origin]);
    }
    // Candidates: the vertex average, the arrangement's sample rounded, fan-triangle centroids.
    std::vector<Point> cand;
    double sx = 0, sy = 0;
    for (auto& p : cell.polygon) sx += p.x(), sy += p.y();
    cand.emplace_back(sx / cell.polygon.size(), sy / cell.polygon.size());
    cand.push_back(geometry::to_double(A.sample(r)));
    for (std::size_t k = 1; k + 1 < cell.polygon.size(); ++k) {
      const Point &a = cell.polygon[0], &b = cell.polygon[k], &c = cell.polygon[k + 1];
      cand.emplace_back((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
    }
    bool found = false;
    for (const Point& p : cand)
      if (A.strictly_inside(r, geometry::to_exact(p))) {
        cell.sample = p, found = true;
        break;
      }
    if (found) {
      cell.shadows = shadows_of(C.vis_->compute(cell.sample), C.pieces_);
    } else {
      // A cell thinner than double precision resolves (near-concurrent rays, e.g. from
      // decimal coordinates rounded to binary): its shadows from its exact sample.
      cell.sample = geometry::to_double(A.sample(r));
      cell.tiny = true;
      cell.shadows = shadows_of(C.vis_->compute(A.sample(r)), C.pieces_);
      ++C.tiny_;
    }
  }

  C.boundary_of_.assign(H.size(), kNone);
  // Boundaries: every piece of a critical segment, with the transitions both ways and a
  // pair of double points close to it on either side.
  for (std::uint32_t s = 0; s < C.critical_.size(); ++s) {
    const auto [first, last] = A.segment_pieces(s);
    const SegmentSight sight = analyse_sight(C.critical_[s]);
    for (std::uint32_t h = first; h < last; h += 2) {
      CellBoundary b;
      b.half_edge = h, b.segment = s;
      b.left = A.region_of(h), b.right = A.region_of(h + 1);
      if (b.left == kNone || b.right == kNone || b.left == b.right)
        throw std::logic_error("pursuit: a critical segment piece does not separate two cells");
      const ExactPoint &a = V[H[h].origin], &z = V[H[h].target];
      const Point pa = P[H[h].origin], pz = P[H[h].target];
      const double dx = pz.x() - pa.x(), dy = pz.y() - pa.y(), len = std::hypot(dx, dy);
      bool ok = false;
      for (double t : {0.5, 0.25, 0.75, 0.125, 0.875}) {
        if (!(len > 0)) break;  // a piece shorter than double precision resolves
        const double mx = pa.x() + t * dx, my = pa.y() + t * dy;
        for (double eta = 1e-2; eta > 1e-12 && !ok; eta /= 8) {
          const double nx = -dy * eta, ny = dx * eta;
          const Point l(mx + nx, my + ny), rt(mx - nx, my - ny);
          const ExactPoint el = geometry::to_exact(l), er = geometry::to_exact(rt);
          if (orientation(a, z, el) <= 0 || orientation(a, z, er) >= 0) continue;
          if (orientation(el, er, a) * orientation(el, er, z) >= 0) continue;  // must cross the open piece
          if (!A.strictly_inside(b.left, el) || !A.strictly_inside(b.right, er)) continue;
          b.near_left = l, b.near_right = rt, ok = true;
        }
        if (ok) break;
      }
      b.drawable = ok;  // else a piece next to a cell thinner than double precision
      b.to_right = gap_transition(sight, +1, C.cells_[b.left].shadows, C.cells_[b.right].shadows);
      // The correspondence is symmetric: the other way is its transpose.
      b.to_left = {b.to_right.after, b.to_right.before, {}};
      for (auto [x, y] : b.to_right.pairs) b.to_left.pairs.push_back({y, x});
      std::sort(b.to_left.pairs.begin(), b.to_left.pairs.end());
      C.boundary_of_[h] = C.boundary_of_[h + 1] = static_cast<std::uint32_t>(C.boundaries_.size());
      C.adjacent_[b.left].push_back(static_cast<std::uint32_t>(C.boundaries_.size()));
      C.adjacent_[b.right].push_back(static_cast<std::uint32_t>(C.boundaries_.size()));
      C.boundaries_.push_back(std::move(b));
    }
  }
  return C;
}

}  // namespace preimage::pursuit
