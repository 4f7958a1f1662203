// The wave-front decomposition (section 6.2.3, Fig. 6.18): a worked room with one pillar
// (every critical slice placed by hand), and on random maps, an office and a floor plan:
// - homology: each of the k holes is a cycle of the Reeb graph or is encircled by closed
//   fronts (E - V + 1 + rank of the closed fronts' hole sets = k);
// - every front point lies at geodesic distance λ by an independent brute force (Dijkstra
//   over all vertices with O(n) exact visibility), and every end of an open front on the
//   boundary (brute-force clearance);
// - random free points fall in a cell whose range of h holds theirs, and the fronts at a
//   level are as many as the cells whose range spans it;
// - nodes and cells are consistent (each cell starts and ends at a node, adjacency symmetric);
// - the same on maps whose holes touch each other or the outer wall (contacts).
#include <gtest/gtest.h>
#include <preimage/decompose/wavefront.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/scene.hpp>

#include "support/path_oracle.hpp"

#include <cmath>
#include <random>
#include <string>

using namespace preimage;
using namespace preimage::geometry;
using namespace preimage::decompose;

namespace {

Point wft_free_point(const Environment& env, std::mt19937_64& rng) {
  const auto b = env.bbox();
  std::uniform_real_distribution<double> ux(b.xmin(), b.xmax()), uy(b.ymin(), b.ymax());
  for (;;) {
    const Point p(ux(rng), uy(rng));
    if (locate(env, p).in_free_space()) return p;
  }
}

// Rank over GF(2) of the hole sets enclosed by the closed fronts (one per cell).
std::size_t wft_closed_front_rank(const WavefrontDecomposition& wd, const Environment& env) {
  const auto box = env.bbox();
  const double sag = 1e-4 * std::max(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  std::vector<std::vector<char>> rows;
  for (std::uint32_t c = 0; c < wd.cells().size(); ++c) {
    const auto& cell = wd.cells()[c];
    for (const auto& f : wd.fronts((cell.lo + cell.hi) / 2)) {
      if (f.cell != c || !f.closed) continue;
      std::vector<Point> poly;
      for (const auto& arc : f.arcs) {
        const auto pts = wd.arc_points(arc, sag);
        poly.insert(poly.end(), pts.begin(), pts.end());
      }
      std::vector<char> row(env.num_holes(), 0);
      for (std::size_t h = 0; h < env.num_holes(); ++h) {  // crossing parity of a ray from one hole vertex
        const Point& q = env.vertex(env.ring_begin(h + 1));
        bool in = false;
        for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
          if ((poly[i].y() > q.y()) != (poly[j].y() > q.y()) &&
              q.x() < poly[j].x() + (q.y() - poly[j].y()) * (poly[i].x() - poly[j].x()) / (poly[i].y() - poly[j].y()))
            in = !in;
        row[h] = in;
      }
      rows.push_back(row);
    }
  }
  std::size_t rank = 0;
  for (std::size_t col = 0; col < env.num_holes() && rank < rows.size(); ++col) {
    std::size_t r = rank;
    while (r < rows.size() && !rows[r][col]) ++r;
    if (r == rows.size()) continue;
    std::swap(rows[r], rows[rank]);
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (i != rank && rows[i][col])
        for (std::size_t k = 0; k < env.num_holes(); ++k) rows[i][k] ^= rows[rank][k];
    ++rank;
  }
  return rank;
}

// Structural checks every decomposition must pass.
void wft_check_graph(const WavefrontDecomposition& wd, const Environment& env, const std::string& name) {
  const auto& nodes = wd.nodes();
  const auto& cells = wd.cells();
  ASSERT_FALSE(nodes.empty()) << name;
  EXPECT_EQ(nodes[0].level, 0) << name;
  EXPECT_TRUE(nodes[0].below.empty()) << name;
  // Homology: free space (a disc with k holes) has k independent cycles; each is either a
  // cycle of the Reeb graph (E - V + 1 of them) or carried by closed fronts encircling holes
  // (r: the rank over GF(2) of the sets of holes the closed fronts enclose, each front taken
  // at the middle of its cell's range; found by point-in-polygon on the sampled front).
  EXPECT_EQ(static_cast<long>(cells.size()) - static_cast<long>(nodes.size()) + 1 + static_cast<long>(wft_closed_front_rank(wd, env)),
            static_cast<long>(env.num_holes()))
      << name;
  for (std::uint32_t c = 0; c < cells.size(); ++c) {
    ASSERT_NE(cells[c].lower, WavefrontCell::kNone) << name << " cell " << c;
    ASSERT_NE(cells[c].upper, WavefrontCell::kNone) << name << " cell " << c << " never ends";
    EXPECT_LE(cells[c].lo, cells[c].hi) << name;
    const auto& a = nodes[cells[c].lower].above;
    const auto& b = nodes[cells[c].upper].below;
    EXPECT_NE(std::find(a.begin(), a.end(), c), a.end()) << name;
    EXPECT_NE(std::find(b.begin(), b.end(), c), b.end()) << name;
  }
  const auto adj = wd.adjacency();
  for (std::uint32_t a = 0; a < adj.size(); ++a)
    for (const auto b : adj[a]) EXPECT_TRUE(std::binary_search(adj[b].begin(), adj[b].end(), a)) << name;
  EXPECT_EQ(wd.unmatched_ends(), 0u) << name;
}

// Fronts at random levels against the brute force; cells of random points.
void wft_check_fronts(const WavefrontDecomposition& wd, const Environment& env, const Point& start, const std::string& name, int levels,
                      int points) {
  const auto& spm = wd.shortest_path_map();
  const double scale = std::max(env.bbox().xmax() - env.bbox().xmin(), env.bbox().ymax() - env.bbox().ymin());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ul(0.01, 1.0);
  for (int k = 0; k < levels; ++k) {
    const double lambda = ul(rng) * spm.max_vertex_distance() * 1.2 + 1e-3;
    const auto fronts = wd.fronts(lambda);
    std::size_t live = 0;
    for (const auto& c : wd.cells()) live += c.lo < lambda && lambda < c.hi;
    bool near_node = false;
    for (const auto& n : wd.nodes()) near_node |= n.lo <= lambda && lambda <= n.hi;
    if (!near_node) {
      EXPECT_EQ(fronts.size(), live) << name << " at " << lambda;
    }
    for (const auto& f : fronts) {
      ASSERT_FALSE(f.arcs.empty()) << name;
      for (const auto& arc : f.arcs) {
        const auto pts = wd.arc_points(arc, scale / 200);
        const Point& mid = pts[pts.size() / 2];
        const double h = preimage::testing::brute_shortest_path(env, start, mid);
        EXPECT_NEAR(h, lambda, 1e-7 * std::max(1.0, lambda)) << name << " front point " << format_point(mid);
      }
      if (!f.closed) {
        const auto first = wd.arc_points(f.arcs.front(), scale / 200).front();
        const auto last = wd.arc_points(f.arcs.back(), scale / 200).back();
        EXPECT_LT(preimage::testing::brute_clearance(env, first), 1e-7 * scale) << name << " chain end " << format_point(first);
        EXPECT_LT(preimage::testing::brute_clearance(env, last), 1e-7 * scale) << name << " chain end " << format_point(last);
      }
    }
  }
  int none = 0;
  for (int i = 0; i < points; ++i) {
    const Point p = wft_free_point(env, rng);
    const std::uint32_t c = wd.cell_at(p);
    if (c == WavefrontCell::kNone) {
      ++none;
      continue;
    }
    const double h = spm.distance(p);
    EXPECT_LE(wd.cells()[c].lo, h + 1e-9) << name << " " << format_point(p);
    EXPECT_GE(wd.cells()[c].hi, h - 1e-9) << name << " " << format_point(p);
  }
  EXPECT_LE(none, points / 50) << name << ": points whose cell was not found";
}

}  // namespace

// A 10 x 10 room with a 2 x 2 pillar at (4..6, 4..6), the start at (1, 5). By hand: the
// circle touches the left wall (h 1: a closed front opens), the pillar (3: it splits), the
// floor and ceiling (5, both: each lower/upper front splits off a corner piece), the corner
// pieces vanish at (0, 0) and (0, 10) (sqrt 26); behind the pillar the fronts round its far
// corners (D = sqrt 10 + 2) and meet on its back face at (6, 5) (sqrt 10 + 3: merge); the
// merged front touches the right wall at (10, 4) and (10, 6) (sqrt 10 + 6: one slice, three
// pieces), the middle one vanishes at (10, 5) (sqrt 10 + 2 + sqrt 17), the others in the far
// corners, which the start sees past the pillar (sqrt 106). Twelve slices, twelve cells, one cycle.
TEST(WavefrontDecomposition, PillarRoomByHand) {
  const Environment env = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}});
  const VisibilityIndex index(env);
  const VisibilityGraph graph(index);
  const ShortestPathMap spm(graph, Point(1, 5));
  const WavefrontDecomposition wd(spm);
  wft_check_graph(wd, env, "pillar");
  const double r10 = std::sqrt(10.0);
  struct Want {
    double level;
    Point at;
    std::size_t below, above;
  };
  const std::vector<Want> want{{0, {1, 5}, 0, 1},
                               {1, {0, 5}, 1, 1},
                               {3, {4, 5}, 1, 2},
                               {5, {1, 10}, 1, 2},
                               {5, {1, 0}, 1, 2},
                               {std::sqrt(26.0), {0, 10}, 1, 0},
                               {std::sqrt(26.0), {0, 0}, 1, 0},
                               {r10 + 3, {6, 5}, 2, 1},
                               {r10 + 6, {10, 6}, 1, 3},
                               {r10 + 2 + std::sqrt(17.0), {10, 5}, 1, 0},
                               {std::sqrt(106.0), {10, 10}, 1, 0},
                               {std::sqrt(106.0), {10, 0}, 1, 0}};
  ASSERT_EQ(wd.nodes().size(), want.size());
  ASSERT_EQ(wd.cells().size(), 12u);
  for (std::size_t i = 0; i < want.size(); ++i) {
    const auto& n = wd.nodes()[i];
    SCOPED_TRACE(i);
    EXPECT_NEAR(n.level, want[i].level, 1e-5);  // maxima along a wall are searched 1e-7 of its length inside
    EXPECT_EQ(n.below.size(), want[i].below);
    EXPECT_EQ(n.above.size(), want[i].above);
    // symmetric pairs at one level may come in either order
    const bool here = std::hypot(n.point.x() - want[i].at.x(), n.point.y() - want[i].at.y()) < 1e-6;
    const bool mirrored = std::hypot(n.point.x() - want[i].at.x(), n.point.y() - (10 - want[i].at.y())) < 1e-6;
    EXPECT_TRUE(here || mirrored) << format_point(n.point);
  }
  // The first front is the start's circle, closed; at h 3.5 two fronts pass the pillar.
  const auto f0 = wd.fronts(0.5);
  ASSERT_EQ(f0.size(), 1u);
  EXPECT_TRUE(f0[0].closed);
  EXPECT_EQ(wd.fronts(3.5).size(), 2u);
  EXPECT_EQ(wd.fronts(9.2).size(), 3u);
  wft_check_fronts(wd, env, Point(1, 5), "pillar", 12, 200);
}

// The start inside a ring of four holes (random map 80/4, seed 9): the first front touches
// a hole and opens (no split), so the Reeb graph has 3 cycles, and the fourth is carried by
// the closed front that later encircles all four holes.
TEST(WavefrontDecomposition, StartInsideARingOfHolesClosesAFrontAroundThem) {
  const Environment env = generators::random_environment(80, 4, 9);
  const Point start(0.30869483299875355, 3.196495984225777);
  const VisibilityIndex index(env);
  const VisibilityGraph graph(index);
  const ShortestPathMap spm(graph, start);
  const WavefrontDecomposition wd(spm);
  wft_check_graph(wd, env, "ring of holes");
  EXPECT_EQ(wd.cells().size() + 1 - wd.nodes().size(), 3u);
  EXPECT_EQ(wft_closed_front_rank(wd, env), 1u);
}

// Found by the bench map (random 300/6, seed 11): two front ends were left apart at one
// level and made a spurious Reeb cycle (a root claimed a sliver across its own extension,
// see the next test; ends so left are also joined to the nearest one now).
TEST(WavefrontDecomposition, NearlyConcurrentCirclesAreJoined) {
  const Environment env = generators::random_environment(300, 6, 11);
  const VisibilityIndex index(env);
  const VisibilityGraph graph(index);
  const ShortestPathMap spm(graph, Point(34.64719687461762, -52.846285480841303));
  const WavefrontDecomposition wd(spm);
  wft_check_graph(wd, env, "random-300-6-11");
}

// A review's reproducers, each named after what it caught:
// - the start at a reflex vertex made two roots with one circle (fronts from nothing);
// - a bend claimed a thin sliver across the extension of its own path (the extension from
//   (4, 6) ends in the corner (10, 10)): unmatched ends and a spurious split;
// - at one level a chain's ends met above a hole while elsewhere the front reached a wall:
//   one open front before and after, but on other obstacles — a slice all the same.
TEST(WavefrontDecomposition, ReviewReproducers) {
  const Environment pillar = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}});
  const Environment ell = Environment::make({{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}, {});
  const Environment rect = generators::random_rectilinear(7, 7, true, 121);
  const struct {
    const char* name;
    const Environment* env;
    Point start;
  } cases[] = {{"L-room from its reflex vertex", &ell, Point(5, 5)},
               {"pillar, extension into a corner", &pillar, Point(1, 4)},
               {"rectilinear-121 from (8, 9)", &rect, Point(8, 9)}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const VisibilityIndex index(*c.env);
    const VisibilityGraph graph(index);
    const ShortestPathMap spm(graph, c.start);
    const WavefrontDecomposition wd(spm);
    for (std::size_t i = 1; i < wd.nodes().size(); ++i) EXPECT_FALSE(wd.nodes()[i].below.empty()) << "a front from nothing at node " << i;
    EXPECT_EQ(wd.unmatched_ends(), 0u);
    wft_check_fronts(wd, *c.env, c.start, c.name, 4, 100);
    if (c.env != &rect) {
      wft_check_graph(wd, *c.env, c.name);
      continue;
    }
    // The start on the hole's edge: the chain's ends close above the hole at h = 4, the
    // very level the front reaches the vertex (12, 9), so no closed front exists at any
    // other level and the cycle lives on that slice alone (the homology count cannot see
    // it); the slice must be there, one front in, one out.
    bool found = false;
    for (const auto& n : wd.nodes()) found |= n.lo <= 4 && 4 <= n.hi && n.below.size() == 1 && n.above.size() == 1;
    EXPECT_TRUE(found);
  }
}

// Holes touching at vertices (contacts): the three contact fixtures, the checkerboard from
// a contact point and from the fixture's start on the diagonal, and touching squares
// (generators::touching_squares(3 + seed % 4, 0.3 + 0.1 (seed % 5), seed, sheared = seed
// odd)) from starts that each caught a bug while contacts were being admitted:
// - touching-10: a sight line along two walls through a contact made the far vertex a
//   sibling of the contact, not its child (circles touching on the ray never glued);
// - checker-2, checker-13: ties (a vertex reached by two shortest paths on the lattice):
//   the ray from the second predecessor was no cut, and then a sliver was claimed twice;
// - checkerboard from (0.5, 0.5): two fronts kiss at a contact and part (a missed cycle);
// - touching-13: a front through a contact merged into another and was overrun at once
//   (it looked like a death);
// - touching-9, touching-14: a point followed back along a wall into a contact lands on the
//   circle of an earlier bend of a straight chain, or on an arc's rounded end;
// - touching-3, touching-19: tiny circles at a vertex (the quadratic lost the crossing
//   with the vertex's own edges) and a wall lying on an extension's ray (a zero-width piece);
// - checker-37: a wall's foot from a root tied with another was not counted as a minimum of
//   h, so a front born and gone on the top wall between two levels was missed;
// - a review's reproducers (fixtures wavefront_*.json, each described there): a root on the
//   segment to a root hung by the map on another root of that line; a point followed back
//   beyond a tied root lands on the tie's source's circle; a start in line with a chain
//   through a contact only to rounding.
// Every node but the start has fronts below it (none from nothing).
TEST(WavefrontDecomposition, TouchingHoles) {
  struct Case {
    std::string name;
    Environment env;
    Point start;
  };
  std::vector<Case> cases;
  for (const char* f : {"checkerboard", "hole_touches_boundary", "corridor_closed_at_points", "wavefront_sibling_chain",
                        "wavefront_sibling_chain_wall_start", "wavefront_tie_followed_back", "wavefront_start_nearly_in_line"}) {
    const auto sc = preimage::scene::load_scene(std::string(PREIMAGE_FIXTURES).append("/contacts/") + f + ".json");
    cases.push_back({f, *sc.environment, *sc.start});
  }
  const Environment checker = cases[0].env;  // (the fixtures' own starts above)
  cases.push_back({"checkerboard from the contact (2, 2)", checker, Point(2, 2)});
  cases.push_back({"checker-2", checker, Point(3.438895804034199, 0.649128101780545)});
  cases.push_back({"checker-13", checker, Point(1.4123832757988941, 0.5409318965594683)});
  cases.push_back({"checker-37", checker, Point(2.3560782000681577, 0.29630750502133724)});
  const struct {
    int seed;
    Point start;
  } squares[] = {{3, Point(6.2346403658110585, 14.165790517471578)}, {9, Point(5.995284763868163, 8.296305630202323)},
                 {10, Point(4.568521817557741, 3.006415536704874)},  {13, Point(4.849222168098065, 9.76456381799049)},
                 {14, Point(0.3807615772830805, 3.360491699828051)},  {19, Point(9.987649542781956, 17.62524011731912)}};
  for (const auto& q : squares)
    cases.push_back({"touching-" + std::to_string(q.seed),
                     generators::touching_squares(static_cast<std::size_t>(3 + q.seed % 4), 0.3 + 0.1 * (q.seed % 5), static_cast<std::uint64_t>(q.seed), q.seed % 2 == 1),
                     q.start});
  std::size_t contacts = 0;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    for (std::size_t v = 0; v < c.env.num_vertices(); ++v) contacts += c.env.is_contact(v);
    ASSERT_TRUE(locate(c.env, c.start).in_free_space());
    const VisibilityIndex index(c.env);
    const VisibilityGraph graph(index);
    const ShortestPathMap spm(graph, c.start);
    const WavefrontDecomposition wd(spm);
    for (std::size_t i = 1; i < wd.nodes().size(); ++i) EXPECT_FALSE(wd.nodes()[i].below.empty()) << "a front from nothing at node " << i;
    wft_check_graph(wd, c.env, c.name);
    wft_check_fronts(wd, c.env, c.start, c.name, 8, 100);
  }
  EXPECT_GE(contacts, 2 * cases.size());  // every map has contacts
}

// Room 1451 (HouseExpo) from starts where its staircase walls (bends in line, and vertices
// reached by two paths at once) left 3 ends without a partner and a spurious Reeb cycle,
// before straight chains and ties were handled for contacts (same degeneracy).
TEST(WavefrontDecomposition, FloorPlan1451StaircaseTies) {
  const Environment env = *scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS).append("/house_expo_room_1451.json")).environment;
  const VisibilityIndex index(env);
  const VisibilityGraph graph(index);
  for (const Point start : {Point(8.82, 1.88), Point(7.98, 4.16)}) {
    SCOPED_TRACE(format_point(start));
    const ShortestPathMap spm(graph, start);
    const WavefrontDecomposition wd(spm);
    wft_check_graph(wd, env, "house_expo_room_1451");
    EXPECT_EQ(wd.snapped_ends(), 0u);
  }
}

TEST(WavefrontDecomposition, RandomMapsOfficeAndFloorPlan) {
  struct Case {
    std::string name;
    Environment env;
  };
  std::vector<Case> cases;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) cases.push_back({"random-60-3-" + std::to_string(seed), generators::random_environment(60, 3, seed)});
  cases.push_back({"random-120-6", generators::random_environment(120, 6, 9)});
  cases.push_back({"office-2x3", generators::office(2, 3)});
  cases.push_back({"house_expo_room_0000", *scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS).append("/house_expo_room_0000.json")).environment});
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::mt19937_64 rng(3);
    const Point start = wft_free_point(c.env, rng);
    const VisibilityIndex index(c.env);
    const VisibilityGraph graph(index);
    const ShortestPathMap spm(graph, start);
    const WavefrontDecomposition wd(spm);
    wft_check_graph(wd, c.env, c.name);
    wft_check_fronts(wd, c.env, start, c.name, 4, 40);
  }
}
