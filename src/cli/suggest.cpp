// SPDX-License-Identifier: Apache-2.0
#include "suggest.hpp"

#include <algorithm>
#include <vector>

namespace preimage::cli {

namespace {

// Edit distance with transpositions (optimal string alignment): "visiblity" is one edit
// from "visibility", "pursiut" one from "pursuit".
std::size_t distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

}  // namespace

std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv) {
  const CLI::App* at = &app;
  std::string path = "preimage";
  for (int i = 1; i < argc; ++i) {
    // (Option groups are unnamed subcommands in CLI11: not commands.)
    const auto subs = at->get_subcommands([](const CLI::App* s) { return !s->get_name().empty(); });
    if (subs.empty()) return std::nullopt;
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') return std::nullopt;  // an option: CLI11 decides
    const CLI::App* next = nullptr;
    for (const CLI::App* s : subs)
      if (s->get_name() == word) next = s;
    if (next) {
      at = next, path += " " + word;
      continue;
    }
    std::vector<std::pair<std::size_t, std::string>> near;
    for (const CLI::App* s : subs) {
      const std::string& name = s->get_name();
      const std::size_t d = distance(word, name);
      // Close: a few edits for its length, or one is a prefix of the other.
      if (d <= std::max<std::size_t>(1, name.size() / 3) || (word.size() >= 3 && name.rfind(word, 0) == 0)) near.emplace_back(d, name);
    }
    std::sort(near.begin(), near.end());
    std::string msg = "unknown command '" + word + "' for '" + path + "'";
    if (!near.empty()) {
      msg += "; did you mean '" + near[0].second + "'";
      for (std::size_t k = 1; k < near.size() && k < 3; ++k) msg += " or '" + near[k].second + "'";
      msg += "?";
    } else {
      msg += "; commands:";
      for (std::size_t k = 0; k < subs.size(); ++k) msg += (k ? ", " : " ") + subs[k]->get_name();
    }
    return msg;
  }
  return std::nullopt;
}

}  // namespace preimage::cli
