// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/geometry/local_frame.hpp>

#include <preimage/error.hpp>
#include <preimage/union_find.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>

namespace preimage::decompose {

BoustrophedonDecomposition::BoustrophedonDecomposition(const Environment& env, double angle_deg)
    : input_(&env), angle_(angle_deg) {
  // Sweep coordinates: rotate the input by -angle so the sweep runs along +x, about the
  // local frame's origin (a georeferenced plan rotated about (0, 0) would lose its digits).
  {
    const geometry::LocalFrame frame = geometry::LocalFrame::of(env);
    dx_ = frame.dx(), dy_ = frame.dy();
  }
  const double turns = angle_deg / 90.0;
  const bool quarter = std::isfinite(turns) && turns == std::round(turns);
  if (!std::isfinite(angle_deg)) throw InputError("--angle: not a finite number of degrees");
  int q = quarter ? static_cast<int>(((static_cast<long long>(std::llround(turns)) % 4) + 4) % 4) : 0;
  if (quarter) {
    const int c[4] = {1, 0, -1, 0}, s[4] = {0, 1, 0, -1};
    cos_ = c[q], sin_ = s[q];
  } else {
    const double a = angle_deg * std::numbers::pi / 180.0;
    cos_ = std::cos(a), sin_ = std::sin(a);
  }
  std::vector<geometry::Ring> rings;
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    geometry::Ring ring;
    for (std::size_t v = env.ring_begin(r); v < env.ring_end(r); ++v) ring.push_back(to_sweep(env.vertex(v)));
    rings.push_back(std::move(ring));
  }
  geometry::Ring outer = std::move(rings[0]);
  rings.erase(rings.begin());
  try {
    rotated_ = std::make_unique<Environment>(Environment::make(std::move(outer), std::move(rings)));
  } catch (const InputError& e) {
    throw InputError("sweep angle " + geometry::format_number(angle_deg) +
                     " degrees: the environment rotated to sweep coordinates is invalid (" + e.what() + ")");
  }
  trap_ = std::make_unique<TrapezoidalDecomposition>(*rotated_);
  by_xy_.resize(rotated_->num_vertices());
  std::iota(by_xy_.begin(), by_xy_.end(), 0u);
  std::sort(by_xy_.begin(), by_xy_.end(),
            [&](auto a, auto b) { return geometry::lex_less_xy(rotated_->vertex(a), rotated_->vertex(b)); });
  const auto& T = trap_->cells();
  const auto& X = trap_->extensions();
  const std::uint32_t nt = static_cast<std::uint32_t>(T.size());

  // Per event line: trapezoids closing (left) and opening (right) there, joined by the
  // extensions on that line. Node ids: 2t = t as a left (closing) cell, 2t+1 = as a right one.
  UnionFind line(2 * nt);
  for (const auto& e : X) line.join(2 * e.left_cell, 2 * e.right_cell + 1);
  struct Component { std::uint32_t left = 0, right = 0; std::uint32_t a_left = UINT32_MAX, a_right = UINT32_MAX; double x = 0; };
  std::map<std::uint32_t, Component> comp;
  for (std::uint32_t t = 0; t < nt; ++t) {
    auto& cl = comp[line.find(2 * t)];  // t closing at its x_right
    ++cl.left, cl.a_left = t, cl.x = T[t].x_right;
    auto& cr = comp[line.find(2 * t + 1)];  // t opening at its x_left
    ++cr.right, cr.a_right = t, cr.x = T[t].x_left;
  }
  // Regular components (one in, one out) glue trapezoids into cells.
  UnionFind cell(nt);
  for (auto& [root, c] : comp)
    if (c.left == 1 && c.right == 1) cell.join(c.a_left, c.a_right);

  std::vector<std::uint32_t> cell_id(nt, UINT32_MAX);
  cell_of_trapezoid_.assign(nt, 0);
  std::vector<std::uint32_t> by_x(nt);
  std::iota(by_x.begin(), by_x.end(), 0u);
  std::sort(by_x.begin(), by_x.end(), [&](auto a, auto b) { return T[a].x_left < T[b].x_left; });
  for (std::uint32_t t : by_x) {
    const std::uint32_t r = cell.find(t);
    if (cell_id[r] == UINT32_MAX) cell_id[r] = static_cast<std::uint32_t>(cells_.size()), cells_.push_back({});
    cell_of_trapezoid_[t] = cell_id[r];
    cells_[cell_id[r]].trapezoids.push_back(t);
  }
  // Critical slices: every other component, with its extent on the line.
  std::map<std::uint32_t, std::uint32_t> slice_of_root;
  for (auto& [root, c] : comp) {
    if (c.left == 1 && c.right == 1) continue;
    slice_of_root[root] = static_cast<std::uint32_t>(slices_.size());
    slices_.push_back({c.x, c.left, c.right, 0, 0});
  }
  std::vector<char> seen(slices_.size(), 0);
  auto widen = [&](std::uint32_t s, const ExactFT& lo, const ExactFT& hi) {
    if (!seen[s]) slices_[s].y_low = lo, slices_[s].y_high = hi, seen[s] = 1;
    slices_[s].y_low = CGAL::min(slices_[s].y_low, lo), slices_[s].y_high = CGAL::max(slices_[s].y_high, hi);
  };
  for (std::uint32_t t = 0; t < nt; ++t) {
    // A trapezoid side on a critical slice contributes its extent (floor to ceiling).
    for (int side = 0; side < 2; ++side) {
      auto it = slice_of_root.find(line.find(2 * t + static_cast<std::uint32_t>(side)));
      if (it == slice_of_root.end()) continue;
      const double x = side == 0 ? T[t].x_right : T[t].x_left;
      widen(it->second, trap_->edge_y(T[t].floor, x), trap_->edge_y(T[t].ceiling, x));
      auto& bc = cells_[cell_of_trapezoid_[t]];
      (side == 0 ? bc.right_slice : bc.left_slice) = it->second;
    }
  }
}

Point BoustrophedonDecomposition::to_sweep(const Point& p) const {  // rotation by -angle
  const double x = p.x() - dx_, y = p.y() - dy_;
  return Point(cos_ * x + sin_ * y, -sin_ * x + cos_ * y);
}

Point BoustrophedonDecomposition::to_input(const Point& p) const {
  return Point(cos_ * p.x() - sin_ * p.y() + dx_, sin_ * p.x() + cos_ * p.y() + dy_);
}

void BoustrophedonDecomposition::vertices_on_line(double c, const ExactFT& lo, const ExactFT& hi,
                                                  std::vector<std::uint32_t>& out) const {
  const Environment& E = *rotated_;
  const ExactFT& bottom = lo < hi ? lo : hi;
  const ExactFT& top = lo < hi ? hi : lo;
  auto it = std::lower_bound(by_xy_.begin(), by_xy_.end(), c, [&](std::uint32_t v, double x) { return E.vertex(v).x() < x; });
  const std::size_t first = out.size();
  for (; it != by_xy_.end() && E.vertex(*it).x() == c; ++it) {
    const ExactFT y = E.vertex(*it).y();
    if (bottom < y && y < top) out.push_back(*it);
  }
  if (hi < lo) std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

CellChains BoustrophedonDecomposition::chains(std::size_t c) const { return chains(cells_[c].trapezoids); }

CellChains BoustrophedonDecomposition::chains(const std::vector<std::uint32_t>& ts) const {
  const auto& T = trap_->cells();
  const Environment& E = *rotated_;
  CellChains out;
  std::vector<std::uint32_t> between;
  // One chain: the floor (or ceiling) edge of each trapezoid from its left side to its
  // right side; where two trapezoids meet on a line x = c and their floors do not, the
  // boundary runs along that line (inside a cell it is a wall, free on one side only;
  // between merged cells also the side of a cell the union leaves out), through every
  // environment vertex on it.
  auto build = [&](bool floor, std::vector<ExactPoint>& pts, std::vector<std::uint32_t>& ids, std::vector<std::uint32_t>& edges) {
    auto push = [&](const ExactPoint& p, std::uint32_t id, std::uint32_t edge) {
      if (!pts.empty() && pts.back() == p) return;
      pts.push_back(p), ids.push_back(id), edges.push_back(edge);
    };
    auto at = [&](std::uint32_t t, double x) {
      const std::uint32_t e = floor ? T[t].floor : T[t].ceiling;
      const std::uint32_t a = e, b = static_cast<std::uint32_t>(E.next(e));
      if (E.vertex(a).x() == x) return std::tuple{E.exact_vertex(a), a, e};
      if (E.vertex(b).x() == x) return std::tuple{E.exact_vertex(b), b, e};
      return std::tuple{ExactPoint(x, trap_->edge_y(e, x)), CellChains::kNoVertex, e};
    };
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const auto [l, lid, le] = at(ts[i], T[ts[i]].x_left);
      if (i > 0 && !pts.empty() && pts.back() != l) {
        between.clear();
        vertices_on_line(T[ts[i]].x_left, pts.back().y(), l.y(), between);
        for (auto v : between) push(E.exact_vertex(v), v, v);
      }
      push(l, lid, le);
      const auto [r, rid, re] = at(ts[i], T[ts[i]].x_right);
      push(r, rid, re);
    }
  };
  build(true, out.floor, out.floor_vertex, out.floor_edge);
  build(false, out.ceiling, out.ceiling_vertex, out.ceiling_edge);
  return out;
}

std::vector<ExactPoint> BoustrophedonDecomposition::outline(std::size_t c, std::vector<std::uint32_t>& ids) const {
  const CellChains ch = chains(c);
  const Environment& E = *rotated_;
  std::vector<ExactPoint> out;
  ids.clear();
  auto push = [&](const ExactPoint& p, std::uint32_t id) {
    if (!out.empty() && out.back() == p) return;
    out.push_back(p), ids.push_back(id);
  };
  std::vector<std::uint32_t> side;
  auto push_side = [&](const ExactPoint& from, const ExactPoint& to) {
    side.clear();
    vertices_on_line(CGAL::to_double(from.x()), from.y(), to.y(), side);
    for (auto v : side) push(E.exact_vertex(v), v);
  };
  // Floor left to right, right side upwards, ceiling right to left, left side downwards;
  // a side is the segment x = const between floor and ceiling, walls and extensions alike.
  for (std::size_t i = 0; i < ch.floor.size(); ++i) push(ch.floor[i], ch.floor_vertex[i]);
  push_side(ch.floor.back(), ch.ceiling.back());
  for (std::size_t i = ch.ceiling.size(); i-- > 0;) push(ch.ceiling[i], ch.ceiling_vertex[i]);
  push_side(ch.ceiling.front(), ch.floor.front());
  if (out.size() > 1 && out.front() == out.back()) out.pop_back(), ids.pop_back();
  // A point inside an edge (where another chain had an event) is a straight vertex of the
  // outline: keep only the corners.
  std::vector<ExactPoint> kept;
  std::vector<std::uint32_t> kept_ids;
  const std::size_t n = out.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (n > 3 && ids[i] == CellChains::kNoVertex &&
        CGAL::collinear(out[(i + n - 1) % n], out[i], out[(i + 1) % n]))
      continue;
    kept.push_back(out[i]), kept_ids.push_back(ids[i]);
  }
  ids = std::move(kept_ids);
  return kept;
}

std::vector<ExactPoint> BoustrophedonDecomposition::exact_polygon(std::size_t c) const {
  std::vector<std::uint32_t> ids;
  return outline(c, ids);
}

std::vector<Point> BoustrophedonDecomposition::polygon(std::size_t c) const {
  std::vector<std::uint32_t> ids;
  const auto exact = outline(c, ids);
  std::vector<Point> out;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    // Environment vertices map back to their input coordinates exactly.
    const Point p = ids[i] != CellChains::kNoVertex ? input_vertex(ids[i]) : to_input(geometry::to_double(exact[i]));
    if (out.empty() || out.back() != p) out.push_back(p);
  }
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

ExactFT BoustrophedonDecomposition::area(std::size_t c) const {
  ExactFT a = 0;
  for (auto t : cells_[c].trapezoids) a += trap_->area(t);
  return a;
}

std::vector<std::vector<std::uint32_t>> BoustrophedonDecomposition::adjacency() const {
  std::vector<std::vector<std::uint32_t>> adj(cells_.size());
  for (const auto& e : trap_->extensions()) {
    const std::uint32_t a = cell_of_trapezoid_[e.left_cell], b = cell_of_trapezoid_[e.right_cell];
    if (a == b) continue;
    if (std::find(adj[a].begin(), adj[a].end(), b) == adj[a].end()) adj[a].push_back(b), adj[b].push_back(a);
  }
  return adj;
}

}  // namespace preimage::decompose
