// Visibility polygons against CGAL's Triangular_expansion_visibility_2 (exact
// constructions): identical regions on >= 1,000 queries of every kind.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/scene.hpp>

#include "support/cgal_oracle.hpp"

#include <cmath>
#include <random>
#include <span>
#include <thread>

using namespace preimage::geometry;
using preimage::testing::CgalVisibility;

namespace {
int compare_with_cgal(const Environment& env, std::size_t interior, std::size_t edges, std::size_t vertices, std::uint64_t seed) {
  VisibilityIndex ours(env);
  CgalVisibility cgal(env);
  int compared = 0;
  for (auto& q : preimage::testing::random_queries(env, interior, edges, vertices, seed)) {
    EXPECT_EQ(ours.locate(q.p).kind, q.loc.kind);
    auto mine = ours.compute(q.p);
    auto a = canonical_cycle(mine.points());
    auto b = canonical_cycle(cgal.compute(q.p, q.loc));
    EXPECT_EQ(a, b) << "query " << format_point(q.p) << " (" << to_string(q.loc.kind) << ") seed " << seed
                    << ": " << a.size() << " vs " << b.size() << " vertices";
    // Every edge tag says something true.
    const std::size_t n = mine.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto p = mine.exact(i), r = mine.exact((i + 1) % n);
      const auto& e = mine.edges[i];
      if (e.kind == VisibilityEdge::Kind::Solid) {
        const auto s = to_exact(env.vertex(e.edge)), t = to_exact(env.vertex(env.next(e.edge)));
        EXPECT_EQ(CGAL::orientation(s, t, p), CGAL::COLLINEAR);
        EXPECT_EQ(CGAL::orientation(s, t, r), CGAL::COLLINEAR);
      } else {
        const auto c = to_exact(env.vertex(e.reflex));
        EXPECT_EQ(CGAL::orientation(to_exact(q.p), c, p), CGAL::COLLINEAR);
        EXPECT_EQ(CGAL::orientation(to_exact(q.p), c, r), CGAL::COLLINEAR);
        EXPECT_TRUE(p == c || r == c) << "a free edge starts or ends at its occluding vertex";
      }
    }
    ++compared;
  }
  return compared;
}
}  // namespace

TEST(Visibility, MatchesCgalWithoutHoles) {
  int n = 0;
  for (std::uint64_t s = 1; s <= 6; ++s)
    n += compare_with_cgal(preimage::testing::snapped_random_environment(150 * s, 0, s), 60, 15, 15, s);
  EXPECT_GE(n, 500);
}

TEST(Visibility, MatchesCgalWithHoles) {
  int n = 0;
  for (std::uint64_t s = 1; s <= 6; ++s)
    n += compare_with_cgal(preimage::testing::snapped_random_environment(200 * s, s * 2, 100 + s), 60, 15, 15, s);
  EXPECT_GE(n, 500);
}

TEST(Visibility, MatchesCgalOnDegenerateFloorPlans) {
  int n = compare_with_cgal(generators::office(3, 4), 100, 0, 60, 77);
  n += compare_with_cgal(Environment::make(generators::comb(12), {}), 60, 0, 40, 78);
  EXPECT_GE(n, 200);
}

// The expansion's static filter bound is the largest determinant error any query in the
// bounding box can see; below extents of 1e-140, where underflow breaks that bound, every
// test goes to CGAL instead (coordinates above 1e12 are refused at input). Scaling by a power
// of two is exact, so the same map (extents about 1e3) at 2^-1000 and 2^-480 (bound off),
// 2^-470 (on, just) and 2^29 (near the largest coordinates) must still match CGAL.
TEST(Visibility, MatchesCgalAtExtremeScales) {
  const Environment base = preimage::testing::snapped_random_environment(120, 4, 31);
  int n = 0;
  for (int e : {-1000, -480, -470, 29}) {
    auto scaled = [&](std::size_t r) {
      Ring ring;
      for (const Point& p : base.ring(r)) ring.push_back(Point(std::ldexp(p.x(), e), std::ldexp(p.y(), e)));
      return ring;
    };
    std::vector<Ring> holes;
    for (std::size_t h = 1; h < base.num_rings(); ++h) holes.push_back(scaled(h));
    n += compare_with_cgal(Environment::make(scaled(0), holes), 40, 10, 10, static_cast<std::uint64_t>(e + 2000));
  }
  EXPECT_GE(n, 200);
}

// Queries within rounding of the line through two vertices a and b, beyond b: seen from
// there, b and a lie in one direction (b may hide a or graze it), and their determinant is
// far below the static bound, so CGAL decides it. Maps with unsnapped coordinates (full
// mantissas), where the double sign of such a determinant can be wrong.
TEST(Visibility, NearlyCollinearQueriesMatchCgal) {
  for (const Environment& env : {generators::random_environment(200, 5, 41), generators::office(3, 3)}) {
    VisibilityIndex ours(env);
    CgalVisibility cgal(env);
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<std::size_t> V(0, env.num_vertices() - 1);
    std::uniform_real_distribution<double> T(1.02, 2.0);  // q beyond b: sees b and a in one direction
    int compared = 0, tries = 0;
    while (compared < 300 && ++tries < 100000) {
      const Point& a = env.vertex(V(rng));
      const Point& b = env.vertex(V(rng));
      const double t = T(rng);
      const Point q(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
      const Location loc = locate(env, q);
      if (!loc.in_free_space()) continue;
      EXPECT_EQ(canonical_cycle(ours.compute(q).points()), canonical_cycle(cgal.compute(q, loc)))
          << "query " << format_point(q) << " on the line through " << format_point(a) << " and " << format_point(b);
      ++compared;
    }
    EXPECT_EQ(compared, 300);
  }
}

TEST(Visibility, RejectsQueriesOutsideFreeSpace) {
  auto env = generators::office(2, 2);
  VisibilityIndex index(env);
  EXPECT_THROW(index.compute(Point(-1, -1)), preimage::InputError);
  EXPECT_THROW(index.compute(Point(4, 1)), preimage::InputError);  // inside a wall
}

// ---------------------------------------------------------------- reusable output, abstract mode, batches
namespace {
Environment vis_houseexpo(const char* name) {
  const std::string path = std::string(PREIMAGE_FLOORPLANS).append("/").append(name);
  return *preimage::scene::import_houseexpo(preimage::scene::read_file(path), path).environment;
}

// Environments with holes, collinear runs and real plans, each with its name for messages.
std::vector<std::pair<std::string, Environment>> vis_environments() {
  std::vector<std::pair<std::string, Environment>> envs;
  envs.emplace_back("random 400 / 6 holes", generators::random_environment(400, 6, 11));
  envs.emplace_back("random 1500 / 20 holes", generators::random_environment(1500, 20, 12));
  envs.emplace_back("snapped 300 / 4 holes", preimage::testing::snapped_random_environment(300, 4, 13));
  envs.emplace_back("office 4x3", generators::office(4, 3));
  envs.emplace_back("comb 60", Environment::make(generators::comb(60), {}));
  // Around the origin: grid-cell bounds on both sides of 0 (the doubles are densest there).
  envs.emplace_back("star 40 around (0, 0)", Environment::make(generators::star(40), {}));
  envs.emplace_back("houseexpo 0000", vis_houseexpo("house_expo_room_0000.json"));
  envs.emplace_back("houseexpo 1451", vis_houseexpo("house_expo_room_1451.json"));
  return envs;
}

void expect_same_polygon(const VisibilityPolygon& a, const VisibilityPolygon& b, bool compare_approx, const std::string& what) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size()) << what;
  ASSERT_EQ(a.edges.size(), b.edges.size()) << what;
  EXPECT_EQ(a.location.kind, b.location.kind) << what;
  EXPECT_EQ(a.location.index, b.location.index) << what;
  EXPECT_EQ(a.query, b.query) << what;
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    const auto &u = a.vertices[i], &v = b.vertices[i];
    EXPECT_TRUE(u.kind == v.kind && u.vertex == v.vertex && u.edge == v.edge) << what << ": vertex " << i;
    if (compare_approx) {
      EXPECT_EQ(u.approx, v.approx) << what << ": vertex " << i;
    }
    const auto &e = a.edges[i], &f = b.edges[i];
    EXPECT_TRUE(e.kind == f.kind && e.edge == f.edge && e.reflex == f.reflex && e.occluder_on_left == f.occluder_on_left)
        << what << ": edge " << i;
  }
}

// Exact brute-force point location: every triangle, exact orientations.
Location brute_locate(const Environment& env, const Triangulation& tri, const Point& q) {
  for (const Triangle& t : tri.triangles()) {
    int o[3];
    bool in = true;
    for (int i = 0; i < 3; ++i) {
      o[i] = static_cast<int>(CGAL::orientation(env.vertex(t.v[i]), env.vertex(t.v[(i + 1) % 3]), q));
      in = in && o[i] >= 0;
    }
    if (!in) continue;
    for (int i = 0; i < 3; ++i)
      if (env.vertex(t.v[i]) == q) return {Location::Kind::AtVertex, t.v[i]};
    for (int i = 0; i < 3; ++i)
      if (o[i] == 0 && t.nbr[i] == kNone) return {Location::Kind::OnEdge, t.edge[i]};
    return {Location::Kind::Interior, 0};
  }
  return preimage::geometry::locate(env, q);  // not in free space: the O(n) locator names hole or outside
}
}  // namespace

TEST(Visibility, ReusedOutputAndAbstractModeEqualByValue) {
  VisibilityPolygon reused, abstract;  // reused across queries and environments
  std::size_t compared = 0;
  for (const auto& [name, env] : vis_environments()) {
    VisibilityIndex index(env);
    const bool snapped = name.rfind("random", 0) != 0;  // points on edges exist exactly
    for (const auto& q : preimage::testing::random_queries(env, 80, snapped ? 20 : 0, 20, 31)) {
      const std::string what = name + " at " + format_point(q.p);
      const VisibilityPolygon v = index.compute(q.p);
      index.compute(q.p, reused);
      expect_same_polygon(v, reused, true, what + " (reused)");
      EXPECT_FALSE(reused.abstract);
      index.compute_abstract(q.p, abstract);
      expect_same_polygon(v, abstract, false, what + " (abstract)");
      EXPECT_TRUE(abstract.abstract);
      for (std::size_t i = 0; i < abstract.vertices.size(); ++i) {
        EXPECT_TRUE(std::isnan(abstract.vertices[i].approx.x())) << what << ": abstract mode fills no coordinates";
        EXPECT_EQ(abstract.approx_point(i), v.vertices[i].approx) << what << ": vertex " << i;
      }
      EXPECT_EQ(abstract.area(), v.area()) << what;
      EXPECT_EQ(abstract.points(), v.points()) << what;
      EXPECT_EQ(v.exact_query(), to_exact(q.p));
      ++compared;
    }
  }
  EXPECT_GE(compared, 600u);
}

TEST(Visibility, ConstructedQueryKeepsItsExactPoint) {
  const auto env = generators::office(2, 2);
  VisibilityIndex index(env);
  // (1/3, 1/3) is no double: the polygon must keep the constructed point, not its rounding.
  const ExactPoint third(ExactKernel::FT(1) / 3, ExactKernel::FT(1) / 3);
  const VisibilityPolygon v = index.compute(third);
  ASSERT_TRUE(v.constructed_query.has_value());
  EXPECT_EQ(v.exact_query(), third);
  EXPECT_NE(to_exact(v.query), third);
  EXPECT_EQ(v.points().size(), index.compute(Point(1.0 / 3, 1.0 / 3)).points().size());
}

TEST(Visibility, ComputeManyEqualsSequentialCompute) {
  for (const auto& [name, env] : vis_environments()) {
    VisibilityIndex index(env);
    std::vector<Point> qs;
    for (const auto& q : preimage::testing::random_queries(env, 300, 0, 30, 41)) qs.push_back(q.p);
    for (unsigned threads : {1u, 2u, 3u, 0u}) {
      const auto all = index.compute_many(qs, threads);
      ASSERT_EQ(all.size(), qs.size());
      for (std::size_t i = 0; i < qs.size(); ++i)
        expect_same_polygon(index.compute(qs[i]), all[i], true, name + " query " + std::to_string(i) + " threads " + std::to_string(threads));
    }
    const auto abstract = index.compute_many(qs, 2, true);
    for (std::size_t i = 0; i < qs.size(); ++i) {
      EXPECT_TRUE(abstract[i].abstract);
      expect_same_polygon(index.compute(qs[i]), abstract[i], false, name + " abstract query " + std::to_string(i));
    }
    // Into reused polygons: batches of other sizes, other queries and the other mode in
    // between leave nothing behind (every polygon is rewritten whole).
    std::vector<VisibilityPolygon> reused;
    const std::span<const Point> all_qs(qs);
    for (auto [from, count, threads, abstract_mode] : {std::tuple{0, 330, 2u, false}, std::tuple{100, 50, 1u, true},
                                                       std::tuple{7, 300, 2u, true}, std::tuple{29, 301, 0u, false}}) {
      index.compute_many(all_qs.subspan(from, count), reused, threads, abstract_mode);
      ASSERT_EQ(reused.size(), static_cast<std::size_t>(count));
      for (int i = 0; i < count; ++i) {
        EXPECT_EQ(reused[i].abstract, abstract_mode);
        expect_same_polygon(index.compute(qs[from + i]), reused[i], !abstract_mode,
                            name + " reused, query " + std::to_string(from + i) + " threads " + std::to_string(threads));
      }
    }
  }
  // A query outside free space: the first one's error, after every thread has finished.
  const auto env = generators::office(2, 2);
  VisibilityIndex index(env);
  std::vector<Point> qs(200, Point(1, 1));
  qs[150] = Point(-1, -1), qs[170] = Point(4, 1);
  try {
    index.compute_many(qs, 2);
    ADD_FAILURE() << "no error for a query outside free space";
  } catch (const preimage::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(-1, -1)"), std::string::npos) << e.what();
  }
  std::vector<VisibilityPolygon> reused;
  try {
    index.compute_many(qs, reused, 2);
    ADD_FAILURE() << "no error for a query outside free space (reused output)";
  } catch (const preimage::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(-1, -1)"), std::string::npos) << e.what();
  }
  EXPECT_EQ(reused[0].location.kind, Location::Kind::Interior) << "the other queries are computed";
}

// compute_many from several callers at once (the helper pool is shared by the process):
// every caller gets its own queries' polygons, equal to sequential compute.
TEST(Visibility, ComputeManyFromConcurrentCallers) {
  const auto env = generators::office(4, 3);
  VisibilityIndex index(env);
  std::vector<Point> qs;
  for (const auto& q : preimage::testing::random_queries(env, 400, 0, 0, 43)) qs.push_back(q.p);
  std::vector<VisibilityPolygon> want;
  for (const Point& q : qs) want.push_back(index.compute(q));
  std::vector<std::vector<VisibilityPolygon>> got(4);
  std::vector<std::thread> callers;
  for (std::size_t c = 0; c < got.size(); ++c)
    callers.emplace_back([&, c] {
      for (int round = 0; round < 5; ++round) got[c] = index.compute_many(std::span<const Point>(qs).subspan(c * 50), 2 + c % 2);
    });
  for (auto& t : callers) t.join();
  for (std::size_t c = 0; c < got.size(); ++c) {
    ASSERT_EQ(got[c].size(), qs.size() - c * 50);
    for (std::size_t i = 0; i < got[c].size(); ++i)
      expect_same_polygon(want[c * 50 + i], got[c][i], true, "caller " + std::to_string(c) + " query " + std::to_string(i));
  }
}

namespace {
// index.locate(p) against the brute-force locator: same kind, same edge, vertex or hole.
Location expect_locate_as_brute_force(const Environment& env, const VisibilityIndex& index, const Point& p, const std::string& name) {
  const Location want = brute_locate(env, index.triangulation(), p);
  const Location got = index.locate(p);
  EXPECT_EQ(got.kind, want.kind) << name << " at " << format_point(p);
  if (want.kind != Location::Kind::Interior) {
    EXPECT_EQ(got.index, want.index) << name << " at " << format_point(p);
  }
  return want;
}
}  // namespace

TEST(Visibility, LocateEqualsBruteForce) {
  std::size_t checked = 0, on_boundary = 0, outside = 0;
  for (const auto& [name, env] : vis_environments()) {
    VisibilityIndex index(env);
    const auto box = env.bbox();
    std::vector<Point> pts;
    std::mt19937_64 rng(5);
    const double w = box.xmax() - box.xmin(), h = box.ymax() - box.ymin();
    std::uniform_real_distribution<double> ux(box.xmin() - 0.05 * w, box.xmax() + 0.05 * w), uy(box.ymin() - 0.05 * h, box.ymax() + 0.05 * h);
    for (int k = 0; k < 1500; ++k) pts.emplace_back(ux(rng), uy(rng));
    // Points on coarse rational grids (many on grid-cell boundaries and on axis-parallel walls).
    for (int d : {7, 16, 64, 100})
      for (int k = 0; k < 300; ++k) {
        std::uniform_int_distribution<int> ui(0, d);
        pts.emplace_back(box.xmin() + w * ui(rng) / d, box.ymin() + h * ui(rng) / d);
      }
    // Every vertex, edge midpoints (on the edge when the midpoint is exact), triangle edge midpoints.
    for (std::size_t v = 0; v < env.vertices().size(); ++v) {
      pts.push_back(env.vertex(v));
      pts.push_back(CGAL::midpoint(env.vertex(v), env.vertex(env.next(v))));
    }
    for (const Triangle& t : index.triangulation().triangles())
      for (int i = 0; i < 3; ++i) pts.push_back(CGAL::midpoint(env.vertex(t.v[i]), env.vertex(t.v[(i + 1) % 3])));
    for (const auto& q : preimage::testing::random_queries(env, 0, name.rfind("random", 0) != 0 ? 200 : 0, 0, 3)) pts.push_back(q.p);
    for (const Point& p : pts) {
      const Location want = expect_locate_as_brute_force(env, index, p, name);
      EXPECT_EQ(index.in_free_space(p), want.in_free_space()) << name << " at " << format_point(p);
      on_boundary += want.kind == Location::Kind::OnEdge || want.kind == Location::Kind::AtVertex;
      outside += !want.in_free_space();
      ++checked;
    }
  }
  EXPECT_GE(checked, 20000u);
  EXPECT_GE(on_boundary, 3000u);
  EXPECT_GE(outside, 1000u);
}

// Combs: the base strip is triangulated as two fans of long thin triangles, so grid cells
// there list hundreds of them and get a slab (edges across the cell, binary search). Turned
// by a quarter, the slabs run bottom to top. Locate equals brute force on points inside,
// on edges, at vertices and on triangle edges; V(q) equals CGAL's; and few tests per locate.
TEST(Visibility, LocateInHeavyCellsEqualsBruteForce) {
  auto turned = [](Ring r) {
    for (Point& p : r) p = Point(-p.y(), p.x());
    return r;
  };
  const std::vector<std::pair<std::string, Environment>> envs = [&] {
    std::vector<std::pair<std::string, Environment>> e;
    e.emplace_back("comb 400", Environment::make(generators::comb(400), {}));
    e.emplace_back("comb 400 turned", Environment::make(turned(generators::comb(400)), {}));
    return e;
  }();
  for (const auto& [name, env] : envs) {
    VisibilityIndex index(env);
    std::vector<Point> pts;
    std::size_t tests = 0, interior = 0;  // per locate of random interior points
    for (const auto& q : preimage::testing::random_queries(env, 3000, 300, 300, 17)) {
      pts.push_back(q.p);
      if (q.loc.kind == Location::Kind::Interior) tests += index.locate_tests(q.p), ++interior;
    }
    for (const Triangle& t : index.triangulation().triangles())
      for (int i = 0; i < 3; ++i) pts.push_back(CGAL::midpoint(env.vertex(t.v[i]), env.vertex(t.v[(i + 1) % 3])));
    for (const Point& p : pts) {
      expect_locate_as_brute_force(env, index, p, name);
    }
    EXPECT_LT(static_cast<double>(tests) / static_cast<double>(interior), 5.0) << name;
    EXPECT_GE(compare_with_cgal(env, 40, 10, 10, 91), 60) << name;
  }
}

// visible_from_vertex (the walk started in the vertex's fan, no point location) against the
// O(n) exact segment test, from every vertex to random points inside and outside free space
// and to every other vertex, on random maps, a rectilinear office, a floor plan with
// collinear walls and a map whose holes touch at vertices.
TEST(Visibility, FromVertexMatchesTheExactSegmentTest) {
  const Environment maps[] = {generators::random_environment(40, 3, 11), generators::office(2, 2),
                              *preimage::scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS).append("/house_expo_room_0000.json")).environment,
                              *preimage::scene::load_scene(std::string(PREIMAGE_FIXTURES).append("/contacts/checkerboard.json")).environment};
  const char* names[] = {"random-40-3", "office-2x2", "house_expo_room_0000", "checkerboard"};
  std::mt19937_64 rng(4);
  for (std::size_t m = 0; m < 4; ++m) {
    const Environment& env = maps[m];
    const std::string name = names[m];
    const VisibilityIndex index(env);
    const auto b = env.bbox();
    std::uniform_real_distribution<double> ux(b.xmin(), b.xmax()), uy(b.ymin(), b.ymax());
    std::size_t seen = 0, tested = 0;
    for (std::uint32_t v = 0; v < env.num_vertices(); v += std::max<std::uint32_t>(1, static_cast<std::uint32_t>(env.num_vertices() / 40))) {
      std::vector<Point> targets;
      for (int k = 0; k < 20; ++k) targets.emplace_back(ux(rng), uy(rng));
      for (std::uint32_t w = 0; w < env.num_vertices(); w += 3) targets.push_back(env.vertex(w));
      for (const Point& q : targets) {
        const bool want = preimage::geometry::visible(env, env.vertex(v), q);
        ASSERT_EQ(index.visible_from_vertex(v, q), want) << name << " vertex " << v << " to " << format_point(q);
        seen += want, ++tested;
      }
    }
    EXPECT_GT(seen, tested / 20) << name;  // the test sees something
  }
}
