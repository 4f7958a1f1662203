// SPDX-License-Identifier: Apache-2.0
#include <preimage/pursuit/examples.hpp>

#include <functional>

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

geometry::Environment room_with_pillar() {
  return geometry::Environment::make({{0, 0}, {6, 0}, {6, 6}, {0, 6}}, {{{2, 2}, {2, 4}, {4, 4}, {4, 2}}});
}

}  // namespace preimage::pursuit::examples
