// SPDX-License-Identifier: Apache-2.0
#include <preimage/filter/subset_filter.hpp>

#include <algorithm>
#include <numeric>

namespace preimage::filter {

SubsetFilter::SubsetFilter(const TransitionSystem& system, const std::vector<State>& initial)
    : sys_(&system), mark_(system.num_states(), 0) {
  if (initial.empty()) {
    cur_.resize(system.num_states());
    std::iota(cur_.begin(), cur_.end(), State{0});
  } else {
    reset(initial);
  }
}

void SubsetFilter::reset(const std::vector<State>& states) {
  ++gen_;
  cur_.clear();
  for (State s : states)
    if (mark_[s] != gen_) mark_[s] = gen_, cur_.push_back(s);
}

bool SubsetFilter::step(Symbol y) {
  // Paper 4.1: m_{k+1}(v) = 1 for every target of an out-edge labelled y of a marked v.
  if (++gen_ == 0) std::fill(mark_.begin(), mark_.end(), 0), gen_ = 1;
  next_.clear();
  for (State s : cur_)
    for (const Transition& t : sys_->out(s, y))
      if (mark_[t.to] != gen_) mark_[t.to] = gen_, next_.push_back(t.to);
  cur_.swap(next_);
  return !cur_.empty();
}

std::vector<State> SubsetFilter::sorted() const {
  std::vector<State> s = cur_;
  std::sort(s.begin(), s.end());
  return s;
}

bool SubsetFilter::contains(State s) const { return std::find(cur_.begin(), cur_.end(), s) != cur_.end(); }

std::vector<State> successors(const TransitionSystem& system, const std::vector<State>& set, Symbol y) {
  std::vector<State> out;
  for (State s : set)
    for (const Transition& t : system.out(s, y)) out.push_back(t.to);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace preimage::filter
