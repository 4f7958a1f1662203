// The generic filter layer against brute force on random transition systems.
#include <preimage/filter/dfa.hpp>
#include <preimage/filter/product_filter.hpp>
#include <preimage/filter/subset_automaton.hpp>
#include <preimage/filter/subset_filter.hpp>
#include <preimage/filter/trellis.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <set>

using namespace preimage::filter;

namespace {

TransitionSystem random_system(std::size_t n, std::size_t syms, std::size_t edges, std::mt19937_64& rng) {
  std::uniform_int_distribution<State> s(0, static_cast<State>(n - 1));
  std::uniform_int_distribution<Symbol> y(0, static_cast<Symbol>(syms - 1));
  std::vector<Transition> tr;
  for (std::size_t i = 0; i < edges; ++i) tr.push_back({s(rng), y(rng), s(rng)});
  return TransitionSystem(n, syms, tr);
}

// Every state sequence explaining the word, by exhaustive search.
std::vector<std::vector<State>> brute_sequences(const TransitionSystem& g, const std::vector<Symbol>& w) {
  std::vector<std::vector<State>> out;
  std::vector<State> seq;
  std::function<void(State)> go = [&](State s) {
    seq.push_back(s);
    if (seq.size() == w.size() + 1) out.push_back(seq);
    else
      for (auto& t : g.out(s, w[seq.size() - 1])) go(t.to);
    seq.pop_back();
  };
  for (State s = 0; s < g.num_states(); ++s) go(s);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(TransitionSystem, DeduplicatesAndFindsSymbolRanges) {
  TransitionSystem g(3, 2, {{0, 1, 2}, {0, 0, 1}, {0, 1, 2}, {0, 1, 0}, {2, 0, 0}});
  EXPECT_EQ(g.num_transitions(), 4u);
  ASSERT_EQ(g.out(0, 1).size(), 2u);
  EXPECT_EQ(g.out(0, 1)[0].to, 0u);
  EXPECT_EQ(g.out(0, 1)[1].to, 2u);
  EXPECT_TRUE(g.out(1, 0).empty());
  EXPECT_THROW(TransitionSystem(2, 1, {{0, 1, 1}}), std::invalid_argument);
}

TEST(SubsetFilter, PlainCachedAndTrellisAgreeWithBruteForce) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const auto g = random_system(6, 3, 14, rng);
    std::uniform_int_distribution<Symbol> y(0, 2);
    std::vector<Symbol> w(1 + trial % 7);
    for (auto& s : w) s = y(rng);
    const auto brute = brute_sequences(g, w);
    std::set<State> last;
    for (auto& s : brute) last.insert(s.back());

    SubsetFilter plain(g);
    SubsetAutomaton tiny(g, 1);  // two I-states: flushes constantly
    SubsetAutomaton roomy(g);
    std::vector<State> all{0, 1, 2, 3, 4, 5};
    auto a = tiny.intern(all), b = roomy.intern(all);
    for (auto s : w) plain.step(s), a = tiny.step(a, s), b = roomy.step(b, s);
    // R_k may also hold states whose sequences die later; it equals the brute-force set of last states.
    const auto R = plain.sorted();
    EXPECT_EQ(std::set<State>(R.begin(), R.end()), last);
    EXPECT_EQ(std::vector<State>(tiny.states(a).begin(), tiny.states(a).end()), R);
    EXPECT_EQ(std::vector<State>(roomy.states(b).begin(), roomy.states(b).end()), R);

    const Trellis T(g, {}, w);
    EXPECT_EQ(T.count(), BigCount(brute.size()));
    bool cut = false;
    auto listed = T.enumerate(1000, &cut);
    EXPECT_FALSE(cut);
    EXPECT_EQ(listed, brute);
    for (auto& s : brute) EXPECT_TRUE(T.contains(s));
    // Pruning: every remaining vertex lies on a complete sequence.
    for (std::size_t i = 0; i <= w.size(); ++i) {
      std::set<State> on;
      for (auto& s : brute) on.insert(s[i]);
      EXPECT_EQ(std::set<State>(T.stage(i).begin(), T.stage(i).end()), on);
    }
    if (brute.size() > 2) {
      auto few = T.enumerate(2, &cut);
      EXPECT_TRUE(cut);
      EXPECT_EQ(few.size(), 2u);
    }
  }
}

TEST(SubsetAutomaton, RepeatedIStatesAreTableLookups) {
  TransitionSystem g(2, 1, {{0, 0, 1}, {1, 0, 0}});
  SubsetAutomaton d(g);
  auto id = d.intern({0});
  for (int i = 0; i < 1000; ++i) id = d.step(id, 0);
  EXPECT_EQ(d.cached_states(), 2u);
  EXPECT_EQ(d.misses(), 2u);
  EXPECT_EQ(d.states(id)[0], 0u);
}

TEST(Trellis, CountsBeyondSixtyFourBits) {
  // Two states, every observation can switch or stay: 2^(k+1) sequences.
  TransitionSystem g(2, 1, {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {1, 0, 1}});
  std::vector<Symbol> w(100, 0);
  const Trellis T(g, {}, w);
  EXPECT_EQ(T.count(), BigCount(1) << 101);
  EXPECT_EQ(T.count().str(), "2535301200456458802993406410752");
}

TEST(Trellis, InconsistentWordEmptiesEveryStage) {
  TransitionSystem g(2, 2, {{0, 0, 1}});
  const std::vector<Symbol> w{0, 0};
  const Trellis T(g, {}, w);
  EXPECT_FALSE(T.consistent());
  EXPECT_EQ(T.inconsistent_at(), 2u);
  EXPECT_TRUE(T.stage(0).empty());
  EXPECT_EQ(T.count(), 0);
}

TEST(ProductFilter, CountingRepresentationMatchesTuples) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    const auto g = random_system(4, 3, 12, rng);
    const std::size_t n = 2 + trial % 2;
    ProductFilter tuples(g, n, true), counts(g, n, false);
    std::uniform_int_distribution<Symbol> y(0, 2);
    for (int k = 0; k < 6; ++k) {
      const Symbol s = y(rng);
      tuples.step(s);
      counts.step(s);
      EXPECT_EQ(tuples.multisets(), counts.assignments());
    }
  }
}

TEST(Explore, FindsEveryReachableIState) {
  // A counter modulo 5 driven by symbol 0, reset by symbol 1.
  auto e = explore<int>(0, 2, [](int s, Symbol y) -> std::optional<int> { return y == 0 ? (s + 1) % 5 : 0; },
                        [](int s) { return std::to_string(s); });
  ASSERT_TRUE(e);
  EXPECT_EQ(e->dfa.size(), 5u);
  const std::vector<Symbol> w{0, 0, 0, 1, 0};
  EXPECT_EQ(e->dfa.names[e->dfa.run(e->dfa.initial, w)], "1");
  EXPECT_FALSE((explore<int>(0, 1, [](int s, Symbol) -> std::optional<int> { return s + 1; },
                             [](int s) { return std::to_string(s); }, 100)));
}
