// The shadow-label filter against a set-based reference of rules 1-4 of 6.3.
#include <preimage/filter/history.hpp>
#include <preimage/filter/shadow_labels.hpp>

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace preimage::filter;

namespace {
// Reference: a new component is contaminated iff some old contaminated one corresponds to it.
std::vector<bool> reference(const std::vector<bool>& old, const ShadowEvent& e) {
  std::vector<bool> out(e.after, false);
  for (auto [o, n] : e.pairs)
    if (old[o]) out[n] = true;
  return out;
}
}  // namespace

TEST(ShadowLabels, RulesOfSection63) {
  ShadowLabels l(3, false);
  l.set(1, true);  // 010
  EXPECT_EQ(update(l, ShadowEvent::appear(3, 0)).str(), "0010");     // rule 2: appears clear
  EXPECT_EQ(update(l, ShadowEvent::disappear(3, 1)).str(), "00");     // rule 1: dropped
  EXPECT_EQ(update(l, ShadowEvent::merge(3, 0, 2)).str(), "10");      // rule 3: one contaminated part taints the merge
  EXPECT_EQ(update(l, ShadowEvent::merge(3, 1, 2)).str(), "01");
  EXPECT_EQ(update(l, ShadowEvent::split(3, 1, 3)).str(), "01110");   // rule 4: parts keep the label
  EXPECT_EQ(update(l, ShadowEvent::identity(3)).str(), "010");
  EXPECT_TRUE(ShadowLabels(70, false).all_clear());
  EXPECT_EQ(ShadowLabels(70, true).contaminated(), 70u);
  EXPECT_THROW(update(ShadowLabels(2, true), ShadowEvent::identity(3)), std::invalid_argument);
  EXPECT_THROW(ShadowTransition(ShadowEvent{1, 1, {{0, 1}}}), std::invalid_argument);
}

TEST(ShadowLabels, RandomCorrespondencesMatchTheSetReference) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::size_t before = rng() % 140, after = rng() % 140;
    ShadowEvent e{before, after, {}};
    if (before && after)
      for (std::size_t k = rng() % 200; k-- > 0;)
        e.pairs.push_back({static_cast<std::uint32_t>(rng() % before), static_cast<std::uint32_t>(rng() % after)});
    ShadowLabels l(before, false);
    std::vector<bool> ref(before);
    for (std::size_t i = 0; i < before; ++i) ref[i] = rng() % 2, l.set(i, ref[i]);
    const auto got = ShadowTransition(e).apply(l);
    const auto want = reference(ref, e);
    ASSERT_EQ(got.size(), after);
    for (std::size_t i = 0; i < after; ++i) ASSERT_EQ(got[i], want[i]) << "trial " << trial << " component " << i;
  }
}

TEST(ShadowLabels, FilterIsADerivedIMap) {
  static_assert(DerivedIMap<ShadowLabelFilter, int, ShadowEvent>);
  History<int, ShadowEvent> eta;
  eta.start(ShadowEvent{0, 2, {}});                  // two shadows, both contaminated
  eta.push(0, ShadowEvent::disappear(2, 0));          // the pursuer sees into the first
  eta.push(0, ShadowEvent::appear(1, 1));             // a new one opens behind it
  eta.push(0, ShadowEvent::merge(2, 0, 2));           // and merges with the contaminated one
  const auto f = replay<ShadowLabelFilter>(eta);
  EXPECT_EQ(f.labels().str(), "1");
  eta.observations.back() = ShadowEvent::disappear(2, 0);
  EXPECT_EQ(replay<ShadowLabelFilter>(eta).labels().str(), "0");
}
