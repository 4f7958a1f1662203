// Morse decompositions with variable slices (6.2.3): circular, spike and squarel. Checked
// independently of the construction: cells tile the free space (areas), Euler's relation for
// the Reeb graph, the slice restricted to a cell is connected (sampled), degenerate inputs
// (flat edges, several critical points on one slice, the centre on the boundary).
#include <gtest/gtest.h>
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/coverage/coverage.hpp>
#include <preimage/decompose/morse.hpp>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/scene/import.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>

using namespace preimage;
using decompose::MorseDecomposition;
using decompose::SliceFamily;
using geometry::Environment;
using geometry::Point;

namespace {

constexpr SliceFamily kFamilies[] = {SliceFamily::Circular, SliceFamily::Spike, SliceFamily::Squarel};

bool in_rings(const std::vector<std::vector<Point>>& rings, const Point& p) {
  bool in = false;
  for (const auto& r : rings)
    for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
      if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
          p.x() < (r[j].x() - r[i].x()) * (p.y() - r[i].y()) / (r[j].y() - r[i].y()) + r[i].x())
        in = !in;
  return in;
}

// A point of the slice at level `lam`, parameter s in [0, 1) around it (closed slices) or
// along the ray up to `reach` (spike).
Point slice_point(SliceFamily f, const Point& c, double lam, double s, double reach) {
  const double t = 2 * std::numbers::pi * s;
  switch (f) {
    case SliceFamily::Circular: return {c.x() + lam * std::cos(t), c.y() + lam * std::sin(t)};
    case SliceFamily::Spike: return {c.x() + s * reach * std::cos(lam), c.y() + s * reach * std::sin(lam)};
    case SliceFamily::Linear: return {lam, c.y() + (s - 0.5) * reach};
    case SliceFamily::Squarel: {
      const double u = 4 * s;  // corners at u = 0, 1, 2, 3: (L,0), (0,L), (-L,0), (0,-L)
      const int k = static_cast<int>(u) & 3;
      const double f2 = u - std::floor(u);
      const double xs[] = {1, 0, -1, 0, 1}, ys[] = {0, 1, 0, -1, 0};
      return {c.x() + lam * (xs[k] + f2 * (xs[k + 1] - xs[k])), c.y() + lam * (ys[k] + f2 * (ys[k + 1] - ys[k]))};
    }
  }
  return c;
}

// Closed slices (circular, squarel) that meet no edge enclose holes; each distinct nonempty
// set of enclosed holes is a loop of the free space the Reeb graph cannot see (it lies in a
// level set). Returns how many such sets there are, sampling each cell's middle level.
std::size_t level_set_loops(const Environment& env, const MorseDecomposition& m) {
  if (m.family() == SliceFamily::Spike) return 0;
  std::vector<double> node_level(m.num_nodes(), 0);
  for (const auto& k : m.critical_points()) node_level[k.node] = k.level;
  std::set<std::size_t> classes;
  for (const auto& cell : m.cells()) {
    if (cell.nodes.size() != 2) continue;
    const double lam = (node_level[cell.nodes[0]] + node_level[cell.nodes[1]]) / 2;
    bool crosses = false;
    for (std::size_t e = 0; e < env.num_vertices() && !crosses; ++e) {
      const Point a = env.vertex(e), b = env.vertex(env.next(e));
      double lo = std::min(m.level(a), m.level(b));
      const double hi = std::max(m.level(a), m.level(b));
      for (int i = 1; i < 256; ++i) lo = std::min(lo, m.level(Point(a.x() + (b.x() - a.x()) * i / 256.0, a.y() + (b.y() - a.y()) * i / 256.0)));
      crosses = lo <= lam && lam <= hi;
    }
    if (crosses) continue;
    std::size_t enclosed = 0;
    for (std::size_t r = 1; r < env.num_rings(); ++r) {
      double top = 0;
      for (std::size_t v = env.ring_begin(r); v < env.ring_end(r); ++v) top = std::max(top, m.level(env.vertex(v)));
      enclosed += top < lam;
    }
    if (enclosed) classes.insert(enclosed);  // nested sets: distinct sizes are distinct sets
  }
  return classes.size();
}

void check(const Environment& env, SliceFamily f, const Point& c, const std::string& what, std::mt19937_64& rng) {
  const MorseDecomposition m(env, f, c);
  const auto& cells = m.cells();
  ASSERT_FALSE(cells.empty()) << what;
  // Cells tile the free space.
  double total = 0;
  for (const auto& cell : cells) {
    EXPECT_GE(cell.area, -1e-9 * env.area()) << what;
    total += cell.area;
  }
  EXPECT_NEAR(total, env.area(), 1e-9 * env.area()) << what;
  // Euler for the Reeb graph (nodes = critical slices, edges = cells): E = V + b1 - 1, where b1
  // counts the free space's loops the slices sweep across: every hole, plus the centre for
  // spike (h is undefined there), minus the loops that lie along closed slices.
  // Holes touching at a vertex close no loop there: one loop fewer per merge.
  const auto loops = static_cast<long>(env.num_holes()) - static_cast<long>(env.contact_merges()) +
                     ((f == SliceFamily::Spike && m.centre_in_free_space()) ? 1 : 0) - static_cast<long>(level_set_loops(env, m));
  const long nodes = std::max<long>(1, static_cast<long>(m.num_nodes()));  // a loop with no critical point: one virtual node
  EXPECT_EQ(static_cast<long>(cells.size()), nodes + loops - 1) << what;
  // Each cell runs between at most two critical slices, and every node bounds a cell.
  std::vector<int> used(m.num_nodes(), 0);
  for (const auto& cell : cells) {
    EXPECT_LE(cell.nodes.size(), 2u) << what;
    if (f != SliceFamily::Spike) {
      EXPECT_EQ(cell.nodes.size(), 2u) << what;
    }
    for (auto k : cell.nodes) used[k] = 1;
  }
  for (std::size_t k = 0; k < used.size(); ++k) EXPECT_TRUE(used[k]) << what << " node " << k;
  // Adjacency is symmetric.
  const auto adj = m.adjacency();
  for (std::size_t a = 0; a < adj.size(); ++a)
    for (auto b : adj[a]) EXPECT_TRUE(std::count(adj[b].begin(), adj[b].end(), a)) << what;
  // The slice restricted to a cell is connected: at a few random points of each cell, walk
  // the whole slice through it and count the runs inside the cell.
  const auto box = env.bbox();
  const double reach = 2 * std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin()) + std::hypot(c.x() - box.xmin(), c.y() - box.ymin());
  std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax());
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (cells[k].area < 1e-6 * env.area()) continue;  // slivers between near-equal critical slices
    const auto rings = m.cell_rings(k, 1e-6 * reach);
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    for (const auto& r : rings)
      for (const auto& p : r) xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x()), ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
    std::uniform_real_distribution<double> cx(xmin, xmax), cy(ymin, ymax);
    int probes = 0;
    for (int attempt = 0; attempt < 400 && probes < 2; ++attempt) {
      const Point p(cx(rng), cy(rng));
      if (!in_rings(rings, p)) continue;
      const double lam = m.level(p);
      // Not next to a critical slice of the cell, where sampling cannot tell the slice from it.
      bool near = false;
      for (const auto nd : cells[k].nodes)
        for (const auto& crit : m.critical_points())
          if (crit.node == nd) near |= std::abs(crit.level - lam) < (f == SliceFamily::Spike ? 1e-3 : 1e-3 * reach);
      if (near) continue;
      ++probes;
      constexpr int kSamples = 4000;
      std::vector<char> inside(kSamples);
      for (int i = 0; i < kSamples; ++i) inside[i] = in_rings(rings, slice_point(f, c, lam, (i + 0.5) / kSamples, reach));
      int runs = 0;
      const bool closed = f != SliceFamily::Spike;
      for (int i = 0; i < kSamples; ++i) {
        const bool prev = i > 0 ? inside[i - 1] : (closed ? inside[kSamples - 1] : false);
        runs += inside[i] && !prev;
      }
      // p itself is on the slice inside the cell: no sample inside means a piece shorter than
      // the sampling step, still one run.
      EXPECT_LE(runs, 1) << what << " cell " << k << " level " << lam << " at " << p;
    }
  }
  (void)ux, (void)uy;
}

Point random_centre(const Environment& env, std::mt19937_64& rng) {
  const auto box = env.bbox();
  std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax());
  return {ux(rng), uy(rng)};
}

}  // namespace

TEST(Morse, RandomEnvironmentsAllFamilies) {
  std::mt19937_64 rng(7);
  for (std::uint64_t seed = 0; seed < 60; ++seed) {
    const Environment env = geometry::generators::random_environment(20 + seed % 50, seed % 6, 300 + seed);
    for (const auto f : kFamilies) {
      const Point c = random_centre(env, rng);
      check(env, f, c, "seed " + std::to_string(seed) + " " + std::string(to_string(f)) + " centre " + geometry::format_point(c), rng);
    }
  }
}

TEST(Morse, OfficesAndRectilinearMapsWithFlatEdges) {
  // Axis-aligned maps: for spike every edge whose line passes through the centre lies on a
  // slice; centres on the grid's lines make many of them.
  std::mt19937_64 rng(11);
  const Environment office = geometry::generators::office(3, 3);
  for (const auto f : kFamilies)
    for (const Point c : {Point(2, 6), Point(6, 6), Point(5.3, 6.7), Point(1, 1), Point(6, 2)})
      check(office, f, c, "office " + std::string(to_string(f)) + " " + geometry::format_point(c), rng);
  for (std::uint64_t seed = 0; seed < 8; ++seed) {
    const Environment env = geometry::generators::random_rectilinear(6, 5, true, seed);
    for (const auto f : kFamilies) check(env, f, random_centre(env, rng), "rectilinear " + std::to_string(seed), rng);
  }
}

TEST(Morse, BothFloorPlans) {
  std::mt19937_64 rng(3);
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"}) {
    const auto s = scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS) + "/" + name);
    const Environment& env = s.require_environment();
    for (int i = 0; i < 4; ++i)
      for (const auto f : kFamilies) check(env, f, random_centre(env, rng), std::string(name) + " " + std::string(to_string(f)), rng);
  }
}

TEST(Morse, SquareRoomCentredHasOneCriticalSliceThroughFourFeet) {
  // h = |p - c| in [-1, 1]^2 around the origin: the circle of radius 1 touches the four walls
  // at once (four critical points on one slice, one node); cells: the disc and four corners.
  const Environment env = Environment::make({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, {});
  const MorseDecomposition m(env, SliceFamily::Circular, Point(0, 0));
  EXPECT_EQ(m.cells().size(), 5u);
  EXPECT_EQ(m.num_nodes(), 6u);  // centre, the unit circle, four corners
  std::size_t feet = 0;
  for (const auto& k : m.critical_points())
    if (k.kind == decompose::CriticalKind::SplitMerge) {
      ++feet;
      EXPECT_DOUBLE_EQ(k.level, 1.0);
    }
  EXPECT_EQ(feet, 4u);
  EXPECT_EQ(m.arcs().size(), 4u);  // quarter circles from foot to foot
  // Squarel around the origin: the diamond of level 1 touches the four walls at its corners.
  const MorseDecomposition q(env, SliceFamily::Squarel, Point(0, 0));
  EXPECT_EQ(q.cells().size(), 5u);
  EXPECT_EQ(q.arcs().size(), 4u);
}

TEST(Morse, HoleAroundTheCentreIsAnAnnulusForSpike) {
  // The centre inside a square hole of a square room: rays cross the hole once and the wall
  // once, no critical point, one annular cell (a loop of the Reeb graph with no node).
  const Environment env = Environment::make({{-4, -4}, {4, -4}, {4, 4}, {-4, 4}}, {{{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}});
  const MorseDecomposition s(env, SliceFamily::Spike, Point(0.25, 0.125));
  EXPECT_EQ(s.cells().size(), 1u);
  EXPECT_EQ(s.cells()[0].cycles.size(), 2u);
  EXPECT_NEAR(s.cells()[0].area, 60.0, 1e-9);
  // Circles: the hole's farthest corner closes the slice into a loop; annulus cells appear.
  const MorseDecomposition c(env, SliceFamily::Circular, Point(0.25, 0.125));
  double total = 0;
  bool annulus = false;
  for (const auto& cell : c.cells()) total += cell.area, annulus |= cell.cycles.size() == 2;
  EXPECT_NEAR(total, 60.0, 1e-9);
  EXPECT_TRUE(annulus);
}

TEST(Morse, FlatEdgesAreCriticalSlicesNotErrors) {
  // A diamond-shaped hole around the centre has every edge on a slice of squarel... except
  // it is one slice entirely: rejected. A hole with one flat side is handled.
  const Environment diamond = Environment::make({{-4, -4}, {4, -4}, {4, 4}, {-4, 4}}, {{{1, 0}, {0, -1}, {-1, 0}, {0, 1}}});
  EXPECT_THROW(MorseDecomposition(diamond, SliceFamily::Squarel, Point(0, 0)), InputError);
  std::mt19937_64 rng(5);
  check(diamond, SliceFamily::Squarel, Point(0.1, 0.05), "diamond off-centre", rng);
  // Spike: an edge on a ray from the centre, from both sides of a hole.
  const Environment room = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}});
  for (const Point c : {Point(5, 2), Point(2, 2), Point(4, 1), Point(1, 5)})
    check(room, SliceFamily::Spike, c, "spike flat " + geometry::format_point(c), rng);
}

TEST(Morse, CentreOnTheBoundaryIsAnError) {
  const Environment room = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}});
  for (const auto f : kFamilies) {
    EXPECT_THROW(MorseDecomposition(room, f, Point(5, 0)), InputError);
    EXPECT_THROW(MorseDecomposition(room, f, Point(4, 4)), InputError);
  }
  try {
    MorseDecomposition(room, SliceFamily::Circular, Point(0, 5));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lies on the boundary"), std::string::npos) << e.what();
  }
}

TEST(Morse, RootNumberSignsAreExact) {
  using decompose::RootNumber;
  // 1 - sqrt(2) / sqrt(2) style cancellations and near-ties.
  EXPECT_EQ((RootNumber{3, -2, 2}).sign(), 1);    // 3 - 2 sqrt 2 = 0.17
  EXPECT_EQ((RootNumber{-3, 2, 2}).sign(), -1);
  EXPECT_EQ((RootNumber{2, -1, 4}).sign(), 0);    // 2 - sqrt 4
  const geometry::ExactFT big = geometry::ExactFT(1) / geometry::ExactFT(1 << 30);
  EXPECT_EQ((RootNumber{geometry::ExactFT(1) + big, -1, 1}).sign(), 1);
}

TEST(Morse, CircleThroughAVertexEndsItsArcThere) {
  // tests/fixtures/morse/circle_through_vertex.json: two critical points on the circle of
  // radius 3 (the square's foot at (3, 0), the triangle's vertex (0, 3)); the arc leaving
  // (3, 0) counter-clockwise ends at (0, 3) and both are one critical slice.
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/morse/circle_through_vertex.json");
  const Environment& env = s.require_environment();
  const MorseDecomposition m(env, SliceFamily::Circular, Point(0, 0));
  bool found = false;
  for (const auto& a : m.arcs())
    if (a.a == Point(3, 0) && a.ccw) {
      EXPECT_EQ(a.b, Point(0, 3));
      EXPECT_NEAR(a.span, std::numbers::pi / 2, 1e-12);
      found = true;
    }
  EXPECT_TRUE(found);
  std::uint32_t foot_node = 0, vertex_node = 1;
  for (const auto& k : m.critical_points()) {
    if (m.points()[k.point].approx == Point(3, 0)) foot_node = k.node;
    if (m.points()[k.point].approx == Point(0, 3)) vertex_node = k.node;
  }
  EXPECT_EQ(foot_node, vertex_node);
  std::mt19937_64 rng(1);
  check(env, SliceFamily::Circular, Point(0, 0), "circle_through_vertex", rng);
}

TEST(Morse, LinearSlicesReproduceTheBoustrophedonDecomposition) {
  // h = x through the generic construction against BoustrophedonDecomposition (a sweep over
  // trapezoids): the same cells (count and exact areas), the same critical slices, on random
  // environments and on maps full of vertical walls (flat runs).
  std::vector<std::pair<std::string, Environment>> envs;
  for (std::uint64_t seed = 0; seed < 40; ++seed)
    envs.emplace_back("random " + std::to_string(seed), geometry::generators::random_environment(20 + seed % 50, seed % 6, 900 + seed));
  envs.emplace_back("office", geometry::generators::office(3, 3));
  for (std::uint64_t seed = 0; seed < 6; ++seed) envs.emplace_back("rectilinear " + std::to_string(seed), geometry::generators::random_rectilinear(6, 5, true, seed));
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"})
    envs.emplace_back(name, *scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS) + "/" + name).environment);
  for (const auto& [what, env] : envs) {
    const decompose::BoustrophedonDecomposition b(env);
    const MorseDecomposition m(env, SliceFamily::Linear, Point(0, 0));
    ASSERT_EQ(m.cells().size(), b.cells().size()) << what;
    EXPECT_EQ(m.num_nodes(), b.critical_slices().size()) << what;
    std::vector<double> mine, theirs;
    for (const auto& c : m.cells()) mine.push_back(c.area);
    for (std::size_t c = 0; c < b.cells().size(); ++c) theirs.push_back(CGAL::to_double(b.area(c)));
    std::sort(mine.begin(), mine.end());
    std::sort(theirs.begin(), theirs.end());
    for (std::size_t i = 0; i < mine.size(); ++i) EXPECT_NEAR(mine[i], theirs[i], 1e-9 * env.area()) << what << " cell " << i;
  }
}

namespace {

// Independent check of a robot's path: points sampled along every segment keep at least r
// (less a rounding allowance) from every environment edge, and lie in the free space.
double min_clearance(const Environment& env, const std::vector<Point>& path) {
  double worst = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    for (int k = 0; k <= 4; ++k) {
      const Point p(path[i].x() + (path[i + 1].x() - path[i].x()) * k / 4.0, path[i].y() + (path[i + 1].y() - path[i].y()) * k / 4.0);
      for (std::size_t e = 0; e < env.num_vertices(); ++e) {
        const Point a = env.vertex(e), b = env.vertex(env.next(e));
        const double ex = b.x() - a.x(), ey = b.y() - a.y(), L2 = ex * ex + ey * ey;
        const double t = std::clamp(((p.x() - a.x()) * ex + (p.y() - a.y()) * ey) / L2, 0.0, 1.0);
        worst = std::min(worst, std::hypot(a.x() + t * ex - p.x(), a.y() + t * ey - p.y()));
      }
    }
  return worst;
}

}  // namespace

TEST(MorseCoverage, PatternsCoverTheConfigurationSpaceAndKeepClear) {
  // Every pattern on a field with three obstacles, an office, a random environment and both
  // floor plans: >= 99% of the configuration space within w/2 of the path (rasterised,
  // measure_coverage), and the robot's disc never nearer than r to a wall.
  std::vector<std::pair<std::string, Environment>> envs;
  envs.emplace_back("field", Environment::make({{0, 0}, {12, 0}, {12, 8}, {0, 8}}, {{{2, 3}, {3.5, 2}, {4, 4}, {2.5, 5}}, {{6, 1.5}, {8.5, 1}, {8, 3}},
                                                                                  {{7, 5}, {9, 4.5}, {10, 6.5}, {8, 7}}}));
  envs.emplace_back("office", geometry::generators::office(2, 3));
  envs.emplace_back("random", geometry::generators::random_environment(200, 3, 77));
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"})
    envs.emplace_back(name, *scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS) + "/" + name).environment);
  for (const auto& [what, env] : envs) {
    const auto box = env.bbox();
    const double r = std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin()) / 120;
    for (const auto pattern : {coverage::Pattern::Spiral, coverage::Pattern::Concentric, coverage::Pattern::Spike, coverage::Pattern::Squarel}) {
      coverage::CoverageOptions o;
      o.robot_radius = r, o.pattern = pattern;
      o.centre = Point((box.xmin() + box.xmax()) / 2 + r / 7, (box.ymin() + box.ymax()) / 2 + r / 11);
      const auto rep = coverage::plan_coverage(env, o);
      const auto m = coverage::measure_coverage(env, rep);
      const std::string tag = what + " " + std::string(coverage::to_string(pattern));
      EXPECT_GE(m.covered_fraction, 0.99) << tag;
      EXPECT_GE(min_clearance(env, rep.path), r * (1 - 1e-6)) << tag;
      EXPECT_GT(rep.laps, 0u) << tag;
      EXPECT_EQ(rep.moves.size() + 1, rep.path.size()) << tag;
    }
  }
}

TEST(MorseCoverage, SpiralReplacesCirclesInAnnularCells) {
  // The centre inside a small hole of a large room: the circles around it are whole loops
  // from the hole's far corner to the nearest wall, one annular cell swept by one spiral
  // instead of concentric circles joined by radial steps (Fig. 6.12).
  const Environment env = Environment::make({{-10, -10}, {10, -10}, {10, 10}, {-10, 10}}, {{{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}});
  coverage::CoverageOptions o;
  o.robot_radius = 0.25, o.centre = Point(0.25, 0.125);
  o.pattern = coverage::Pattern::Spiral;
  const auto spiral = coverage::plan_coverage(env, o);
  o.pattern = coverage::Pattern::Concentric;
  const auto circles = coverage::plan_coverage(env, o);
  EXPECT_LT(spiral.laps + 10, circles.laps);
  EXPECT_GE(coverage::measure_coverage(env, spiral).covered_fraction, 0.99);
  EXPECT_GE(coverage::measure_coverage(env, circles).covered_fraction, 0.99);
  // A spiral has no radial steps: fewer turns over a degree.
  EXPECT_LT(spiral.turns, circles.turns);
}

TEST(Morse, HolesTouchingAtVerticesAreOnePointOfSeveralWedges) {
  // Contacts (issue 29): every ring's vertex at a contact is one point of the graph; each free
  // wedge there is classified on its own; Euler loses one loop per merge. Random touching
  // squares, plain and sheared, and the checkerboard fixture, every family.
  std::mt19937_64 rng(29);
  std::vector<std::pair<std::string, Environment>> envs;
  envs.emplace_back("checkerboard", *scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/contacts/checkerboard.json").environment);
  envs.emplace_back("hole_touches_boundary", *scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/contacts/hole_touches_boundary.json").environment);
  for (std::uint64_t seed = 0; seed < 8; ++seed)
    envs.emplace_back("touching squares " + std::to_string(seed), geometry::generators::touching_squares(5, 0.5, seed, seed % 2 == 1));
  int checked = 0, with_contacts = 0;
  for (const auto& [what, env] : envs) {
    if (!env.has_contacts()) continue;  // a random draw without one
    ++with_contacts;
    for (const auto f : kFamilies)
      for (int k = 0; k < 3; ++k) {
        const Point c = random_centre(env, rng);
        try {
          check(env, f, c, what + " " + std::string(to_string(f)) + " " + geometry::format_point(c), rng);
          ++checked;
        } catch (const InputError& e) {
          // a centre on a wall or a flat edge ending at a contact: named, never a wrong answer
          EXPECT_NE(std::string(e.what()).find("--center"), std::string::npos) << e.what();
        }
      }
  }
  EXPECT_GE(with_contacts, 8);
  EXPECT_GT(checked, 60);
}
