// The geodesic distance and the shortest path map against an independent brute force:
// Dijkstra over ALL environment vertices (no reflex or tangency pruning), with visibility
// decided here by an O(n) exact test of the closed segment (no edge crossed properly, every
// piece between boundary vertices on it has its midpoint in free space, by geometry::locate),
// not by VisibilityIndex.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/generators.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/shortest_path_map.hpp>
#include <preimage/scene/import.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <queue>
#include <random>
#include <string>

using namespace preimage;
using namespace preimage::geometry;

namespace {

double spmt_len(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

// Closed segment pq in closed free space, in O(n) exact tests.
bool spmt_visible(const Environment& env, const Point& p, const Point& q) {
  if (!locate(env, p).in_free_space() || !locate(env, q).in_free_space()) return false;
  if (p == q) return true;
  std::vector<Point> cuts{p, q};
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    const Point& a = env.vertex(e);
    const Point& b = env.vertex(env.next(e));
    const int oa = orientation(p, q, a), ob = orientation(p, q, b);
    if (oa * ob < 0 && orientation(a, b, p) * orientation(a, b, q) < 0) return false;  // proper crossing
    if (oa == 0 && CGAL::collinear_are_strictly_ordered_along_line(p, a, q)) cuts.push_back(a);
  }
  const ExactPoint ep = to_exact(p);
  // pieces between consecutive cut points along pq (sorted by exact distance from p)
  std::sort(cuts.begin(), cuts.end(), [&](const Point& a, const Point& b) {
    return CGAL::compare_squared_distance(ep, to_exact(a), CGAL::squared_distance(ep, to_exact(b))) == CGAL::SMALLER;
  });
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i] == cuts[i + 1]) continue;
    if (!locate(env, CGAL::midpoint(to_exact(cuts[i]), to_exact(cuts[i + 1]))).in_free_space()) return false;
  }
  return true;
}

// Dijkstra from s over all environment vertices; the brute distance to any point.
struct SpmtBrute {
  const Environment* env;
  Point s;
  std::vector<double> d;
  SpmtBrute(const Environment& e, const Point& source) : env(&e), s(source) {
    const std::size_t n = e.num_vertices();
    std::vector<std::vector<std::uint32_t>> adj(n);
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = a + 1; b < n; ++b)
        if (spmt_visible(e, e.vertex(a), e.vertex(b))) adj[a].push_back(b), adj[b].push_back(a);
    d.assign(n, std::numeric_limits<double>::infinity());
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
    for (std::uint32_t v = 0; v < n; ++v)
      if (spmt_visible(e, s, e.vertex(v))) d[v] = spmt_len(s, e.vertex(v)), open.push({d[v], v});
    while (!open.empty()) {
      auto [dv, v] = open.top();
      open.pop();
      if (dv > d[v]) continue;
      for (auto w : adj[v])
        if (dv + spmt_len(e.vertex(v), e.vertex(w)) < d[w]) d[w] = dv + spmt_len(e.vertex(v), e.vertex(w)), open.push({d[w], w});
    }
  }
  double distance(const Point& p) const {
    double best = spmt_visible(*env, s, p) ? spmt_len(s, p) : std::numeric_limits<double>::infinity();
    for (std::uint32_t v = 0; v < env->num_vertices(); ++v)
      if (d[v] + spmt_len(env->vertex(v), p) < best && spmt_visible(*env, env->vertex(v), p)) best = d[v] + spmt_len(env->vertex(v), p);
    return best;
  }
};

Point spmt_free_point(const Environment& env, std::mt19937_64& rng) {
  const auto b = env.bbox();
  std::uniform_real_distribution<double> ux(b.xmin(), b.xmax()), uy(b.ymin(), b.ymax());
  for (;;) {
    const Point p(ux(rng), uy(rng));
    if (locate(env, p).in_free_space()) return p;
  }
}

struct SpmtCase {
  std::string name;
  Environment env;
  std::size_t samples;
};

std::vector<SpmtCase> spmt_cases() {
  std::vector<SpmtCase> c;
  for (std::uint64_t seed : {1u, 2u, 3u}) c.push_back({"random-60-3-" + std::to_string(seed), generators::random_environment(60, 3, seed), 60});
  c.push_back({"random-150-6", generators::random_environment(150, 6, 4), 40});
  c.push_back({"office-2x3", generators::office(2, 3), 60});
  for (std::uint64_t seed : {5u, 6u}) c.push_back({"rectilinear-" + std::to_string(seed), generators::random_rectilinear(7, 6, true, seed), 50});
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"})
    c.push_back({name, *scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS) + "/" + name).environment, 50});
  return c;
}

bool spmt_close(double a, double b) { return std::fabs(a - b) <= 1e-9 * std::max({1.0, std::fabs(a), std::fabs(b)}); }

}  // namespace

TEST(ShortestPathMap, GeodesicDistanceAgainstBruteForce) {
  std::mt19937_64 rng(20);
  std::size_t points = 0, vertices = 0, bent = 0, reflex_roots = 0;
  for (const auto& c : spmt_cases()) {
    VisibilityIndex index(c.env);
    VisibilityGraph graph(index);
    for (int k = 0; k < 2; ++k) {
      const Point s = k == 0 ? spmt_free_point(c.env, rng) : c.env.vertex(graph.reflex_vertices()[rng() % graph.reflex_vertices().size()]);
      const ShortestPathMap spm(graph, s);
      const SpmtBrute brute(c.env, s);
      ASSERT_EQ(spm.num_reached(), spm.num_reflex()) << c.name;
      for (auto v : graph.reflex_vertices()) {
        ASSERT_TRUE(spmt_close(spm.vertex_distance(v), brute.d[v])) << c.name << " vertex " << v << ": " << spm.vertex_distance(v) << " vs " << brute.d[v];
        ++vertices;
      }
      for (std::size_t i = 0; i < c.samples; ++i) {
        const Point p = spmt_free_point(c.env, rng);
        const auto q = spm.query(p);
        const double want = brute.distance(p);
        ASSERT_TRUE(spmt_close(q.distance, want)) << c.name << " source " << format_point(s) << " p " << format_point(p) << ": " << q.distance << " vs " << want;
        // the root: seen from p, tangent there, and D(root) + |root p| is h(p)
        ASSERT_NE(q.root, kNone);
        const Point r = spm.root_point(q.root);
        ASSERT_TRUE(spmt_visible(c.env, r, p)) << c.name;
        const double via = (q.root == ShortestPathMap::kSource ? 0.0 : spm.vertex_distance(q.root)) + spmt_len(r, p);
        ASSERT_TRUE(spmt_close(via, want)) << c.name;
        if (q.root != ShortestPathMap::kSource) {
          ASSERT_TRUE(tangent_at(c.env, q.root, p));
          ++reflex_roots;
        }
        // the whole path: free, of length h(p)
        const auto path = spm.path_to(p);
        double len = 0;
        for (std::size_t j = 0; j + 1 < path.size(); ++j) {
          ASSERT_TRUE(spmt_visible(c.env, path[j], path[j + 1])) << c.name << " path segment " << j;
          len += spmt_len(path[j], path[j + 1]);
        }
        ASSERT_TRUE(spmt_close(len, want)) << c.name;
        bent += path.size() > 2, ++points;
        EXPECT_EQ(spm.region_of(p), q.root);
      }
    }
  }
  std::cout << "[ counts   ] " << points << " points, " << vertices << " reflex vertices, " << bent << " bent paths, " << reflex_roots << " reflex roots\n";
  EXPECT_GT(points, 900u);
  EXPECT_GT(vertices, 500u);
  EXPECT_GT(bent, 300u);  // most samples are reached round obstacles, not straight
  EXPECT_GT(reflex_roots, 300u);
}

TEST(ShortestPathMap, ExtensionsAndCollisions) {
  std::mt19937_64 rng(21);
  std::size_t extensions = 0, collisions = 0, fronts = 0;
  for (const auto& c : spmt_cases()) {
    VisibilityIndex index(c.env);
    VisibilityGraph graph(index);
    const Point s = spmt_free_point(c.env, rng);
    const ShortestPathMap spm(graph, s);
    const SpmtBrute brute(c.env, s);
    const auto ext = spm.extensions();
    for (const auto& e : ext) {
      const ExactPoint u = to_exact(spm.root_point(e.from)), v = c.env.exact_vertex(e.vertex);
      // a bend: the predecessor is v's, and the hit is on the ray beyond v, on the boundary
      ASSERT_EQ(spm.vertex_predecessor(e.vertex), e.from);
      ASSERT_EQ(orientation(u, v, e.hit), 0);
      ASSERT_TRUE(CGAL::collinear_are_strictly_ordered_along_line(u, v, e.hit));
      const auto loc = locate(c.env, e.hit);
      ASSERT_TRUE(loc.kind == Location::Kind::OnEdge || loc.kind == Location::Kind::AtVertex) << c.name;
      ASSERT_TRUE(visible(c.env, v, e.hit)) << c.name;
      // the wave front is tangent at v: the obstacle lies on one side of the line
      const Point& V = c.env.vertex(e.vertex);
      ASSERT_TRUE(tangent_at(c.env, e.vertex, spm.root_point(e.from)));
      // along the extension h = D(v) + |v x| up to `end`, shorter just beyond a collision
      const Point H = to_double(e.hit);
      const double L = spmt_len(V, H);
      const Point dir((H.x() - V.x()) / L, (H.y() - V.y()) / L);
      const double te = spmt_len(V, e.end);
      for (double f : {0.25, 0.5, 0.9}) {
        const Point x(V.x() + f * te * dir.x(), V.y() + f * te * dir.y());
        if (locate(c.env, x).in_free_space()) {
          ASSERT_TRUE(spmt_close(brute.distance(x), spm.vertex_distance(e.vertex) + spmt_len(V, x))) << c.name;
        }
      }
      if (e.collides) {
        ++collisions;
        ASSERT_NE(e.collider, e.vertex);
        ASSERT_LT(te, L);
        const double t = te + 1e-3 * (L - te);  // a little beyond: another front is shorter
        const Point x(V.x() + t * dir.x(), V.y() + t * dir.y());
        if (locate(c.env, x).in_free_space()) {
          ASSERT_LT(brute.distance(x), spm.vertex_distance(e.vertex) + spmt_len(V, x) - 1e-12) << c.name;
        }
      }
      ++extensions;
    }
    // (c) first collisions of two fronts: h through both roots, the brute force agrees, and
    // h decreases at unit rate from x towards either root
    for (const auto& k : spm.collisions()) {
      const Point &A = c.env.vertex(k.a), &B = c.env.vertex(k.b);
      ASSERT_TRUE(spmt_visible(c.env, A, B)) << c.name;
      ASSERT_TRUE(spmt_close(spm.vertex_distance(k.a) + spmt_len(A, k.point), k.distance));
      ASSERT_TRUE(spmt_close(spm.vertex_distance(k.b) + spmt_len(B, k.point), k.distance));
      ASSERT_TRUE(spmt_close(brute.distance(k.point), k.distance)) << c.name << " " << format_point(k.point);
      const double ab = spmt_len(A, B), delta = 1e-3 * std::min(spmt_len(A, k.point), spmt_len(B, k.point));
      for (const Point& toward : {A, B}) {
        const double l = spmt_len(toward, k.point);
        const Point y(k.point.x() + delta / l * (toward.x() - k.point.x()), k.point.y() + delta / l * (toward.y() - k.point.y()));
        if (locate(c.env, y).in_free_space()) {
          ASSERT_LE(brute.distance(y), k.distance - delta / 2) << c.name;
        }
      }
      ASSERT_GT(ab, 0);
      ++fronts;
    }
  }
  std::cout << "[ counts   ] " << fronts << " collisions of two fronts\n";
  EXPECT_GT(fronts, 20u);
  std::cout << "[ counts   ] " << extensions << " extensions, " << collisions << " collisions\n";
  EXPECT_GT(extensions, 200u);
  EXPECT_GT(collisions, 20u);
}

TEST(ShortestPathMap, SquareAroundASquareHoleByHand) {
  // Outer [0,10]^2, hole [4,6]^2, source (1,5): the four bends and their extensions hit the
  // right wall at y = 8, 2 (source -> corners) and 6, 4 (along the hole's top and bottom).
  const Environment env = Environment::make({{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}});
  VisibilityIndex index(env);
  VisibilityGraph graph(index);
  const ShortestPathMap spm(graph, {1, 5});
  EXPECT_NEAR(spm.distance({9, 5}), 2 + 2 * std::sqrt(10.0), 1e-12);
  EXPECT_NEAR(spm.distance({9, 9}), std::hypot(8, 4), 1e-12);
  EXPECT_EQ(spm.region_of({9, 9}), ShortestPathMap::kSource);
  std::vector<ExactPoint> hits;
  for (const auto& e : spm.extensions()) {
    hits.push_back(e.hit);
    EXPECT_FALSE(e.collides);
  }
  std::sort(hits.begin(), hits.end());
  const std::vector<ExactPoint> want{{10, 2}, {10, 4}, {10, 6}, {10, 8}};
  EXPECT_EQ(hits, want);
  EXPECT_EQ(spm.num_reached(), 4u);
  // the fronts round the top and the bottom of the hole meet behind it, at (6, 5)
  const auto meet = spm.collisions();
  ASSERT_EQ(meet.size(), 1u);
  EXPECT_EQ(meet[0].point, Point(6, 5));
  EXPECT_NEAR(meet[0].distance, 3 + std::sqrt(10.0), 1e-12);
  EXPECT_THROW(ShortestPathMap(graph, Point(5, 5)), InputError);
  EXPECT_THROW(ShortestPathMap(graph, Point(11, 5)), InputError);
  try {
    ShortestPathMap(graph, Point(5, 5));
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  EXPECT_EQ(spm.query({5, 5}).root, kNone);
}

// sample() scan-converts every root's visibility polygon (issue 49: the wave front's time)
// instead of a visibility query per sample: it must agree with a full query on every
// sample, in root and distance (to rounding), and leave samples outside free space unset.
TEST(ShortestPathMap, SamplesAgreeWithFullQueries) {
  std::size_t total = 0, agree = 0, distance = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const Environment env = generators::random_environment(60, 1 + seed % 3, seed);
    const VisibilityIndex index(env);
    const VisibilityGraph graph(index);
    const auto b = env.bbox();
    const Point s = index.in_free_space(Point((b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2))
                        ? Point((b.xmin() + b.xmax()) / 2, (b.ymin() + b.ymax()) / 2)
                        : env.vertex(0);
    if (!index.in_free_space(s)) continue;
    const ShortestPathMap spm(graph, s);
    const auto S = spm.sample(150, 1);
    for (std::size_t j = 0; j < S.rows; ++j)
      for (std::size_t i = 0; i < S.columns; ++i) {
        const auto q = spm.query(S.point(i, j));
        const auto& got = S.at(i, j);
        if (q.root == geometry::kNone) {
          EXPECT_EQ(got.root, geometry::kNone) << "seed " << seed << " sample " << i << "," << j << " outside free space";
          continue;
        }
        ++total;
        const bool same = std::fabs(got.distance - q.distance) <= 1e-9 * (1 + q.distance);
        agree += got.root == q.root && same;
        distance += same;
      }
  }
  ASSERT_GT(total, 10000u);
  // Every sample: each root's visibility polygon scan-converted gives the full query's root
  // and distance (the sampling that inferred samples from their neighbours' roots agreed on
  // 99.5 %; this test allowed that).
  EXPECT_EQ(distance, total);
  EXPECT_EQ(agree, total);
}
