// SPDX-License-Identifier: Apache-2.0
#include <preimage/pursuit/examples.hpp>

#include <preimage/geometry/generators.hpp>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace preimage::pursuit::examples {

using geometry::Point;
using geometry::Ring;

geometry::Environment corridor_with_rooms(std::size_t rooms) {
  const double L = 4.0 * static_cast<double>(rooms) + 1;
  Ring r{{0, 0}, {L, 0}, {L, 1}};
  for (std::size_t i = rooms; i-- > 0;) {
    const double a = 1 + 4.0 * static_cast<double>(i);
    for (Point p : {Point(a + 2, 1), Point(a + 2, 1.5), Point(a + 3, 1.5), Point(a + 3, 4), Point(a, 4), Point(a, 1.5),
                    Point(a + 1, 1.5), Point(a + 1, 1)})
      r.push_back(p);
  }
  r.emplace_back(0, 1);
  return geometry::Environment::make(std::move(r), {});
}

geometry::Environment three_arms(double leg) {
  // The right arm, traced counter-clockwise from the hub; the others are rotations of it.
  const double a = 1 + leg, b = leg;
  const Ring arm{{1, -0.5}, {a + 0.5, -0.5}, {a + 0.5, b - 0.5}, {a + leg, b - 0.5}, {a + leg, b + 0.5},
                 {a - 0.5, b + 0.5}, {a - 0.5, 0.5}, {1, 0.5}};
  auto rotated = [&](std::function<Point(const Point&)> f) {
    Ring out;
    for (auto& p : arm) out.push_back(f(p));
    return out;
  };
  Ring r{{-1, -1}, {1, -1}};
  for (auto& p : arm) r.push_back(p);
  r.emplace_back(1, 1);
  for (auto& p : rotated([](const Point& p) { return Point(-p.y(), p.x()); })) r.push_back(p);
  r.emplace_back(-1, 1);
  for (auto& p : rotated([](const Point& p) { return Point(-p.x(), -p.y()); })) r.push_back(p);
  return geometry::Environment::make(std::move(r), {});
}

namespace {
struct Footprint {
  long w, h;  // cells; the entrance is the bottom-left cell
};
constexpr long kBend = 2;  // cells each arm runs up, then right, then up again
Footprint footprint(std::size_t level) {
  if (level == 1) return {1, 2};
  const Footprint c = footprint(level - 1);
  return {2 + 2 * (kBend + c.w + 2) + kBend + c.w, 2 * kBend + 2 + c.h};
}
void draw_nested_u(std::size_t level, long x0, long y0, long cols, std::vector<char>& cells) {
  auto fill = [&](long x, long y) { cells[static_cast<std::size_t>(y * cols + x)] = 1; };
  if (level == 1) {
    fill(x0, y0), fill(x0, y0 + 1);
    return;
  }
  const Footprint c = footprint(level - 1);
  long arm = x0;
  for (int k = 0; k < 3; ++k) {
    arm = x0 + 2 + k * (kBend + c.w + 2);
    for (long y = y0 + 1; y <= y0 + kBend; ++y) fill(arm, y);              // up
    for (long x = arm; x <= arm + kBend; ++x) fill(x, y0 + kBend + 1);     // right
    for (long y = y0 + kBend + 2; y <= y0 + 2 * kBend + 1; ++y) fill(arm + kBend, y);  // up
    draw_nested_u(level - 1, arm + kBend, y0 + 2 * kBend + 2, cols, cells);
  }
  for (long x = x0; x <= arm; ++x) fill(x, y0);  // the hub
}
}  // namespace

geometry::Environment nested_u(std::size_t level) {
  if (level < 1 || level > 6) throw std::invalid_argument("nested_u: level " + std::to_string(level) + " is not in 1..6");
  const Footprint f = footprint(level);
  std::vector<char> cells(static_cast<std::size_t>(f.w * f.h), 0);
  draw_nested_u(level, 0, 0, f.w, cells);
  return geometry::generators::from_cells(cells, static_cast<std::size_t>(f.w), static_cast<std::size_t>(f.h));
}

geometry::Environment room_with_pillar() {
  return geometry::Environment::make({{0, 0}, {6, 0}, {6, 6}, {0, 6}}, {{{2, 2}, {2, 4}, {4, 4}, {4, 2}}});
}

}  // namespace preimage::pursuit::examples
