// SPDX-License-Identifier: Apache-2.0
// Morse decompositions with variable slices (6.2.3); the method is described in morse.hpp.
#include <preimage/decompose/morse.hpp>

#include "cell_graph.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace preimage::decompose {

std::string_view to_string(SliceFamily f) {
  switch (f) {
    case SliceFamily::Circular: return "circular";
    case SliceFamily::Spike: return "spike";
    case SliceFamily::Squarel: return "squarel";
    case SliceFamily::Linear: return "linear";
  }
  return "?";
}

std::optional<SliceFamily> parse_slice_family(std::string_view s) {
  if (s == "circular") return SliceFamily::Circular;
  if (s == "spike") return SliceFamily::Spike;
  if (s == "squarel") return SliceFamily::Squarel;
  if (s == "linear") return SliceFamily::Linear;
  return std::nullopt;
}

namespace {

using FT = ExactFT;
constexpr double kTwoPi = 2 * std::numbers::pi;

int sgn(const FT& v) { return static_cast<int>(CGAL::sign(v)); }

// sign(P + Q sqrt(d1) + R sqrt(d2) + S sqrt(d1 d2)), by grouping U + V sqrt(d2) with U, V
// in Q(sqrt(d1)) and comparing squares when their signs differ.
int sign_two_roots(const FT& P, const FT& Q, const FT& R, const FT& S, const FT& d1, const FT& d2) {
  const int su = RootNumber{P, Q, d1}.sign(), sv = RootNumber{R, S, d1}.sign();
  if (sv == 0 || sgn(d2) == 0) return su;
  if (su == 0) return sv;
  if (su == sv) return su;
  // |U| versus |V| sqrt(d2): U^2 - d2 V^2 in Q(sqrt(d1)).
  const RootNumber w{P * P + Q * Q * d1 - d2 * (R * R + S * S * d1), 2 * P * Q - 2 * d2 * R * S, d1};
  const int sw = w.sign();
  return sw > 0 ? su : sw < 0 ? sv : 0;
}

struct V2 {
  FT x, y;
};
FT cross(const V2& a, const V2& b) { return a.x * b.y - a.y * b.x; }
FT dot(const V2& a, const V2& b) { return a.x * b.x + a.y * b.y; }
V2 sub(const ExactPoint& a, const ExactPoint& b) { return {a.x() - b.x(), a.y() - b.y()}; }

// Angle order of directions measured counter-clockwise from `ref`, in [0, 2 pi).
bool ccw_from_less(const V2& ref, const V2& a, const V2& b) {
  auto half = [&](const V2& v) {
    const int c = sgn(cross(ref, v));
    if (c > 0) return 0;
    if (c == 0 && sgn(dot(ref, v)) > 0) return -1;  // angle 0
    return 1;
  };
  const int ha = half(a), hb = half(b);
  if (ha != hb) return ha < hb;
  if (ha == -1) return false;
  return sgn(cross(a, b)) > 0;
}

// Strictly inside the counter-clockwise wedge from direction a to direction b (a != b).
bool strictly_in_wedge(const V2& a, const V2& b, const V2& t) {
  if (sgn(cross(a, t)) == 0 && sgn(dot(a, t)) > 0) return false;
  if (sgn(cross(b, t)) == 0 && sgn(dot(b, t)) > 0) return false;
  return ccw_from_less(a, t, b);
}

struct EdgeKey {  // order of points inside an edge (see the circular family below)
  int side = 0;
  FT value = 0;
  bool operator<(const EdgeKey& o) const { return side != o.side ? side < o.side : value < o.value; }
  bool operator==(const EdgeKey& o) const { return side == o.side && value == o.value; }
};

struct Candidate {  // a possible end of an arc
  MorsePoint::Kind kind;
  std::uint32_t id;
  EdgeKey key;
  RootNumber x, y;
  double angle = 0;  // circle: swept angle from the start; otherwise the parameter along the walk
};

}  // namespace

int RootNumber::sign() const {
  const int sa = sgn(a), sb = sgn(b);
  if (sb == 0 || sgn(d) == 0) return sa;
  if (sa == 0) return sb;
  if (sa == sb) return sa;
  const int c = sgn(a * a - b * b * d);
  return c > 0 ? sa : c < 0 ? sb : 0;
}

double RootNumber::approx() const { return CGAL::to_double(a) + CGAL::to_double(b) * std::sqrt(std::max(0.0, CGAL::to_double(d))); }

int root_orientation(const RootNumber& ox, const RootNumber& oy, const RootNumber& px, const RootNumber& py, const RootNumber& qx,
                     const RootNumber& qy) {
  // o is rational here in every use (the centre or a vertex) or shares d with p or q.
  // Write u = p - o, v = q - o; each has one radicand (o's b must be 0 or share it).
  auto shift = [](const RootNumber& p, const RootNumber& o) {
    if (sgn(o.b) == 0) return RootNumber{p.a - o.a, p.b, p.d};
    if (sgn(p.b) == 0) return RootNumber{p.a - o.a, -o.b, o.d};
    if (p.d != o.d) throw std::logic_error("root_orientation: three radicands");
    return RootNumber{p.a - o.a, p.b - o.b, p.d};
  };
  const RootNumber ux = shift(px, ox), uy = shift(py, oy), vx = shift(qx, ox), vy = shift(qy, oy);
  const FT d1 = sgn(ux.b) != 0 ? ux.d : uy.d, d2 = sgn(vx.b) != 0 ? vx.d : vy.d;
  // (ux.a + ux.b r1)(vy.a + vy.b r2) - (uy.a + uy.b r1)(vx.a + vx.b r2)
  const FT P = ux.a * vy.a - uy.a * vx.a;
  const FT Q = ux.b * vy.a - uy.b * vx.a;
  const FT R = ux.a * vy.b - uy.a * vx.b;
  const FT S = ux.b * vy.b - uy.b * vx.b;
  return sign_two_roots(P, Q, R, S, d1, d2);
}

std::vector<Point> MorseArc::polyline(double max_error) const {
  std::vector<Point> out{a};
  if (family == SliceFamily::Circular) {
    const double rho = std::sqrt(std::max(0.0, CGAL::to_double(level)));
    const double a0 = std::atan2(a.y() - centre.y(), a.x() - centre.x());
    double step = rho > max_error ? 2 * std::acos(std::max(-1.0, 1 - max_error / rho)) : std::numbers::pi / 2;
    step = std::max(step, 1e-4);
    const auto n = static_cast<std::size_t>(std::min(1e5, std::ceil(std::abs(span) / step)));
    for (std::size_t i = 1; i < n; ++i) {
      const double t = a0 + span * static_cast<double>(i) / static_cast<double>(n);
      out.emplace_back(centre.x() + rho * std::cos(t), centre.y() + rho * std::sin(t));
    }
  } else {
    out.insert(out.end(), corners.begin(), corners.end());
  }
  out.push_back(b);
  return out;
}

MorseDecomposition::MorseDecomposition(const Environment& env, SliceFamily family, const Point& centre)
    : env_(&env), family_(family), centre_(centre) {
  if (!std::isfinite(centre.x()) || !std::isfinite(centre.y())) throw InputError("--center: must be two finite numbers");
  build();
}

std::size_t MorseDecomposition::domain_loops() const {
  return env_->num_holes() + ((family_ == SliceFamily::Spike && centre_free_) ? 1 : 0);
}

double MorseDecomposition::level(const Point& p) const {
  const double dx = p.x() - centre_.x(), dy = p.y() - centre_.y();
  switch (family_) {
    case SliceFamily::Circular: return std::hypot(dx, dy);
    case SliceFamily::Squarel: return std::abs(dx) + std::abs(dy);
    case SliceFamily::Linear: return p.x();
    case SliceFamily::Spike: {
      double a = std::atan2(dy, dx);
      if (a < 0) a += kTwoPi;
      return a;
    }
  }
  return 0;
}

namespace {

// Where an edge's name is printed for the user.
std::string edge_name(const Environment& env, std::size_t e) {
  const std::size_t r = env.ring_of(e);
  return env.ring_name(r) + " edge " + std::to_string(env.input_index(e)) + " " + geometry::format_point(env.vertex(e)) + "-" +
         geometry::format_point(env.vertex(env.next(e)));
}

// Quadrants of squarel, numbered counter-clockwise 0..3 = (+,+), (-,+), (-,-), (+,-).
int quadrant_sx(int q) { return (q == 0 || q == 3) ? 1 : -1; }
int quadrant_sy(int q) { return q < 2 ? 1 : -1; }
int quadrant_ccw_after(const V2& d) {
  const int sx = sgn(d.x), sy = sgn(d.y);
  if (sx > 0 && sy >= 0) return 0;
  if (sx <= 0 && sy > 0) return 1;
  if (sx < 0 && sy <= 0) return 2;
  return 3;
}
int quadrant_cw_before(const V2& d) {
  const int sx = sgn(d.x), sy = sgn(d.y);
  if (sx >= 0 && sy > 0) return 0;
  if (sx < 0 && sy >= 0) return 1;
  if (sx <= 0 && sy < 0) return 2;
  return 3;
}
// Direction of the diamond's side in quadrant q, run counter-clockwise or clockwise.
V2 diamond_direction(int q, bool ccw) {
  const FT sx = quadrant_sx(q), sy = quadrant_sy(q);
  return ccw ? V2{-sy, sx} : V2{sy, -sx};
}

struct Builder {
  const Environment& env;
  SliceFamily fam;
  ExactPoint c;
  Point capprox;
  std::size_t n;
  std::vector<MorsePoint>& points;
  std::vector<std::uint32_t> vertex_point;                       // vertex -> point
  std::vector<std::vector<std::pair<EdgeKey, std::uint32_t>>> on_edge;  // per edge, unsorted
  std::vector<FT> foot;                                          // circular: parameter of the foot per edge
  std::uint32_t centre_point = UINT32_MAX;

  // Edges by the range of h over them, padded: the slice at level lam can only meet the
  // edges of lam's bucket, so shooting tests a few edges instead of all (the exact tests
  // below decide; the buckets only have to hold a superset). Spike levels are cyclic angles.
  double index_lo = 0, index_width = 1;
  std::vector<std::vector<std::uint32_t>> buckets;
  double level_of(const Point& p) const {
    const double dx = p.x() - capprox.x(), dy = p.y() - capprox.y();
    switch (fam) {
      case SliceFamily::Circular: return std::hypot(dx, dy);
      case SliceFamily::Squarel: return std::abs(dx) + std::abs(dy);
      case SliceFamily::Linear: return p.x();
      case SliceFamily::Spike: return std::atan2(dy, dx);
    }
    return 0;
  }
  void build_index() {
    std::vector<std::pair<double, double>> range(n);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t e = 0; e < n; ++e) {
      const Point &a = env.vertex(e), &b = env.vertex(env.next(e));
      double l0 = level_of(a), l1 = level_of(b);
      if (fam == SliceFamily::Spike) {
        const double d = std::remainder(l1 - l0, 2 * std::numbers::pi);  // the edge subtends less than pi
        l1 = l0 + d;
      }
      double mn = std::min(l0, l1), mx = std::max(l0, l1);
      const double dx = b.x() - a.x(), dy = b.y() - a.y(), L2 = dx * dx + dy * dy;
      if (fam == SliceFamily::Circular && L2 > 0) {
        const double t = ((capprox.x() - a.x()) * dx + (capprox.y() - a.y()) * dy) / L2;
        if (t > 0 && t < 1) mn = std::min(mn, level_of(Point(a.x() + t * dx, a.y() + t * dy)));
      } else if (fam == SliceFamily::Squarel) {
        for (const double t : {dx != 0 ? (capprox.x() - a.x()) / dx : -1.0, dy != 0 ? (capprox.y() - a.y()) / dy : -1.0})
          if (t > 0 && t < 1) mn = std::min(mn, level_of(Point(a.x() + t * dx, a.y() + t * dy)));
      }
      range[e] = {mn, mx};
      lo = std::min(lo, mn), hi = std::max(hi, mx);
    }
    const double pad = 1e-7 * (1 + hi - lo) + 1e-9 * std::max(std::abs(lo), std::abs(hi));
    if (fam == SliceFamily::Spike) lo = -std::numbers::pi, hi = std::numbers::pi;
    const std::size_t k = std::clamp<std::size_t>(n / 4, 1, 4096);
    index_lo = lo, index_width = std::max((hi - lo) / static_cast<double>(k), 1e-300);
    buckets.assign(k, {});
    for (std::size_t e = 0; e < n; ++e) {
      const auto b0 = static_cast<long>(std::floor((range[e].first - pad - lo) / index_width));
      const auto b1 = static_cast<long>(std::floor((range[e].second + pad - lo) / index_width));
      const long kk = static_cast<long>(k);
      if (fam == SliceFamily::Spike) {
        for (long b = b0; b <= std::min(b1, b0 + kk - 1); ++b) buckets[static_cast<std::size_t>(((b % kk) + kk) % kk)].push_back(static_cast<std::uint32_t>(e));
      } else {
        for (long b = std::max(0L, b0); b <= std::min(kk - 1, b1); ++b) buckets[static_cast<std::size_t>(b)].push_back(static_cast<std::uint32_t>(e));
      }
    }
  }
  const std::vector<std::uint32_t>& candidates(const Point& q) const {
    const long kk = static_cast<long>(buckets.size());
    long b = static_cast<long>(std::floor((level_of(q) - index_lo) / index_width));
    b = fam == SliceFamily::Spike ? ((b % kk) + kk) % kk : std::clamp(b, 0L, kk - 1);
    return buckets[static_cast<std::size_t>(b)];
  }

  V2 edge_dir(std::size_t e) const { return sub(env.exact_vertex(env.next(e)), env.exact_vertex(e)); }

  std::uint32_t add_point(MorsePoint p) {
    points.push_back(std::move(p));
    return static_cast<std::uint32_t>(points.size() - 1);
  }
  std::uint32_t edge_point(std::uint32_t e, const EdgeKey& key, const RootNumber& x, const RootNumber& y) {
    for (const auto& [k, id] : on_edge[e])
      if (k == key) return id;
    MorsePoint p;
    p.kind = MorsePoint::Kind::OnEdge, p.id = e, p.x = x, p.y = y, p.approx = Point(x.approx(), y.approx());
    const std::uint32_t id = add_point(std::move(p));
    on_edge[e].emplace_back(key, id);
    return id;
  }
  // A rational point at parameter t of edge e (0 < t < 1).
  std::uint32_t rational_edge_point(std::uint32_t e, const FT& t) {
    const ExactPoint& a = env.exact_vertex(e);
    const V2 d = edge_dir(e);
    const FT x = a.x() + t * d.x, y = a.y() + t * d.y;
    EdgeKey key{0, t};
    if (fam == SliceFamily::Circular) {
      const FT r2 = (x - c.x()) * (x - c.x()) + (y - c.y()) * (y - c.y());
      const int s = sgn(t - foot[e]);
      key = EdgeKey{s, s < 0 ? FT(-r2) : s > 0 ? r2 : FT(0)};
    }
    return edge_point(e, key, RootNumber{x, 0, 0}, RootNumber{y, 0, 0});
  }
  std::uint32_t point_at(const Candidate& k) {
    if (k.kind == MorsePoint::Kind::Vertex) return vertex_point[k.id];
    if (k.kind == MorsePoint::Kind::Centre) return centre_point;
    return edge_point(k.id, k.key, k.x, k.y);
  }

  // Exact coordinates of a point with b == 0.
  static V2 rational(const MorsePoint& p) { return {p.x.a, p.y.a}; }

  // The two directions of the slice at a rational boundary point q: leaving "ccw"
  // (spike: outwards) and "cw" (spike: inwards).
  V2 slice_direction(const V2& q, bool ccw) const {
    const V2 u{q.x - c.x(), q.y - c.y()};
    switch (fam) {
      case SliceFamily::Circular: return ccw ? V2{-u.y, u.x} : V2{u.y, -u.x};
      case SliceFamily::Spike: return ccw ? u : V2{-u.x, -u.y};
      case SliceFamily::Linear: return ccw ? V2{0, 1} : V2{0, -1};
      case SliceFamily::Squarel: return diamond_direction(ccw ? quadrant_ccw_after(u) : quadrant_cw_before(u), ccw);
    }
    return u;
  }

  // Does the slice leaving q in direction t enter the free space (wedge from a to b)?
  // Circular ties: the circle is tangent to the edge there and bends towards c, so it enters
  // iff c is on the free side of that edge.
  bool enters(const V2& q, const V2& a, const V2& b, const V2& t) const {
    if (fam == SliceFamily::Circular) {
      for (const V2* side : {&a, &b}) {
        if (sgn(cross(*side, t)) == 0 && sgn(dot(*side, t)) > 0) {
          // side a is the out-edge direction (free space on its left); side b points back
          // along the in-edge (free space on its right).
          const V2 cq{c.x() - q.x, c.y() - q.y};
          const int o = sgn(cross(*side, cq));
          return side == &a ? o > 0 : o < 0;
        }
      }
    }
    return strictly_in_wedge(a, b, t);
  }

  // ---- shooting along the slice -------------------------------------------------------------

  // First boundary point along the slice from q (rational, a graph point) in direction ccw.
  // Returns the candidate and fills the squarel corners passed.
  Candidate shoot(std::uint32_t from, bool ccw, std::vector<Point>& corners, double& span) {
    corners.clear();
    const V2 q = rational(points[from]);
    switch (fam) {
      case SliceFamily::Spike: return shoot_ray(from, q, ccw, span);
      case SliceFamily::Linear: return shoot_ray(from, q, ccw, span);
      case SliceFamily::Squarel: return shoot_diamond(from, q, ccw, corners, span);
      case SliceFamily::Circular: return shoot_circle(from, q, ccw, span);
    }
    throw std::logic_error("morse: family");
  }

  bool is_self(const Candidate& k, std::uint32_t from) const {
    const MorsePoint& p = points[from];
    if (k.kind != p.kind) return false;
    if (k.kind == MorsePoint::Kind::Vertex) return vertex_point[k.id] == from;
    if (k.kind == MorsePoint::Kind::OnEdge)
      for (const auto& [key, id] : on_edge[k.id])
        if (id == from) return key == k.key;
    return false;
  }

  Candidate vertex_candidate(std::uint32_t v) const {
    Candidate k;
    k.kind = MorsePoint::Kind::Vertex, k.id = v;
    k.x = RootNumber{env.exact_vertex(v).x(), 0, 0}, k.y = RootNumber{env.exact_vertex(v).y(), 0, 0};
    return k;
  }
  Candidate candidate_at(std::uint32_t e, const FT& t) {
    Candidate k;
    if (sgn(t) == 0 || t == 1) {
      k = vertex_candidate(static_cast<std::uint32_t>(sgn(t) == 0 ? e : env.next(e)));
    } else {
      const ExactPoint& a = env.exact_vertex(e);
      const V2 d = edge_dir(e);
      k.kind = MorsePoint::Kind::OnEdge, k.id = e, k.key = EdgeKey{0, t};
      k.x = RootNumber{a.x() + t * d.x, 0, 0}, k.y = RootNumber{a.y() + t * d.y, 0, 0};
    }
    return k;
  }

  // Segment s + u (z - s), u in (lo, 1], against every edge: the smallest u. Exact.
  std::optional<std::pair<FT, Candidate>> first_hit_on_segment(const V2& s, const V2& z, bool skip_start,
                                                               const std::vector<std::uint32_t>& edges) {
    const V2 w{z.x - s.x, z.y - s.y};
    const double sx = CGAL::to_double(s.x), sy = CGAL::to_double(s.y), zx = CGAL::to_double(z.x), zy = CGAL::to_double(z.y);
    const double pad = 1e-9 * (1 + std::max({std::abs(sx), std::abs(sy), std::abs(zx), std::abs(zy)}));
    const double lox = std::min(sx, zx) - pad, hix = std::max(sx, zx) + pad, loy = std::min(sy, zy) - pad, hiy = std::max(sy, zy) + pad;
    std::optional<std::pair<FT, Candidate>> best;
    for (const std::size_t e : edges) {
      const Point &a = env.vertex(e), &b = env.vertex(env.next(e));
      if (std::max(a.x(), b.x()) < lox || std::min(a.x(), b.x()) > hix || std::max(a.y(), b.y()) < loy || std::min(a.y(), b.y()) > hiy)
        continue;
      const ExactPoint& ea = env.exact_vertex(e);
      const V2 d = edge_dir(e);
      const FT den = cross(w, d);
      const V2 as{ea.x() - s.x, ea.y() - s.y};
      if (sgn(den) == 0) {
        if (sgn(cross(as, w)) != 0) continue;
        // The edge lies on this piece of the slice (a flat edge): met at its nearer end.
        const FT ww = dot(w, w);
        for (const std::uint32_t v : {static_cast<std::uint32_t>(e), static_cast<std::uint32_t>(env.next(e))}) {
          const ExactPoint& pv = env.exact_vertex(v);
          const FT u = dot(V2{pv.x() - s.x, pv.y() - s.y}, w) / ww;
          if (sgn(u) < 0 || u > 1 || (skip_start && sgn(u) == 0)) continue;
          if (best && !(u < best->first)) continue;
          best.emplace(u, vertex_candidate(v));
        }
        continue;
      }
      FT u = cross(as, d) / den, t = cross(as, w) / den;
      if (sgn(t) < 0 || t > 1 || sgn(u) < 0 || u > 1) continue;
      if (skip_start && sgn(u) == 0) continue;
      if (best && !(u < best->first)) continue;
      best.emplace(u, candidate_at(static_cast<std::uint32_t>(e), t));
    }
    return best;
  }

  // Spike: the ray from q away from c (outwards) or towards it, stopping at c. Linear: the
  // vertical ray up (outwards) or down. Both are segments long enough to leave the map.
  Candidate shoot_ray(std::uint32_t from, const V2& q, bool outwards, double& span) {
    const bool linear = fam == SliceFamily::Linear;
    span = 0;
    V2 z;
    if (!linear && !outwards) {
      z = V2{c.x(), c.y()};  // the ray ends at the centre, where h is undefined
    } else {
      const V2 u = linear ? V2{0, 1} : V2{q.x - c.x(), q.y - c.y()};
      const V2 dir = outwards ? u : V2{-u.x, -u.y};
      const auto box = env.bbox();
      // |dir|_1 >= |dir|_2, so this length in units of dir reaches beyond the map's box.
      const FT reach = FT(2 * (box.xmax() - box.xmin() + box.ymax() - box.ymin()) + 1) / (CGAL::abs(dir.x) + CGAL::abs(dir.y));
      z = V2{q.x + reach * dir.x, q.y + reach * dir.y};
    }
    if (const auto hit = first_hit_on_segment(q, z, true, candidates(points[from].approx))) return hit->second;
    if (!linear && !outwards) {
      Candidate k;
      k.kind = MorsePoint::Kind::Centre, k.id = 0;
      return k;
    }
    throw std::logic_error("morse: a ray left the environment");
  }

  Candidate shoot_diamond(std::uint32_t from, const V2& q, bool ccw, std::vector<Point>& corners, double& span) {
    const V2 u{q.x - c.x(), q.y - c.y()};
    const FT L = CGAL::abs(u.x) + CGAL::abs(u.y);
    auto corner_of = [&](int k) {  // corners ccw: (L,0), (0,L), (-L,0), (0,-L)
      switch (k & 3) {
        case 0: return V2{c.x() + L, c.y()};
        case 1: return V2{c.x(), c.y() + L};
        case 2: return V2{c.x() - L, c.y()};
        default: return V2{c.x(), c.y() - L};
      }
    };
    // The first corner met: the ccw end of the quadrant after q, or the cw end of the one before.
    int k;
    if (ccw) {
      const int quad = quadrant_ccw_after(u);
      k = quad + 1;  // quadrant 0 ends (ccw) at corner 1, ..., quadrant 3 at corner 0
    } else {
      const int quad = quadrant_cw_before(u);
      k = quad;  // quadrant 0 starts at corner 0, which is its cw end
    }
    const bool at_corner = sgn(u.x) == 0 || sgn(u.y) == 0;
    const auto& edges = candidates(points[from].approx);
    std::vector<V2> walk;
    const int pieces = at_corner ? 3 : 4;
    for (int i = 0; i < pieces; ++i) walk.push_back(corner_of(ccw ? k + i : k - i + 4));
    walk.push_back(q);
    V2 s = q;
    for (std::size_t i = 0; i < walk.size(); ++i) {
      const auto hit = first_hit_on_segment(s, walk[i], i == 0, edges);
      if (hit) {
        span = 0;
        return hit->second;
      }
      if (i + 1 < walk.size()) corners.emplace_back(CGAL::to_double(walk[i].x), CGAL::to_double(walk[i].y));
      s = walk[i];
    }
    throw std::logic_error("morse: a diamond slice met no boundary, not even its start");
  }

  // Circle |p - c|^2 = R through q: every crossing with an edge, ordered by the angle swept.
  Candidate shoot_circle(std::uint32_t from, const V2& q, bool ccw, double& span) {
    const V2 u0{q.x - c.x(), q.y - c.y()};
    const FT R = dot(u0, u0);
    const double Rd = CGAL::to_double(R), cx = capprox.x(), cy = capprox.y();
    const double u0x = CGAL::to_double(u0.x), u0y = CGAL::to_double(u0.y);
    std::vector<Candidate> cands;
    // Phase 1, double: where each edge crosses the circle and at what angle from q. An edge
    // is *unsure* when the crossing is near an end of a monotone piece or nearly tangent;
    // phase 2 decides exactly the unsure edges, the edges at q, and every edge whose crossing
    // comes within 1e-6 rad of the first sure one (far beyond double's error elsewhere).
    const double qx = CGAL::to_double(q.x), qy = CGAL::to_double(q.y);
    // A pseudo-angle (monotone in the angle swept from q, in (0, 4]; no trigonometry).
    auto swept = [&](double zx, double zy) {
      const double X = u0x * zx + u0y * zy, Y = (ccw ? 1 : -1) * (u0x * zy - u0y * zx);
      const double p = Y >= 0 ? (X >= 0 ? Y / (X + Y) : 1 - X / (Y - X)) : (X < 0 ? 2 - Y / (-X - Y) : 3 + X / (X - Y));
      return p <= 0 ? 4.0 : p;
    };
    std::vector<std::pair<std::uint32_t, double>> phase1;  // edge, first angle (infinity: unsure)
    double first_sure = std::numeric_limits<double>::infinity();
    for (const std::size_t e : candidates(points[from].approx)) {
      const Point &a = env.vertex(e), &b = env.vertex(env.next(e));
      const double ax = a.x() - cx, ay = a.y() - cy, dx = b.x() - a.x(), dy = b.y() - a.y();
      const double A = dx * dx + dy * dy, B = 2 * (ax * dx + ay * dy), C = ax * ax + ay * ay - Rd;
      const double scale2 = ax * ax + ay * ay + A + Rd;
      const bool at_q = (a.x() == qx && a.y() == qy) || (b.x() == qx && b.y() == qy) || (points[from].kind == MorsePoint::Kind::OnEdge && points[from].id == e);
      const double D = B * B - 4 * A * C;
      if (D < -1e-9 * B * B - 1e-9 * scale2 * A) {
        if (at_q) phase1.emplace_back(static_cast<std::uint32_t>(e), std::numeric_limits<double>::infinity());
        continue;  // misses the circle by far
      }
      const double fa = C, fb = A + B + C;  // |p - c|^2 - R at the two ends
      bool unsure = at_q || std::abs(D) <= 1e-6 * B * B + 1e-12 * scale2 * A || std::abs(fa) <= 1e-9 * scale2 || std::abs(fb) <= 1e-9 * scale2;
      double best_here = std::numeric_limits<double>::infinity();
      if (!unsure) {
        const double r = std::sqrt(std::max(0.0, D));
        for (const double t : {(-B - r) / (2 * A), (-B + r) / (2 * A)}) {
          if (std::abs(t) <= 1e-9 || std::abs(t - 1) <= 1e-9) unsure = true;
          if (t > 0 && t < 1) best_here = std::min(best_here, swept(ax + t * dx, ay + t * dy));
        }
      }
      if (unsure) {
        phase1.emplace_back(static_cast<std::uint32_t>(e), std::numeric_limits<double>::infinity());
      } else if (best_here < std::numeric_limits<double>::infinity()) {
        phase1.emplace_back(static_cast<std::uint32_t>(e), best_here);
        first_sure = std::min(first_sure, best_here);
      }
    }
    for (const auto& [e, angle] : phase1) {
      if (angle < std::numeric_limits<double>::infinity() && angle > first_sure + 1e-6) continue;
      const Point &a = env.vertex(e), &b = env.vertex(env.next(e));
      (void)a, (void)b;
      // Exact: the monotone sub-edges [0, foot] and [foot, 1].
      const ExactPoint& ea = env.exact_vertex(e);
      const V2 d = edge_dir(e);
      const V2 ac{ea.x() - c.x(), ea.y() - c.y()};
      const FT A = dot(d, d), B = 2 * dot(d, ac), C = dot(ac, ac) - R;
      const FT& tf = foot[e];
      struct Sub { FT t0, t1; int side; };
      std::vector<Sub> subs;
      if (sgn(tf) > 0 && tf < 1) subs = {{0, tf, -1}, {tf, 1, 1}};
      else subs = {{0, 1, sgn(tf) <= 0 ? 1 : -1}};
      auto r2at = [&](const FT& t) { return A * t * t + B * t + C; };  // |p(t) - c|^2 - R
      for (const Sub& sb : subs) {
        const int s0 = sgn(r2at(sb.t0)), s1 = sgn(r2at(sb.t1));
        if (s0 == 0 || s1 == 0) {
          for (const FT* t : {&sb.t0, &sb.t1}) {
            if (sgn(r2at(*t)) != 0) continue;
            Candidate k;
            if (sgn(*t) == 0 || *t == 1) {
              k = candidate_at(static_cast<std::uint32_t>(e), *t);
            } else {  // the foot: a tangency (a critical point of the same level)
              k.kind = MorsePoint::Kind::OnEdge, k.id = static_cast<std::uint32_t>(e), k.key = EdgeKey{0, 0};
              k.x = RootNumber{ea.x() + *t * d.x, 0, 0}, k.y = RootNumber{ea.y() + *t * d.y, 0, 0};
            }
            cands.push_back(std::move(k));
          }
          continue;
        }
        if (s0 == s1) continue;
        // t = (-B + side sqrt(Delta)) / (2A): x = a.x + d.x t.
        const FT Delta = B * B - 4 * A * C;
        const FT inv = FT(1) / (2 * A);
        Candidate k;
        k.kind = MorsePoint::Kind::OnEdge, k.id = static_cast<std::uint32_t>(e);
        k.key = EdgeKey{sb.side, sb.side < 0 ? FT(-R) : R};
        k.x = RootNumber{ea.x() - d.x * B * inv, sb.side * d.x * inv, Delta};
        k.y = RootNumber{ea.y() - d.y * B * inv, sb.side * d.y * inv, Delta};
        cands.push_back(std::move(k));
      }
    }
    // Angle swept from q, in (0, 2 pi]; q itself (reached again) is 2 pi.
    for (Candidate& k : cands) {
      if (is_self(k, from)) {
        k.angle = kTwoPi;
        continue;
      }
      const double zx = k.x.approx() - cx, zy = k.y.approx() - cy;
      double a = std::atan2(u0x * zy - u0y * zx, u0x * zx + u0y * zy);
      if (!ccw) a = -a;
      if (a <= 0) a += kTwoPi;
      k.angle = a;
    }
    if (cands.empty()) throw std::logic_error("morse: a circle slice met no boundary, not even its start");
    std::size_t best = 0;
    for (std::size_t i = 1; i < cands.size(); ++i)
      if (before(cands[i], cands[best], u0, ccw, from)) best = i;
    span = ccw ? cands[best].angle : -cands[best].angle;
    return cands[best];
  }

  std::string describe(const Candidate& k) const {
    const char* kinds[] = {"vertex", "edge", "centre"};
    return std::string(kinds[static_cast<int>(k.kind)]) + " " + std::to_string(k.id) + " key (" + std::to_string(k.key.side) + ", " +
           std::to_string(CGAL::to_double(k.key.value)) + ") at " + geometry::format_point(Point(k.x.approx(), k.y.approx()));
  }
  // Exact "a is met before b" going around the circle from direction u0.
  bool before(const Candidate& a, const Candidate& b, const V2& u0, bool ccw, std::uint32_t from) const {
    const double gap = a.angle - b.angle;
    if (std::abs(gap) > 1e-7) return gap < 0;
    const bool sa = is_self(a, from), sb = is_self(b, from);
    if (sa || sb) return !sa && sb;
    if (a.kind == b.kind && (a.kind == MorsePoint::Kind::Vertex ? vertex_point[a.id] == vertex_point[b.id] : a.id == b.id) &&
        (a.kind != MorsePoint::Kind::OnEdge || a.key == b.key))
      return false;  // one point
    // Relative to c, mirrored for clockwise so the order is always counter-clockwise.
    auto my = [&](const RootNumber& y) { return ccw ? RootNumber{y.a - c.y(), y.b, y.d} : RootNumber{c.y() - y.a, -y.b, y.d}; };
    const RootNumber ax{a.x.a - c.x(), a.x.b, a.x.d}, ay = my(a.y), bx{b.x.a - c.x(), b.x.b, b.x.d}, by = my(b.y);
    const RootNumber zero{0, 0, 0}, rx{u0.x, 0, 0}, ry{ccw ? u0.y : FT(-u0.y), 0, 0};
    auto half = [&](const RootNumber& x, const RootNumber& y) {
      const int cr = root_orientation(zero, zero, rx, ry, x, y);
      return cr > 0 ? 0 : 1;  // angle 0 is q itself, excluded above
    };
    const int ha = half(ax, ay), hb = half(bx, by);
    if (ha != hb) return ha < hb;
    const int o = root_orientation(zero, zero, ax, ay, bx, by);
    if (o == 0)
      throw std::logic_error("morse: two boundary points at one place on a critical circle: " + describe(a) + " and " + describe(b));
    return o > 0;
  }
};

// Union-find.
std::uint32_t find(std::vector<std::uint32_t>& p, std::uint32_t x) {
  while (p[x] != x) x = p[x] = p[p[x]];
  return x;
}

// Crossings of the ray from x in direction (cos phi, sin phi) with a closed polyline,
// certified: throws if x or a vertex is within `margin` of deciding otherwise.
bool ray_parity(const Point& x, double phi, const std::vector<Point>& ring, double margin, bool& unsure) {
  const double dx = std::cos(phi), dy = std::sin(phi);
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point &a = ring[i], &b = ring[(i + 1) % ring.size()];
    // Signed distances of a, b from the ray's line, and distance of x from the segment.
    const double sa = (a.x() - x.x()) * dy - (a.y() - x.y()) * dx, sb = (b.x() - x.x()) * dy - (b.y() - x.y()) * dx;
    const double ex = b.x() - a.x(), ey = b.y() - a.y(), L2 = ex * ex + ey * ey;
    double t = L2 > 0 ? ((x.x() - a.x()) * ex + (x.y() - a.y()) * ey) / L2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    if (std::hypot(a.x() + t * ex - x.x(), a.y() + t * ey - x.y()) < margin) unsure = true;
    if ((sa > 0) == (sb > 0)) {
      if (std::abs(sa) < margin || std::abs(sb) < margin) {
        // a vertex near the line: unsure only if it is ahead of x
        const double pa = (a.x() - x.x()) * dx + (a.y() - x.y()) * dy, pb = (b.x() - x.x()) * dx + (b.y() - x.y()) * dy;
        if ((std::abs(sa) < margin && pa > -margin) || (std::abs(sb) < margin && pb > -margin)) unsure = true;
      }
      continue;
    }
    const double k = sa / (sa - sb);
    const double px = a.x() + k * ex, py = a.y() + k * ey;
    const double along = (px - x.x()) * dx + (py - x.y()) * dy;
    if (std::abs(sa) < margin || std::abs(sb) < margin || std::abs(along) < margin) unsure = true;
    if (along > 0) inside = !inside;
  }
  return inside;
}

}  // namespace

void MorseDecomposition::build() {
  const Environment& env = *env_;
  const std::string who = std::string("the ") + std::string(to_string(family_)) + " decomposition";
  const ExactPoint c = geometry::to_exact(centre_);
  if (family_ != SliceFamily::Linear) {  // h = x has no centre
    const auto loc = geometry::locate(env, c);
    using K = geometry::Location::Kind;
    if (loc.kind == K::OnEdge || loc.kind == K::AtVertex)
      throw InputError("--center " + geometry::format_point(centre_) + " lies on the boundary (" +
                       edge_name(env, loc.index) + "): the slices all meet there; move the centre");
    centre_free_ = loc.kind == K::Interior;
  }
  const std::size_t n = env.num_vertices();
  Builder B{env, family_, c, centre_, n, points_, {}, {}, {}, UINT32_MAX, 0, 1, {}};
  B.build_index();
  B.vertex_point.resize(n);
  B.on_edge.resize(n);
  for (std::size_t v = 0; v < n; ++v) {
    // A contact is one point of the graph, whichever ring's vertex names it.
    if (env.is_contact(v)) {
      std::size_t first = v;
      for (std::size_t u = env.same_point_next(v); u != v; u = env.same_point_next(u)) first = std::min(first, u);
      if (first < v) {
        B.vertex_point[v] = B.vertex_point[first];
        continue;
      }
    }
    MorsePoint p;
    p.kind = MorsePoint::Kind::Vertex, p.id = static_cast<std::uint32_t>(v);
    p.x = RootNumber{env.exact_vertex(v).x(), 0, 0}, p.y = RootNumber{env.exact_vertex(v).y(), 0, 0};
    p.approx = env.vertex(v);
    B.vertex_point[v] = B.add_point(std::move(p));
  }
  if (centre_free_) {
    MorsePoint p;
    p.kind = MorsePoint::Kind::Centre, p.x = RootNumber{c.x(), 0, 0}, p.y = RootNumber{c.y(), 0, 0}, p.approx = centre_;
    B.centre_point = B.add_point(std::move(p));
  }

  // Events inside edges: feet of perpendiculars (circular), axis crossings (squarel).
  if (family_ == SliceFamily::Circular) B.foot.resize(n);
  for (std::uint32_t e = 0; e < n; ++e) {
    const ExactPoint& a = env.exact_vertex(e);
    const V2 d = B.edge_dir(e);
    const V2 ca = sub(c, a);
    if (family_ == SliceFamily::Circular) {
      const FT t = dot(ca, d) / dot(d, d);
      B.foot[e] = t;
      if (sgn(t) > 0 && t < 1) B.rational_edge_point(e, t);
    } else if (family_ == SliceFamily::Squarel) {
      if (sgn(d.x) != 0) {
        const FT t = ca.x / d.x;
        if (sgn(t) > 0 && t < 1) B.rational_edge_point(e, t);
      }
      if (sgn(d.y) != 0) {
        const FT t = ca.y / d.y;
        if (sgn(t) > 0 && t < 1) B.rational_edge_point(e, t);
      }
    }
  }
  // The boundary as runs of sub-edges between consecutive events, ring by ring. A sub-edge is
  // *flat* when h is constant along it (it lies on a slice: spike, an edge on a line through
  // c; squarel, an edge parallel to the diamond's side in its quadrant). A maximal run of
  // flat sub-edges is one event, like a vertical wall in the boustrophedon decomposition:
  // the slice continues beyond each end or not, and the pair is one critical slice.
  // Critical points by (point, free wedge): at a contact each wedge is its own boundary point
  // of the open free space (named by the ring vertex whose out-edge starts it); elsewhere 0.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> critical_at;
  auto critical_of = [&](std::uint32_t pid, std::uint32_t wedge) -> std::int32_t {
    const auto it = critical_at.find({pid, wedge});
    return it == critical_at.end() ? -1 : static_cast<std::int32_t>(it->second);
  };
  // The wedge of a contact point that a direction leaving it lies in (0 elsewhere).
  auto wedge_of = [&](std::uint32_t pid, const V2& dir) -> std::uint32_t {
    const MorsePoint& p = points_[pid];
    if (p.kind != MorsePoint::Kind::Vertex || !env.is_contact(p.id)) return 0;
    std::size_t v = p.id;
    do {
      const std::size_t u = env.wedge_end(v);
      if (strictly_in_wedge(B.edge_dir(v), sub(env.exact_vertex(env.prev(u)), env.exact_vertex(u)), dir)) return static_cast<std::uint32_t>(v);
      v = env.same_point_next(v);
    } while (v != p.id);
    return 0;
  };
  struct Shot { std::uint32_t point; bool ccw; std::uint32_t critical; };
  std::vector<Shot> shots;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> same_node;  // critical points joined by a flat run
  auto add_critical = [&](std::uint32_t pid, CriticalKind kind, std::uint32_t wedge = 0) {
    const auto [it, fresh] = critical_at.emplace(std::make_pair(pid, wedge), static_cast<std::uint32_t>(critical_.size()));
    if (fresh) critical_.push_back({pid, kind, level(points_[pid].approx), 0});
    return it->second;
  };
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    std::vector<std::uint32_t> seq;  // event points around the ring, free space on the left
    std::vector<std::uint32_t> seq_vertex;  // the ring vertex of each, or UINT32_MAX inside an edge
    for (std::size_t e = env.ring_begin(r); e < env.ring_end(r); ++e) {
      seq.push_back(B.vertex_point[e]), seq_vertex.push_back(static_cast<std::uint32_t>(e));
      auto list = B.on_edge[e];
      std::sort(list.begin(), list.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      for (const auto& [k, id] : list) seq.push_back(id), seq_vertex.push_back(UINT32_MAX);
    }
    auto contact = [&](std::size_t i) { return seq_vertex[i % seq.size()] != UINT32_MAX && env.is_contact(seq_vertex[i % seq.size()]); };
    const std::size_t m = seq.size();
    auto P = [&](std::size_t i) { return Builder::rational(points_[seq[i % m]]); };
    auto dir = [&](std::size_t i) { const V2 a = P(i), b = P(i + 1); return V2{b.x - a.x, b.y - a.y}; };  // piece i
    std::vector<char> flat(m, 0);
    for (std::size_t i = 0; i < m; ++i) {
      const V2 a = P(i), d = dir(i);
      if (family_ == SliceFamily::Linear) {
        flat[i] = sgn(d.x) == 0;  // a vertical wall
      } else if (family_ == SliceFamily::Spike) {
        flat[i] = sgn(cross(d, V2{c.x() - a.x, c.y() - a.y})) == 0;
      } else if (family_ == SliceFamily::Squarel) {
        const V2 mid{a.x + d.x / 2 - c.x(), a.y + d.y / 2 - c.y()};
        const int q = quadrant_ccw_after(mid);
        flat[i] = sgn(mid.x) != 0 && sgn(mid.y) != 0 && sgn(quadrant_sx(q) * d.x + quadrant_sy(q) * d.y) == 0;
      }
    }
    std::size_t first_bent = m;
    for (std::size_t i = 0; i < m; ++i)
      if (!flat[i]) { first_bent = i; break; }
    if (first_bent == m)
      throw InputError(env.ring_name(r) + " lies entirely on one slice of the " + std::string(to_string(family_)) + " decomposition around --center " +
                       geometry::format_point(centre_) + ": move the centre");
    // Walk from a bent piece so every flat run is seen whole.
    for (std::size_t k = 1; k <= m; ++k) {
      const std::size_t i = (first_bent + k) % m;  // point seq[i] between piece i-1 and piece i
      const std::size_t prev = (i + m - 1) % m;
      if ((flat[prev] || flat[i]) && contact(i))
        throw InputError(std::string(to_string(family_)) + " decomposition around --center " + geometry::format_point(centre_) + ": " +
                         edge_name(env, flat[i] ? seq_vertex[i] : env.prev(seq_vertex[i])) +
                         " lies on a slice and ends where holes touch; move the centre");
      if (flat[prev]) continue;  // inside or at the end of a run: handled at its start
      const V2 q = P(i);
      if (!flat[i]) {
        // The free wedge from this vertex's out-edge to the in-edge of the ring vertex that
        // closes it (another ring's at a contact, Environment::wedge_end).
        V2 b;
        if (contact(i)) {
          const std::size_t u = env.wedge_end(seq_vertex[i]);
          b = sub(env.exact_vertex(env.prev(u)), env.exact_vertex(u));
        } else {
          const V2 din = dir(prev);
          b = V2{-din.x, -din.y};
        }
        const V2 a = dir(i);
        const int count = B.enters(q, a, b, B.slice_direction(q, true)) + B.enters(q, a, b, B.slice_direction(q, false));
        if (count == 1) continue;
        const std::uint32_t k = add_critical(seq[i], count == 2 ? CriticalKind::SplitMerge : CriticalKind::BirthDeath,
                                             contact(i) ? seq_vertex[i] : 0);
        if (count == 2) shots.push_back({seq[i], true, k}), shots.push_back({seq[i], false, k});
        continue;
      }
      // A flat run from seq[i] to seq[j].
      std::size_t j = i;
      while (flat[j % m]) ++j;
      const std::size_t last = (j + m - 1) % m;
      if (contact(j))
        throw InputError(std::string(to_string(family_)) + " decomposition around --center " + geometry::format_point(centre_) + ": " +
                         edge_name(env, env.prev(seq_vertex[j % m])) + " lies on a slice and ends where holes touch; move the centre");
      const V2 d0 = dir(i), w = P(j), dl = dir(last), dn = dir(j);
      const V2 sc = B.slice_direction(q, true);
      const bool travel = sgn(dot(d0, sc)) > 0 && sgn(cross(d0, sc)) == 0;  // the run goes ccw (spike: outwards)
      const V2 tv = B.slice_direction(q, !travel), tw = B.slice_direction(w, travel);
      const V2 din = dir(prev);
      const bool ev = strictly_in_wedge(d0, V2{-din.x, -din.y}, tv), ew = strictly_in_wedge(dn, V2{-dl.x, -dl.y}, tw);
      const int count = ev + ew;
      if (count == 1) continue;
      const auto kind = count == 2 ? CriticalKind::SplitMerge : CriticalKind::BirthDeath;
      const std::uint32_t kv = add_critical(seq[i], kind), kw = add_critical(seq[j % m], kind);
      same_node.emplace_back(kv, kw);
      if (count == 2) shots.push_back({seq[i], !travel, kv}), shots.push_back({seq[j % m], travel, kw});
    }
  }
  if (centre_free_ && family_ != SliceFamily::Spike) add_critical(B.centre_point, CriticalKind::Minimum);
  // Arcs, each once: an arc's two ends are (from, leaving ccw) and (to, leaving the other way).
  std::map<std::pair<std::uint32_t, bool>, std::uint32_t> end_used;
  std::vector<std::uint32_t> arc_critical;  // per arc: the critical point it leaves
  for (const Shot& shot : shots) {
    const std::uint32_t pid = shot.point;
    const bool ccw = shot.ccw;
    {
      if (end_used.count({pid, ccw})) continue;
      MorseArc arc;
      double span = 0;
      const Candidate hit = B.shoot(pid, ccw, arc.corners, span);
      const std::uint32_t to = B.point_at(hit);
      arc.from = pid, arc.to = to, arc.ccw = ccw, arc.family = family_, arc.centre = centre_;
      const V2 u{points_[pid].x.a - c.x(), points_[pid].y.a - c.y()};
      arc.level = family_ == SliceFamily::Circular ? dot(u, u) : family_ == SliceFamily::Squarel ? FT(CGAL::abs(u.x) + CGAL::abs(u.y)) : FT(0);
      arc.a = points_[pid].approx, arc.b = points_[to].approx, arc.span = span;
      const auto id = static_cast<std::uint32_t>(arcs_.size());
      end_used[{pid, ccw}] = id;
      if (to != B.centre_point) end_used[{to, !ccw}] = id;
      arcs_.push_back(std::move(arc));
      arc_critical.push_back(shot.critical);
    }
  }

  // Reeb nodes: critical points joined by arcs (not through the centre, where h is undefined
  // for spike and which is its own minimum otherwise).
  std::vector<std::uint32_t> parent(critical_.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::size_t i = 0; i < arcs_.size(); ++i) {
    const MorseArc& arc = arcs_[i];
    if (arc.to == B.centre_point) continue;
    // The end: a critical point of the same level if the arc stops at one (in the wedge it
    // arrives in, at a contact).
    std::int32_t b = -1;
    if (sgn(points_[arc.to].x.b) == 0 && sgn(points_[arc.to].y.b) == 0)
      b = critical_of(arc.to, wedge_of(arc.to, B.slice_direction(Builder::rational(points_[arc.to]), !arc.ccw)));
    if (b >= 0) parent[find(parent, arc_critical[i])] = find(parent, static_cast<std::uint32_t>(b));
  }
  for (const auto& [x, y] : same_node) parent[find(parent, x)] = find(parent, y);
  std::vector<std::int32_t> node_of_root(critical_.size(), -1);
  for (std::uint32_t i = 0; i < critical_.size(); ++i) {
    const std::uint32_t r = find(parent, i);
    if (node_of_root[r] < 0) node_of_root[r] = static_cast<std::int32_t>(num_nodes_++);
    critical_[i].node = static_cast<std::uint32_t>(node_of_root[r]);
  }
  for (std::size_t i = 0; i < arcs_.size(); ++i) arcs_[i].node = critical_[arc_critical[i]].node;

  // ---- the plane graph: boundary pieces and arcs, with the free space on the left ----
  struct Half {
    std::uint32_t from, to;
    std::int32_t arc;  // -1: boundary piece
    std::uint32_t edge;
    bool forward;      // arcs: run in their own direction
    std::int32_t next = -1;
  };
  std::vector<Half> halves;
  struct Spoke {
    V2 dir;
    int rank;  // 0 boundary out, 1 arc, 2 boundary in
    std::int32_t out = -1, in = -1;
    bool known = true;  // direction known exactly (false: an arc at an irrational point, alone)
  };
  std::vector<std::vector<Spoke>> spokes(points_.size());
  for (std::uint32_t e = 0; e < n; ++e) {
    auto& list = B.on_edge[e];
    std::sort(list.begin(), list.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::uint32_t> chain{B.vertex_point[e]};
    for (const auto& [k, id] : list) chain.push_back(id);
    chain.push_back(B.vertex_point[env.next(e)]);
    const V2 d = B.edge_dir(e);
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const auto h = static_cast<std::int32_t>(halves.size());
      halves.push_back({chain[i], chain[i + 1], -1, e, true});
      spokes[chain[i]].push_back({d, 0, h, -1});
      spokes[chain[i + 1]].push_back({V2{-d.x, -d.y}, 2, -1, h});
    }
  }
  auto rational_point = [&](std::uint32_t id) { return sgn(points_[id].x.b) == 0 && sgn(points_[id].y.b) == 0; };
  for (std::uint32_t i = 0; i < arcs_.size(); ++i) {
    const MorseArc& arc = arcs_[i];
    const auto h = static_cast<std::int32_t>(halves.size());
    halves.push_back({arc.from, arc.to, static_cast<std::int32_t>(i), 0, true});
    halves.push_back({arc.to, arc.from, static_cast<std::int32_t>(i), 0, false});
    const V2 qf = Builder::rational(points_[arc.from]);
    spokes[arc.from].push_back({B.slice_direction(qf, arc.ccw), 1, h, h + 1});
    Spoke at_to{V2{0, 0}, 1, h + 1, h};
    if (arc.to == B.centre_point) {
      at_to.dir = V2{qf.x - c.x(), qf.y - c.y()};
    } else if (rational_point(arc.to)) {
      at_to.dir = B.slice_direction(Builder::rational(points_[arc.to]), !arc.ccw);
    } else {
      at_to.known = false;
    }
    spokes[arc.to].push_back(at_to);
  }
  for (std::uint32_t p = 0; p < points_.size(); ++p) {
    auto& s = spokes[p];
    if (s.empty()) continue;
    V2 ref{1, 0};
    for (const Spoke& k : s)
      if (k.rank == 0) ref = k.dir;
    int unknown = 0;
    for (const Spoke& k : s) unknown += !k.known;
    if (unknown > 0 && s.size() > 3) throw std::logic_error("morse: several arcs meet at an irrational point");
    // Counter-clockwise from an out-edge; at equal directions an out-edge comes first and an
    // in-edge last (an arc tangent to an edge runs on its free side). With one free wedge
    // (no contact) that is: out-edge, arcs, in-edge. An arc at an irrational point is alone
    // between its edge's two pieces.
    std::stable_sort(s.begin(), s.end(), [&](const Spoke& x, const Spoke& y) {
      if (!x.known || !y.known) return x.rank < y.rank;
      if (ccw_from_less(ref, x.dir, y.dir)) return true;
      if (ccw_from_less(ref, y.dir, x.dir)) return false;
      return x.rank < y.rank;
    });
    // The centre: only arcs, ordered by angle from +x (rank 1 throughout; ref = (1, 0)).
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i].in < 0) continue;
      const Spoke& cw = s[(i + s.size() - 1) % s.size()];
      if (cw.out < 0) throw std::logic_error("morse: a face turned into an obstacle at " + geometry::format_point(points_[p].approx));
      halves[static_cast<std::size_t>(s[i].in)].next = cw.out;
    }
  }

  // ---- faces ----
  auto piece_polyline = [&](const Half& h, double err) {
    if (h.arc < 0) return std::vector<Point>{points_[h.from].approx, points_[h.to].approx};
    auto pl = arcs_[static_cast<std::size_t>(h.arc)].polyline(err);
    if (!h.forward) std::reverse(pl.begin(), pl.end());
    return pl;
  };
  // Green's terms about the centre, not the origin: a cycle's sum is the same, and a plan
  // 1e10 from the origin keeps its digits (terms of 1e20 would round by 16384 each).
  const double cx = centre_.x(), cy = centre_.y();
  auto cross_about_centre = [&](const Point& a, const Point& b) { return (a.x() - cx) * (b.y() - cy) - (a.y() - cy) * (b.x() - cx); };
  auto piece_area2 = [&](const Half& h) {  // twice the signed area term (Green), circles exact
    const Point &a = points_[h.from].approx, &b = points_[h.to].approx;
    if (h.arc < 0 || family_ == SliceFamily::Spike || family_ == SliceFamily::Linear) return cross_about_centre(a, b);
    const MorseArc& arc = arcs_[static_cast<std::size_t>(h.arc)];
    if (family_ == SliceFamily::Squarel) {
      auto pl = arc.polyline(0);
      if (!h.forward) std::reverse(pl.begin(), pl.end());
      double s = 0;
      for (std::size_t i = 0; i + 1 < pl.size(); ++i) s += cross_about_centre(pl[i], pl[i + 1]);
      return s;
    }
    // A circle's arc about the centre: rho^2 times the angle it spans.
    const double rho2 = CGAL::to_double(arc.level);
    return rho2 * (h.forward ? arc.span : -arc.span);
  };
  std::vector<std::vector<std::uint32_t>> cycles;
  std::vector<double> cycle_area;
  std::vector<char> seen(halves.size(), 0);
  for (std::uint32_t h0 = 0; h0 < halves.size(); ++h0) {
    if (seen[h0]) continue;
    std::vector<std::uint32_t> cyc;
    double a2 = 0;
    std::uint32_t h = h0;
    while (!seen[h]) {
      seen[h] = 1;
      cyc.push_back(h);
      a2 += piece_area2(halves[h]);
      if (halves[h].next < 0) throw std::logic_error("morse: open face boundary");
      h = static_cast<std::uint32_t>(halves[h].next);
      if (cyc.size() > halves.size()) throw std::logic_error("morse: face tracing did not close");
    }
    if (h != h0) throw std::logic_error("morse: face tracing joined a cycle in its middle");
    cycles.push_back(std::move(cyc));
    cycle_area.push_back(a2 / 2);
  }
  // Components of the graph (inner cycles belong to the face around their component).
  std::vector<std::uint32_t> comp(points_.size());
  std::iota(comp.begin(), comp.end(), 0u);
  for (const Half& h : halves) comp[find(comp, h.from)] = find(comp, h.to);
  const auto box = env.bbox();
  const double scale = std::max({box.xmax() - box.xmin(), box.ymax() - box.ymin(), 1e-300});
  const double err = 1e-8 * scale, margin = 1e-7 * scale;
  // Cycles as polylines only where a point must be located: a coarse, padded box first, the
  // fine ring (arcs within err) on demand.
  std::vector<CGAL::Bbox_2> cycle_box(cycles.size());
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    CGAL::Bbox_2 b;
    for (const std::uint32_t h : cycles[k])
      for (const Point& p : piece_polyline(halves[h], 1e-3 * scale)) b += p.bbox();
    const double pad = 2e-3 * scale + margin;
    cycle_box[k] = CGAL::Bbox_2(b.xmin() - pad, b.ymin() - pad, b.xmax() + pad, b.ymax() + pad);
  }
  std::vector<std::vector<Point>> rings(cycles.size());
  auto ring = [&](std::size_t k) -> const std::vector<Point>& {
    if (rings[k].empty())
      for (const std::uint32_t h : cycles[k]) {
        auto pl = piece_polyline(halves[h], err);
        rings[k].insert(rings[k].end(), pl.begin(), pl.end() - 1);
      }
    return rings[k];
  };
  // Which cycles are inner: every component but the outer boundary's has one cycle around it
  // (its most negative); all other cycles bound cells. (Signs alone would misfile the slivers
  // between two critical slices that are exactly distinct but closer than double rounding.)
  std::vector<char> inner(cycles.size(), 0);
  {
    const std::uint32_t outer_comp = find(comp, B.vertex_point[0]);
    std::map<std::uint32_t, std::size_t> most_negative;
    for (std::size_t k = 0; k < cycles.size(); ++k) {
      const std::uint32_t cc = find(comp, halves[cycles[k][0]].from);
      if (cc == outer_comp) continue;
      auto [it, fresh] = most_negative.emplace(cc, k);
      if (!fresh && cycle_area[k] < cycle_area[it->second]) it->second = k;
    }
    for (const auto& [cc, k] : most_negative) inner[k] = 1;
  }
  std::vector<std::int32_t> cell_of_cycle(cycles.size(), -1);
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    if (inner[k]) continue;
    cell_of_cycle[k] = static_cast<std::int32_t>(cells_.size());
    MorseCell cell;
    cell.cycles.emplace_back();
    cells_.push_back(std::move(cell));
  }
  // The innermost outer cycle around a point (certified in double, else an error).
  auto enclosing = [&](const Point& x, std::uint32_t skip_comp) -> std::int32_t {
    for (const double phi : {0.3141592653589793, 1.9, 4.1, 5.3}) {
      bool unsure = false;
      std::int32_t best = -1;
      for (std::size_t k = 0; k < cycles.size(); ++k) {
        if (inner[k]) continue;
        if (find(comp, halves[cycles[k][0]].from) == skip_comp) continue;
        const auto& bb = cycle_box[k];
        if (x.x() < bb.xmin() || x.x() > bb.xmax() || x.y() < bb.ymin() || x.y() > bb.ymax()) continue;  // cannot hold x
        if (!ray_parity(x, phi, ring(k), margin, unsure)) continue;
        if (best < 0 || cycle_area[k] < cycle_area[static_cast<std::size_t>(best)]) best = static_cast<std::int32_t>(k);
      }
      if (!unsure) return best;
    }
    throw InputError("the " + std::string(to_string(family_)) + " decomposition around --center " + geometry::format_point(centre_) + ": " +
                     geometry::format_point(x) + " is within " + geometry::format_number(margin) +
                     " of a critical slice it is not on, too close to decide which cell holds it; move the centre slightly");
  };
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    if (!inner[k]) continue;
    const std::uint32_t cc = find(comp, halves[cycles[k][0]].from);
    const std::int32_t outer = enclosing(points_[halves[cycles[k][0]].from].approx, cc);
    if (outer < 0)
      throw std::logic_error("morse: an inner boundary (from " + geometry::format_point(points_[halves[cycles[k][0]].from].approx) +
                             ", area " + geometry::format_number(cycle_area[k]) + ", " + std::to_string(cycles[k].size()) + " pieces) lies in no cell" + [&] {
                               std::string t;
                               for (auto h : cycles[k]) t += " [" + geometry::format_point(points_[halves[h].from].approx) + "->" + geometry::format_point(points_[halves[h].to].approx) + " arc " + std::to_string(halves[h].arc) + (halves[h].forward ? "+" : "-") + "]";
                               return t; }());
    cell_of_cycle[k] = cell_of_cycle[static_cast<std::size_t>(outer)];
  }
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    MorseCell& cell = cells_[static_cast<std::size_t>(cell_of_cycle[k])];
    std::vector<MorsePiece> pieces;
    for (const std::uint32_t h : cycles[k]) pieces.push_back({halves[h].from, halves[h].to, halves[h].arc, halves[h].edge, halves[h].forward});
    if (!inner[k]) cell.cycles[0] = std::move(pieces);
    else cell.cycles.push_back(std::move(pieces));
    cell.area += cycle_area[k];
  }
  // Reeb nodes on each cell: its arcs, the birth/death points on its boundary, the minimum.
  for (MorseCell& cell : cells_) {
    for (const auto& cyc : cell.cycles)
      for (const MorsePiece& p : cyc) {
        if (p.arc >= 0) cell.nodes.push_back(arcs_[static_cast<std::size_t>(p.arc)].node);
        // A boundary piece leaving a contact leaves it in the wedge its edge starts.
        const bool at_contact = p.arc < 0 && points_[p.from].kind == MorsePoint::Kind::Vertex && env.is_contact(points_[p.from].id);
        const int k = critical_of(p.from, at_contact ? p.edge : 0);
        if (k >= 0 && critical_[static_cast<std::size_t>(k)].kind == CriticalKind::BirthDeath)
          cell.nodes.push_back(critical_[static_cast<std::size_t>(k)].node);
      }
  }
  if (centre_free_ && family_ != SliceFamily::Spike) {
    const std::int32_t k = enclosing(centre_, UINT32_MAX);
    if (k < 0) throw std::logic_error("morse: the centre lies in no cell");
    cells_[static_cast<std::size_t>(cell_of_cycle[static_cast<std::size_t>(k)])].nodes.push_back(
        critical_[static_cast<std::size_t>(critical_of(B.centre_point, 0))].node);
  }
  for (MorseCell& cell : cells_) {
    std::sort(cell.nodes.begin(), cell.nodes.end());
    cell.nodes.erase(std::unique(cell.nodes.begin(), cell.nodes.end()), cell.nodes.end());
  }
}

std::vector<std::vector<std::uint32_t>> MorseDecomposition::adjacency() const {
  std::vector<std::vector<std::uint32_t>> by_arc(arcs_.size());
  for (std::uint32_t k = 0; k < cells_.size(); ++k)
    for (const auto& cyc : cells_[k].cycles)
      for (const MorsePiece& p : cyc)
        if (p.arc >= 0) by_arc[static_cast<std::size_t>(p.arc)].push_back(k);
  return detail::adjacency_from_groups(by_arc, cells_.size());
}

std::vector<std::vector<Point>> MorseDecomposition::cell_rings(std::size_t cell, double max_error) const {
  std::vector<std::vector<Point>> out;
  for (const auto& cyc : cells_.at(cell).cycles) {
    std::vector<Point> ring;
    for (const MorsePiece& p : cyc) {
      std::vector<Point> pl;
      if (p.arc < 0) {
        pl = {points_[p.from].approx, points_[p.to].approx};
      } else {
        const MorseArc& a = arcs_[static_cast<std::size_t>(p.arc)];
        pl = a.polyline(max_error);
        if (!p.forward) std::reverse(pl.begin(), pl.end());
      }
      ring.insert(ring.end(), pl.begin(), pl.end() - 1);
    }
    out.push_back(std::move(ring));
  }
  return out;
}

std::optional<std::size_t> MorseDecomposition::cell_of(const Point& p) const {
  const auto box = env_->bbox();
  const double scale = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const auto rings = cell_rings(k, 1e-7 * scale);
    bool unsure = false, in = false;
    for (const auto& r : rings) in ^= ray_parity(p, 0.3141592653589793, r, 0, unsure);
    if (in) return k;
  }
  return std::nullopt;
}

}  // namespace preimage::decompose
