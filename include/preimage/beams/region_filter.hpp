// SPDX-License-Identifier: Apache-2.0
// Region filters over a beam arrangement (beams paper, section 4): the single-body
// filter R_{k+1} = phi(R_k, y_{k+1}) in plain or cached (lazy subset automaton) mode,
// the choice of R_0, and the compact two-body and parity filters of 4.2.
#pragma once
#include <preimage/beams/arrangement.hpp>
#include <preimage/filter/dfa.hpp>
#include <preimage/filter/product_filter.hpp>
#include <preimage/filter/subset_automaton.hpp>
#include <preimage/filter/subset_filter.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace preimage::beams {

/// R_0 from region ids and points (each point must lie strictly inside a region);
/// all regions if both are empty. InputError names the bad id or point.
std::vector<std::uint32_t> initial_regions(const BeamArrangement& arrangement, const std::vector<std::uint32_t>& ids,
                                           const std::vector<ExactPoint>& points);

/// The initial I-state of several bodies (4.2) in the regions `R0` (sorted, distinct):
/// every tuple (distinguishable bodies, |R0|^n of them), every multiset as a sorted
/// tuple (indistinguishable, C(|R0|+n-1, n), enumerated directly rather than by sorting
/// |R0|^n tuples), or with `together` all bodies in one region of R0 (|R0|).
std::vector<filter::ProductFilter::Assignment> initial_assignments(const std::vector<std::uint32_t>& R0, std::size_t bodies,
                                                                   bool distinguishable, bool together);
/// How many assignments initial_assignments returns for |R0| = `regions`, saturating at
/// UINT64_MAX (so a caller can refuse an I-state too large to build before building it).
std::uint64_t count_initial_assignments(std::size_t regions, std::size_t bodies, bool distinguishable, bool together);

enum class FilterMode { Plain, Cached };

/// The single-body region filter (4.1).
class RegionFilter {
 public:
  RegionFilter(const BeamArrangement& arrangement, const std::vector<std::uint32_t>& initial = {},
               FilterMode mode = FilterMode::Plain, std::size_t cache_bytes = std::size_t(64) << 20);
  // Keeps a pointer to the arrangement's transition system.
  RegionFilter(BeamArrangement&&, const std::vector<std::uint32_t>& = {}, FilterMode = FilterMode::Plain, std::size_t = 0) = delete;
  /// One observation; false once no region explains the word so far.
  bool step(Symbol y);
  std::vector<std::uint32_t> regions() const;
  bool empty() const;
  FilterMode mode() const { return mode_; }
  const filter::SubsetAutomaton* automaton() const { return dfa_ ? &*dfa_ : nullptr; }

 private:
  FilterMode mode_;
  filter::SubsetFilter plain_;
  std::optional<filter::SubsetAutomaton> dfa_;
  filter::SubsetAutomaton::Id id_ = 0;
};

/// The four-state filter of Fig. 11(b) for two bodies in three regions: T (together)
/// and D_x (separated by beam x). Needs exactly three regions with every label
/// separating one pair of distinct regions; InputError otherwise. Initial state: T.
filter::Dfa together_filter(const BeamArrangement& arrangement);
/// The Fig. 11(b) state a two-body product I-state determines ("T", "D_a", ...), or
/// nullopt when it mixes together and separated assignments.
std::optional<std::string> together_reading(const BeamArrangement& arrangement,
                                            const std::vector<filter::ProductFilter::Assignment>& pairs);

/// One parity bit per region (4.2): crossing a beam toggles the two regions it joins.
/// Needs every observation to name one pair of regions (or only self-loops).
class ParityFilter {
 public:
  /// `bodies_in`: the initial region of each body.
  ParityFilter(const BeamArrangement& arrangement, const std::vector<std::uint32_t>& bodies_in);
  void step(Symbol y);
  const std::vector<bool>& parity() const { return bits_; }
  /// The update as a pure function on parity vectors (for search over I-states).
  std::vector<bool> next(const std::vector<bool>& bits, Symbol y) const;

 private:
  std::vector<std::pair<std::uint32_t, std::uint32_t>> toggles_;  // per symbol; kNone: no change
  std::vector<bool> bits_;
};

}  // namespace preimage::beams
