// SPDX-License-Identifier: Apache-2.0
#include <preimage/filter/product_filter.hpp>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace preimage::filter {

ProductFilter::ProductFilter(const TransitionSystem& system, std::size_t bodies, bool distinguishable,
                             const std::vector<Assignment>& initial)
    : sys_(&system), n_(bodies), distinguishable_(distinguishable) {
  if (bodies == 0) throw std::invalid_argument("ProductFilter: at least one body");
  std::vector<State> all;
  if (initial.empty()) {
    all.resize(system.num_states());
    std::iota(all.begin(), all.end(), State{0});
  }
  for (const Assignment& a : initial.empty() ? all_assignments(all, n_) : initial) {
    if (a.size() != n_) throw std::invalid_argument("ProductFilter: assignment of the wrong size");
    flat_.insert(flat_.end(), a.begin(), a.end());
  }
  normalise(flat_);
}

std::vector<ProductFilter::Assignment> ProductFilter::all_assignments(const std::vector<State>& states, std::size_t n) {
  // Mixed-radix counting over indices into `states`.
  std::vector<Assignment> out;
  std::vector<std::size_t> idx(n, 0);
  for (bool more = !states.empty(); more;) {
    Assignment t;
    for (auto i : idx) t.push_back(states[i]);
    out.push_back(std::move(t));
    std::size_t i = 0;
    while (i < n && ++idx[i] == states.size()) idx[i++] = 0;
    more = i < n;
  }
  return out;
}

void ProductFilter::normalise(std::vector<State>& flat) const {
  const std::size_t k = flat.size() / n_;
  if (!distinguishable_)
    for (std::size_t i = 0; i < k; ++i) std::sort(flat.begin() + i * n_, flat.begin() + (i + 1) * n_);
  std::vector<std::size_t> idx(k);
  std::iota(idx.begin(), idx.end(), 0);
  auto less = [&](std::size_t a, std::size_t b) {
    return std::lexicographical_compare(flat.begin() + a * n_, flat.begin() + (a + 1) * n_, flat.begin() + b * n_,
                                        flat.begin() + (b + 1) * n_);
  };
  auto equal = [&](std::size_t a, std::size_t b) {
    return std::equal(flat.begin() + a * n_, flat.begin() + (a + 1) * n_, flat.begin() + b * n_);
  };
  std::sort(idx.begin(), idx.end(), less);
  std::vector<State> out;
  out.reserve(flat.size());
  for (std::size_t j = 0; j < k; ++j)
    if (j == 0 || !equal(idx[j], idx[j - 1])) out.insert(out.end(), flat.begin() + idx[j] * n_, flat.begin() + (idx[j] + 1) * n_);
  flat.swap(out);
}

bool ProductFilter::step(Symbol y) {
  // One body, any of them, takes a transition labelled y; the others stay (4.2).
  std::vector<State> next;
  const std::size_t k = size();
  for (std::size_t a = 0; a < k; ++a) {
    const State* t = flat_.data() + a * n_;
    for (std::size_t b = 0; b < n_; ++b) {
      if (!distinguishable_ && b > 0 && t[b] == t[b - 1]) continue;  // same multiset move
      for (const Transition& tr : sys_->out(t[b], y)) {
        const std::size_t at = next.size();
        next.insert(next.end(), t, t + n_);
        next[at + b] = tr.to;
      }
    }
  }
  normalise(next);
  flat_.swap(next);
  return !flat_.empty();
}

std::vector<ProductFilter::Assignment> ProductFilter::assignments() const {
  std::vector<Assignment> out;
  for (std::size_t a = 0; a < size(); ++a) out.emplace_back(flat_.begin() + a * n_, flat_.begin() + (a + 1) * n_);
  return out;
}

std::vector<ProductFilter::Assignment> ProductFilter::multisets() const {
  std::vector<Assignment> out = assignments();
  for (auto& a : out) std::sort(a.begin(), a.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace preimage::filter
