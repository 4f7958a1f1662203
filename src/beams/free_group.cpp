// SPDX-License-Identifier: Apache-2.0
#include <preimage/beams/free_group.hpp>

#include <algorithm>
#include <stdexcept>

namespace preimage::beams {

FreeWord FreeWord::reduce(std::span<const Letter> letters) {
  FreeWord w;
  w.letters_.reserve(letters.size());
  for (Letter x : letters) {
    if (x == 0) throw std::invalid_argument("FreeWord: 0 is not a letter");
    w.push(x);
  }
  return w;
}

FreeWord& FreeWord::operator*=(const FreeWord& w) {
  // Both are reduced: only the junction can cancel.
  std::size_t k = 0;
  while (k < w.letters_.size() && !letters_.empty() && letters_.back() == -w.letters_[k]) letters_.pop_back(), ++k;
  letters_.insert(letters_.end(), w.letters_.begin() + static_cast<std::ptrdiff_t>(k), w.letters_.end());
  return *this;
}

FreeWord FreeWord::inverse() const {
  FreeWord w;
  w.letters_.assign(letters_.rbegin(), letters_.rend());
  for (Letter& x : w.letters_) x = -x;
  return w;
}

std::vector<std::int64_t> FreeWord::abelianised(std::size_t rank) const {
  std::vector<std::int64_t> v(rank, 0);
  for (Letter x : letters_) {
    const std::uint32_t g = generator_of(x);
    if (g >= rank) throw std::invalid_argument("FreeWord::abelianised: generator beyond the rank");
    v[g] += x > 0 ? 1 : -1;
  }
  return v;
}

std::string FreeWord::format(const std::vector<std::string>& names) const {
  if (letters_.empty()) return "1";
  std::string s;
  for (Letter x : letters_) {
    if (!s.empty()) s += ' ';
    const std::uint32_t g = generator_of(x);
    s += g < names.size() ? names[g] : std::string("s").append(std::to_string(g + 1));
    if (x < 0) s += '\'';
  }
  return s;
}

std::strong_ordering operator<=>(const FreeWord& a, const FreeWord& b) {
  if (a.letters_.size() != b.letters_.size()) return a.letters_.size() <=> b.letters_.size();
  return std::lexicographical_compare_three_way(a.letters_.begin(), a.letters_.end(), b.letters_.begin(), b.letters_.end());
}

CayleyTree::Node CayleyTree::times(Node w, Letter x) {
  if (w != kIdentity && last_[w] == -x) return parent_[w];
  const std::uint64_t key = (std::uint64_t(w) << 32) | std::uint32_t(x);
  auto [it, fresh] = child_.try_emplace(key, static_cast<Node>(parent_.size()));
  if (fresh) {
    if (parent_.size() == UINT32_MAX) throw std::length_error("CayleyTree: too many words");
    parent_.push_back(w);
    last_.push_back(x);
    depth_.push_back(depth_[w] + 1);
  }
  return it->second;
}

FreeWord CayleyTree::word(Node w) const {
  std::vector<Letter> back;
  for (; w != kIdentity; w = parent_[w]) back.push_back(last_[w]);
  std::reverse(back.begin(), back.end());
  return FreeWord::reduce(back);
}

}  // namespace preimage::beams
