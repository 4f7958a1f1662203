// Trapezoidal decomposition: exact areas, adjacency, and cell counts against CGAL's
// vertical decomposition of the arrangement (test-only oracle).
#include <gtest/gtest.h>
#include <preimage/decompose/planner.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/scene.hpp>

#include "support/cgal_oracle.hpp"


#include <cmath>
#include <fstream>

using namespace preimage;
using decompose::TrapezoidalDecomposition;
using geometry::Environment;

namespace {

// Number of free-space faces after adding, for every vertex, the vertical extensions CGAL's
// decompose() reports that run into free space.
std::size_t cgal_cell_count(const Environment& env) {
  using Arr = preimage::testing::CgalVisibility::Arrangement;
  using EK = geometry::ExactKernel;
  const Arr arr = preimage::testing::make_arrangement(env);
  const auto vd = preimage::testing::vertical_decomposition(arr);
  Arr cut = arr;
  std::vector<EK::Segment_2> extra;
  for (auto& [v, below_above] : vd) {
    const EK::Point_2 p = v->point();
    const geometry::Point pd = geometry::to_double(p);
    std::size_t id = 0;
    while (env.vertex(id) != pd) ++id;
    for (int up = 0; up < 2; ++up) {
      const auto& obj = up ? below_above.second : below_above.first;
      if (!obj) continue;
      const geometry::Point probe(pd.x(), up ? std::nextafter(pd.y(), INFINITY) : std::nextafter(pd.y(), -INFINITY));
      if (!geometry::in_free_wedge(env, id, probe)) continue;
      EK::Point_2 q;
      if (auto* w = boost::get<Arr::Vertex_const_handle>(&*obj)) q = (*w)->point();
      else if (auto* h = boost::get<Arr::Halfedge_const_handle>(&*obj)) {
        EK::Line_2 line((*h)->source()->point(), (*h)->target()->point());
        q = EK::Point_2(p.x(), line.y_at_x(p.x()));
      } else continue;
      extra.emplace_back(p, q);
    }
  }
  CGAL::insert(cut, extra.begin(), extra.end());
  return cut.number_of_faces() - 1 - env.num_holes();
}

void check(const Environment& env, const std::string& what, bool with_cgal = true) {
  TrapezoidalDecomposition d(env);
  geometry::ExactFT total = 0;
  for (std::size_t c = 0; c < d.cells().size(); ++c) {
    const auto a = d.area(c);
    EXPECT_GT(a, 0) << what << ": cell " << c << " has no area";
    total += a;
    EXPECT_LT(d.cells()[c].x_left, d.cells()[c].x_right);
  }
  EXPECT_EQ(total, env.exact_area()) << what << ": cell areas do not sum to the free area";
  // Adjacency: the cell graph of one connected free space is connected (with contacts,
  // cells may meet only at a contact point: Trapezoidal.TouchingHoles checks the planner).
  std::vector<int> seen(d.cells().size(), 0);
  std::vector<std::uint32_t> stack{0};
  seen[0] = 1;
  while (!stack.empty()) {
    auto c = stack.back();
    stack.pop_back();
    for (auto x : d.extensions_of(c))
      for (auto o : {d.extensions()[x].left_cell, d.extensions()[x].right_cell})
        if (!seen[o]) seen[o] = 1, stack.push_back(o);
  }
  if (!env.has_contacts()) {
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(d.cells().size())) << what << ": cell graph not connected";
  }
  // Extensions run through free space, on x = const, between their two cells.
  for (std::size_t x = 0; x < d.extensions().size(); ++x) {
    auto [p, q] = d.segment(x);
    EXPECT_EQ(p.x(), q.x());
    EXPECT_LT(p.y(), q.y());
    const auto& ext = d.extensions()[x];
    EXPECT_EQ(d.cells()[ext.left_cell].x_right, ext.x);
    EXPECT_EQ(d.cells()[ext.right_cell].x_left, ext.x);
  }
  if (with_cgal) {
    EXPECT_EQ(d.cells().size(), cgal_cell_count(env)) << what;
  }
}

}  // namespace

TEST(Trapezoidal, SquareWithHole) {
  auto env = Environment::make({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}});
  TrapezoidalDecomposition d(env);
  // x = 1 and x = 2 each carry two extensions (above and below the hole): 4 cells.
  EXPECT_EQ(d.cells().size(), 4u);
  EXPECT_EQ(d.extensions().size(), 4u);
  check(env, "square with hole");
}

TEST(Trapezoidal, GeneralPositionTriangleFan) {
  auto env = Environment::make({{0, 0}, {5, 1}, {3, 2}, {6, 4}, {1, 3}}, {});
  check(env, "pentagon");
}

TEST(Trapezoidal, RandomEnvironmentsMatchCgal) {
  for (std::uint64_t s = 1; s <= 10; ++s) check(geometry::generators::random_environment(100 + 40 * s, s % 5, s), "seed " + std::to_string(s));
}

TEST(Trapezoidal, DegenerateInputsMatchCgal) {
  // Axis-aligned office plans: equal x everywhere, vertical walls, collinear vertices.
  check(geometry::generators::office(2, 3), "office 2x3");
  check(geometry::generators::office(4, 4), "office 4x4");
  check(Environment::make(geometry::generators::comb(8), {}), "comb");
  for (std::uint64_t s = 1; s <= 15; ++s)
    check(preimage::testing::snapped_random_environment(30 + 2 * s, s % 3, s, 40.0), "snapped seed " + std::to_string(s));
  // Vertices stacked on one vertical line with free space between them.
  check(Environment::make({{0, 0}, {6, 0}, {6, 6}, {0, 6}},
                          {{{2, 1}, {3, 1.5}, {2, 2}}, {{2, 3}, {3, 3.5}, {2, 4}}, {{2, 5}, {1, 5.2}, {1.5, 5.5}}}),
        "stacked vertical vertices");
}

TEST(Trapezoidal, RealHouseExpoFloorPlansMatchCgal) {
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"}) {
    const std::string path = std::string(PREIMAGE_FLOORPLANS) + "/" + name;
    if (!std::ifstream(path)) GTEST_SKIP() << "shared data not found beside the checkout: " << path;
    check(*scene::import_houseexpo(scene::read_file(path), path).environment, name);
  }
}

TEST(CellLocator, AgreesWithExactContainment) {
  for (std::uint64_t s = 1; s <= 6; ++s) {
    auto env = preimage::testing::snapped_random_environment(30 + 4 * s, s % 3, s, 50.0);
    TrapezoidalDecomposition d(env);
    decompose::CellLocator loc(d);
    // Integer queries land on vertices, edges, extensions and event lines often.
    const auto box = env.bbox();
    int in = 0, out = 0;
    for (int x = static_cast<int>(box.xmin()) - 1; x <= static_cast<int>(box.xmax()) + 1; ++x)
      for (int y = static_cast<int>(box.ymin()) - 1; y <= static_cast<int>(box.ymax()) + 1; ++y) {
        const geometry::Point q(x, y);
        const bool free = geometry::locate(env, q).in_free_space();
        auto c = loc.locate(q);
        ASSERT_EQ(c.has_value(), free) << "seed " << s << " at " << geometry::format_point(q);
        if (!c) {
          ++out;
          continue;
        }
        ++in;
        // The cell's closure contains q: exact test against its corners.
        auto poly = d.polygon(*c);
        for (std::size_t i = 0; i < poly.size(); ++i)
          EXPECT_GE(CGAL::orientation(poly[i], poly[(i + 1) % poly.size()], geometry::to_exact(q)), CGAL::COLLINEAR);
      }
    EXPECT_GT(in, 100);
    EXPECT_GT(out, 100);
  }
}

TEST(Planner, PathsAreCollisionFreeAndConnectStartToGoal) {
  for (std::uint64_t s = 1; s <= 5; ++s) {
    auto env = geometry::generators::random_environment(150 + 50 * s, s, s);
    TrapezoidalDecomposition d(env);
    decompose::TrapezoidalPlanner planner(d);
    auto qs = preimage::testing::random_queries(env, 20, 0, 0, s);
    for (std::size_t k = 0; k + 1 < qs.size(); k += 2) {
      for (bool shorten : {false, true}) {
        auto plan = planner.plan(qs[k].p, qs[k + 1].p, shorten);
        ASSERT_TRUE(plan.found);  // one connected free space
        EXPECT_EQ(plan.path.front(), qs[k].p);
        EXPECT_EQ(plan.path.back(), qs[k + 1].p);
        for (std::size_t i = 0; i + 1 < plan.path.size(); ++i)
          EXPECT_TRUE(geometry::visible(env, plan.path[i], plan.path[i + 1]))
              << "seed " << s << " segment " << i << (shorten ? " (shortened)" : "");
      }
    }
  }
}

// Holes touching at vertices (issue 29): the same checks against CGAL's vertical
// decomposition, on the contact fixtures and random touching squares (sheared too), and
// the planner joins cells through contact points, every segment in free space.
TEST(Trapezoidal, TouchingHolesMatchCgalAndPlansPassContacts) {
  std::vector<std::pair<std::string, Environment>> envs;
  for (const char* name : {"checkerboard", "hole_touches_boundary", "corridor_closed_at_points"})
    envs.emplace_back(name, std::move(*scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/contacts/" + name + ".json").environment));
  for (std::uint64_t s = 1; s <= 8; ++s)
    envs.emplace_back("touching_squares " + std::to_string(s), geometry::generators::touching_squares(4 + s % 4, 0.8, s, s % 2 == 0));
  for (const auto& [what, env] : envs) {
    ASSERT_TRUE(env.has_contacts()) << what;
    check(env, what);
    TrapezoidalDecomposition d(env);
    decompose::TrapezoidalPlanner planner(d);
    auto qs = preimage::testing::random_queries(env, 16, 0, 0, 5);
    for (std::size_t k = 0; k + 1 < qs.size(); k += 2)
      for (bool shorten : {false, true}) {
        auto plan = planner.plan(qs[k].p, qs[k + 1].p, shorten);
        ASSERT_TRUE(plan.found) << what;
        for (std::size_t i = 0; i + 1 < plan.path.size(); ++i)
          EXPECT_TRUE(geometry::visible(env, plan.path[i], plan.path[i + 1])) << what << " segment " << i;
      }
  }
  // Through the contacts only: the corridor's halves meet at three points.
  const auto& corridor = envs[2].second;
  TrapezoidalDecomposition d(corridor);
  EXPECT_TRUE(decompose::TrapezoidalPlanner(d).plan(geometry::Point(1, 1), geometry::Point(9, 1)).found);
}

TEST(Planner, RejectsPointsOutsideFreeSpace) {
  auto env = Environment::make({{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}});
  TrapezoidalDecomposition d(env);
  decompose::TrapezoidalPlanner planner(d);
  EXPECT_TRUE(planner.plan(geometry::Point(0.5, 0.5), geometry::Point(3.5, 3.5)).found);
  try {
    planner.plan(geometry::Point(2, 2), geometry::Point(0.5, 0.5));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "start (2, 2) is not in free space: it lies inside obstacles[0]");
  }
  EXPECT_THROW(planner.plan(geometry::Point(0.5, 0.5), geometry::Point(9, 9)), InputError);
}
