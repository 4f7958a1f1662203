// SPDX-License-Identifier: Apache-2.0
#include <preimage/beams/alphabet.hpp>
#include <preimage/error.hpp>

#include <cctype>
#include <sstream>

namespace preimage::beams {

bool Alphabet::add(const std::string& label, bool directed, std::uint32_t* id) {
  auto [it, fresh] = index_.try_emplace(label, static_cast<std::uint32_t>(names_.size()));
  if (fresh) {
    names_.push_back(label);
    directed_.push_back(directed);
    if (label.size() != 1) all_single_char_ = false;
  }
  *id = it->second;
  return directed_[it->second] == directed;
}

std::optional<std::uint32_t> Alphabet::find(const std::string& label) const {
  auto it = index_.find(label);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

std::string Alphabet::format(Symbol y) const { return names_[label_of(y)] + ((y & 1) ? "'" : ""); }

std::string Alphabet::format(std::span<const Symbol> word, const char* sep) const {
  std::string out;
  for (std::size_t i = 0; i < word.size(); ++i) out += (i ? sep : "") + format(word[i]);
  return out;
}

std::vector<Symbol> Alphabet::parse_token(const std::string& tok, std::size_t number, std::size_t offset) const {
  auto where = [&] { return "token " + std::to_string(number) + " '" + tok + "' at offset " + std::to_string(offset); };
  auto symbol = [&](const std::string& label, bool neg, std::size_t at) -> Symbol {
    auto id = find(label);
    if (!id)
      throw InputError(where() + ": unknown beam label '" + label + "'" +
                       (at ? " (character " + std::to_string(at + 1) + ")" : ""));
    if (neg && !directed_[*id])
      throw InputError(where() + ": beam label '" + label + "' is undirected, so " + label + "' cannot be observed");
    return neg ? negative(*id) : positive(*id);
  };
  // A whole label (with an optional prime) first: multi-character labels win.
  const bool primed = tok.size() > 1 && tok.back() == '\'';
  const std::string base = primed ? tok.substr(0, tok.size() - 1) : tok;
  if (find(base) || !all_single_char_) return {symbol(base, primed, 0)};
  // The one-character stream: each character a label, each optionally primed.
  std::vector<Symbol> out;
  for (std::size_t i = 0; i < tok.size(); ++i) {
    if (tok[i] == '\'') throw InputError(where() + ": a prime must follow a label (character " + std::to_string(i + 1) + ")");
    const bool neg = i + 1 < tok.size() && tok[i + 1] == '\'';
    out.push_back(symbol(std::string(1, tok[i]), neg, i));
    if (neg) ++i;
  }
  return out;
}

std::vector<Symbol> Alphabet::parse_word(const std::string& text) const {
  std::istringstream in(text);
  WordReader r(*this, in);
  std::vector<Symbol> word;
  Symbol y;
  while (r.next(y)) word.push_back(y);
  return word;
}

bool WordReader::next(Symbol& y, std::string* token) {
  while (pending_pos_ == pending_.size()) {
    // Read the next whitespace-separated token, tracking its offset in the stream.
    token_.clear();
    int c;
    while ((c = in_->get()) != EOF && std::isspace(c)) ++offset_;
    if (c == EOF) return false;
    const std::size_t start = offset_;
    do {
      token_.push_back(static_cast<char>(c));
      ++offset_;
    } while ((c = in_->get()) != EOF && !std::isspace(c));
    if (c != EOF) ++offset_;
    pending_ = alpha_->parse_token(token_, ++tokens_, start);
    pending_pos_ = 0;
  }
  y = pending_[pending_pos_++];
  if (token) *token = alpha_->format(y);
  ++count_;
  return true;
}

}  // namespace preimage::beams
