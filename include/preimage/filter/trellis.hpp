// SPDX-License-Identifier: Apache-2.0
// The (k+1)-partite graph H of the beams paper, 4.1: stage i holds the states of R_i,
// and an edge joins r in stage i to r' in stage i+1 when a transition r -y_{i+1}-> r'
// exists. After pruning, only vertices on a complete sequence V_0 -> V_k remain, so
// later observations refine what is known about earlier stages. The number of
// sequences is counted in arbitrary precision; sequences are enumerated up to a limit.
#pragma once
#include <preimage/filter/subset_filter.hpp>

#include <boost/multiprecision/cpp_int.hpp>

#include <span>
#include <vector>

namespace preimage::filter {

using BigCount = boost::multiprecision::cpp_int;

class Trellis {
 public:
  /// Builds and prunes H for `word` from `initial` (all states if empty).
  Trellis(const TransitionSystem& system, const std::vector<State>& initial, std::span<const Symbol> word);

  std::size_t length() const { return stages_.size() - 1; }  // k
  /// Pruned stage i (sorted states). Empty everywhere when the word is inconsistent.
  const std::vector<State>& stage(std::size_t i) const { return stages_[i]; }
  /// Successors in stage i+1 of the j-th vertex of stage i (indices into stage(i+1)).
  std::span<const std::uint32_t> next(std::size_t i, std::size_t j) const {
    return {targets_[i].data() + offsets_[i][j], targets_[i].data() + offsets_[i][j + 1]};
  }
  bool consistent() const { return !stages_.back().empty(); }
  /// First observation (1-based) after which the unpruned I-state was empty; 0 if none.
  std::size_t inconsistent_at() const { return inconsistent_at_; }
  /// Unpruned size of R_i as the forward filter saw it.
  std::size_t filtered_size(std::size_t i) const { return filtered_size_[i]; }

  std::size_t num_vertices() const;
  std::size_t num_edges() const;
  /// Number of complete state sequences (paths V_0 -> V_k in H).
  BigCount count() const;
  /// Up to `limit` sequences in lexicographic order; *truncated set if more exist.
  std::vector<std::vector<State>> enumerate(std::size_t limit, bool* truncated = nullptr) const;
  /// Is `sequence` (k+1 states) one of the possible sequences?
  bool contains(std::span<const State> sequence) const;

 private:
  std::vector<std::vector<State>> stages_;
  std::vector<std::vector<std::uint32_t>> offsets_, targets_;
  std::vector<std::size_t> filtered_size_;
  std::size_t inconsistent_at_ = 0;
};

}  // namespace preimage::filter
