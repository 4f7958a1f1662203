// SPDX-License-Identifier: Apache-2.0
#include "common.hpp"

#include <preimage/error.hpp>

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

std::string exact_string(const geometry::ExactFT& v) {
  std::ostringstream ss;
  ss << CGAL::exact(v);
  return ss.str();
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

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << "\n"; }

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
