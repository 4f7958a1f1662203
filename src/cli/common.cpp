// SPDX-License-Identifier: Apache-2.0
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/scene/scene.hpp>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace preimage::cli {

geometry::Point parse_point(const std::string& text, const std::string& flag) {
  auto bad = [&] { return InputError(flag + ": expected X,Y (two numbers separated by a comma), got '" + text + "'"); };
  const auto comma = text.find(',');
  if (comma == std::string::npos) throw bad();
  auto num = [&](const std::string& s) {
    std::size_t used = 0;
    double v;
    try {
      v = std::stod(s, &used);
    } catch (const std::exception&) {
      throw bad();
    }
    while (used < s.size() && std::isspace(static_cast<unsigned char>(s[used]))) ++used;
    if (used != s.size() || !std::isfinite(v)) throw bad();
    return v;
  };
  return geometry::Point(num(text.substr(0, comma)), num(text.substr(comma + 1)));
}

void make_dirs(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir + ": cannot create directory (" + ec.message() + ")");
}

nlohmann::json edge_json(const geometry::Environment& env, std::size_t e) {
  return {{"ring", env.ring_name(env.ring_of(e))}, {"index", env.input_edge_index(e)}};
}

nlohmann::json points_json(const std::vector<geometry::Point>& pts) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : pts) out.push_back({p.x(), p.y()});
  return out;
}

CLI::Validator integer_in(std::int64_t lo, std::int64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const std::string range = "expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
        std::int64_t v = 0;
        const char* first = text.data();
        const char* last = text.data() + text.size();
        if (first != last && *first == '+') ++first;
        const auto [ptr, ec] = std::from_chars(first, last, v);
        if (ec == std::errc::result_out_of_range) return range + ", got '" + text + "' (out of range)";
        if (ec != std::errc() || ptr != last || first == last) return range + ", got '" + text + "'";
        if (v < lo || v > hi) return range + ", got " + text;
        return {};
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

CLI::Validator number_in(double lo, double hi, bool lo_open, bool hi_open) {
  auto fmt = [](double v) {
    std::ostringstream ss;
    ss << v;
    return ss.str();
  };
  const std::string range = std::string(lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + (hi_open ? ")" : "]");
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        std::size_t used = 0;
        double v = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(v)) return "expected a number in " + range + ", got '" + text + "'";
        if (v < lo || v > hi || (lo_open && v == lo) || (hi_open && v == hi)) return "expected a number in " + range + ", got " + text;
        return {};
      },
      "NUMBER in " + range);
}

std::string count_of(std::size_t n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural.empty() ? singular + "s" : plural);
}

namespace {
scene::JsonLayout json_layout = scene::JsonLayout::Compact;
}

void set_examples(CLI::App* cmd, const std::vector<std::string>& lines) {
  std::string text = "Examples:\n";
  for (const auto& line : lines) text += "  " + line + "\n";
  cmd->footer(text);
}

CLI::Option* add_json_flag(CLI::App* cmd, bool& json, const std::string& help) {
  CLI::Option* option = cmd->add_flag("--json", json, help);
  cmd->add_flag_callback(
      "--pretty",
      [&json] {
        json = true;
        json_layout = scene::JsonLayout::Pretty;
      },
      "JSON indented for reading, short arrays on one line (implies --json)");
  return option;
}

// File names (and other command-line text) need not be UTF-8: stray bytes print as U+FFFD.
void print_json(const nlohmann::json& j) { std::cout << scene::format_json(j, json_layout) << "\n"; }

std::string tuple_string(std::span<const std::int64_t> v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) s.append(i ? ", " : "").append(std::to_string(v[i]));
  return s + ")";
}

nlohmann::json point_json(const geometry::ExactPoint& p) {
  const geometry::Point q = geometry::to_double(p);
  return nlohmann::json::array({q.x(), q.y()});
}

}  // namespace preimage::cli
