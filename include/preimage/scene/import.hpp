// SPDX-License-Identifier: Apache-2.0
// Importers so floor plans people already have run through every command.
#pragma once
#include <preimage/scene/scene.hpp>

namespace preimage::scene {

/// HouseExpo floor plan JSON: {"verts": [[x, y], ...], "id": ..., "room_category": ...}.
/// The outer contour becomes the boundary; errors name "$.verts".
Scene import_houseexpo(const std::string& text, const std::string& source = "<houseexpo>");

/// VisiLibity environment file: "x y" lines, polygons separated by comment lines
/// starting with "//"; the first polygon is the outer boundary, the others holes.
/// Errors name the line: "room.txt:7: expected 'x y', got 'abc'".
Scene import_visilibity(const std::string& text, const std::string& source = "<visilibity>");

}  // namespace preimage::scene
