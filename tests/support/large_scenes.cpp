#include "large_scenes.hpp"

#include <preimage/geometry/generators.hpp>

#include <cmath>
#include <numbers>

namespace preimage::testing {

namespace {

scene::Scene make(geometry::Environment env, geometry::Point start, geometry::Point goal, const std::string& what) {
  scene::Scene s;
  s.name = what;
  s.description = what;
  s.environment = std::move(env);
  s.start = start;
  s.goal = goal;
  return s;
}

}  // namespace

std::vector<LargeScene> large_scenes() {
  using geometry::Environment;
  using geometry::Point;
  using geometry::Ring;
  std::vector<LargeScene> out;

  // Circle of radius 100: every vertex convex, no two collinear, visibility sees all.
  Ring circle;
  const std::size_t n = 100000;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    circle.emplace_back(100 * std::cos(a), 100 * std::sin(a));
  }
  out.push_back({"circle_100k", make(Environment::make(std::move(circle), {}), Point(1.5, 1.25), Point(-50.5, 20.25),
                                     "circle of 100,000 vertices")});

  // Star of 50,000 tips: half the vertices reflex, a shadow behind every one.
  out.push_back({"star_100k", make(Environment::make(geometry::generators::star(50000, 40, 100), {}), Point(1.5, 1.25),
                                   Point(-20.5, 10.25), "star of 100,000 vertices")});

  // Square of side 100 with 25,000 vertices on every side, 0.004 apart (straight
  // vertices), and a thin tooth of two vertices up from the floor: 100,002 vertices.
  Ring square;
  const std::size_t side = 25000;
  const double step = 100.0 / static_cast<double>(side);
  for (std::size_t i = 0; i < side; ++i) {
    square.emplace_back(static_cast<double>(i) * step, 0);
    if (i == side / 2) square.emplace_back(static_cast<double>(i) * step + step / 4, 2), square.emplace_back(static_cast<double>(i) * step + 3 * step / 4, 2);
  }
  for (std::size_t i = 0; i < side; ++i) square.emplace_back(100, static_cast<double>(i) * step);
  for (std::size_t i = 0; i < side; ++i) square.emplace_back(100 - static_cast<double>(i) * step, 100);
  for (std::size_t i = 0; i < side; ++i) square.emplace_back(0, 100 - static_cast<double>(i) * step);
  out.push_back({"collinear_100k", make(Environment::make(std::move(square), {}), Point(1.5, 1.25), Point(90.5, 1.25),
                                        "square with 25,000 collinear vertices per side and a tooth: 100,002 vertices")});

  // Random simple polygon of 3,000 vertices in general position, for the wall-following
  // commands (issue 26: count and cut-ordering took more than 10 s), started at vertex 0.
  {
    Environment env = geometry::generators::random_environment(3000, 0, 26);
    const Point v0 = env.vertex(0), v1 = env.vertex(1);
    out.push_back({"random_3k", make(std::move(env), v0, v1, "random simple polygon of 3,000 vertices")});
  }

  // Office floor plan: 65 x 65 rooms of side 4, 16,640 walls with doors.
  out.push_back({"office_100k", make(geometry::generators::office(65, 65), Point(2.1, 2.3), Point(257.9, 257.7),
                                     "office of 65 x 65 rooms")});
  return out;
}

}  // namespace preimage::testing
