// The brushfire decomposition (6.2.3, Figs. 6.15–6.17) and its coverage pattern. Checked
// independently of the construction: the number of wave fronts alive at every level between
// critical values equals the number of boundary curves of the free space eroded by that
// level (ConfigurationSpace: Clipper offsets, no Voronoi diagram), the cells tile the free
// space, the fronts lie at distance λ from the obstacles (brute force), the GVD's saddles
// between obstacles are among the decomposition's, a worked dumbbell room, and the coverage
// pattern covers the configuration space and keeps clear of the walls.
#include <gtest/gtest.h>
#include <preimage/decompose/brushfire.hpp>
#include <preimage/coverage/coverage.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/scene/import.hpp>

#include "support/path_oracle.hpp"
#include <preimage/scene/scene.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

using namespace preimage;
using decompose::BrushfireCell;
using decompose::BrushfireCriticalPoint;
using decompose::BrushfireDecomposition;
using geometry::Environment;
using geometry::Point;

namespace {

double extent(const Environment& env) {
  const auto b = env.bbox();
  return std::max(b.xmax() - b.xmin(), b.ymax() - b.ymin());
}

double shoelace(const std::vector<Point>& poly) {
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point& p = poly[i];
    const Point& q = poly[(i + 1) % poly.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a / 2;
}

std::string numbered(const char* what, std::uint64_t n) {
  std::string s(what);
  s.append(std::to_string(n));
  return s;
}

struct Named {
  Named(std::string w, Environment e) : what(std::move(w)), env(std::move(e)) {}
  std::string what;
  Environment env;
};

std::vector<Named> maps() {
  std::vector<Named> envs;
  for (std::uint64_t seed = 1; seed <= 12; ++seed)
    envs.emplace_back(numbered("random ", seed), geometry::generators::random_environment(40 + 10 * (seed % 5), seed % 6, seed));
  envs.emplace_back("office 2x3", geometry::generators::office(2, 3));
  envs.emplace_back("rectilinear", geometry::generators::random_rectilinear(7, 6, true, 5));
  envs.emplace_back("comb", Environment::make(geometry::generators::comb(8), {}));
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    envs.emplace_back(numbered("touching squares ", seed), geometry::generators::touching_squares(5, 0.6, seed, seed % 2 == 0));
  envs.emplace_back("checkerboard", *scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/contacts/checkerboard.json").environment);
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"})
    envs.emplace_back(name, *scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS) + "/" + name).environment);
  return envs;
}

}  // namespace

TEST(Brushfire, FrontsAliveMatchTheErodedFreeSpaceBoundaries) {
  // Between consecutive critical values the slice D = λ has one component per cell alive at
  // λ, and those are the boundary curves of {D >= λ}: counted by the configuration space of
  // a disc of radius λ (offsets, certified; no Voronoi diagram involved).
  int levels = 0;
  for (const auto& [what, env] : maps()) {
    const BrushfireDecomposition b(env);
    std::vector<double> lv{0};
    for (const auto& n : b.nodes()) lv.push_back(n.level);
    std::sort(lv.begin(), lv.end());
    const double ext = extent(env);
    for (std::size_t i = 0; i + 1 < lv.size(); ++i) {
      if (lv[i + 1] - lv[i] < 1e-3 * ext) continue;  // Clipper's arcs need room
      const double lam = (lv[i] + lv[i + 1]) / 2;
      std::size_t alive = 0;
      for (const auto& c : b.cells()) alive += c.lo < lam && lam < c.hi;
      const auto curves = b.level_curves(lam, 1e-4 * ext);
      const geometry::ConfigurationSpace cs(env, lam);
      std::size_t rings = 0;
      for (const auto& c : cs.components()) rings += c.num_rings();
      std::set<std::uint32_t> cells;
      for (const auto& c : curves) cells.insert(c.cell);
      EXPECT_EQ(curves.size(), alive) << what << " at " << lam;
      EXPECT_EQ(rings, alive) << what << " at " << lam;
      EXPECT_EQ(cells.size(), curves.size()) << what << " at " << lam << ": two fronts in one cell";
      for (const auto& c : curves) {
        const auto& cell = b.cells()[c.cell];
        EXPECT_TRUE(cell.lo < lam && lam < cell.hi) << what;
      }
      ++levels;
    }
  }
  EXPECT_GT(levels, 150);
}

TEST(Brushfire, CellsTileTheFreeSpaceAndFormAReebGraph) {
  for (const auto& [what, env] : maps()) {
    const BrushfireDecomposition b(env);
    // the sheets (from the axis to the sites) tile free space exactly, up to rounding
    double sheets = 0;
    const auto& g = b.gvd();
    for (const auto& e : g.medial_edges())
      for (int s = 0; s < 2; ++s) {
        std::vector<Point> poly;
        auto P = e.polyline;
        if (s == 1) std::reverse(P.begin(), P.end());
        poly.push_back(g.nearest_on_site(e.sites[s], P.front()));
        poly.insert(poly.end(), P.begin(), P.end());
        poly.push_back(g.nearest_on_site(e.sites[s], P.back()));
        sheets += shoelace(poly);
      }
    EXPECT_NEAR(sheets, b.free_area(), 1e-7 * b.free_area()) << what;
    double cells = 0;
    std::size_t bands = 0;
    for (const auto& c : b.cells()) {
      cells += c.area;
      bands += c.bands.size();
      EXPECT_LT(c.lo, c.hi) << what;
      // a cell starts from an obstacle or from a slice below it and ends at a slice above it
      EXPECT_NE(c.lower == BrushfireCell::kNone, c.obstacle == BrushfireCell::kNone) << what;
      if (c.lower != BrushfireCell::kNone) {
        EXPECT_EQ(b.nodes()[c.lower].level, c.lo) << what;
      }
      ASSERT_NE(c.upper, BrushfireCell::kNone) << what << ": a cell with no slice above it";
      EXPECT_EQ(b.nodes()[c.upper].level, c.hi) << what;
    }
    EXPECT_EQ(bands, b.num_bands()) << what;
    EXPECT_NEAR(cells, b.free_area(), 1e-4 * b.free_area()) << what;
    // one cell born per obstacle (fronts start as the obstacles' boundaries)
    std::set<std::uint32_t> born;
    for (const auto& c : b.cells())
      if (c.obstacle != BrushfireCell::kNone) {
        EXPECT_TRUE(born.insert(c.obstacle).second) << what;
      }
    EXPECT_EQ(born.size(), g.num_obstacles()) << what;
    // every node is some cell's upper end; maxima end cells and start none
    std::vector<int> ends(b.num_nodes(), 0), starts(b.num_nodes(), 0);
    for (const auto& c : b.cells()) {
      ++ends[c.upper];
      if (c.lower != BrushfireCell::kNone) ++starts[c.lower];
    }
    for (std::size_t n = 0; n < b.num_nodes(); ++n) {
      EXPECT_GE(ends[n], 1) << what;
      bool only_maxima = true;
      for (const auto k : b.nodes()[n].critical_points) only_maxima = only_maxima && b.critical_points()[k].kind == BrushfireCriticalPoint::Kind::Maximum;
      if (only_maxima) {
        EXPECT_EQ(starts[n], 0) << what;
      }
    }
    // adjacency: symmetric, and the Reeb graph is connected (free space is)
    const auto adj = b.adjacency();
    std::vector<char> seen(b.cells().size(), 0);
    std::vector<std::uint32_t> stack{0};
    seen[0] = 1;
    while (!stack.empty()) {
      const auto c = stack.back();
      stack.pop_back();
      for (const auto d : adj[c]) {
        EXPECT_TRUE(std::binary_search(adj[d].begin(), adj[d].end(), c)) << what;
        if (!seen[d]) seen[d] = 1, stack.push_back(d);
      }
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(b.cells().size())) << what;
  }
}

TEST(Brushfire, FrontsAndCriticalPointsAgreeWithBruteForceDistances) {
  // Fronts are at distance λ from the nearest obstacle (brute force over every edge, within
  // the sampling and the grid); critical points are medial-axis points (clearance by brute
  // force equal to their level); the GVD's saddles between two obstacles are saddles here.
  for (const auto& [what, env] : maps()) {
    const BrushfireDecomposition b(env);
    const double ext = extent(env), tol = 1e-6 * ext + 4 * b.gvd().resolution();
    double top = 0;
    for (const auto& k : b.critical_points()) {
      EXPECT_NEAR(preimage::testing::brute_clearance(env, k.p), k.level, tol) << what;
      top = std::max(top, k.level);
    }
    for (const double f : {0.21, 0.55, 0.83}) {
      const double lam = f * top, sag = 1e-5 * ext;
      for (const auto& c : b.level_curves(lam, sag))
        for (std::size_t i = 0; i < c.points.size(); i += 7) EXPECT_NEAR(preimage::testing::brute_clearance(env, c.points[i]), lam, tol + sag) << what;
    }
    for (const auto& s : b.gvd().saddles()) {
      if (s.kind != geometry::GvdCriticalPoint::Kind::Interior) continue;
      bool found = false;
      for (const auto& k : b.critical_points())
        found = found || (k.kind == BrushfireCriticalPoint::Kind::Saddle && std::hypot(k.p.x() - s.p.x(), k.p.y() - s.p.y()) <= 4 * b.gvd().resolution());
      EXPECT_TRUE(found) << what << ": GVD saddle " << s.p << " missing";
    }
  }
}

TEST(Brushfire, DumbbellRoomHasOneSaddleInTheCorridorAndTwoMaxima) {
  // Two 4 x 4 rooms joined by a corridor 1 wide: the one front of the outer wall pinches in
  // the corridor (a plateau saddle at D = 1/2: fronts of one obstacle collide, which the GVD
  // between obstacles alone would miss) and shrinks to the two rooms' centres (maxima at 2).
  const Environment env = Environment::make({{0, 0}, {4, 0}, {4, 1.5}, {7, 1.5}, {7, 0}, {11, 0}, {11, 4}, {7, 4}, {7, 2.5}, {4, 2.5}, {4, 4}, {0, 4}}, {});
  const BrushfireDecomposition b(env);
  std::vector<const BrushfireCriticalPoint*> saddles, maxima;
  for (const auto& k : b.critical_points()) (k.kind == BrushfireCriticalPoint::Kind::Saddle ? saddles : maxima).push_back(&k);
  ASSERT_EQ(saddles.size(), 1u);
  ASSERT_EQ(maxima.size(), 2u);
  EXPECT_NEAR(saddles[0]->level, 0.5, 1e-7);
  EXPECT_NEAR(saddles[0]->p.y(), 2.0, 1e-7);
  EXPECT_TRUE(saddles[0]->p.x() >= 4 && saddles[0]->p.x() <= 7);  // a point of the corridor's plateau
  for (const auto* m : maxima) {
    // a plateau too: between the room's floor and ceiling from its centre to where the door
    // jambs are 2 away, x = 4 - sqrt(3.75) (mirrored for the other room)
    EXPECT_NEAR(m->level, 2.0, 1e-7);
    EXPECT_NEAR(m->p.y(), 2.0, 1e-7);
    const double x = std::min(m->p.x(), 11 - m->p.x());
    EXPECT_TRUE(x >= 2 - 1e-7 && x <= 4 - std::sqrt(3.75) + 1e-7) << x;
  }
  ASSERT_EQ(b.cells().size(), 3u);  // the outer front up to the corridor, then one per room
  EXPECT_EQ(b.num_nodes(), 3u);
  EXPECT_TRUE(b.gvd().edges().empty());  // one obstacle: no GVD at all
  int born = 0;
  for (const auto& c : b.cells()) {
    if (c.lower == BrushfireCell::kNone) {
      ++born;
      EXPECT_NEAR(c.hi, 0.5, 1e-7);
    } else {
      EXPECT_NEAR(c.lo, 0.5, 1e-7);
      EXPECT_NEAR(c.hi, 2.0, 1e-7);
      EXPECT_NEAR(c.area, 9, 0.6);  // a room less its band of width 1/2 along the walls
    }
  }
  EXPECT_EQ(born, 1);
}

TEST(BrushfireCoverage, CoversTheConfigurationSpaceAndKeepsClear) {
  std::vector<Named> envs;
  envs.emplace_back("field", Environment::make({{0, 0}, {12, 0}, {12, 8}, {0, 8}}, {{{2, 3}, {3.5, 2}, {4, 4}, {2.5, 5}}, {{6, 1.5}, {8.5, 1}, {8, 3}},
                                                                                  {{7, 5}, {9, 4.5}, {10, 6.5}, {8, 7}}}));
  envs.emplace_back("office", geometry::generators::office(2, 3));
  envs.emplace_back("random", geometry::generators::random_environment(200, 3, 77));
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"})
    envs.emplace_back(name, *scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS) + "/" + name).environment);
  for (const auto& [what, env] : envs) {
    const double r = extent(env) / 120;
    coverage::CoverageOptions o;
    o.robot_radius = r, o.pattern = coverage::Pattern::Brushfire;
    const auto rep = coverage::plan_coverage(env, o);
    const auto m = coverage::measure_coverage(env, rep);
    EXPECT_GE(m.covered_fraction, 0.99) << what;
    double worst = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < rep.path.size(); ++i)
      for (int k = 0; k <= 4; ++k)
        worst = std::min(worst, preimage::testing::brute_clearance(env, Point(rep.path[i].x() + (rep.path[i + 1].x() - rep.path[i].x()) * k / 4.0,
                                                             rep.path[i].y() + (rep.path[i + 1].y() - rep.path[i].y()) * k / 4.0)));
    EXPECT_GE(worst, r * (1 - 1e-6)) << what;
    EXPECT_GT(rep.laps, 0u) << what;
    EXPECT_EQ(rep.moves.size() + 1, rep.path.size()) << what;
  }
}
