// SPDX-License-Identifier: Apache-2.0
// The JSON scene format (docs/scene-format.md): an environment plus the slots the
// modules read (start/goal, robot size, landmarks, beams). Every error names its
// JSON path, e.g. "$.environment.obstacles[2][3]: expected [x, y] with finite numbers".
#pragma once
#include <preimage/geometry/environment.hpp>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace preimage::scene {

using geometry::Point;

/// A labelled point landmark (landmark module; also beams in the unbounded plane).
struct Landmark {
  std::string label;
  Point at;
};

/// A sensor beam with a label. Beams sharing a label are indistinguishable; a directed
/// beam reports which way it was crossed: positive when the body crosses from the right
/// of from->to to its left (counter-clockwise about `from`), negative (a') otherwise.
/// Shape: a segment from `from` to `to`; a ray from `from` through `to` (to the first
/// boundary contact, or unbounded in a scene of point landmarks); or the line through
/// both points (clipped to the free-space chord containing `from` in a bounded scene).
struct Beam {
  enum class Shape { Segment, Ray, Line };
  std::string label;
  Point from, to;
  bool directed = true;
  Shape shape = Shape::Segment;
};
const char* to_string(Beam::Shape s);

/// The tracking slot (escape-path tracking module): where the observer and the target
/// start, the target's radius and speed, and an optional scripted path for it.
struct TrackingSetup {
  std::optional<Point> observer, target;
  double heading = 0;          // observer heading, degrees
  double target_radius = 0.2;
  double target_speed = 0.5;   // m/s
  std::vector<Point> target_path;
};

struct Scene {
  std::string name;
  std::string description;
  std::optional<geometry::Environment> environment;
  std::optional<Point> start, goal;
  std::optional<double> robot_radius;
  std::vector<Landmark> landmarks;
  std::vector<Beam> beams;
  /// A user-chosen basis for homotopy classes (beams paper 5.3, step 4): disjoint
  /// directed beams with a spanning tree joining every obstacle to the outer boundary.
  std::vector<Beam> imaginary_beams;
  std::optional<TrackingSetup> tracking;

  /// The environment, or InputError("<source>: the scene has no environment").
  const geometry::Environment& require_environment() const;
  std::string source;  // file name, for messages
};

/// Parses scene JSON text. `source` (a file name) prefixes syntax errors as
/// "source:line:column: ...". Throws InputError.
Scene parse_scene(const std::string& text, const std::string& source = "<scene>");
/// Reads and parses a scene file. Throws InputError (also for unreadable files).
Scene load_scene(const std::string& path);

/// The scene as JSON in the same format (round-trips through parse_scene).
nlohmann::json to_json(const Scene& scene);
void save_scene(const Scene& scene, const std::string& path);

/// Reads a whole file, or throws InputError naming it.
std::string read_file(const std::string& path);

/// JSON text to a document. Throws InputError "source:line:column: JSON syntax error: ..."
/// or, for a number a double cannot hold, "source: $.verts[3][1]: number 1e400 is outside
/// the range of doubles". Every reader of JSON input goes through it.
nlohmann::json parse_json(const std::string& text, const std::string& source);

/// Document to JSON text. Compact: one line, no spaces (what the CLI prints by default).
/// Pretty: indented, but every value that fits in `width` columns stays on one line and
/// arrays of short items (numbers, points) fill their lines, so a floor plan reads as a
/// few lines per ring rather than one number per line (what scene files and --pretty use).
/// Text that is not UTF-8 (a name taken from a file name) prints as U+FFFD.
enum class JsonLayout { Compact, Pretty };
std::string format_json(const nlohmann::json& doc, JsonLayout layout, std::size_t width = 100);

}  // namespace preimage::scene
