// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/pursuit/paths_input.hpp>
#include <preimage/scene/scene.hpp>

namespace preimage::pursuit {

using nlohmann::json;

Paths PathsInput::rounded() const { return to_double(exact); }

PathsInput parse_paths(const std::string& text, const std::string& source) {
  json j = scene::parse_json(text, source);
  std::string where = "$";
  if (j.is_object()) {
    if (j.contains("plan") && j["plan"].is_object()) j = json(j["plan"]), where += ".plan";
    const char* key = j.contains("paths") ? "paths" : "pursuers";
    if (!j.contains(key)) throw InputError(source + ": " + where + ": expected \"paths\" (one polyline per pursuer)");
    j = json(j[key]);
    where += std::string(".") + key;
  }
  if (!j.is_array() || j.empty()) throw InputError(source + ": " + where + ": expected a non-empty array of points or of polylines");
  auto is_coordinate = [](const json& c) { return c.is_number() || c.is_string(); };
  const bool one = j[0].is_array() && !j[0].empty() && is_coordinate(j[0][0]);
  PathsInput paths;
  auto coordinate = [&](const json& c, const std::string& at) -> geometry::ExactFT {
    if (c.is_number()) {
      const double v = c.get<double>();
      if (auto why = geometry::coordinate_problem(v); !why.empty()) throw InputError(source + ": " + at + ": " + why);
      return v;
    }
    const std::string t = c.get<std::string>();
    const auto v = geometry::parse_exact_number(t);
    if (!v) throw InputError(source + ": " + at + ": expected a number or a rational string \"p/q\", got " + json(t).dump());
    // The range of doubles (docs/scene-format.md, "Numbers"), compared exactly.
    if (CGAL::abs(*v) > geometry::ExactFT(geometry::kMaxCoordinate))
      throw InputError(source + ": " + at + ": coordinate " + t + " is outside the supported range [-1e12, 1e12]");
    paths.exact_strings = true;
    return *v;
  };
  auto point = [&](const json& p, const std::string& at) {
    if (!p.is_array() || p.size() != 2 || !is_coordinate(p[0]) || !is_coordinate(p[1]))
      throw InputError(source + ": " + at + ": expected [x, y] with finite numbers or rational strings");
    return geometry::ExactPoint(coordinate(p[0], at + "[0]"), coordinate(p[1], at + "[1]"));
  };
  auto polyline = [&](const json& arr, const std::string& at) {
    if (!arr.is_array() || arr.empty()) throw InputError(source + ": " + at + ": expected a non-empty array of [x, y] points");
    std::vector<geometry::ExactPoint> pts;
    for (std::size_t i = 0; i < arr.size(); ++i) pts.push_back(point(arr[i], at + "[" + std::to_string(i) + "]"));
    return pts;
  };
  if (one) {
    paths.exact.push_back(polyline(j, where));
  } else {
    for (std::size_t k = 0; k < j.size(); ++k) paths.exact.push_back(polyline(j[k], where + "[" + std::to_string(k) + "]"));
  }
  return paths;
}

CheckResult check_paths(const geometry::Environment& env, const PathsInput& paths, const CheckOptions& options) {
  return paths.exact_strings ? check_exact_paths(env, paths.exact, options) : check_paths(env, paths.rounded(), options);
}

}  // namespace preimage::pursuit
