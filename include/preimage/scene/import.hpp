// SPDX-License-Identifier: Apache-2.0
// Importers so floor plans people already have run through every command.
#pragma once
#include <preimage/scene/scene.hpp>

namespace preimage::scene {

/// What an importer may change in the input, on request only.
struct ImportOptions {
  /// Replace holes that overlap (share an edge, cross, nest) by their union
  /// (geometry::merge_overlapping_holes: Clipper on a stated power-of-two grid). Holes
  /// touching only at a vertex need nothing: they are contacts.
  bool merge_holes = false;
};
/// Applies `options` to the holes an importer read (the importers call it).
void apply_import_options(std::vector<geometry::Ring>& holes, const ImportOptions& options);

// Each importer has two forms, told apart by their number of arguments: one argument is a
// file to read (InputError "<path>: cannot open file" if it cannot be read); two are the
// file's text and a name for messages, e.g. import_houseexpo(read_file(p), p).

/// HouseExpo floor plan JSON: {"verts": [[x, y], ...], "id": ..., "room_category": ...}.
/// The outer contour becomes the boundary; errors name the JSON path ("$.verts[3]").
Scene import_houseexpo(const std::string& path);
Scene import_houseexpo(const std::string& text, const std::string& source);

/// VisiLibity environment file: "x y" lines, polygons separated by comment lines
/// starting with "//"; the first polygon is the outer boundary, the others holes.
/// Errors name the line: "room.txt:7: expected 'x y', got 'abc'".
Scene import_visilibity(const std::string& path, const ImportOptions& options = {});
Scene import_visilibity(const std::string& text, const std::string& source, const ImportOptions& options = {});

/// GeoJSON (RFC 7946) with one polygon: a Polygon, a MultiPolygon of one polygon, or a
/// Feature / FeatureCollection holding exactly one of those. The first ring is the
/// boundary, the others holes; rings must be closed as GeoJSON requires (the closing
/// position is dropped); a third coordinate (altitude) is ignored. Errors name the JSON
/// path: "plan.geojson: $.features[0].geometry.coordinates[1]: ...".
Scene import_geojson(const std::string& path, const ImportOptions& options = {});
Scene import_geojson(const std::string& text, const std::string& source, const ImportOptions& options = {});

/// WKT `POLYGON ((x y, ...), (x y, ...))` or a `MULTIPOLYGON` of one polygon (Z/M
/// coordinates are refused); rings closed or not. Errors name the character:
/// "room.wkt: character 17: expected a number, got 'a'".
Scene import_wkt(const std::string& path, const ImportOptions& options = {});
Scene import_wkt(const std::string& text, const std::string& source, const ImportOptions& options = {});

}  // namespace preimage::scene
