// SPDX-License-Identifier: Apache-2.0
#include <preimage/landmarks/swap_cells.hpp>
#include <preimage/union_find.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace preimage::landmarks {
namespace {

using geometry::ExactFT;
using geometry::ExactPoint;
using EVector = geometry::ExactKernel::Vector_2;

// Where a vertex sits on a ray: parameter t of p_from + t (p_from - p_away), and vertex.
struct Stop {
  ExactFT t;
  std::uint32_t vertex;
};

}  // namespace

SwapCellDecomposition SwapCellDecomposition::of(std::span<const geometry::Point> landmarks,
                                                const std::function<void(double)>& progress) {
  require_general_position(landmarks);
  SwapCellDecomposition D;
  const std::uint32_t n = static_cast<std::uint32_t>(landmarks.size());
  for (const auto& p : landmarks) D.P_.push_back(geometry::to_exact(p));
  const auto& L = landmarks;
  const auto& P = D.P_;
  D.hull_ = OrderType::of(landmarks).hull();
  for (std::uint32_t i = 0; i < n; ++i) {
    D.vertices_.push_back({P[i], Vertex::Kind::Landmark, i});
    for (std::uint32_t j = 0; j < n; ++j)
      if (i != j) D.rays_.push_back({i, j});
  }
  const std::uint32_t R = static_cast<std::uint32_t>(D.rays_.size());
  auto ray_id = [n](std::uint32_t i, std::uint32_t j) { return i * (n - 1) + (j < i ? j : j - 1); };
  std::vector<EVector> dir(R);
  for (std::uint32_t r = 0; r < R; ++r) dir[r] = P[D.rays_[r].from] - P[D.rays_[r].away];

  // 1. Crossings, one per pair of lines of four distinct landmarks at most. On line ij,
  //    line kl meets a swap ray iff k and l lie on one side of line ij, and then the ray
  //    of the one nearer to line ij (equal distance: parallel lines).
  std::vector<std::vector<Stop>> on_ray(R);
  auto which_ray = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k, std::uint32_t l) -> std::uint32_t {
    const int ok = geometry::orientation(L[i], L[j], L[k]), ol = geometry::orientation(L[i], L[j], L[l]);
    if (ok != ol) return kNone;  // line ij crosses the segment p_k p_l
    const auto c = CGAL::compare_signed_distance_to_line(L[i], L[j], L[k], L[l]);
    if (c == CGAL::EQUAL) return kNone;
    const bool k_nearer = (c == CGAL::SMALLER) == (ok > 0);
    return k_nearer ? ray_id(k, l) : ray_id(l, k);
  };
  for (std::uint32_t i = 0; i < n; ++i) {
    if (progress) {  // the work left after row i shrinks as (n - i)^3
      const double left = double(n - i) / n;
      progress(0.6 * (1 - left * left * left));
    }
    for (std::uint32_t j = i + 1; j < n; ++j)
      for (std::uint32_t k = i + 1; k < n; ++k)
        for (std::uint32_t l = k + 1; l < n; ++l) {
          if (k == j || l == j) continue;
          const std::uint32_t s = which_ray(i, j, k, l);  // the ray of line kl that meets line ij
          if (s == kNone) continue;
          const std::uint32_t r = which_ray(k, l, i, j);
          if (r == kNone) continue;
          // The crossing X = p_r + t dir_r with f(X) = 0, f the signed area against line s.
          const auto& a = P[D.rays_[s].from];
          const EVector e = dir[s];
          const ExactPoint& o = P[D.rays_[r].from];
          const ExactFT fo = CGAL::determinant(e, o - a), fd = CGAL::determinant(e, dir[r]);
          const ExactFT t = -fo / fd;
          const ExactPoint X = o + dir[r] * t;
          // The parameter along s: X = a + u dir_s, by the same rule against line r.
          const ExactFT u = -CGAL::determinant(dir[r], a - o) / CGAL::determinant(dir[r], dir[s]);
          const std::uint32_t v = static_cast<std::uint32_t>(D.vertices_.size());
          D.vertices_.push_back({X, Vertex::Kind::Crossing, kNone});
          on_ray[r].push_back({t, v});
          on_ray[s].push_back({u, v});
        }
  }

  // 2. Concurrent crossings (three or more rays through one point) are one vertex: equal
  //    parameters on a ray are equal points; union them.
  UnionFind same(D.vertices_.size());
  for (auto& stops : on_ray) {
    std::sort(stops.begin(), stops.end(), [](const Stop& a, const Stop& b) { return a.t < b.t; });
    for (std::size_t q = 1; q < stops.size(); ++q)
      if (stops[q].t == stops[q - 1].t) same.join(stops[q].vertex, stops[q - 1].vertex);
  }

  // 3. A box strictly containing every vertex. Interval bounding boxes are enclosures,
  //    but not always finite: far crossings of nearly parallel lines, or tiny coordinates
  //    whose products underflow, give infinite intervals (an infinite box once made GMP
  //    raise SIGFPE). Then the exact coordinates bound the box instead.
  if (progress) progress(0.6);
  ExactFT x0, x1, y0, y1;
  {
    CGAL::Bbox_2 box = D.vertices_.front().p.bbox();
    for (const auto& v : D.vertices_) box += v.p.bbox();
    const double margin = 1.0 + 0.25 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    const double b[4] = {box.xmin() - margin, box.xmax() + margin, box.ymin() - margin, box.ymax() + margin};
    if (std::all_of(b, b + 4, [](double v) { return std::isfinite(v); })) {
      x0 = b[0], x1 = b[1], y0 = b[2], y1 = b[3];
    } else {
      ExactFT lo[2], hi[2];
      for (std::size_t q = 0; q < D.vertices_.size(); ++q) {
        const auto& p = D.vertices_[q].p;
        const auto bb = p.bbox();
        for (int c = 0; c < 2; ++c) {
          const double l = c ? bb.ymin() : bb.xmin(), h = c ? bb.ymax() : bb.xmax();
          const ExactFT exact = c ? p.y() : p.x();
          const ExactFT L = std::isfinite(l) ? ExactFT(l) : exact, H = std::isfinite(h) ? ExactFT(h) : exact;
          if (q == 0 || L < lo[c]) lo[c] = L;
          if (q == 0 || H > hi[c]) hi[c] = H;
        }
      }
      const ExactFT m = 1 + CGAL::max(hi[0] - lo[0], hi[1] - lo[1]) / 4;
      x0 = lo[0] - m, x1 = hi[0] + m, y0 = lo[1] - m, y1 = hi[1] + m;
    }
  }
  // Exits: each ray leaves the box once; perimeter position (side, coordinate) orders them
  // counter-clockwise from the corner (x0, y0): bottom, right, top, left.
  struct Exit {
    int side;
    ExactFT along;  // increasing counter-clockwise
    std::uint32_t vertex;
  };
  std::vector<Exit> exits;
  std::vector<std::uint32_t> exit_vertex(R);
  for (std::uint32_t r = 0; r < R; ++r) {
    const ExactPoint& o = P[D.rays_[r].from];
    const EVector& d = dir[r];
    std::optional<ExactFT> best;
    int side = 0;
    auto consider = [&](int s, const ExactFT& t) {
      if (!best || t < *best) best = t, side = s;
    };
    if (d.x() > 0) consider(1, (x1 - o.x()) / d.x());
    if (d.x() < 0) consider(3, (x0 - o.x()) / d.x());
    if (d.y() > 0) consider(2, (y1 - o.y()) / d.y());
    if (d.y() < 0) consider(0, (y0 - o.y()) / d.y());
    const ExactPoint X = o + d * *best;
    const ExactFT along = side == 0 ? X.x() : side == 1 ? X.y() : side == 2 ? -X.x() : -X.y();
    exit_vertex[r] = static_cast<std::uint32_t>(D.vertices_.size());
    exits.push_back({side, along, exit_vertex[r]});
    D.vertices_.push_back({X, Vertex::Kind::Box, kNone});
  }
  // Corners start their side (a ray leaving through a corner merges with it).
  const ExactPoint corner[4] = {ExactPoint(x0, y0), ExactPoint(x1, y0), ExactPoint(x1, y1), ExactPoint(x0, y1)};
  for (int s = 0; s < 4; ++s) {
    const std::uint32_t v = static_cast<std::uint32_t>(D.vertices_.size());
    D.vertices_.push_back({corner[s], Vertex::Kind::Box, kNone});
    const ExactFT along = s == 0 ? x0 : s == 1 ? y0 : s == 2 ? -x1 : -y1;
    exits.push_back({s, along, v});
  }
  same.grow(D.vertices_.size());
  std::sort(exits.begin(), exits.end(), [](const Exit& a, const Exit& b) {
    if (a.side != b.side) return a.side < b.side;
    return a.along < b.along;
  });
  for (std::size_t q = 1; q < exits.size(); ++q)
    if (exits[q].side == exits[q - 1].side && exits[q].along == exits[q - 1].along)
      same.join(exits[q].vertex, exits[q - 1].vertex);
  // An exit exactly at a corner sorts at the end of the previous side: merge it too.
  for (std::size_t q = 0; q < exits.size(); ++q) {
    const auto& e = exits[q];
    if (D.vertices_[e.vertex].p == corner[(e.side + 1) % 4])
      same.join(e.vertex, static_cast<std::uint32_t>(D.vertices_.size() - 4 + (e.side + 1) % 4));
  }

  // 4. Half-edges: the pieces of each ray and of the box; twins are h and h ^ 1.
  std::vector<ExactPoint> heading;  // a point in the direction of each half-edge, from the origin
  auto add_edge = [&](std::uint32_t a, std::uint32_t b, std::uint32_t ray, const EVector& d) {
    a = same.find(a), b = same.find(b);
    if (a == b) return;
    D.half_edges_.push_back({a, b, kNone, kNone, ray});
    D.half_edges_.push_back({b, a, kNone, kNone, ray});
    heading.push_back(CGAL::ORIGIN + d);
    heading.push_back(CGAL::ORIGIN - d);
  };
  // The hull's interior along each ray of an interior landmark: up to the hull edge it
  // leaves through (rays of hull landmarks never enter it).
  std::vector<bool> on_hull(n, false);
  for (auto h : D.hull_) on_hull[h] = true;
  for (std::uint32_t r = 0; r < R; ++r) {
    const std::uint32_t i = D.rays_[r].from;
    std::optional<ExactFT> t_hull;
    if (!on_hull[i]) {
      const std::size_t m = D.hull_.size();
      for (std::size_t q = 0; q < m && !t_hull; ++q) {
        const ExactPoint &a = P[D.hull_[q]], &b = P[D.hull_[(q + 1) % m]];
        // The ray leaves through edge ab iff its direction points between a and b.
        const ExactPoint far = P[i] + dir[r];
        if (geometry::orientation(P[i], far, a) < 0 && geometry::orientation(P[i], far, b) > 0) {
          const ExactFT fo = CGAL::determinant(b - a, P[i] - a), fd = CGAL::determinant(b - a, dir[r]);
          t_hull = -fo / fd;
        }
      }
    }
    std::uint32_t prev = i;
    ExactFT prev_t = 0;
    auto piece = [&](std::uint32_t v, const ExactFT* t) {
      const std::size_t before = D.half_edges_.size();
      add_edge(prev, v, r, dir[r]);
      if (D.half_edges_.size() > before && t_hull && prev_t < *t_hull)
        D.half_edges_[before].meets_hull = D.half_edges_[before + 1].meets_hull = true;
      prev = v;
      if (t) prev_t = *t;
    };
    for (std::size_t q = 0; q < on_ray[r].size(); ++q)
      if (q == 0 || on_ray[r][q].t != on_ray[r][q - 1].t) piece(on_ray[r][q].vertex, &on_ray[r][q].t);
    piece(exit_vertex[r], nullptr);
  }
  for (std::size_t q = 0; q < exits.size(); ++q) {
    const auto& a = exits[q];
    const auto& b = exits[(q + 1) % exits.size()];
    const int s = a.side;  // to the next exit on this side, or to the corner that ends it
    static const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
    add_edge(a.vertex, b.vertex, kNone, EVector(dx[s], dy[s]));
  }

  if (progress) progress(0.75);
  // 5. Around each vertex, outgoing half-edges counter-clockwise; next(h) is the
  //    clockwise neighbour of twin(h) at h's target (the cell on the left continues).
  const std::uint32_t H = static_cast<std::uint32_t>(D.half_edges_.size());
  std::vector<std::vector<std::uint32_t>> out(D.vertices_.size());
  for (std::uint32_t h = 0; h < H; ++h) out[D.half_edges_[h].origin].push_back(h);
  const ExactPoint O = CGAL::ORIGIN;
  for (auto& o : out) {
    std::sort(o.begin(), o.end(), [&](std::uint32_t a, std::uint32_t b) { return geometry::ccw_less(O, heading[a], heading[b]); });
    for (std::size_t q = 0; q < o.size(); ++q) D.half_edges_[twin(o[q])].next = o[(q + o.size() - 1) % o.size()];
  }
  for (std::uint32_t h = 0; h < H; ++h)
    if (D.half_edges_[h].next == kNone) throw std::logic_error("swap cells: an unlinked half-edge");

  // 6. Cells: cycles of next; the outside of the box (left of the box's twins) is none.
  std::vector<std::uint32_t> cycle(H, kNone);
  std::uint32_t outside = kNone;
  for (std::uint32_t h = 0; h < H; ++h) {
    if (cycle[h] != kNone) continue;
    const std::uint32_t c = static_cast<std::uint32_t>(D.cells_.size());
    bool box_outside = false, touches_box = false;
    for (std::uint32_t e = h; cycle[e] == kNone; e = D.half_edges_[e].next) {
      cycle[e] = c;
      if (D.half_edges_[e].ray == kNone) {
        touches_box = true;
        // Box half-edges run counter-clockwise (odd twins clockwise, outside on the left).
        if (e % 2 == 1) box_outside = true;
      }
    }
    if (box_outside) {
      outside = c;
    }
    D.cells_.push_back({{}, false, touches_box, h});
  }
  if (outside == kNone) throw std::logic_error("swap cells: no outer face");
  // Drop the outside: renumber.
  D.cells_.erase(D.cells_.begin() + outside);
  for (std::uint32_t h = 0; h < H; ++h)
    D.half_edges_[h].cell = cycle[h] == outside ? kNone : (cycle[h] > outside ? cycle[h] - 1 : cycle[h]);

  if (progress) progress(0.9);
  // 7. Permutations: read one cell, then transpose across rays (Lemma 6's first case).
  //    The cell left of a piece of ray (i, j) traversed forwards (direction p_j -> p_i)
  //    sees j right before i; a reading at the piece's midpoint with that tie is exact.
  auto read_left_of = [&](std::uint32_t h) {
    const auto& e = D.half_edges_[h];
    const ExactPoint mid = CGAL::midpoint(D.vertices_[e.origin].p, D.vertices_[e.target].p);
    const EVector d = heading[h] - O;
    const ExactPoint left = mid + EVector(-d.y(), d.x());
    return normalized(angular_reading(P, mid, std::nullopt, &left, {}));
  };
  std::vector<bool> seen(D.cells_.size(), false);
  std::vector<std::uint32_t> queue;
  for (std::uint32_t h = 0; h < H && queue.empty(); ++h)
    if (D.half_edges_[h].ray != kNone && D.half_edges_[h].cell != kNone) {
      D.cells_[D.half_edges_[h].cell].permutation = read_left_of(h);
      seen[D.half_edges_[h].cell] = true;
      queue.push_back(D.half_edges_[h].cell);
    }
  std::vector<std::vector<std::uint32_t>> cell_half_edges(D.cells_.size());
  for (std::uint32_t h = 0; h < H; ++h)
    if (D.half_edges_[h].cell != kNone) cell_half_edges[D.half_edges_[h].cell].push_back(h);
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const std::uint32_t c = queue[q];
    for (auto h : cell_half_edges[c]) {
      const auto& e = D.half_edges_[h];
      if (e.ray == kNone) continue;
      const std::uint32_t g = D.half_edges_[twin(h)].cell;
      Reading p = normalized(transposed(D.cells_[c].permutation, D.rays_[e.ray].from, D.rays_[e.ray].away));
      if (!seen[g]) {
        seen[g] = true;
        D.cells_[g].permutation = std::move(p);
        queue.push_back(g);
      } else if (D.cells_[g].permutation != p) {
        throw std::logic_error("swap cells: inconsistent permutations across a swap ray");
      }
    }
  }
  if (queue.size() != D.cells_.size()) throw std::logic_error("swap cells: the dual is not connected");

  // 8. Cells meeting the hull: those along a ray piece inside it; with no interior
  //    landmark no ray enters, and the one cell read at a point inside the hull.
  bool any = false;
  for (std::uint32_t h = 0; h < H; ++h)
    if (D.half_edges_[h].meets_hull && D.half_edges_[h].cell != kNone) D.cells_[D.half_edges_[h].cell].meets_hull = any = true;
  if (!any) {
    const ExactPoint inside = CGAL::centroid(P[D.hull_[0]], P[D.hull_[1]], P[D.hull_[2]]);
    const Reading r = normalized(angular_reading(P, inside, std::nullopt, nullptr, {}));
    for (auto& c : D.cells_)
      if (c.permutation == r) c.meets_hull = true;
  }

  // 9. The swap graph. With three landmarks a cell outside the hull borders the inside
  //    cell along both swap lines of its landmark (either transposition gives the same
  //    cyclic order): one edge, labelled by the least pair.
  std::unordered_map<std::uint64_t, std::size_t> edge_of;
  for (std::uint32_t h = 0; h < H; h += 2) {
    const auto& e = D.half_edges_[h];
    if (e.ray == kNone) continue;
    std::uint32_t a = e.cell, b = D.half_edges_[h + 1].cell;
    if (a > b) std::swap(a, b);
    const std::uint64_t key = (std::uint64_t(a) << 32) | b;
    auto [it, fresh] = edge_of.emplace(key, D.graph_.size());
    const auto [i, j] = std::minmax(D.rays_[e.ray].from, D.rays_[e.ray].away);
    if (fresh) D.graph_.push_back({a, b, i, j, false});
    auto& edge = D.graph_[it->second];
    if (std::pair{i, j} < std::pair{edge.i, edge.j}) edge.i = i, edge.j = j;
    edge.meets_hull = edge.meets_hull || e.meets_hull;
  }

  // Lines through each crossing vertex, for vertex keys.
  D.vertex_rays_.assign(D.vertices_.size(), {});
  for (std::uint32_t h = 0; h < H; h += 2) {
    const auto& e = D.half_edges_[h];
    if (e.ray == kNone) continue;
    for (auto v : {e.origin, e.target})
      if (D.vertices_[v].kind == Vertex::Kind::Crossing) D.vertex_rays_[v].push_back(e.ray);
  }
  for (auto& v : D.vertex_rays_) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  return D;
}

std::vector<std::uint32_t> SwapCellDecomposition::boundary(std::uint32_t cell) const {
  std::vector<std::uint32_t> out;
  const std::uint32_t h0 = cells_.at(cell).half_edge;
  std::uint32_t h = h0;
  do {
    out.push_back(half_edges_[h].origin);
    h = half_edges_[h].next;
  } while (h != h0);
  return out;
}

std::vector<std::uint32_t> SwapCellDecomposition::vertex_key(std::uint32_t v) const {
  const std::uint32_t n = static_cast<std::uint32_t>(P_.size());
  const auto& V = vertices_.at(v);
  if (V.kind == Vertex::Kind::Landmark) return {n * n + V.landmark};
  std::vector<std::uint32_t> key;
  for (auto r : vertex_rays_[v]) {
    const auto [i, j] = std::minmax(rays_[r].from, rays_[r].away);
    key.push_back(i * n + j);
  }
  std::sort(key.begin(), key.end());
  key.erase(std::unique(key.begin(), key.end()), key.end());
  return key;
}

std::vector<std::vector<std::uint32_t>> SwapCellDecomposition::vertex_keys(std::uint32_t cell) const {
  std::vector<std::vector<std::uint32_t>> keys;
  for (auto v : boundary(cell))
    if (vertices_[v].kind != Vertex::Kind::Box) keys.push_back(vertex_key(v));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace preimage::landmarks
