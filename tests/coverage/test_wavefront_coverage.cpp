// The tethered robot's coverage pattern (6.2.3, Fig. 6.18): fronts of the geodesic distance
// from the anchor, w apart, run outwards. Checked: coverage of the configuration space
// (rasterised), clearance by brute force, and that the laps lie on the fronts in
// non-decreasing order of tether length (the geodesic distance of the configuration space,
// from the shortest path map tested against brute force in tests/geometry).
#include <gtest/gtest.h>
#include <preimage/coverage/coverage.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/shortest_path_map.hpp>
#include <preimage/scene/import.hpp>

#include "support/path_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace preimage;
using geometry::Environment;
using geometry::Point;

namespace {

struct Case {
  Case(std::string w, Environment e, Point s) : what(std::move(w)), env(std::move(e)), start(s) {}
  std::string what;
  Environment env;
  Point start;
};

}  // namespace

TEST(WavefrontCoverage, FrontsRunOutwardsCoverAndKeepClear) {
  std::vector<Case> cases;
  cases.emplace_back("field", Environment::make({{0, 0}, {12, 0}, {12, 8}, {0, 8}}, {{{2, 3}, {3.5, 2}, {4, 4}, {2.5, 5}}, {{6, 1.5}, {8.5, 1}, {8, 3}},
                                                                                  {{7, 5}, {9, 4.5}, {10, 6.5}, {8, 7}}}),
                     Point(0.5, 0.5));
  cases.emplace_back("office", geometry::generators::office(2, 3), Point(1, 1));
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"}) {
    std::string file(PREIMAGE_FLOORPLANS);  // appended, not `+`: GCC 12 warns falsely (-Warray-bounds)
    file.append("/").append(name);
    cases.emplace_back(name, *scene::import_houseexpo(file).environment, Point(1, 1));
  }
  for (const auto& [what, env, start] : cases) {
    const auto box = env.bbox();
    const double r = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin()) / 60, w = 2 * r;
    coverage::CoverageOptions o;
    o.robot_radius = r, o.pattern = coverage::Pattern::Wavefront, o.start = start;
    const auto rep = coverage::plan_coverage(env, o);
    EXPECT_GE(coverage::measure_coverage(env, rep).covered_fraction, 0.99) << what;
    double worst = std::numeric_limits<double>::infinity();
    for (const Point& p : rep.path) worst = std::min(worst, preimage::testing::brute_clearance(env, p));
    EXPECT_GE(worst, r * (1 - 1e-6)) << what;
    // laps on the fronts h = w/2 + k w of the configuration space, k never decreasing
    const geometry::ConfigurationSpace cs(env, r);
    const auto& E = cs.components()[*cs.component_of(start)];
    const geometry::VisibilityIndex index(E);
    const geometry::VisibilityGraph graph(index);
    const geometry::ShortestPathMap spm(graph, start);
    long last = -1;
    std::size_t on_front = 0, lap_points = 0;
    for (std::size_t i = 0; i < rep.moves.size(); ++i) {
      if (rep.moves[i] != coverage::Move::Lap) continue;
      const double h = spm.distance(rep.path[i + 1]);
      ASSERT_TRUE(std::isfinite(h)) << what;
      const long k = std::lround((h - w / 2) / w);
      ++lap_points;
      on_front += std::fabs(h - (w / 2 + static_cast<double>(k) * w)) <= w / 3;
      EXPECT_GE(k, last - 1) << what << ": the tether shortens by more than a front";
      last = std::max(last, k);
    }
    EXPECT_GE(static_cast<double>(on_front), 0.97 * static_cast<double>(lap_points)) << what;
    EXPECT_GT(rep.laps, 5u) << what;
  }
}

TEST(WavefrontCoverage, NeedsAnAnchor) {
  coverage::CoverageOptions o;
  o.robot_radius = 0.2, o.pattern = coverage::Pattern::Wavefront;
  EXPECT_THROW(coverage::plan_coverage(geometry::generators::office(1, 2), o), InputError);
}
