// SPDX-License-Identifier: Apache-2.0
// Beam labels and sensor words (beams paper, section 2). Label l gives observation
// symbols 2l (crossing in the positive direction, written "l", or any crossing of an
// undirected beam) and 2l+1 (negative direction, written "l'").
//
// Words are read as whitespace-separated tokens. A token is a label, optionally
// followed by ', or — the one-character ASCII stream of the paper's beam hardware
// (7.1) — a run of one-character labels such as "cbabdeeefe" or "aba'bb'".
#pragma once
#include <preimage/filter/transition_system.hpp>

#include <istream>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace preimage::beams {

using filter::Symbol;

class Alphabet {
 public:
  /// Adds a label (or returns the existing one). Directedness must agree across beams
  /// sharing a label; returns false if it does not.
  bool add(const std::string& label, bool directed, std::uint32_t* id);

  std::size_t num_labels() const { return names_.size(); }
  std::size_t num_symbols() const { return 2 * names_.size(); }
  const std::string& name(std::uint32_t label) const { return names_[label]; }
  bool directed(std::uint32_t label) const { return directed_[label]; }
  std::optional<std::uint32_t> find(const std::string& label) const;

  static Symbol positive(std::uint32_t label) { return 2 * label; }
  static Symbol negative(std::uint32_t label) { return 2 * label + 1; }
  static std::uint32_t label_of(Symbol y) { return y / 2; }
  /// "a" or "a'".
  std::string format(Symbol y) const;
  std::string format(std::span<const Symbol> word, const char* sep = " ") const;

  /// Parses one token. Throws InputError "token N 'tok' at offset K: ..." naming the
  /// unknown label or the negated undirected one.
  std::vector<Symbol> parse_token(const std::string& token, std::size_t token_number, std::size_t offset) const;
  /// Parses a whole word (command line or file contents).
  std::vector<Symbol> parse_word(const std::string& text) const;

 private:
  std::vector<std::string> names_;
  std::vector<bool> directed_;
  std::unordered_map<std::string, std::uint32_t> index_;
  bool all_single_char_ = true;
};

/// Streams observations from an istream token by token, so a filter can run on an
/// unbounded sensor feed. Throws InputError on a bad token; everything before it has
/// already been delivered.
class WordReader {
 public:
  WordReader(const Alphabet& alphabet, std::istream& in) : alpha_(&alphabet), in_(&in) {}
  WordReader(Alphabet&&, std::istream&) = delete;  // keeps a pointer to the alphabet
  /// Next observation, or false at end of stream.
  bool next(Symbol& y, std::string* token = nullptr);
  std::size_t observations() const { return count_; }

 private:
  const Alphabet* alpha_;
  std::istream* in_;
  std::vector<Symbol> pending_;
  std::size_t pending_pos_ = 0;
  std::string token_;
  std::size_t tokens_ = 0, offset_ = 0, count_ = 0;
};

}  // namespace preimage::beams
