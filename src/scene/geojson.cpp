// SPDX-License-Identifier: Apache-2.0
// GeoJSON in (one polygon with holes) and out (features for QGIS and Shapely users).
#include <preimage/error.hpp>
#include <preimage/scene/geojson.hpp>
#include <preimage/scene/import.hpp>

#include <fstream>

namespace preimage::scene {

namespace {
using nlohmann::json;

[[noreturn]] void geojson_fail(const std::string& source, const std::string& path, const std::string& what) {
  throw InputError(source + ": " + path + ": " + what);
}

// A GeoJSON linear ring: at least four positions, the last equal to the first.
geometry::Ring geojson_ring(const json& j, const std::string& source, const std::string& path) {
  if (!j.is_array()) geojson_fail(source, path, "expected an array of positions, got " + std::string(j.type_name()));
  geometry::Ring r;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const auto& p = j[i];
    const std::string at = path + "[" + std::to_string(i) + "]";
    if (!p.is_array() || p.size() < 2 || p.size() > 3)
      geojson_fail(source, at, "expected a position [x, y] or [x, y, z]");
    for (std::size_t k = 0; k < p.size(); ++k)
      if (!p[k].is_number()) geojson_fail(source, at + "[" + std::to_string(k) + "]", "expected a number, got " + std::string(p[k].type_name()));
    r.emplace_back(p[0].get<double>(), p[1].get<double>());
  }
  if (r.size() < 4) geojson_fail(source, path, "a ring needs at least 4 positions (GeoJSON closes it), got " + std::to_string(r.size()));
  if (r.front() != r.back()) geojson_fail(source, path, "the ring is not closed (its last position must equal the first, RFC 7946 3.1.6)");
  r.pop_back();
  return r;
}

// The polygon's coordinates member: [outer, hole, ...].
Scene polygon_scene(const json& coords, const std::string& source, const std::string& path, const ImportOptions& options) {
  if (!coords.is_array() || coords.empty()) geojson_fail(source, path, "expected an array of rings (boundary first)");
  geometry::Ring outer = geojson_ring(coords[0], source, path + "[0]");
  std::vector<geometry::Ring> holes;
  for (std::size_t i = 1; i < coords.size(); ++i) holes.push_back(geojson_ring(coords[i], source, path + "[" + std::to_string(i) + "]"));
  Scene s;
  s.source = source;
  s.name = source;
  s.description = "GeoJSON polygon";
  try {
    apply_import_options(holes, options);
    s.environment = geometry::Environment::make(std::move(outer), std::move(holes), path + "[0]", path + "[1+]");
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
  return s;
}

Scene geometry_scene(const json& g, const std::string& source, const std::string& path, const ImportOptions& options) {
  if (!g.is_object() || !g.contains("type") || !g["type"].is_string()) geojson_fail(source, path, "expected a GeoJSON object with a \"type\"");
  const std::string type = g["type"].get<std::string>();
  if (type == "Feature") {
    if (!g.contains("geometry") || g["geometry"].is_null()) geojson_fail(source, path + ".geometry", "the feature has no geometry");
    Scene s = geometry_scene(g["geometry"], source, path + ".geometry", options);
    if (g.contains("properties") && g["properties"].is_object() && g["properties"].contains("name") && g["properties"]["name"].is_string())
      s.name = g["properties"]["name"].get<std::string>();
    return s;
  }
  if (type == "FeatureCollection") {
    if (!g.contains("features") || !g["features"].is_array()) geojson_fail(source, path + ".features", "expected an array of features");
    if (g["features"].size() != 1)
      geojson_fail(source, path + ".features", "expected exactly one feature (one floor plan), got " + std::to_string(g["features"].size()));
    return geometry_scene(g["features"][0], source, path + ".features[0]", options);
  }
  if (!g.contains("coordinates")) geojson_fail(source, path + ".coordinates", "missing");
  if (type == "Polygon") return polygon_scene(g["coordinates"], source, path + ".coordinates", options);
  if (type == "MultiPolygon") {
    const auto& c = g["coordinates"];
    if (!c.is_array() || c.size() != 1)
      geojson_fail(source, path + ".coordinates", "expected a MultiPolygon of exactly one polygon, got " +
                                                      (c.is_array() ? std::to_string(c.size()) : std::string(c.type_name())));
    return polygon_scene(c[0], source, path + ".coordinates[0]", options);
  }
  geojson_fail(source, path + ".type", "expected Polygon, MultiPolygon, Feature or FeatureCollection, got \"" + type + "\"");
}

json ring_json(const std::vector<geometry::Point>& ring) {
  json r = json::array();
  for (const auto& p : ring) r.push_back({p.x(), p.y()});
  if (!ring.empty()) r.push_back({ring.front().x(), ring.front().y()});  // GeoJSON rings are closed
  return r;
}
}  // namespace

Scene import_geojson(const std::string& text, const std::string& source, const ImportOptions& options) {
  return geometry_scene(parse_json(text, source), source, "$", options);
}

Scene import_geojson(const std::string& path, const ImportOptions& options) { return import_geojson(read_file(path), path, options); }

GeoJsonWriter& GeoJsonWriter::polygon(const std::vector<std::vector<geometry::Point>>& rings, nlohmann::json properties) {
  nlohmann::json coords = nlohmann::json::array();
  for (const auto& r : rings) coords.push_back(ring_json(r));
  features_.push_back({{"type", "Feature"}, {"properties", std::move(properties)}, {"geometry", {{"type", "Polygon"}, {"coordinates", coords}}}});
  return *this;
}

GeoJsonWriter& GeoJsonWriter::environment(const geometry::Environment& env, nlohmann::json properties) {
  std::vector<std::vector<geometry::Point>> rings;
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    std::vector<geometry::Point> ring;
    for (std::size_t v = env.ring_begin(r); v < env.ring_end(r); ++v) ring.push_back(env.vertex(v));
    rings.push_back(std::move(ring));
  }
  return polygon(rings, std::move(properties));
}

GeoJsonWriter& GeoJsonWriter::line(const std::vector<geometry::Point>& pts, nlohmann::json properties) {
  nlohmann::json coords = nlohmann::json::array();
  for (const auto& p : pts) coords.push_back({p.x(), p.y()});
  features_.push_back({{"type", "Feature"}, {"properties", std::move(properties)}, {"geometry", {{"type", "LineString"}, {"coordinates", coords}}}});
  return *this;
}

GeoJsonWriter& GeoJsonWriter::point(const geometry::Point& p, nlohmann::json properties) {
  features_.push_back({{"type", "Feature"}, {"properties", std::move(properties)},
                       {"geometry", {{"type", "Point"}, {"coordinates", {p.x(), p.y()}}}}});
  return *this;
}

nlohmann::json GeoJsonWriter::json() const { return {{"type", "FeatureCollection"}, {"features", features_}}; }

void GeoJsonWriter::save(const std::string& path) const {
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot write file");
  out << format_json(json(), JsonLayout::Compact) << "\n";
  if (!out) throw InputError(path + ": write error");
}

}  // namespace preimage::scene
