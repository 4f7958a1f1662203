// Weakly simple environments: holes touching one another or the outer boundary at single
// vertices (issue 29). Visibility against CGAL's triangular expansion (per free wedge at a
// contact), two-point visibility and shortest paths against brute force, the
// triangulation's invariants, and the errors for rings that overlap at a contact.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/geometry/range_visibility.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/geometry/visibility_graph.hpp>
#include <preimage/geometry/visibility_graphs.hpp>
#include <preimage/scene/scene.hpp>

#include "support/cgal_oracle.hpp"
#include "support/path_oracle.hpp"

#include <cmath>
#include <random>

using namespace preimage;
using namespace preimage::geometry;
using preimage::testing::CgalVisibility;

namespace {

std::string fixture(const std::string& name) { return std::string(PREIMAGE_FIXTURES) + "/contacts/" + name + ".json"; }

std::string load_error(const std::string& path) {
  try {
    scene::load_scene(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every contact environment the tests use: the fixtures and random touching squares.
std::vector<std::pair<std::string, Environment>> contact_environments() {
  std::vector<std::pair<std::string, Environment>> out;
  for (const char* name : {"checkerboard", "hole_touches_boundary", "corridor_closed_at_points"})
    out.emplace_back(name, std::move(*scene::load_scene(fixture(name)).environment));
  for (std::uint64_t seed = 1; seed <= 8; ++seed)
    out.emplace_back("touching_squares seed " + std::to_string(seed),
                     generators::touching_squares(4 + seed % 4, 0.8, seed, seed % 2 == 0));
  return out;
}

// Free-space point at random (y then x, geometry::random_point), in closed free space.
Point random_free_point(const Environment& env, const VisibilityIndex& index, std::mt19937_64& rng) {
  const auto box = env.bbox();
  std::uniform_real_distribution<double> dx(box.xmin(), box.xmax()), dy(box.ymin(), box.ymax());
  for (;;) {
    const Point p = random_point<Point>(rng, dx, dy);
    if (index.in_free_space(p)) return p;
  }
}

}  // namespace

TEST(Contacts, FixturesLoadWithTheirContacts) {
  EXPECT_EQ(scene::load_scene(fixture("checkerboard")).environment->num_contacts(), 4u);
  EXPECT_EQ(scene::load_scene(fixture("hole_touches_boundary")).environment->num_contacts(), 1u);
  EXPECT_EQ(scene::load_scene(fixture("corridor_closed_at_points")).environment->num_contacts(), 3u);
  const auto env = std::move(*scene::load_scene(fixture("corridor_closed_at_points")).environment);
  // (5, 1): the lower diamond's top vertex and the upper's bottom vertex; the free wedges
  // there are the left one (from the upper diamond's out-edge) and the right one.
  std::size_t v = 0;
  while (env.vertex(v) != Point(5, 1)) ++v;
  EXPECT_TRUE(env.is_contact(v));
  const std::size_t w = env.same_point_next(v);
  EXPECT_NE(w, v);
  EXPECT_EQ(env.same_point_next(w), v);
  EXPECT_EQ(env.wedge_end(env.wedge_end(v)), v);
  EXPECT_EQ(env.wedge_start(env.wedge_end(v)), v);
  EXPECT_NE(env.ring_of(env.wedge_end(v)), env.ring_of(v));
}

TEST(Contacts, RingsThatOverlapOrTouchAnEdgeAreStillErrors) {
  EXPECT_EQ(load_error(fixture("overlap_at_contact")),
            "$.environment.obstacles[1] vertex 0 and $.environment.obstacles[0] vertex 2 overlap at (4, 4): rings may "
            "touch at a contact, not cross or overlap there");
  EXPECT_EQ(load_error(fixture("vertex_on_edge")),
            "$.environment.obstacles[1] edge 0 touches $.environment.obstacles[0] edge 1 near (4, 3)");
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  auto error_of = [&](std::vector<Ring> holes) {
    try {
      Environment::make(square, std::move(holes));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Two holes sharing a whole edge overlap along it.
  EXPECT_NE(error_of({{{1, 1}, {3, 1}, {3, 3}, {1, 3}}, {{3, 1}, {5, 1}, {5, 3}, {3, 3}}}).find("touches obstacles[0] edge"),
            std::string::npos);
  // A hole inside another touching it only at one corner: overlap, not "lies inside".
  EXPECT_NE(error_of({{{1, 1}, {5, 1}, {5, 5}, {1, 5}}, {{5, 5}, {4, 3}, {3, 4}}}).find("overlap at (5, 5)"), std::string::npos);
  // A hole outside the outer boundary touching its corner.
  EXPECT_NE(error_of({{{0, 0}, {-1, -2}, {-2, -1}}}).find("overlap at (0, 0)"), std::string::npos);
  // A ring touching itself is still a repeated vertex.
  EXPECT_NE(error_of({{{1, 1}, {3, 1}, {2, 2}, {3, 3}, {1, 3}, {2, 2}}}).find("are repeated at (2, 2)"), std::string::npos);
  // Three holes at one point, sectors alternating with free wedges: valid.
  EXPECT_EQ(error_of({{{5, 5}, {7, 5}, {7, 6}}, {{5, 5}, {4, 7}, {3, 6}}, {{5, 5}, {4, 3}, {5, 3}}}), "");
}

TEST(Contacts, TriangulationInvariantsHold) {
  for (const auto& [what, env] : contact_environments()) {
    const Triangulation tri(env);
    EXPECT_NO_THROW(tri.check()) << what;
    EXPECT_EQ(tri.non_delaunay_edges(), 0u) << what;
  }
}

// Per free wedge, V(q) at a contact equals CGAL's visibility in the face on the left of the
// wedge's in-edge; the union compute(q) gives is the wedges one after the other.
TEST(Contacts, VisibilityMatchesCgalInTheInteriorOnEdgesAndInEveryWedge) {
  std::size_t compared = 0, wedges = 0;
  for (const auto& [what, env] : contact_environments()) {
    const VisibilityIndex ours(env);
    const CgalVisibility cgal(env);
    for (auto& q : preimage::testing::random_queries(env, 60, 20, 0, 11)) {
      EXPECT_EQ(canonical_cycle(ours.compute(q.p).points()), canonical_cycle(cgal.compute(q.p, q.loc)))
          << what << " query " << format_point(q.p);
      ++compared;
    }
    for (std::uint32_t v = 0; v < env.num_vertices(); ++v) {
      const auto mine = ours.compute_in_wedge(v);
      const auto theirs = cgal.compute_in_wedge(v);
      EXPECT_EQ(canonical_cycle(mine.points()), canonical_cycle(theirs)) << what << " wedge of vertex " << v;
      ++wedges;
      if (!env.is_contact(v)) continue;
      // The union: every wedge's polygon, areas adding up.
      const auto all = ours.compute(env.vertex(v));
      double sum = 0;
      std::size_t vertices = 0, k = 0;
      for (std::size_t w = v;; ++k) {
        const auto one = ours.compute_in_wedge(static_cast<std::uint32_t>(w));
        sum += one.area(), vertices += one.vertices.size();
        w = env.wedge_end(w);
        if (w == v) break;
      }
      EXPECT_GE(k, 1u);
      EXPECT_NEAR(all.area(), sum, 1e-9 * std::max(1.0, sum)) << what;
      EXPECT_EQ(all.vertices.size(), vertices) << what;
      EXPECT_EQ(all.location.kind, Location::Kind::AtVertex);
      // The reusable and abstract forms give the same union, id for id.
      VisibilityPolygon reused, abstract;
      ours.compute(env.vertex(v), reused);
      ours.compute_abstract(env.vertex(v), abstract);
      ASSERT_EQ(reused.vertices.size(), all.vertices.size()) << what;
      ASSERT_EQ(abstract.vertices.size(), all.vertices.size()) << what;
      for (std::size_t i = 0; i < all.vertices.size(); ++i) {
        EXPECT_EQ(abstract.vertices[i].kind, all.vertices[i].kind) << what;
        EXPECT_EQ(abstract.vertices[i].vertex, all.vertices[i].vertex) << what;
        EXPECT_EQ(abstract.vertices[i].edge, all.vertices[i].edge) << what;
        EXPECT_EQ(reused.exact(i), all.exact(i)) << what;
      }
    }
  }
  EXPECT_GE(compared, 800u);
  EXPECT_GE(wedges, 300u);
}

// A segment may pass through a contact point (free space is closed): the triangle walk of
// VisibilityIndex::visible against the O(n) exact edge scan, on random pairs and on pairs
// through contact points.
TEST(Contacts, TwoPointVisibilityMatchesBruteForce) {
  std::mt19937_64 rng(29);
  std::size_t through = 0, pairs = 0;
  for (const auto& [what, env] : contact_environments()) {
    const VisibilityIndex index(env);
    std::vector<Point> pts;
    for (int i = 0; i < 40; ++i) pts.push_back(random_free_point(env, index, rng));
    for (std::size_t v = 0; v < env.num_vertices(); ++v) pts.push_back(env.vertex(v));
    // Points beyond each contact on lines through it: many of these segments pass through.
    for (std::size_t v = 0; v < env.num_vertices(); ++v) {
      if (!env.is_contact(v)) continue;
      const Point& c = env.vertex(v);
      for (double dx : {-0.25, 0.0, 0.25})
        for (double dy : {-0.25, 0.0, 0.25}) {
          const Point p(c.x() + dx, c.y() + dy), q(c.x() - dx, c.y() - dy);
          if (p == c || !index.in_free_space(p) || !index.in_free_space(q)) continue;
          EXPECT_EQ(index.visible(p, q), visible(env, p, q)) << what << ": " << format_point(p) << " -> " << format_point(q);
          through += visible(env, p, q);
        }
    }
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = 0; j < pts.size(); j += 3) {
        EXPECT_EQ(index.visible(pts[i], pts[j]), visible(env, pts[i], pts[j]))
            << what << ": " << format_point(pts[i]) << " -> " << format_point(pts[j]);
        ++pairs;
      }
  }
  EXPECT_GE(through, 20u) << "segments through a contact point that are visible";
  EXPECT_GE(pairs, 5000u);
}

// Shortest paths bend at contact points too: the visibility graph against Dijkstra over
// every vertex with brute-force visibility.
TEST(Contacts, ShortestPathsMatchBruteForce) {
  std::mt19937_64 rng(2929);
  for (const auto& [what, env] : contact_environments()) {
    const VisibilityIndex index(env);
    const VisibilityGraph graph(index);
    for (int k = 0; k < 6; ++k) {
      const Point s = random_free_point(env, index, rng), t = random_free_point(env, index, rng);
      const auto path = graph.shortest_path(s, t);
      ASSERT_TRUE(path.found) << what;
      for (std::size_t i = 0; i + 1 < path.points.size(); ++i) EXPECT_TRUE(visible(env, path.points[i], path.points[i + 1])) << what;
      const double brute = preimage::testing::brute_shortest_path(env, s, t);
      EXPECT_NEAR(path.length, brute, 1e-9 * std::max(1.0, brute)) << what << ": " << format_point(s) << " -> " << format_point(t);
    }
  }
  // Through the three contacts closing the corridor: the straight line.
  const auto env = std::move(*scene::load_scene(fixture("corridor_closed_at_points")).environment);
  const VisibilityIndex index(env);
  const VisibilityGraph graph(index);
  EXPECT_DOUBLE_EQ(graph.shortest_path({1, 1}, {9, 1}).length, 8);
  EXPECT_TRUE(index.visible({4, 0.75}, {6, 1.25}));   // through (5, 1), between the diamonds on both sides
  EXPECT_FALSE(index.visible({4.5, 0}, {5.5, 2}));    // through (5, 1) but across both diamonds
  EXPECT_FALSE(visible(env, Point(4.5, 0), Point(5.5, 2)));
}

// Range-limited visibility and the vertex visibility graph where holes touch: membership
// against brute force (|p - q| <= R and the segment in free space), at contact points too.
TEST(Contacts, RangeVisibilityAndVertexGraphMatchBruteForce) {
  std::mt19937_64 rng(77);
  std::size_t samples = 0, at_contacts = 0, edges = 0;
  for (const auto& [what, env] : contact_environments()) {
    const VisibilityIndex index(env);
    std::vector<Point> qs;
    for (int i = 0; i < 4; ++i) qs.push_back(random_free_point(env, index, rng));
    for (std::size_t v = 0; v < env.num_vertices(); ++v)
      if (env.is_contact(v) && v < env.same_point_next(v)) qs.push_back(env.vertex(v)), ++at_contacts;
    for (const Point& q : qs)
      for (double R : {0.7, 1.9}) {
        const auto r = range_visibility(index, q, R);
        for (int k = 0; k < 60; ++k) {
          const Point p = random_free_point(env, index, rng);
          const bool in = CGAL::squared_distance(to_exact(p), to_exact(q)) <= ExactFT(R) * ExactFT(R) && visible(env, q, p);
          EXPECT_EQ(r.contains(p), in) << what << ": q " << format_point(q) << " R " << R << " p " << format_point(p);
          ++samples;
        }
      }
    // Edges present iff the vertices see each other (two ids at one contact do).
    const auto graph = vertex_visibility_graph(index, 2);
    std::size_t g = 0;
    for (std::uint32_t a = 0; a < env.num_vertices(); ++a)
      for (std::uint32_t b = a + 1; b < env.num_vertices(); ++b) {
        const bool listed = g < graph.size() && graph[g] == std::make_pair(a, b);
        g += listed;
        EXPECT_EQ(listed, visible(env, env.vertex(a), env.vertex(b))) << what << ": vertices " << a << ", " << b;
        edges += listed;
      }
    EXPECT_EQ(g, graph.size()) << what;
  }
  EXPECT_GE(at_contacts, 20u);
  EXPECT_GE(samples, 10000u);
  EXPECT_GE(edges, 1000u);
}
