// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/generators.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace preimage::geometry::generators {

Ring random_simple_polygon(std::size_t n, std::uint64_t seed, double size) {
  if (n < 3) throw std::invalid_argument("random_simple_polygon: n < 3");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(0.0, size), unit(0.05, 0.95);
  std::vector<Point> pts;
  pts.reserve(n);
  while (pts.size() < n) {
    pts.emplace_back(coord(rng), coord(rng));
    if (pts.size() == n) {  // distinct points only
      std::sort(pts.begin(), pts.end(), lex_less_xy);
      pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
      std::shuffle(pts.begin(), pts.end(), rng);
    }
  }
  // Tasks: chain from a to b (b excluded) through the points idx[lo, hi).
  std::vector<std::uint32_t> idx(n - 2);
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<std::uint32_t>(i + 2);
  struct Task { std::uint32_t a, b; std::size_t lo, hi; };
  const std::uint32_t s = 0, t = 1;
  // First split by the line s t; points on it are rare and are moved off by resampling.
  auto mid = std::partition(idx.begin(), idx.end(), [&](auto i) { return orientation(pts[s], pts[t], pts[i]) < 0; });
  for (auto it = mid; it != idx.end(); ++it)
    while (orientation(pts[s], pts[t], pts[*it]) == 0) pts[*it] = Point(coord(rng), coord(rng));
  mid = std::partition(idx.begin(), idx.end(), [&](auto i) { return orientation(pts[s], pts[t], pts[i]) < 0; });
  const std::size_t k = static_cast<std::size_t>(mid - idx.begin());
  std::vector<Task> stack{{t, s, k, idx.size()}, {s, t, 0, k}};  // right chain s->t first
  Ring out;
  out.reserve(n);
  while (!stack.empty()) {
    Task task = stack.back();
    stack.pop_back();
    if (task.lo == task.hi) {
      out.push_back(pts[task.a]);
      continue;
    }
    std::uniform_int_distribution<std::size_t> pick(task.lo, task.hi - 1);
    std::swap(idx[task.lo], idx[pick(rng)]);
    const std::uint32_t c = idx[task.lo];
    const Point &a = pts[task.a], &b = pts[task.b];
    // A random line through c that crosses segment ab; no point may lie on it.
    for (int attempt = 0;; ++attempt) {
      const double u = unit(rng);
      const Point m(a.x() + u * (b.x() - a.x()), a.y() + u * (b.y() - a.y()));
      const int side_a = orientation(pts[c], m, a);
      if (side_a == 0 || side_a == orientation(pts[c], m, b)) continue;
      bool clean = true;
      for (std::size_t i = task.lo + 1; i < task.hi && clean; ++i) clean = orientation(pts[c], m, pts[idx[i]]) != 0;
      if (!clean) {
        if (attempt > 100) throw std::runtime_error("random_simple_polygon: degenerate split");
        continue;
      }
      auto first = idx.begin() + static_cast<std::ptrdiff_t>(task.lo + 1);
      auto split = std::partition(first, idx.begin() + static_cast<std::ptrdiff_t>(task.hi),
                                  [&](auto i) { return orientation(pts[c], m, pts[i]) == side_a; });
      const std::size_t sp = static_cast<std::size_t>(split - idx.begin());
      stack.push_back({c, task.b, sp, task.hi});
      stack.push_back({task.a, c, task.lo + 1, sp});
      break;
    }
  }
  return out;
}

Environment random_environment(std::size_t n, std::size_t holes, std::uint64_t seed) {
  if (holes == 0) return Environment::make(random_simple_polygon(n, seed, 100.0), {});
  std::mt19937_64 rng(seed);
  const std::size_t per_hole = std::max<std::size_t>(3, n / 2 / holes);
  const std::size_t outer_n = std::max<std::size_t>(8, n - per_hole * holes);
  // Star-shaped outer boundary: radius in [0.9 R, R] keeps the disc of 0.9 R free.
  const double R = 100.0;
  std::uniform_real_distribution<double> rad(0.9 * R, R);
  Ring outer;
  for (std::size_t i = 0; i < outer_n; ++i) {
    const double th = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(outer_n);
    const double r = rad(rng);
    outer.emplace_back(r * std::cos(th), r * std::sin(th));
  }
  // Holes in the cells of a g x g grid inside the square inscribed in the free disc.
  const std::size_t g = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(holes))));
  const double half = 0.9 * R / std::sqrt(2.0) * 0.98, cell = 2 * half / static_cast<double>(g);
  std::vector<std::size_t> cells(g * g);
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = i;
  std::shuffle(cells.begin(), cells.end(), rng);
  std::vector<Ring> hs;
  std::uniform_real_distribution<double> fill(0.5, 0.8);
  for (std::size_t h = 0; h < holes; ++h) {
    Ring r = random_simple_polygon(per_hole, rng(), 1.0);
    const double s = cell * fill(rng);
    const double ox = -half + static_cast<double>(cells[h] % g) * cell + (cell - s) / 2;
    const double oy = -half + static_cast<double>(cells[h] / g) * cell + (cell - s) / 2;
    for (auto& p : r) p = Point(ox + s * p.x(), oy + s * p.y());
    hs.push_back(std::move(r));
  }
  return Environment::make(std::move(outer), std::move(hs));
}

Ring star(std::size_t points, double r_in, double r_out) {
  Ring r;
  for (std::size_t i = 0; i < 2 * points; ++i) {
    const double th = std::numbers::pi * static_cast<double>(i) / static_cast<double>(points);
    const double rad = i % 2 ? r_in : r_out;
    r.emplace_back(rad * std::cos(th), rad * std::sin(th));
  }
  return r;
}

Ring comb(std::size_t teeth, double w, double gap, double height) {
  Ring r;
  const double base = 1.0;
  const double width = static_cast<double>(teeth) * (w + gap) - gap;
  r.emplace_back(0, 0);
  r.emplace_back(width, 0);
  for (std::size_t k = teeth; k-- > 0;) {
    const double x0 = static_cast<double>(k) * (w + gap);
    r.emplace_back(x0 + w, base + height);
    r.emplace_back(x0, base + height);
    if (k > 0) {
      r.emplace_back(x0, base);
      r.emplace_back(x0 - gap, base);
    }
  }
  // The first pushed tooth corner sits above (width, 0): make that side vertical.
  r[2] = Point(width, base + height);
  r.insert(r.begin() + 2, Point(width, base));  // collinear vertex on the right side
  return r;
}

Ring spiral(double turns, double corridor, std::size_t per_turn) {
  const double pitch = 2.0 * corridor;  // walls between turns are one corridor thick
  const std::size_t n = std::max<std::size_t>(8, static_cast<std::size_t>(turns * static_cast<double>(per_turn)));
  Ring inner, outer;
  for (std::size_t i = 0; i <= n; ++i) {
    const double th = 2 * std::numbers::pi * turns * static_cast<double>(i) / static_cast<double>(n);
    const double rc = 2.0 * corridor + pitch * th / (2 * std::numbers::pi);
    outer.emplace_back((rc + corridor / 2) * std::cos(th), (rc + corridor / 2) * std::sin(th));
    inner.emplace_back((rc - corridor / 2) * std::cos(th), (rc - corridor / 2) * std::sin(th));
  }
  Ring r(outer.begin(), outer.end());
  r.insert(r.end(), inner.rbegin(), inner.rend());
  return r;
}

Environment office(std::size_t rows, std::size_t cols, double room) {
  const double W = static_cast<double>(cols) * room, H = static_cast<double>(rows) * room;
  const double t = 0.1 * room / 4, door = room / 4, junction = room / 8;
  // Outer wall with a collinear vertex at every room boundary.
  Ring outer;
  for (std::size_t i = 0; i < cols; ++i) outer.emplace_back(static_cast<double>(i) * room, 0);
  for (std::size_t j = 0; j < rows; ++j) outer.emplace_back(W, static_cast<double>(j) * room);
  for (std::size_t i = cols; i > 0; --i) outer.emplace_back(static_cast<double>(i) * room, H);
  for (std::size_t j = rows; j > 0; --j) outer.emplace_back(0, static_cast<double>(j) * room);
  // Interior walls: on every grid line, between junctions, split by a door in the middle.
  std::vector<Ring> walls;
  auto wall = [&](double x0, double y0, double x1, double y1) {  // axis-aligned box, midpoint vertices on long sides
    const double mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
    if (x1 - x0 > y1 - y0)
      walls.push_back({{x0, y0}, {mx, y0}, {x1, y0}, {x1, y1}, {mx, y1}, {x0, y1}});
    else
      walls.push_back({{x0, y0}, {x1, y0}, {x1, my}, {x1, y1}, {x0, y1}, {x0, my}});
  };
  const double seg = (room - 2 * junction - door) / 2;
  for (std::size_t j = 1; j < rows; ++j)
    for (std::size_t i = 0; i < cols; ++i) {
      const double y = static_cast<double>(j) * room, x = static_cast<double>(i) * room + junction;
      wall(x, y - t, x + seg, y + t);
      wall(x + seg + door, y - t, x + 2 * seg + door, y + t);
    }
  for (std::size_t i = 1; i < cols; ++i)
    for (std::size_t j = 0; j < rows; ++j) {
      const double x = static_cast<double>(i) * room, y = static_cast<double>(j) * room + junction;
      wall(x - t, y, x + t, y + seg);
      wall(x - t, y + seg + door, x + t, y + 2 * seg + door);
    }
  return Environment::make(std::move(outer), std::move(walls));
}

}  // namespace preimage::geometry::generators
