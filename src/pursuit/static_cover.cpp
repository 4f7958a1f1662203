// SPDX-License-Identifier: Apache-2.0
// Guards standing still who together see free space within range (see static_cover.hpp).
#include <preimage/pursuit/static_cover.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/local_frame.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/geometry/visibility_graph.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace preimage::pursuit {

StaticCover static_range_cover(const geometry::Environment& env, double range, std::size_t range_sides, const std::optional<Point>& start) {
  const std::vector<Point> q = range_sensor(range, range_sides);
  const geometry::VisibilityIndex input_vis(env);
  if (start && !input_vis.in_free_space(*start))
    throw InputError("start " + geometry::format_point(*start) + " is not in free space");
  // The samples and the greedy choice run in the plan's canonical frame (its box at the
  // origin, the same for every exact translate), so a georeferenced plan gets the guards it
  // gets at the origin, moved; the check below is in input coordinates.
  const geometry::LocalFrame frame = geometry::LocalFrame::canonical(env);
  const geometry::Environment local = frame.to_local(env);
  const geometry::VisibilityIndex vis(local);
  // Samples half the sensor's inner radius apart: every sample is seen from its neighbours.
  const double inner = range * std::cos(std::numbers::pi / static_cast<double>(range_sides));
  const auto box = local.bbox();
  const double s = inner / 2;
  const auto nx = static_cast<std::size_t>(std::floor((box.xmax() - box.xmin()) / s)) + 1;
  const auto ny = static_cast<std::size_t>(std::floor((box.ymax() - box.ymin()) / s)) + 1;
  if (static_cast<double>(nx) * static_cast<double>(ny) > 4e6)
    throw InputError("range " + geometry::format_number(range) + ": the plan is " + geometry::format_number(box.xmax() - box.xmin()) + " x " +
                     geometry::format_number(box.ymax() - box.ymin()) +
                     " across; a cover of sensors this small needs more than 4 million samples");
  std::vector<Point> sample;
  std::vector<std::size_t> cell_of(nx * ny, SIZE_MAX);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const Point p(box.xmin() + s * (static_cast<double>(i) + 0.5), box.ymin() + s * (static_cast<double>(j) + 0.5));
      if (!vis.in_free_space(p)) continue;
      cell_of[j * nx + i] = sample.size();
      sample.push_back(p);
    }
  // (A part of the plan thinner than the spacing may hold no sample: the exact check below
  // finds it, and a guard is posted inside it.)
  auto sees = [&](const Point& g, const Point& x) {
    for (std::size_t k = 0; k < q.size(); ++k) {
      const Point a(g.x() + q[k].x(), g.y() + q[k].y()), b(g.x() + q[(k + 1) % q.size()].x(), g.y() + q[(k + 1) % q.size()].y());
      if (geometry::orientation(a, b, x) < 0) return false;
    }
    return vis.visible(g, x);
  };
  const auto reach = static_cast<std::ptrdiff_t>(std::ceil(inner / s)) + 1;
  std::vector<std::vector<std::uint32_t>> seen_by(sample.size());
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t g = cell_of[j * nx + i];
      if (g == SIZE_MAX) continue;
      for (std::ptrdiff_t dj = -reach; dj <= reach; ++dj)
        for (std::ptrdiff_t di = -reach; di <= reach; ++di) {
          const auto ii = static_cast<std::ptrdiff_t>(i) + di, jj = static_cast<std::ptrdiff_t>(j) + dj;
          if (ii < 0 || jj < 0 || ii >= static_cast<std::ptrdiff_t>(nx) || jj >= static_cast<std::ptrdiff_t>(ny)) continue;
          const std::size_t x = cell_of[static_cast<std::size_t>(jj) * nx + static_cast<std::size_t>(ii)];
          if (x != SIZE_MAX && sees(sample[g], sample[x])) seen_by[g].push_back(static_cast<std::uint32_t>(x));
        }
    }
  // Greedy set cover over the samples.
  StaticCover out;
  out.samples = sample.size();
  std::vector<char> covered(sample.size(), 0);
  std::size_t left = sample.size();
  while (left > 0) {
    // The most samples not yet seen; of those, the one nearest them (the middle of a room
    // rather than its edge, where the exact check finds corners left).
    std::size_t best = SIZE_MAX, most = 0;
    double spread = 0;
    for (std::size_t g = 0; g < sample.size(); ++g) {
      std::size_t n = 0;
      double d2 = 0;
      for (auto x : seen_by[g])
        if (!covered[x]) {
          ++n;
          const double dx = sample[x].x() - sample[g].x(), dy = sample[x].y() - sample[g].y();
          d2 += dx * dx + dy * dy;
        }
      if (n > most || (n == most && n > 0 && d2 < spread)) most = n, best = g, spread = d2;
    }
    if (best == SIZE_MAX) break;  // cannot happen: every sample sees itself
    // Back in input coordinates; a sample that rounding moves out of free space is left to
    // the completions.
    const Point g = frame.to_input(sample[best]);
    if (input_vis.in_free_space(g)) out.guards.push_back(g);
    for (auto x : seen_by[best])
      if (!covered[x]) covered[x] = 1, --left;
  }
  // Posted, and checked exactly; a region the samples missed gets a guard inside it.
  const geometry::VisibilityGraph graph(input_vis);
  // With a start, the guards walk to their posts one at a time (the others wait), so every
  // step of the check has one mover and its exact events.
  auto make_plan = [&] {
    Plan plan;
    plan.paths.assign(out.guards.size(), {});
    for (std::size_t g = 0; g < out.guards.size(); ++g) plan.paths[g].push_back(start ? *start : out.guards[g]);
    if (!start) return plan;
    for (std::size_t g = 0; g < out.guards.size(); ++g) {
      const auto sp = graph.shortest_path(*start, out.guards[g]);
      if (!sp.found) throw std::logic_error("pursuit: no path from the start to a guard's post");
      for (std::size_t i = 1; i < sp.points.size(); ++i)
        for (std::size_t h = 0; h < out.guards.size(); ++h) plan.paths[h].push_back(h == g ? sp.points[i] : plan.paths[h].back());
      plan.length += sp.length;
    }
    return plan;
  };
  CheckOptions co;
  co.range = range, co.range_sides = range_sides;
  for (int round = 0;; ++round) {
    if (out.guards.empty()) out.guards.push_back(start ? *start : env.vertex(0));
    out.plan = make_plan();
    out.check = check_paths(env, out.plan.paths, co);
    if (out.check.cleared) return out;
    if (round >= 200) throw std::logic_error("pursuit: the static range cover still leaves a region after 200 completions");
    const std::size_t before = out.guards.size();
    for (const Point& p : out.check.contaminated_at_end)
      if (input_vis.in_free_space(p)) out.guards.push_back(p), ++out.completions;
    if (out.guards.size() == before) throw std::logic_error("pursuit: the static range cover's regions left have no point in free space");
  }
}

}  // namespace preimage::pursuit
