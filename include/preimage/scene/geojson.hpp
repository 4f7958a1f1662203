// SPDX-License-Identifier: Apache-2.0
// Results as GeoJSON (RFC 7946) features, so QGIS and Shapely users can open them.
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/scene/scene.hpp>

#include <string>
#include <vector>

namespace preimage::scene {

/// A FeatureCollection built feature by feature; rings are written closed, coordinates
/// in the scene's units (no CRS: preimage's plane is not the Earth).
class GeoJsonWriter {
 public:
  GeoJsonWriter& polygon(const std::vector<std::vector<geometry::Point>>& rings, nlohmann::json properties = nlohmann::json::object());
  GeoJsonWriter& environment(const geometry::Environment& env, nlohmann::json properties = nlohmann::json::object());
  GeoJsonWriter& line(const std::vector<geometry::Point>& pts, nlohmann::json properties = nlohmann::json::object());
  GeoJsonWriter& point(const geometry::Point& p, nlohmann::json properties = nlohmann::json::object());
  nlohmann::json json() const;
  /// Compact JSON; InputError "<path>: cannot write file".
  void save(const std::string& path) const;

 private:
  nlohmann::json features_ = nlohmann::json::array();
};

}  // namespace preimage::scene
