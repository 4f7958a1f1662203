// SPDX-License-Identifier: Apache-2.0
#include <preimage/filter/subset_automaton.hpp>
#include <preimage/filter/subset_filter.hpp>

#include <algorithm>
#include <cstring>

namespace preimage::filter {

SubsetAutomaton::SubsetAutomaton(const TransitionSystem& system, std::size_t max_bytes)
    : sys_(&system), nsym_(std::max<std::size_t>(1, system.num_symbols())), max_bytes_(max_bytes) {
  // A row costs nsym ids; budget the member lists at one average-sized set per row.
  const std::size_t row = nsym_ * sizeof(Id) + 16 * sizeof(State) + 64;
  max_states_ = std::max<std::size_t>(2, max_bytes_ / row);
  begin_.push_back(0);
}

std::string SubsetAutomaton::key(std::span<const State> s) {
  std::string k(s.size() * sizeof(State), '\0');
  if (!s.empty()) std::memcpy(k.data(), s.data(), k.size());
  return k;
}

void SubsetAutomaton::flush() {
  table_.clear();
  pool_.clear();
  begin_.assign(1, 0);
  index_.clear();
  ++flushes_;
}

SubsetAutomaton::Id SubsetAutomaton::intern(const std::vector<State>& set) {
  std::string k = key(set);
  if (auto it = index_.find(k); it != index_.end()) return it->second;
  if (cached_states() >= max_states_) flush();
  const Id id = static_cast<Id>(cached_states());
  pool_.insert(pool_.end(), set.begin(), set.end());
  begin_.push_back(pool_.size());
  table_.resize(table_.size() + nsym_, kUnknown);
  index_.emplace(std::move(k), id);
  return id;
}

SubsetAutomaton::Id SubsetAutomaton::miss(Id id, Symbol y) {
  ++misses_;
  const auto cur = states(id);
  std::vector<State> from(cur.begin(), cur.end());
  std::vector<State> to = successors(*sys_, from, y);
  std::string k = key(to);
  if (auto it = index_.find(k); it != index_.end()) {
    table_[static_cast<std::size_t>(id) * nsym_ + y] = it->second;
    return it->second;
  }
  if (cached_states() + 1 >= max_states_) {
    // Flush, keeping the current I-state so the transition can still be cached.
    flush();
    id = intern(from);
  }
  const Id nid = intern(to);
  table_[static_cast<std::size_t>(id) * nsym_ + y] = nid;
  return nid;
}

}  // namespace preimage::filter
