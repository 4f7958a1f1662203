// SPDX-License-Identifier: Apache-2.0
#include <preimage/filter/transition_system.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

namespace preimage::filter {

TransitionSystem::TransitionSystem(std::size_t num_states, std::size_t num_symbols, std::vector<Transition> tr)
    : num_symbols_(num_symbols), offset_(num_states + 1, 0), tr_(std::move(tr)) {
  for (const Transition& t : tr_)
    if (t.from >= num_states || t.to >= num_states || t.symbol >= num_symbols)
      throw std::invalid_argument("transition (" + std::to_string(t.from) + ", " + std::to_string(t.symbol) + ", " +
                                  std::to_string(t.to) + ") out of range");
  std::sort(tr_.begin(), tr_.end(), [](const Transition& a, const Transition& b) {
    return std::tie(a.from, a.symbol, a.to) < std::tie(b.from, b.symbol, b.to);
  });
  tr_.erase(std::unique(tr_.begin(), tr_.end()), tr_.end());
  for (const Transition& t : tr_) ++offset_[t.from + 1];
  for (std::size_t s = 0; s < num_states; ++s) offset_[s + 1] += offset_[s];
}

std::span<const Transition> TransitionSystem::out(State s, Symbol y) const {
  const auto all = out(s);
  const auto lo = std::lower_bound(all.begin(), all.end(), y, [](const Transition& t, Symbol v) { return t.symbol < v; });
  auto hi = lo;
  while (hi != all.end() && hi->symbol == y) ++hi;
  return {lo, hi};
}

}  // namespace preimage::filter
