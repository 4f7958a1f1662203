// SPDX-License-Identifier: Apache-2.0
// The shadow-label filter of visibility-based pursuit (Choset et al. 6.3; Guibas, Latombe,
// LaValle, Lin, Motwani 1999; wall-following paper VI.B): the parts of free space a
// pursuer cannot see ("shadow components") carry a label, 1 if the evader may be there
// (contaminated) and 0 if not (clear). When the shadows change, each new component is
// contaminated iff it shares evader positions with a contaminated old one:
//   1. a component disappears: its label is dropped;
//   2. a component appears: it is clear (0);
//   3. components merge: the new one is contaminated if any of them was;
//   4. a component splits: every part keeps its label.
// All four, and any combination in one event, are one rule over the correspondence
// (old, new) of components: new label = OR of the old labels it corresponds to. The
// filter knows nothing about geometry; pursuit computes correspondences from exact
// visibility, a wall-following robot gets them from its gap sensor.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace preimage::filter {

/// One 0/1 label per shadow component (a bitset; 1 = contaminated).
class ShadowLabels {
 public:
  ShadowLabels() = default;
  ShadowLabels(std::size_t n, bool contaminated);

  std::size_t size() const { return n_; }
  bool operator[](std::size_t i) const { return (w_[i >> 6] >> (i & 63)) & 1u; }
  void set(std::size_t i, bool contaminated);
  /// Number of contaminated components.
  std::size_t contaminated() const;
  /// No component may hold the evader (the search goal).
  bool all_clear() const;
  /// "0110": component 0 first.
  std::string str() const;

  const std::vector<std::uint64_t>& words() const { return w_; }
  std::size_t hash() const;
  friend bool operator==(const ShadowLabels& a, const ShadowLabels& b) { return a.n_ == b.n_ && a.w_ == b.w_; }

 private:
  std::size_t n_ = 0;
  std::vector<std::uint64_t> w_;
};

/// The correspondence between the shadow components before an event (0..before-1) and
/// after it (0..after-1): pairs (old, new) whose regions share evader positions.
struct ShadowEvent {
  std::size_t before = 0, after = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;

  /// Nothing changes: component i stays component i.
  static ShadowEvent identity(std::size_t n);
  /// Rule 2: a component appears at index `at` of the new list (others keep their order).
  static ShadowEvent appear(std::size_t n, std::size_t at);
  /// Rule 1: old component `at` disappears (others keep their order).
  static ShadowEvent disappear(std::size_t n, std::size_t at);
  /// Rule 4: old component `at` splits into `parts` components at indices at..at+parts-1.
  static ShadowEvent split(std::size_t n, std::size_t at, std::size_t parts);
  /// Rule 3: old components at..at+parts-1 merge into one component at index `at`.
  static ShadowEvent merge(std::size_t n, std::size_t at, std::size_t parts);
};

/// A correspondence compiled for repeated use: per new component, the set of old ones.
class ShadowTransition {
 public:
  ShadowTransition() = default;
  /// Throws std::invalid_argument if a pair names a component out of range.
  explicit ShadowTransition(const ShadowEvent& e);
  std::size_t before() const { return before_; }
  std::size_t after() const { return after_; }
  /// The labels after the event (rules 1-4). Throws std::invalid_argument on a size mismatch.
  ShadowLabels apply(const ShadowLabels& labels) const;

 private:
  std::size_t before_ = 0, after_ = 0, words_ = 0;
  std::vector<std::uint64_t> mask_;  // after_ rows of words_ words
};

/// One event applied once.
inline ShadowLabels update(const ShadowLabels& labels, const ShadowEvent& e) { return ShadowTransition(e).apply(labels); }

/// The filter as a derived I-map (filter::DerivedIMap): the first observation says how
/// many components there are (all contaminated, `after` of the event); each later one
/// is the event; the action is ignored (the correspondence already says what happened).
class ShadowLabelFilter {
 public:
  void start(const ShadowEvent& first) { labels_ = ShadowLabels(first.after, true); }
  template <class U>
  void step(const U& /*action*/, const ShadowEvent& e) {
    labels_ = update(labels_, e);
  }
  const ShadowLabels& labels() const { return labels_; }

 private:
  ShadowLabels labels_;
};

}  // namespace preimage::filter

template <>
struct std::hash<preimage::filter::ShadowLabels> {
  std::size_t operator()(const preimage::filter::ShadowLabels& l) const { return l.hash(); }
};
