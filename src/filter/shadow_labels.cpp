// SPDX-License-Identifier: Apache-2.0
#include <preimage/filter/shadow_labels.hpp>

#include <stdexcept>

namespace preimage::filter {

namespace {
std::size_t words_for(std::size_t n) { return (n + 63) / 64; }
}  // namespace

ShadowLabels::ShadowLabels(std::size_t n, bool contaminated) : n_(n), w_(words_for(n), contaminated ? ~std::uint64_t{0} : 0) {
  if (contaminated && n % 64) w_.back() = (std::uint64_t{1} << (n % 64)) - 1;  // unused bits stay 0
}

void ShadowLabels::set(std::size_t i, bool contaminated) {
  const std::uint64_t bit = std::uint64_t{1} << (i & 63);
  if (contaminated) w_[i >> 6] |= bit;
  else w_[i >> 6] &= ~bit;
}

std::size_t ShadowLabels::contaminated() const {
  std::size_t c = 0;
  for (auto w : w_) c += static_cast<std::size_t>(__builtin_popcountll(w));
  return c;
}

bool ShadowLabels::all_clear() const {
  for (auto w : w_)
    if (w) return false;
  return true;
}

std::string ShadowLabels::str() const {
  std::string s(n_, '0');
  for (std::size_t i = 0; i < n_; ++i)
    if ((*this)[i]) s[i] = '1';
  return s;
}

std::size_t ShadowLabels::hash() const {
  std::uint64_t h = 0x9e3779b97f4a7c15ull ^ n_;
  for (auto w : w_) h = (h ^ w) * 0x100000001b3ull, h ^= h >> 29;
  return static_cast<std::size_t>(h);
}

ShadowEvent ShadowEvent::identity(std::size_t n) {
  ShadowEvent e{n, n, {}};
  for (std::uint32_t i = 0; i < n; ++i) e.pairs.push_back({i, i});
  return e;
}

ShadowEvent ShadowEvent::appear(std::size_t n, std::size_t at) {
  ShadowEvent e{n, n + 1, {}};
  for (std::uint32_t i = 0; i < n; ++i) e.pairs.push_back({i, static_cast<std::uint32_t>(i < at ? i : i + 1)});
  return e;
}

ShadowEvent ShadowEvent::disappear(std::size_t n, std::size_t at) {
  ShadowEvent e{n, n - 1, {}};
  for (std::uint32_t i = 0; i < n; ++i)
    if (i != at) e.pairs.push_back({i, static_cast<std::uint32_t>(i < at ? i : i - 1)});
  return e;
}

ShadowEvent ShadowEvent::split(std::size_t n, std::size_t at, std::size_t parts) {
  ShadowEvent e{n, n + parts - 1, {}};
  for (std::uint32_t i = 0; i < n; ++i) {
    if (i < at) e.pairs.push_back({i, i});
    else if (i > at) e.pairs.push_back({i, static_cast<std::uint32_t>(i + parts - 1)});
    else
      for (std::size_t k = 0; k < parts; ++k) e.pairs.push_back({i, static_cast<std::uint32_t>(at + k)});
  }
  return e;
}

ShadowEvent ShadowEvent::merge(std::size_t n, std::size_t at, std::size_t parts) {
  ShadowEvent e{n, n - parts + 1, {}};
  for (std::uint32_t i = 0; i < n; ++i) {
    std::size_t to = i < at ? i : i < at + parts ? at : i - parts + 1;
    e.pairs.push_back({i, static_cast<std::uint32_t>(to)});
  }
  return e;
}

ShadowTransition::ShadowTransition(const ShadowEvent& e)
    : before_(e.before), after_(e.after), words_(words_for(e.before)), mask_(e.after * words_for(e.before), 0) {
  for (auto [o, n] : e.pairs) {
    if (o >= before_ || n >= after_)
      throw std::invalid_argument("shadow event: pair (" + std::to_string(o) + ", " + std::to_string(n) + ") out of range");
    mask_[n * words_ + (o >> 6)] |= std::uint64_t{1} << (o & 63);
  }
}

ShadowLabels ShadowTransition::apply(const ShadowLabels& labels) const {
  if (labels.size() != before_)
    throw std::invalid_argument("shadow event: " + std::to_string(labels.size()) + " labels for " +
                                std::to_string(before_) + " components");
  ShadowLabels out(after_, false);
  const auto& w = labels.words();
  for (std::size_t j = 0; j < after_; ++j) {
    const std::uint64_t* m = mask_.data() + j * words_;
    for (std::size_t k = 0; k < words_; ++k)
      if (m[k] & w[k]) {
        out.set(j, true);
        break;
      }
  }
  return out;
}

}  // namespace preimage::filter
