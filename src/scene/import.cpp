// SPDX-License-Identifier: Apache-2.0
#include <preimage/scene/import.hpp>

#include <preimage/geometry/hole_union.hpp>

#include <preimage/error.hpp>

#include <cmath>
#include <sstream>

namespace preimage::scene {

Scene import_houseexpo(const std::string& text, const std::string& source) {
  nlohmann::json doc = parse_json(text, source);
  if (!doc.is_object() || !doc.contains("verts")) throw InputError(source + ": $: not a HouseExpo plan (no \"verts\")");
  const auto& verts = doc["verts"];
  if (!verts.is_array()) throw InputError(source + ": $.verts: expected an array of [x, y]");
  geometry::Ring outer;
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const auto& v = verts[i];
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
      throw InputError(source + ": $.verts[" + std::to_string(i) + "]: expected [x, y] with two numbers");
    outer.emplace_back(v[0].get<double>(), v[1].get<double>());
  }
  // Some exports repeat the first vertex at the end to close the contour.
  if (outer.size() > 1 && outer.front() == outer.back()) outer.pop_back();
  Scene s;
  s.source = source;
  s.name = doc.contains("id") && doc["id"].is_string() ? doc["id"].get<std::string>() : source;
  s.description = "HouseExpo floor plan";
  if (doc.contains("room_category") && doc["room_category"].is_object()) {
    std::string rooms;
    for (auto it = doc["room_category"].begin(); it != doc["room_category"].end(); ++it)
      rooms += (rooms.empty() ? "" : ", ") + it.key();
    if (!rooms.empty()) s.description += " (" + rooms + ")";
  }
  try {
    s.environment = geometry::Environment::make(std::move(outer), {}, "$.verts", "holes");
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
  return s;
}

void apply_import_options(std::vector<geometry::Ring>& holes, const ImportOptions& options) {
  if (options.merge_holes) holes = geometry::merge_overlapping_holes(holes).holes;
}

Scene import_visilibity(const std::string& text, const std::string& source, const ImportOptions& options) {
  std::vector<geometry::Ring> rings;
  std::vector<std::size_t> first_line;
  bool need_new = true;
  std::istringstream in(text);
  std::string line;
  std::size_t lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;          // blank line
    if (line.compare(first, 2, "//") == 0) {           // comment: ends the current polygon
      need_new = true;
      continue;
    }
    std::istringstream ls(line);
    double x, y;
    std::string rest;
    if (!(ls >> x >> y) || (ls >> rest) || !std::isfinite(x) || !std::isfinite(y))
      throw InputError(source + ":" + std::to_string(lineno) + ": expected 'x y', got '" + line.substr(first) + "'");
    if (need_new) rings.emplace_back(), first_line.push_back(lineno), need_new = false;
    rings.back().emplace_back(x, y);
  }
  if (rings.empty()) throw InputError(source + ": no polygon found (expected 'x y' lines)");
  Scene s;
  s.source = source;
  s.name = source;
  s.description = "VisiLibity environment";
  geometry::Ring outer = std::move(rings[0]);
  rings.erase(rings.begin());
  try {
    if (options.merge_holes) first_line.resize(1);  // merged holes no longer match the file's polygons
    apply_import_options(rings, options);
    s.environment = geometry::Environment::make(std::move(outer), std::move(rings), "outer boundary (line " +
                                                std::to_string(first_line[0]) + ")", "holes");
  } catch (const InputError& e) {
    // Point the reader at the file line where the named hole starts.
    std::string msg = e.what();
    auto at = msg.find("holes[");
    if (at != std::string::npos) {
      const std::size_t k = std::stoul(msg.substr(at + 6));
      if (k + 1 < first_line.size()) msg += " (holes[" + std::to_string(k) + "] starts at line " + std::to_string(first_line[k + 1]) + ")";
    }
    throw InputError(source + ": " + msg);
  }
  return s;
}

Scene import_houseexpo(const std::string& path) { return import_houseexpo(read_file(path), path); }

Scene import_visilibity(const std::string& path, const ImportOptions& options) {
  return import_visilibity(read_file(path), path, options);
}

}  // namespace preimage::scene
