// SPDX-License-Identifier: Apache-2.0
// Importers so floor plans people already have run through every command.
#pragma once
#include <preimage/scene/scene.hpp>

namespace preimage::scene {

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
Scene import_visilibity(const std::string& path);
Scene import_visilibity(const std::string& text, const std::string& source);

}  // namespace preimage::scene
