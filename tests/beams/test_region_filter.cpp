// Region filters against ground truth: simulated body paths, sample paths traced back,
// and the compact filters of 4.2 against the product filter.
#include <preimage/beams/examples.hpp>
#include <preimage/beams/paths.hpp>
#include <preimage/beams/region_filter.hpp>
#include <preimage/error.hpp>
#include <preimage/filter/trellis.hpp>

#include <support/beam_scenes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <sstream>

using namespace preimage;
using beams::Alphabet;
using beams::BeamArrangement;

TEST(Words, TokensPrimesAndTheOneCharacterStream) {
  const auto A = BeamArrangement::build(beams::fig3b_scene());
  const auto& al = A.alphabet();
  EXPECT_EQ(al.format(al.parse_word("a' b c")), "a' b c");
  EXPECT_EQ(al.format(al.parse_word("a'bcd'a")), "a' b c d' a");
  try {
    al.parse_word("a b x");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "token 3 'x' at offset 4: unknown beam label 'x'");
  }
  EXPECT_THROW(al.parse_word("b'"), InputError);  // b is undirected
  // Streams deliver everything before a bad token.
  std::istringstream in("a b\nc  zz a");
  beams::WordReader r(al, in);
  beams::Symbol y;
  int n = 0;
  try {
    while (r.next(y)) ++n;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("token 4 'zz' at offset 7"), std::string::npos) << e.what();
  }
  EXPECT_EQ(n, 3);
}

TEST(RegionFilter, Fig1WordHasOneExplanation) {
  const auto A = BeamArrangement::build(beams::fig1_scene());
  const auto w = A.alphabet().parse_word("cbabdeeefe");
  beams::RegionFilter F(A);
  for (auto y : w) ASSERT_TRUE(F.step(y));
  EXPECT_EQ(F.regions(), std::vector<std::uint32_t>{2});
  const filter::Trellis T(A.graph(), {}, w);
  EXPECT_EQ(T.count(), 1);
  // Later observations refined the start: only the middle region explains "d" at step 5.
  EXPECT_EQ(T.stage(0), std::vector<std::uint32_t>{1});
  EXPECT_EQ(T.filtered_size(0), 3u);
}

TEST(RegionFilter, InconsistentWordIsReportedNotFatal) {
  const auto A = BeamArrangement::build(beams::fig3b_scene());
  beams::RegionFilter F(A);
  const auto w = A.alphabet().parse_word("a' a'");
  EXPECT_TRUE(F.step(w[0]));
  EXPECT_FALSE(F.step(w[1]));
  EXPECT_TRUE(F.empty());
  EXPECT_FALSE(F.step(w[0]));  // stays empty
}

TEST(RegionFilter, SimulatedPathsAreAlwaysExplained) {
  // Property (4.1): the true region is in R_k at every k, the true sequence is among
  // the possible ones, and plain and cached modes agree.
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const auto s = preimage::testing::random_beam_scene(24, seed % 3, 8, seed, 4, 0.5);
    const auto A = BeamArrangement::build(s);
    const auto sim = beams::simulate(A, seed, 40);
    const auto& w = sim.trace.word;
    beams::RegionFilter plain(A), cached(A, {}, beams::FilterMode::Cached, 1 << 12);
    for (std::size_t k = 0; k < w.size(); ++k) {
      plain.step(w[k]);
      cached.step(w[k]);
      const auto R = plain.regions();
      ASSERT_TRUE(std::binary_search(R.begin(), R.end(), sim.trace.regions[k + 1])) << "seed " << seed << " k " << k;
      ASSERT_EQ(cached.regions(), R);
    }
    const filter::Trellis T(A.graph(), {}, w);
    EXPECT_TRUE(T.contains(sim.trace.regions)) << "seed " << seed;
    // Every listed sequence has a sample path producing exactly the word and the sequence.
    for (const auto& seq : T.enumerate(5)) {
      const auto path = beams::sample_path(A, seq, w);
      const auto tr = beams::trace_path(A, path);
      EXPECT_EQ(tr.word, w) << "seed " << seed;
      EXPECT_EQ(tr.regions, seq) << "seed " << seed;
    }
  }
}

TEST(RegionFilter, SamplePathsInLandmarkScenes) {
  const auto s = beams::with_landmark_beams(beams::landmark_scene(5, 3), beams::LandmarkModel::Crossing, false, false);
  const auto A = BeamArrangement::build(s);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto sim = beams::simulate(A, seed, 25);
    const filter::Trellis T(A.graph(), {}, sim.trace.word);
    ASSERT_TRUE(T.contains(sim.trace.regions));
    for (const auto& seq : T.enumerate(3)) EXPECT_EQ(beams::trace_path(A, beams::sample_path(A, seq, sim.trace.word)).regions, seq);
  }
}

namespace {
// A random consistent word for n bodies: each step one random body takes a random edge of G.
std::vector<beams::Symbol> random_multibody_word(const BeamArrangement& A, std::vector<std::uint32_t> at, std::size_t k,
                                                 std::mt19937_64& rng) {
  std::vector<beams::Symbol> w;
  while (w.size() < k) {
    const std::size_t b = rng() % at.size();
    const auto out = A.graph().out(at[b]);
    if (out.empty()) continue;
    const auto& t = out[rng() % out.size()];
    w.push_back(t.symbol);
    at[b] = t.to;
  }
  return w;
}
}  // namespace

TEST(MultiBody, Fig11FilterMatchesTheProductFilter) {
  const auto A = BeamArrangement::build(beams::fig11_scene());
  const auto d = beams::together_filter(A);
  EXPECT_EQ(d.size(), 4u);  // T, D_a, D_b, D_c
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const std::uint32_t r = rng() % 3;
    const auto w = random_multibody_word(A, {r, r}, 1 + trial % 30, rng);
    std::vector<filter::ProductFilter::Assignment> init{{0, 0}, {1, 1}, {2, 2}};
    filter::ProductFilter P(A.graph(), 2, true, init);
    filter::State s = d.initial;
    for (auto y : w) {
      ASSERT_TRUE(P.step(y));
      s = d.step(s, y);
      ASSERT_NE(s, filter::kNoState);
      const auto reading = beams::together_reading(A, P.assignments());
      ASSERT_TRUE(reading.has_value());
      ASSERT_EQ(*reading, d.names[s]);
    }
  }
}

TEST(MultiBody, ParityFilterMatchesTheCountingFilter) {
  for (const auto& sc : {beams::fig11_scene(), beams::fig1_scene()}) {
    const auto A = BeamArrangement::build(sc);
    std::mt19937_64 rng(9);
    for (int trial = 0; trial < 100; ++trial) {
      const std::size_t n = 2 + trial % 3;
      std::vector<std::uint32_t> start(n);
      for (auto& r : start) r = rng() % A.num_regions();
      beams::ParityFilter par(A, start);
      filter::ProductFilter counts(A.graph(), n, false, {start});
      for (auto y : random_multibody_word(A, start, 20, rng)) {
        par.step(y);
        ASSERT_TRUE(counts.step(y));
        for (const auto& m : counts.assignments()) {
          std::vector<bool> bits(A.num_regions(), false);
          for (auto r : m) bits[r] = !bits[r];
          ASSERT_EQ(bits, par.parity());
        }
      }
    }
    // Its I-states, found by search: parity vectors reachable from two bodies together.
    beams::ParityFilter p2(A, {0, 0});
    auto e = filter::explore<std::vector<bool>>(p2.parity(), A.alphabet().num_symbols(),
                                                [&](const std::vector<bool>& b, beams::Symbol y) { return std::optional(p2.next(b, y)); },
                                                [](const std::vector<bool>&) { return std::string(); });
    ASSERT_TRUE(e);
    EXPECT_EQ(e->dfa.size(), A.num_regions() == 3 ? 4u : 4u);  // 000 and the three "two odd regions" vectors
  }
}

TEST(MultiBody, ParityFilterRejectsAmbiguousLabels) {
  const auto A = BeamArrangement::build(beams::fig3b_scene());  // 'c' joins two different region pairs
  EXPECT_THROW(beams::ParityFilter(A, {0}), InputError);
  EXPECT_THROW(beams::together_filter(A), InputError);
}

// Regression: the Fig. 1 sample path runs along x = 6, the line of beam f, above f's
// end; tracing once called that a touch of f. Found by `preimage demo`.
TEST(Regressions, PathCollinearWithABeamLineButApartIsNotATouch) {
  const auto A = BeamArrangement::build(scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/beams/fig01_six_beams.json"));
  const auto w = A.alphabet().parse_word("cbabdeeefe");
  const filter::Trellis T(A.graph(), {}, w);
  const auto path = beams::sample_path(A, T.enumerate(1).front(), w);
  EXPECT_EQ(beams::trace_path(A, path).word, w);
  const geometry::ExactPoint apart[] = {geometry::to_exact(geometry::Point(6, 5)), geometry::to_exact(geometry::Point(6, 3))};
  EXPECT_TRUE(beams::trace_path(A, apart).word.empty());
}

// The initial I-state of several bodies against brute force: the multisets are the
// distinct sorted tuples of the full product, enumerated directly, and the counts
// (used to refuse an I-state too large to build) are exact, saturating past 2^64.
TEST(MultiBody, InitialAssignmentsAgainstTheFullProduct) {
  for (std::size_t m = 1; m <= 4; ++m)
    for (std::size_t n = 1; n <= 5; ++n) {
      std::vector<std::uint32_t> R0;
      for (std::uint32_t r = 0; r < m; ++r) R0.push_back(2 * r + 1);
      const auto tuples = beams::initial_assignments(R0, n, true, false);
      EXPECT_EQ(tuples, filter::ProductFilter::all_assignments(R0, n));
      std::set<filter::ProductFilter::Assignment> sorted;
      for (auto t : tuples) std::sort(t.begin(), t.end()), sorted.insert(t);
      const auto multisets = beams::initial_assignments(R0, n, false, false);
      EXPECT_EQ(std::set(multisets.begin(), multisets.end()), sorted) << m << " regions, " << n << " bodies";
      EXPECT_EQ(multisets.size(), sorted.size());
      EXPECT_EQ(beams::count_initial_assignments(m, n, true, false), tuples.size());
      EXPECT_EQ(beams::count_initial_assignments(m, n, false, false), multisets.size());
      const auto together = beams::initial_assignments(R0, n, false, true);
      EXPECT_EQ(together.size(), m);
      EXPECT_EQ(beams::count_initial_assignments(m, n, true, true), m);
      for (const auto& t : together) EXPECT_EQ(std::set(t.begin(), t.end()).size(), 1u);
    }
  EXPECT_EQ(beams::count_initial_assignments(3, 1000000, false, false), 500001500001u);  // C(1000002, 2)
  EXPECT_EQ(beams::count_initial_assignments(3, 1000000, true, false), UINT64_MAX);     // 3^1000000
  EXPECT_EQ(beams::count_initial_assignments(2, 64, true, false), UINT64_MAX);          // 2^64 does not fit
  EXPECT_EQ(beams::count_initial_assignments(2, 63, true, false), std::uint64_t(1) << 63);
  EXPECT_EQ(beams::count_initial_assignments(1, 1000000000, true, false), 1u);
  EXPECT_EQ(beams::count_initial_assignments(100, 100, false, false), UINT64_MAX);  // C(199, 99) ~ 4.5e58
}

// Fig. 12's caption says "2^3 = 9" region assignments of two bodies in three regions: it
// is 3^2 = 9 (m^n for m regions and n bodies, as 4.2's text says), against
// C(3+2-1, 2) = 6 multisets.
TEST(MultiBody, Fig12CaptionIsThreeSquaredNotTwoCubed) {
  const auto A = BeamArrangement::build(beams::fig11_scene());
  ASSERT_EQ(A.num_regions(), 3u);
  const std::vector<std::uint32_t> all{0, 1, 2};
  EXPECT_EQ(filter::ProductFilter(A.graph(), 2, true, beams::initial_assignments(all, 2, true, false)).size(), 9u);
  EXPECT_EQ(filter::ProductFilter(A.graph(), 2, false, beams::initial_assignments(all, 2, false, false)).size(), 6u);
  // Three bodies in two regions would be 2^3 = 8, not 9.
  EXPECT_EQ(beams::count_initial_assignments(2, 3, true, false), 8u);
}

TEST(Simulate, ReportsProgressOncePerSegment) {
  const auto A = BeamArrangement::build(beams::fig3b_scene());
  std::vector<std::size_t> seen;
  const auto sim = beams::simulate(A, 4, 30, [&](std::size_t k) { seen.push_back(k); });
  ASSERT_EQ(sim.path.size(), 31u);
  std::vector<std::size_t> want(30);
  std::iota(want.begin(), want.end(), std::size_t(1));
  EXPECT_EQ(seen, want);
  EXPECT_EQ(beams::simulate(A, 4, 30).trace.word, sim.trace.word);  // the callback changes nothing
}
