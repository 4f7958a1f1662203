// The beam arrangement against the paper's figures and CGAL's Arrangement_2.
#include <preimage/beams/arrangement.hpp>
#include <preimage/beams/examples.hpp>
#include <preimage/beams/export.hpp>
#include <preimage/error.hpp>

#include <support/beam_scenes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

using namespace preimage;
using beams::BeamArrangement;
using geometry::Point;

namespace {

std::string build_error(const scene::Scene& s) {
  try {
    (void)BeamArrangement::build(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_matches_cgal(const BeamArrangement& A, const std::string& what) {
  const auto o = preimage::testing::cgal_regions(A);
  EXPECT_EQ(A.num_regions(), o.free_faces) << what;
  std::set<long> seen;
  for (std::size_t r = 0; r < o.face_of_sample.size(); ++r) {
    EXPECT_GE(o.face_of_sample[r], 0) << what << ": sample of region " << r << " is not in a free face";
    EXPECT_TRUE(seen.insert(o.face_of_sample[r]).second) << what << ": two regions share a CGAL face";
  }
}

}  // namespace

TEST(BeamArrangement, PaperFigures) {
  const auto f1 = BeamArrangement::build(beams::fig1_scene());
  EXPECT_EQ(f1.num_regions(), 3u);  // Fig. 3(a): three regions
  // Six pieces, two crossings each; the undirected self-loop f gives (r1, f, r1) twice.
  EXPECT_EQ(f1.edges().size(), 12u);
  EXPECT_EQ(f1.graph().num_transitions(), 11u);
  // f joins an obstacle to the wall inside one region: a self-loop (4.1).
  const auto f = *f1.alphabet().find("f");
  EXPECT_NE(f1.find_edge(1, beams::Alphabet::positive(f), 1), nullptr);
  const auto f3 = BeamArrangement::build(beams::fig3b_scene());
  EXPECT_EQ(f3.num_regions(), 8u);  // Fig. 3(b): "There are 8 regions"
  EXPECT_EQ(f3.num_crossings(), 3u);
  // 5 beams cut 3 times (each cut splits two beams): 11 pieces, 22 edges of the multigraph.
  EXPECT_EQ(f3.num_pieces(), 11u);
  EXPECT_EQ(f3.edges().size(), 22u);
  EXPECT_EQ(f3.graph().num_transitions(), 20u);
  const auto f11 = BeamArrangement::build(beams::fig11_scene());
  EXPECT_EQ(f11.num_regions(), 3u);
  for (auto* A : {&f1, &f3, &f11}) expect_matches_cgal(*A, "figure");
}

TEST(BeamArrangement, ExampleFilesMatchBuiltInScenes) {
  const std::string dir = std::string(PREIMAGE_EXAMPLES) + "/beams/";
  const std::pair<const char*, scene::Scene> cases[] = {{"fig01_six_beams.json", beams::fig1_scene()},
                                                         {"fig03b_crossing.json", beams::fig3b_scene()},
                                                         {"fig11_ring.json", beams::fig11_scene()},
                                                         {"fig13_perfect.json", beams::fig13_scene()},
                                                         {"fig18_commutator.json", beams::fig18_scene()}};
  for (auto& [file, built] : cases) {
    auto a = scene::to_json(scene::load_scene(dir + file)), b = scene::to_json(built);
    EXPECT_EQ(a, b) << file;
  }
}

TEST(BeamArrangement, DirectedCrossingsFollowTheRightToLeftConvention) {
  const auto A = BeamArrangement::build(beams::fig3b_scene());
  // Beam a runs from (0, 1) to (12, 2.5): its left side is above.
  const auto below = *A.locate(geometry::to_exact(Point(1, 0.5))), above = *A.locate(geometry::to_exact(Point(1, 4)));
  const auto a = *A.alphabet().find("a");
  EXPECT_NE(A.find_edge(below, beams::Alphabet::positive(a), above), nullptr);
  EXPECT_NE(A.find_edge(above, beams::Alphabet::negative(a), below), nullptr);
  EXPECT_EQ(A.find_edge(below, beams::Alphabet::negative(a), above), nullptr);
}

TEST(BeamArrangement, RandomScenesMatchCgalArrangement) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const auto s = preimage::testing::random_beam_scene(20 + 5 * seed, seed % 4, 3 + 3 * seed, seed, 0, 0.3);
    const auto A = BeamArrangement::build(s);
    expect_matches_cgal(A, "seed " + std::to_string(seed));
    // Every sample point locates back to its own region.
    for (std::uint32_t r = 0; r < A.num_regions(); ++r) EXPECT_EQ(A.locate(A.regions()[r].sample), r);
  }
}

// Faces thinner than a unit in the last place: the sample point computed in doubles
// is rejected by the exact inside test and the exact construction takes over.
TEST(BeamArrangement, SliverFacesGetExactSamplePoints) {
  const auto A = BeamArrangement::build(scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/beam_sliver_faces.json"));
  EXPECT_EQ(A.num_regions(), 5u);
  expect_matches_cgal(A, "sliver");
  for (std::uint32_t r = 0; r < A.num_regions(); ++r) EXPECT_EQ(A.locate(A.regions()[r].sample), r);
}

TEST(BeamArrangement, LandmarkScenesInTheUnboundedPlane) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const auto L = beams::landmark_scene(3 + seed % 4, seed);
    for (auto model : {beams::LandmarkModel::Crossing, beams::LandmarkModel::North}) {
      const auto s = beams::with_landmark_beams(L, model, true, true);
      const auto A = BeamArrangement::build(s);
      EXPECT_TRUE(A.unbounded());
      expect_matches_cgal(A, "landmarks seed " + std::to_string(seed));
      if (model == beams::LandmarkModel::North) {
        EXPECT_EQ(A.num_regions(), 1u);  // rays north never separate the plane
      }
    }
  }
}

TEST(BeamArrangement, InvalidBeamsAreNamed) {
  auto s = beams::fig1_scene();
  s.beams[2].from = Point(4, 6);  // inside an obstacle
  EXPECT_NE(build_error(s).find("$.beams[2] ('c'): from (4, 6) is not on the boundary (it is inside $.environment.obstacles[1])"),
            std::string::npos)
      << build_error(s);
  s = beams::fig1_scene();
  s.beams.push_back({"g", Point(0, 2), Point(12, 2), true});  // through two obstacles
  EXPECT_NE(build_error(s).find("$.beams[6] ('g'): the beam touches edge"), std::string::npos) << build_error(s);
  s = beams::fig1_scene();
  s.beams.push_back({"a", Point(0, 1), Point(3.5, 1.5 + 0), true});  // directed beam sharing undirected label a
  EXPECT_NE(build_error(s).find("shared by directed and undirected"), std::string::npos) << build_error(s);
  s = beams::fig3b_scene();
  s.beams.push_back({"e", Point(0, 6), Point(12, 6), true});
  s.beams.push_back({"g", Point(0, 4), Point(4, 8), true});
  s.beams.push_back({"h", Point(1, 8), Point(5, 0), true});  // three beams through (2, 6)
  EXPECT_NE(build_error(s).find("at one point (2, 6)"), std::string::npos) << build_error(s);
  s = beams::fig3b_scene();
  s.beams.push_back({"e", Point(3, 0), Point(3, 8), true});  // on top of b
  EXPECT_NE(build_error(s).find("overlaps $.beams[1] ('b')"), std::string::npos) << build_error(s);
  s = beams::fig1_scene();
  s.beams.push_back({"g", Point(4.5, 2), Point(8, 2), true});  // ends on beam d? no: d is x = 8, from y 0 to 3.5
  EXPECT_NE(build_error(s).find("$.beams[6] ('g'): "), std::string::npos) << build_error(s);
  auto L = beams::landmark_scene(3, 1);
  L.landmarks.push_back({"4", Point(2 * L.landmarks[1].at.x() - L.landmarks[0].at.x(), 2 * L.landmarks[1].at.y() - L.landmarks[0].at.y())});
  EXPECT_NE(build_error(beams::with_landmark_beams(L, beams::LandmarkModel::Crossing, true, true)).find("passes through landmark"),
            std::string::npos);
}

TEST(BeamArrangement, ExportsJsonAndDot) {
  const auto A = BeamArrangement::build(beams::fig3b_scene());
  const auto j = beams::graph_json(A);
  EXPECT_EQ(j["counts"]["regions"], 8);
  EXPECT_EQ(j["edges"].size(), 22u);
  EXPECT_EQ(j["counts"]["merged_edges"], 20);
  EXPECT_EQ(beams::graph_json(A, true)["edges"].size(), 20u);
  const std::string dot = beams::graph_dot(A);
  EXPECT_NE(dot.find("r0 -> r1 [label=\"a (beam 0 piece 0, right to left)\"]"), std::string::npos) << dot;
  EXPECT_EQ(std::count(dot.begin(), dot.end(), '>'), 22);
  EXPECT_NE(beams::graph_dot(A, true).find("r0 -> r1 [label=\"a\"]"), std::string::npos);
  EXPECT_NE(beams::arrangement_figure(A).str().find("fill-rule=\"evenodd\""), std::string::npos);
}

// G is a multigraph (4.1): the printed graph once merged the two pieces of a label that
// join the same two regions, so an obstacle with two beams labelled c showed 2 edges
// instead of 4 and its JSON named one beam only (issue 32).
TEST(BeamArrangement, TwoPiecesWithOneLabelAreFourEdges) {
  const auto A = BeamArrangement::build(scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/beams_two_pieces_one_label.json"));
  ASSERT_EQ(A.num_regions(), 2u);
  EXPECT_EQ(A.edges().size(), 4u);
  EXPECT_EQ(A.graph().num_transitions(), 2u);
  const auto j = beams::graph_json(A);
  std::set<std::pair<int, std::string>> crossings;  // (beam, r0->r1 or r1->r0)
  for (const auto& e : j["edges"]) {
    EXPECT_EQ(e["piece"], 0);
    crossings.insert({e["beam"].get<int>(), std::to_string(e["from"].get<int>()) + "->" + std::to_string(e["to"].get<int>())});
    // Beam 0 runs up at x = 5 (its left is r0), beam 1 runs down (its left is r1).
    EXPECT_EQ(e["positive"], e["to"] == (e["beam"] == 0 ? 0 : 1)) << e.dump();
  }
  EXPECT_EQ(crossings.size(), 4u) << j["edges"].dump();
  const auto m = beams::graph_json(A, true);
  ASSERT_EQ(m["edges"].size(), 2u);
  for (const auto& e : m["edges"]) EXPECT_EQ(e["pieces"].size(), 2u);
}

// Every beam piece gives exactly two edges, each naming its piece; pieces chain along
// their beam from `from` to `to`; the transition relation is the set of distinct
// (from, symbol, to). Against counts from first principles on random scenes with
// shared labels: a beam with c crossings has c + 1 pieces.
TEST(BeamArrangement, MultigraphHasTwoEdgesPerBeamPiece) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto s = preimage::testing::random_beam_scene(16 + 3 * seed, seed % 3, 4 + 2 * seed, seed, 3, 0.4);
    const auto A = BeamArrangement::build(s);
    const auto& H = A.half_edges();
    EXPECT_EQ(A.num_pieces(), A.beams().size() + 2 * A.num_crossings()) << "seed " << seed;
    EXPECT_EQ(A.edges().size(), 2 * A.num_pieces()) << "seed " << seed;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> per_piece;
    std::set<std::tuple<std::uint32_t, beams::Symbol, std::uint32_t>> distinct;
    for (const auto& e : A.edges()) {
      const auto p = A.piece(e.half_edge);
      ++per_piece[{p.beam, p.index}];
      distinct.insert({e.from, e.symbol, e.to});
      EXPECT_EQ(A.region_of(e.half_edge), e.to);
      EXPECT_EQ(A.region_of(BeamArrangement::twin(e.half_edge)), e.from);
      EXPECT_EQ(H[e.half_edge].beam, p.beam);
      if (A.beams()[p.beam].directed) {
        EXPECT_EQ(e.symbol == beams::Alphabet::positive(A.beams()[p.beam].label), e.half_edge % 2 == 0);
      }
    }
    EXPECT_EQ(per_piece.size(), A.num_pieces());
    for (auto& [piece, n] : per_piece) EXPECT_EQ(n, 2) << "beam " << piece.first << " piece " << piece.second;
    EXPECT_EQ(A.graph().num_transitions(), distinct.size());
    for (std::uint32_t b = 0; b < A.beams().size(); ++b) {
      const auto [first, last] = A.beam_pieces(b);
      EXPECT_EQ(A.vertices()[H[first].origin], A.beams()[b].from);
      EXPECT_EQ(A.vertices()[H[last - 2].target], A.beams()[b].to);
      for (std::uint32_t h = first; h < last; h += 2) {
        EXPECT_EQ(A.piece(h).index, (h - first) / 2);
        EXPECT_EQ(A.piece(h + 1).index, (h - first) / 2);
        if (h + 2 < last) {
          EXPECT_EQ(H[h].target, H[h + 2].origin);
        }
      }
    }
  }
}
