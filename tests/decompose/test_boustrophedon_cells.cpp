// Boustrophedon cell polygons are exactly the cells, and coverage paths stay in free space,
// on the inputs where slices run along edges: rectilinear plans at quarter-turn angles
// (issue 28). Checked independently of the decomposition with CGAL's Boolean set
// operations on exact polygons (GPL, test-only), rational areas, and exact visibility.
#include <gtest/gtest.h>
#include <preimage/coverage/coverage.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/scene.hpp>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <fstream>
#include <random>

#include "support/cgal_oracle.hpp"

using namespace preimage;
using decompose::BoustrophedonDecomposition;
using geometry::Environment;
using geometry::ExactFT;
using geometry::ExactKernel;
using geometry::Point;

namespace {

using ExactPolygon = CGAL::Polygon_2<ExactKernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<ExactKernel>;

ExactPolygon ring_polygon(const Environment& env, std::size_t r) {
  ExactPolygon p;
  for (std::size_t v = env.ring_begin(r); v < env.ring_end(r); ++v) p.push_back(env.exact_vertex(v));
  if (p.orientation() != CGAL::COUNTERCLOCKWISE) p.reverse_orientation();
  return p;
}

ExactFT area_of(const std::vector<ExactPolygonWithHoles>& parts) {
  ExactFT a = 0;
  for (const auto& pw : parts) {
    a += pw.outer_boundary().area();
    for (auto h = pw.holes_begin(); h != pw.holes_end(); ++h) a += h->area();  // holes are clockwise: negative
  }
  return a;
}

// (a) simple, inside free space, pairwise interior-disjoint; (b) areas sum to the free
// area exactly; (c) the reported area is the polygon's. All in the swept frame, where the
// decomposition is exact (at quarter turns it is the input, rotated exactly).
void check_cells(const Environment& env, double angle, const std::string& what) {
  const BoustrophedonDecomposition b(env, angle);
  const Environment& E = b.sweep_environment();
  const ExactPolygon outer = ring_polygon(E, 0);
  std::vector<ExactPolygon> holes;
  for (std::size_t h = 1; h < E.num_rings(); ++h) holes.push_back(ring_polygon(E, h));
  std::vector<ExactPolygon> cells;
  std::vector<CGAL::Bbox_2> boxes;
  ExactFT total = 0;
  for (std::size_t c = 0; c < b.cells().size(); ++c) {
    const auto pts = b.exact_polygon(c);
    ExactPolygon poly(pts.begin(), pts.end());
    ASSERT_TRUE(poly.is_simple()) << what << ": cell " << c << " is not simple";
    ASSERT_EQ(poly.orientation(), CGAL::COUNTERCLOCKWISE) << what << ": cell " << c;
    EXPECT_EQ(poly.area(), b.area(c)) << what << ": cell " << c << " reports an area that is not its polygon's";
    total += poly.area();
    // Inside free space: nothing outside the boundary, nothing inside a hole.
    std::vector<ExactPolygonWithHoles> out;
    CGAL::difference(poly, outer, std::back_inserter(out));
    EXPECT_EQ(area_of(out), 0) << what << ": cell " << c << " leaves the boundary";
    for (const auto& h : holes) {
      if (!CGAL::do_overlap(poly.bbox(), h.bbox())) continue;
      out.clear();
      CGAL::intersection(poly, h, std::back_inserter(out));
      EXPECT_EQ(area_of(out), 0) << what << ": cell " << c << " overlaps an obstacle";
    }
    cells.push_back(std::move(poly));
    boxes.push_back(cells.back().bbox());
  }
  EXPECT_EQ(total, E.exact_area()) << what << ": cell areas do not sum to the free area";
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (std::size_t j = i + 1; j < cells.size(); ++j) {
      if (!CGAL::do_overlap(boxes[i], boxes[j])) continue;
      std::vector<ExactPolygonWithHoles> out;
      CGAL::intersection(cells[i], cells[j], std::back_inserter(out));
      ASSERT_EQ(area_of(out), 0) << what << ": cells " << i << " and " << j << " overlap";
    }
}

// (d) every segment of the coverage path lies in closed free space (exact, O(n) per
// segment, independent of the library's own certification).
void check_cover(const Environment& env, double width, std::optional<double> angle, const std::string& what) {
  coverage::CoverageOptions o;
  o.width = width, o.angle_deg = angle;
  const auto rep = coverage::plan_coverage(env, o);
  ASSERT_GE(rep.path.size(), 2u) << what;
  for (std::size_t i = 0; i + 1 < rep.path.size(); ++i)
    ASSERT_TRUE(geometry::visible(env, rep.path[i], rep.path[i + 1]))
        << what << ": segment " << i << " " << geometry::format_point(rep.path[i]) << " -> " << geometry::format_point(rep.path[i + 1])
        << " leaves free space";
  if (angle && std::fmod(*angle, 90.0) == 0) {
    EXPECT_EQ(rep.rounding_detours, 0u) << what;
  }
}

const double kAngles[] = {0, 90, 180, 270, 45, 23.7};

Environment load_houseexpo(const std::string& name) {
  const std::string path = std::string(PREIMAGE_FLOORPLANS) + "/" + name;
  return *scene::import_houseexpo(scene::read_file(path), path).environment;
}

}  // namespace

TEST(BoustrophedonCells, StepInTheFloorKeepsBothEndsOfTheWall) {
  // Issue 28's reproduction: vertex (2, 0) was dropped, the outline cut through the wall,
  // and the coverage path went straight from (1.75, 0) to (2, -1).
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/step_in_the_floor.json");
  const Environment& env = *s.environment;
  const BoustrophedonDecomposition b(env, 0);
  ASSERT_EQ(b.cells().size(), 1u);
  const std::vector<Point> want{{0, 0}, {2, 0}, {2, -1}, {4, -1}, {4, 2}, {0, 2}};
  EXPECT_EQ(b.polygon(0), want);
  EXPECT_EQ(b.area(0), 10);
  for (double a : kAngles) check_cells(env, a, "step at " + std::to_string(a));
  for (double a : kAngles) check_cover(env, 0.5, a, "step at " + std::to_string(a));
}

TEST(BoustrophedonCells, RectilinearRoomWithRectilinearHole) {
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/rectilinear_room_with_hole.json");
  for (double a : kAngles) {
    check_cells(*s.environment, a, "room with hole at " + std::to_string(a));
    check_cover(*s.environment, 0.5, a, "room with hole at " + std::to_string(a));
  }
}

TEST(BoustrophedonCells, RandomRectilinearEnvironments) {
  std::size_t with_holes = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const bool holes = seed % 2 == 0;
    const auto env = geometry::generators::random_rectilinear(6 + seed % 5, 5 + seed % 4, holes, seed);
    with_holes += env.num_holes() > 0;
    if (!holes) {
      EXPECT_EQ(env.num_holes(), 0u);
    }
    for (double a : kAngles) {
      const std::string what = "rectilinear seed " + std::to_string(seed) + " at " + std::to_string(a);
      check_cells(env, a, what);
      check_cover(env, 1.0, a, what);
    }
  }
  EXPECT_GE(with_holes, 4u);  // the generator does make holes
}

TEST(BoustrophedonCells, RandomGeneralEnvironments) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto env = geometry::generators::random_environment(60 + 10 * seed, seed % 4, seed);
    const auto box = env.bbox();
    const double w = 0.03 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    for (double a : kAngles) {
      check_cells(env, a, "random seed " + std::to_string(seed) + " at " + std::to_string(a));
      check_cover(env, w, a, "random seed " + std::to_string(seed) + " at " + std::to_string(a));
    }
  }
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto env = preimage::testing::snapped_random_environment(30 + 2 * seed, seed % 3, seed, 40.0);
    for (double a : kAngles) check_cells(env, a, "snapped seed " + std::to_string(seed) + " at " + std::to_string(a));
  }
}

TEST(BoustrophedonCells, OfficeAndCombGenerators) {
  const auto office = geometry::generators::office(2, 3);
  const auto comb = Environment::make(geometry::generators::comb(6), {});
  for (double a : kAngles) {
    check_cells(office, a, "office at " + std::to_string(a));
    check_cover(office, 0.4, a, "office at " + std::to_string(a));
    check_cells(comb, a, "comb at " + std::to_string(a));
    check_cover(comb, 0.3, a, "comb at " + std::to_string(a));
  }
}

TEST(BoustrophedonCells, HouseExpoFloorPlans) {
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"}) {
    const Environment env = load_houseexpo(name);
    for (double a : kAngles) check_cells(env, a, std::string(name) + " at " + std::to_string(a));
    for (double w : {0.3, 0.4, 0.5}) {
      for (double a : {0.0, 90.0, 45.0}) check_cover(env, w, a, std::string(name) + " width " + std::to_string(w) + " at " + std::to_string(a));
      check_cover(env, w, std::nullopt, std::string(name) + " width " + std::to_string(w) + " auto");
    }
  }
}

TEST(BoustrophedonCells, StackedVerticalVerticesFixture) {
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/stacked_vertical_vertices.json");
  const Environment& env = *s.environment;
  const BoustrophedonDecomposition b(env);
  EXPECT_EQ(b.cells().size(), b.critical_slices().size() + env.num_holes() - 1);
  for (double a : kAngles) {
    check_cells(env, a, "stacked vertical vertices at " + std::to_string(a));
    check_cover(env, 0.3, a, "stacked vertical vertices at " + std::to_string(a));
  }
}
