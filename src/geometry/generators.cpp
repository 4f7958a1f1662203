// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/random_point.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
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
    pts.push_back(random_point(rng, coord));
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
    while (orientation(pts[s], pts[t], pts[*it]) == 0) pts[*it] = random_point(rng, coord);
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

Environment touching_squares(std::size_t m, double fill, std::uint64_t seed, bool sheared) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coin(0, 1);
  auto map = [&](double x, double y) { return sheared ? Point(2 * x + y, x + 3 * y) : Point(x, y); };
  const double M = static_cast<double>(m);
  Ring outer;
  for (std::size_t k = 0; k < m; ++k) outer.push_back(map(static_cast<double>(k), 0));
  outer.push_back(map(M, 0)), outer.push_back(map(M, M)), outer.push_back(map(0, M));
  std::vector<Ring> holes;
  for (std::size_t j = 1; j + 1 < m; ++j)
    for (std::size_t i = 1; i + 1 < m; ++i) {
      if ((i + j) % 2 != 0 || coin(rng) >= fill) continue;
      const double x = static_cast<double>(i), y = static_cast<double>(j);
      holes.push_back({map(x, y), map(x + 1, y), map(x + 1, y + 1), map(x, y + 1)});
    }
  for (std::size_t k = 1; k < m; ++k)
    if (coin(rng) < fill / 2) {
      const double x = static_cast<double>(k);
      holes.push_back({map(x, 0), map(x + 0.375, 0.75), map(x - 0.375, 0.75)});
    }
  return Environment::make(std::move(outer), std::move(holes));
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

namespace {
// The union of the filled cells of a cols x rows grid (filled[y * cols + x]; no two filled
// cells touching at a corner only) with grid lines at gx, gy: boundary edges with a filled
// cell on their left, chained; a straight vertex is kept when keep() says so.
Environment cells_environment(const std::vector<char>& in, std::size_t cols, std::size_t rows, const std::vector<double>& gx,
                              const std::vector<double>& gy, const std::function<bool()>& keep) {
  const long W = static_cast<long>(cols), H = static_cast<long>(rows);
  auto cell = [&](long x, long y) { return x >= 0 && y >= 0 && x < W && y < H && in[static_cast<std::size_t>(y * W + x)]; };
  // Boundary edges with the filled cell on their left, as a successor map on grid points.
  auto id = [&](long x, long y) { return static_cast<std::size_t>(y * (W + 1) + x); };
  std::vector<std::size_t> succ((cols + 1) * (rows + 1), SIZE_MAX);
  for (long y = 0; y < H; ++y)
    for (long x = 0; x < W; ++x) {
      if (!cell(x, y)) continue;
      if (!cell(x, y - 1)) succ[id(x, y)] = id(x + 1, y);          // bottom, going right
      if (!cell(x + 1, y)) succ[id(x + 1, y)] = id(x + 1, y + 1);  // right, going up
      if (!cell(x, y + 1)) succ[id(x + 1, y + 1)] = id(x, y + 1);  // top, going left
      if (!cell(x - 1, y)) succ[id(x, y + 1)] = id(x, y);          // left, going down
    }
  std::vector<Ring> loops;
  std::vector<double> areas;
  for (std::size_t start = 0; start < succ.size(); ++start) {
    if (succ[start] == SIZE_MAX) continue;
    std::vector<std::size_t> loop;
    for (std::size_t v = start; succ[v] != SIZE_MAX;) {
      loop.push_back(v);
      const std::size_t w = succ[v];
      succ[v] = SIZE_MAX;
      v = w;
    }
    Ring ring;
    const std::size_t n = loop.size();
    auto pt = [&](std::size_t v) { return Point(gx[v % (cols + 1)], gy[v / (cols + 1)]); };
    for (std::size_t i = 0; i < n; ++i) {
      const Point a = pt(loop[(i + n - 1) % n]), b = pt(loop[i]), c = pt(loop[(i + 1) % n]);
      if (orientation(a, b, c) != 0 || keep()) ring.push_back(b);
    }
    double twice = 0;
    for (std::size_t i = 0; i < ring.size(); ++i)
      twice += ring[i].x() * ring[(i + 1) % ring.size()].y() - ring[(i + 1) % ring.size()].x() * ring[i].y();
    loops.push_back(std::move(ring));
    areas.push_back(twice);
  }
  // The outer boundary is the one counter-clockwise loop (filled cells on the left, and a
  // polyomino without pinches has one outer boundary); the clockwise ones bound the holes.
  const auto outer = static_cast<std::size_t>(std::max_element(areas.begin(), areas.end()) - areas.begin());
  std::vector<Ring> hole_rings;
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (i != outer) hole_rings.push_back(std::move(loops[i]));
  return Environment::make(std::move(loops[outer]), std::move(hole_rings));
}
}  // namespace

Environment random_rectilinear(std::size_t cols, std::size_t rows, bool holes, std::uint64_t seed) {
  if (cols < 2 || rows < 2) throw std::invalid_argument("random_rectilinear: need at least a 2 x 2 grid");
  std::mt19937_64 rng(seed);
  const long W = static_cast<long>(cols), H = static_cast<long>(rows);
  std::vector<char> in(cols * rows, 0);
  auto cell = [&](long x, long y) -> char { return x < 0 || y < 0 || x >= W || y >= H ? 0 : in[static_cast<std::size_t>(y * W + x)]; };
  // A 2 x 2 block whose only filled cells are diagonal would pinch the boundary at a point.
  auto pinches = [&](long x, long y) {
    for (long bx = x - 1; bx <= x; ++bx)
      for (long by = y - 1; by <= y; ++by) {
        const char a = cell(bx, by), b = cell(bx + 1, by), c = cell(bx, by + 1), d = cell(bx + 1, by + 1);
        if ((a && d && !b && !c) || (b && c && !a && !d)) return true;
      }
    return false;
  };
  // Grow from the centre to about 70% of the grid.
  in[static_cast<std::size_t>((H / 2) * W + W / 2)] = 1;
  std::vector<std::pair<long, long>> frontier{{W / 2, H / 2}};
  const std::size_t target = cols * rows * 7 / 10;
  std::size_t filled = 1;
  for (std::size_t attempts = 0; filled < target && attempts < 50 * cols * rows; ++attempts) {
    const auto [fx, fy] = frontier[std::uniform_int_distribution<std::size_t>(0, frontier.size() - 1)(rng)];
    static const long dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    const int d = std::uniform_int_distribution<int>(0, 3)(rng);
    const long x = fx + dx[d], y = fy + dy[d];
    if (x < 0 || y < 0 || x >= W || y >= H || cell(x, y)) continue;
    in[static_cast<std::size_t>(y * W + x)] = 1;
    if (pinches(x, y)) {
      in[static_cast<std::size_t>(y * W + x)] = 0;
      continue;
    }
    frontier.emplace_back(x, y);
    ++filled;
  }
  // Holes: punch some out of the inside, each a few cells grown from one whose whole 3 x 3
  // neighbourhood is filled, never next to another hole (so no two boundaries touch).
  if (holes) {
    std::vector<int> hole_of(cols * rows, -1);
    auto hole_at = [&](long x, long y) { return x < 0 || y < 0 || x >= W || y >= H ? -2 : hole_of[static_cast<std::size_t>(y * W + x)]; };
    // x, y may join hole h: filled, and every cell around it filled or already in h.
    auto may_join = [&](long x, long y, int h) {
      if (!cell(x, y)) return false;
      for (long ax = x - 1; ax <= x + 1; ++ax)
        for (long ay = y - 1; ay <= y + 1; ++ay)
          if (!(ax == x && ay == y) && !cell(ax, ay) && hole_at(ax, ay) != h) return false;
      return true;
    };
    const std::size_t want = std::max<std::size_t>(1, cols * rows / 25);
    for (int h = 0; h < static_cast<int>(want); ++h) {
      for (int attempt = 0; attempt < 200; ++attempt) {
        const long x = std::uniform_int_distribution<long>(1, W - 2)(rng), y = std::uniform_int_distribution<long>(1, H - 2)(rng);
        if (!may_join(x, y, h)) continue;
        std::vector<std::pair<long, long>> grown{{x, y}};
        in[static_cast<std::size_t>(y * W + x)] = 0, hole_of[static_cast<std::size_t>(y * W + x)] = h;
        for (int more = std::uniform_int_distribution<int>(0, 3)(rng); more > 0; --more) {
          const auto [gx0, gy0] = grown[std::uniform_int_distribution<std::size_t>(0, grown.size() - 1)(rng)];
          static const long ddx[4] = {1, -1, 0, 0}, ddy[4] = {0, 0, 1, -1};
          const int d = std::uniform_int_distribution<int>(0, 3)(rng);
          const long nx = gx0 + ddx[d], ny = gy0 + ddy[d];
          if (!may_join(nx, ny, h)) continue;
          in[static_cast<std::size_t>(ny * W + nx)] = 0, hole_of[static_cast<std::size_t>(ny * W + nx)] = h;
          if (pinches(nx, ny)) {
            in[static_cast<std::size_t>(ny * W + nx)] = 1, hole_of[static_cast<std::size_t>(ny * W + nx)] = -1;
            continue;
          }
          grown.emplace_back(nx, ny);
        }
        break;
      }
    }
  }
  // Gaps not connected to the outside are holes; without holes they are filled (a gap is
  // enclosed by filled cells, so filling it cannot pinch).
  {
    std::vector<char> outside(cols * rows, 0);
    std::vector<std::pair<long, long>> stack;
    for (long x = 0; x < W; ++x) stack.emplace_back(x, 0), stack.emplace_back(x, H - 1);
    for (long y = 0; y < H; ++y) stack.emplace_back(0, y), stack.emplace_back(W - 1, y);
    while (!stack.empty()) {
      auto [x, y] = stack.back();
      stack.pop_back();
      if (x < 0 || y < 0 || x >= W || y >= H) continue;
      const std::size_t i = static_cast<std::size_t>(y * W + x);
      if (in[i] || outside[i]) continue;
      outside[i] = 1;
      stack.emplace_back(x + 1, y), stack.emplace_back(x - 1, y), stack.emplace_back(x, y + 1), stack.emplace_back(x, y - 1);
    }
    if (!holes)
      for (std::size_t i = 0; i < in.size(); ++i)
        if (!outside[i]) in[i] = 1;
  }
  // Grid lines at random integer offsets: many equal coordinates, exact arithmetic.
  std::vector<double> gx(cols + 1, 0), gy(rows + 1, 0);
  std::uniform_int_distribution<int> width(1, 4);
  for (std::size_t i = 1; i <= cols; ++i) gx[i] = gx[i - 1] + width(rng);
  for (std::size_t i = 1; i <= rows; ++i) gy[i] = gy[i - 1] + width(rng);
  std::bernoulli_distribution keep_straight(0.3);
  return cells_environment(in, cols, rows, gx, gy, [&] { return keep_straight(rng); });
}

Environment from_cells(const std::vector<char>& filled, std::size_t cols, std::size_t rows) {
  if (filled.size() != cols * rows) throw std::invalid_argument("from_cells: the grid has " + std::to_string(filled.size()) + " cells, not cols x rows");
  std::vector<double> gx(cols + 1), gy(rows + 1);
  for (std::size_t i = 0; i <= cols; ++i) gx[i] = static_cast<double>(i);
  for (std::size_t i = 0; i <= rows; ++i) gy[i] = static_cast<double>(i);
  return cells_environment(filled, cols, rows, gx, gy, [] { return false; });
}

}  // namespace preimage::geometry::generators
