// SPDX-License-Identifier: Apache-2.0
#include <preimage/filter/trellis.hpp>

#include <algorithm>
#include <numeric>

namespace preimage::filter {

Trellis::Trellis(const TransitionSystem& sys, const std::vector<State>& initial, std::span<const Symbol> word) {
  const std::size_t k = word.size();
  stages_.resize(k + 1);
  offsets_.resize(k);
  targets_.resize(k);
  filtered_size_.resize(k + 1, 0);

  // Forward: the region filter, recording H's edges (local indices, stage i -> i+1).
  std::vector<State>& s0 = stages_[0];
  if (initial.empty()) {
    s0.resize(sys.num_states());
    std::iota(s0.begin(), s0.end(), State{0});
  } else {
    s0 = initial;
    std::sort(s0.begin(), s0.end());
    s0.erase(std::unique(s0.begin(), s0.end()), s0.end());
  }
  filtered_size_[0] = s0.size();
  std::vector<std::uint32_t> local(sys.num_states(), UINT32_MAX);
  for (std::size_t i = 0; i < k; ++i) {
    std::vector<State> next = successors(sys, stages_[i], word[i]);
    for (std::uint32_t j = 0; j < next.size(); ++j) local[next[j]] = j;
    auto& off = offsets_[i];
    auto& tgt = targets_[i];
    off.assign(1, 0);
    for (State s : stages_[i]) {
      State last = kNoState;
      for (const Transition& t : sys.out(s, word[i]))
        if (t.to != last) tgt.push_back(local[t.to]), last = t.to;  // sorted by target: H edges deduplicated
      off.push_back(static_cast<std::uint32_t>(tgt.size()));
    }
    for (State s : next) local[s] = UINT32_MAX;
    stages_[i + 1] = std::move(next);
    filtered_size_[i + 1] = stages_[i + 1].size();
    if (stages_[i + 1].empty() && !inconsistent_at_) inconsistent_at_ = i + 1;
  }

  // Backward: keep only vertices with a path to stage k, then reindex every stage.
  std::vector<char> alive(stages_[k].size(), 1);
  for (std::size_t i = k; i-- > 0;) {
    const auto& off = offsets_[i];
    std::vector<char> a(stages_[i].size(), 0);
    for (std::size_t j = 0; j < a.size(); ++j)
      for (std::uint32_t e = off[j]; e < off[j + 1] && !a[j]; ++e) a[j] = alive[targets_[i][e]];
    // Reindex stage i+1 and stage i's edge lists.
    std::vector<std::uint32_t> remap(alive.size(), UINT32_MAX);
    std::uint32_t n = 0;
    std::vector<State> kept;
    for (std::size_t j = 0; j < alive.size(); ++j)
      if (alive[j]) remap[j] = n++, kept.push_back(stages_[i + 1][j]);
    stages_[i + 1] = std::move(kept);
    std::vector<std::uint32_t> noff{0}, ntgt;
    for (std::size_t j = 0; j < a.size(); ++j) {
      if (!a[j]) continue;
      for (std::uint32_t e = off[j]; e < off[j + 1]; ++e)
        if (alive[targets_[i][e]]) ntgt.push_back(remap[targets_[i][e]]);
      noff.push_back(static_cast<std::uint32_t>(ntgt.size()));
    }
    offsets_[i] = std::move(noff);
    targets_[i] = std::move(ntgt);
    alive = std::move(a);
  }
  std::vector<State> kept;
  for (std::size_t j = 0; j < alive.size(); ++j)
    if (alive[j]) kept.push_back(stages_[0][j]);
  stages_[0] = std::move(kept);
}

std::size_t Trellis::num_vertices() const {
  std::size_t n = 0;
  for (auto& s : stages_) n += s.size();
  return n;
}

std::size_t Trellis::num_edges() const {
  std::size_t n = 0;
  for (auto& t : targets_) n += t.size();
  return n;
}

BigCount Trellis::count() const {
  // Paths to the last stage, accumulated backwards (rolling, one stage in memory).
  std::vector<BigCount> c(stages_.back().size(), 1);
  for (std::size_t i = length(); i-- > 0;) {
    std::vector<BigCount> p(stages_[i].size());
    for (std::size_t j = 0; j < p.size(); ++j)
      for (std::uint32_t t : next(i, j)) p[j] += c[t];
    c = std::move(p);
  }
  BigCount total = 0;
  for (auto& v : c) total += v;
  return total;
}

std::vector<std::vector<State>> Trellis::enumerate(std::size_t limit, bool* truncated) const {
  std::vector<std::vector<State>> out;
  if (truncated) *truncated = false;
  const std::size_t k = length();
  std::vector<std::uint32_t> idx;  // idx[i]: vertex at stage i on the current path
  std::vector<std::uint32_t> pos;  // pos[i]: next alternative to try at stage i+1
  for (std::uint32_t v0 = 0; v0 < stages_[0].size(); ++v0) {
    idx.assign(1, v0);
    pos.assign(1, 0);
    while (!idx.empty()) {
      const std::size_t i = idx.size() - 1;
      if (i == k) {
        if (out.size() == limit) {
          if (truncated) *truncated = true;
          return out;
        }
        std::vector<State> seq(k + 1);
        for (std::size_t s = 0; s <= k; ++s) seq[s] = stages_[s][idx[s]];
        out.push_back(std::move(seq));
        idx.pop_back();
        pos.pop_back();
        continue;
      }
      const auto nx = next(i, idx[i]);
      if (pos[i] == nx.size()) {
        idx.pop_back();
        pos.pop_back();
        continue;
      }
      idx.push_back(nx[pos[i]++]);
      pos.push_back(0);
    }
  }
  return out;
}

bool Trellis::contains(std::span<const State> seq) const {
  if (seq.size() != stages_.size()) return false;
  auto find = [&](std::size_t i, State s) -> std::uint32_t {
    auto it = std::lower_bound(stages_[i].begin(), stages_[i].end(), s);
    return it != stages_[i].end() && *it == s ? static_cast<std::uint32_t>(it - stages_[i].begin()) : UINT32_MAX;
  };
  std::uint32_t j = find(0, seq[0]);
  if (j == UINT32_MAX) return false;
  for (std::size_t i = 0; i + 1 < seq.size(); ++i) {
    const std::uint32_t t = find(i + 1, seq[i + 1]);
    if (t == UINT32_MAX) return false;
    const auto nx = next(i, j);
    if (std::find(nx.begin(), nx.end(), t) == nx.end()) return false;
    j = t;
  }
  return true;
}

}  // namespace preimage::filter
