// SPDX-License-Identifier: Apache-2.0
#include <preimage/scene/scene.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace preimage::scene {

using nlohmann::json;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return ss.str();
}

const char* to_string(Beam::Shape s) {
  switch (s) {
    case Beam::Shape::Segment: return "segment";
    case Beam::Shape::Ray: return "ray";
    case Beam::Shape::Line: return "line";
  }
  return "?";
}

const geometry::Environment& Scene::require_environment() const {
  if (!environment) throw InputError((source.empty() ? "scene" : source) + ": the scene has no environment");
  return *environment;
}

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw InputError(path + ": " + what); }

std::string type_name(const json& j) { return j.type_name(); }

void allow_keys(const json& obj, const std::string& path, std::initializer_list<const char*> keys) {
  if (!obj.is_object()) fail(path, "expected an object, got " + type_name(obj));
  std::set<std::string> ok(keys.begin(), keys.end());
  for (auto it = obj.begin(); it != obj.end(); ++it)
    if (!ok.count(it.key())) {
      std::string list;
      for (auto* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(path + "." + it.key(), "unknown key (expected one of: " + list + ")");
    }
}

double number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, "expected a number, got " + type_name(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "number is not finite");
  return v;
}

double coordinate(const json& j, const std::string& path) {
  const double v = number(j, path);
  if (auto why = geometry::coordinate_problem(v); !why.empty()) fail(path, why);
  return v;
}

Point point(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 2) fail(path, "expected [x, y], got " + (j.is_array() ? "an array of " + std::to_string(j.size()) : type_name(j)));
  const double x = coordinate(j[0], path + "[0]");  // x first: the error names the first bad one
  const double y = coordinate(j[1], path + "[1]");
  return Point(x, y);
}

geometry::Ring ring(const json& j, const std::string& path) {
  if (!j.is_array()) fail(path, "expected an array of [x, y] vertices, got " + type_name(j));
  geometry::Ring r;
  for (std::size_t i = 0; i < j.size(); ++i) r.push_back(point(j[i], path + "[" + std::to_string(i) + "]"));
  // A closed ring (last vertex = first, as GeoJSON and Shapely write them) is the same ring.
  if (r.size() > 3 && r.front() == r.back()) r.pop_back();
  return r;
}

std::string string_at(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, "expected a string, got " + type_name(j));
  return j.get<std::string>();
}

json point_json(const Point& p) { return json::array({p.x(), p.y()}); }

}  // namespace

Scene parse_scene(const std::string& text, const std::string& source) {
  json doc = parse_json(text, source);
  Scene s;
  s.source = source;
  allow_keys(doc, "$", {"name", "description", "environment", "start", "goal", "robot", "landmarks", "beams", "imaginary_beams", "tracking"});
  if (doc.contains("name")) s.name = string_at(doc["name"], "$.name");
  if (doc.contains("description")) s.description = string_at(doc["description"], "$.description");
  if (doc.contains("environment")) {
    const json& e = doc["environment"];
    allow_keys(e, "$.environment", {"boundary", "obstacles"});
    if (!e.contains("boundary")) fail("$.environment", "missing key \"boundary\"");
    geometry::Ring outer = ring(e["boundary"], "$.environment.boundary");
    std::vector<geometry::Ring> holes;
    if (e.contains("obstacles")) {
      const json& obs = e["obstacles"];
      if (!obs.is_array()) fail("$.environment.obstacles", "expected an array of polygons, got " + type_name(obs));
      for (std::size_t i = 0; i < obs.size(); ++i) holes.push_back(ring(obs[i], "$.environment.obstacles[" + std::to_string(i) + "]"));
    }
    s.environment = geometry::Environment::make(std::move(outer), std::move(holes), "$.environment.boundary",
                                                "$.environment.obstacles");
  }
  if (doc.contains("start")) s.start = point(doc["start"], "$.start");
  if (doc.contains("goal")) s.goal = point(doc["goal"], "$.goal");
  if (doc.contains("robot")) {
    allow_keys(doc["robot"], "$.robot", {"radius"});
    if (doc["robot"].contains("radius")) {
      const double r = number(doc["robot"]["radius"], "$.robot.radius");
      if (r < 0) fail("$.robot.radius", "must not be negative");
      s.robot_radius = r;
    }
  }
  if (doc.contains("landmarks")) {
    const json& L = doc["landmarks"];
    if (!L.is_array()) fail("$.landmarks", "expected an array, got " + type_name(L));
    for (std::size_t i = 0; i < L.size(); ++i) {
      const std::string p = "$.landmarks[" + std::to_string(i) + "]";
      allow_keys(L[i], p, {"label", "at"});
      if (!L[i].contains("at")) fail(p, "missing key \"at\"");
      Landmark lm{L[i].contains("label") ? string_at(L[i]["label"], p + ".label") : std::to_string(i + 1),
                  point(L[i]["at"], p + ".at")};
      s.landmarks.push_back(std::move(lm));
    }
  }
  if (doc.contains("tracking")) {
    const json& T = doc["tracking"];
    allow_keys(T, "$.tracking", {"observer", "heading", "target", "target_radius", "target_speed", "target_path"});
    TrackingSetup t;
    if (T.contains("observer")) t.observer = point(T["observer"], "$.tracking.observer");
    if (T.contains("target")) t.target = point(T["target"], "$.tracking.target");
    if (T.contains("heading")) t.heading = number(T["heading"], "$.tracking.heading");
    if (T.contains("target_radius")) {
      t.target_radius = number(T["target_radius"], "$.tracking.target_radius");
      if (t.target_radius <= 0) fail("$.tracking.target_radius", "must be positive");
    }
    if (T.contains("target_speed")) {
      t.target_speed = number(T["target_speed"], "$.tracking.target_speed");
      if (t.target_speed < 0) fail("$.tracking.target_speed", "must not be negative");
    }
    if (T.contains("target_path")) {
      const json& P = T["target_path"];
      if (!P.is_array()) fail("$.tracking.target_path", "expected an array of points, got " + type_name(P));
      for (std::size_t i = 0; i < P.size(); ++i) t.target_path.push_back(point(P[i], "$.tracking.target_path[" + std::to_string(i) + "]"));
    }
    s.tracking = t;
  }
  // "beams" and "imaginary_beams" share one format.
  for (const char* key : {"beams", "imaginary_beams"}) {
    if (!doc.contains(key)) continue;
    const json& B = doc[key];
    const std::string root = std::string("$.") + key;
    if (!B.is_array()) fail(root, "expected an array, got " + type_name(B));
    auto& out = std::string(key) == "beams" ? s.beams : s.imaginary_beams;
    for (std::size_t i = 0; i < B.size(); ++i) {
      const std::string p = root + "[" + std::to_string(i) + "]";
      allow_keys(B[i], p, {"label", "from", "to", "directed", "shape"});
      for (const char* k : {"label", "from", "to"})
        if (!B[i].contains(k)) fail(p, std::string("missing key \"") + k + "\"");
      Beam b{string_at(B[i]["label"], p + ".label"), point(B[i]["from"], p + ".from"), point(B[i]["to"], p + ".to"), true};
      // Observation words are white-space-separated labels with an optional prime, so a
      // label with white space, a trailing prime or no characters could never be observed.
      const bool spaced = std::any_of(b.label.begin(), b.label.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
      if (b.label.empty() || spaced || b.label.back() == '\'')
        fail(p + ".label", "'" + b.label + "' cannot be written in an observation word (a label is one or more characters, no white space, not ending in ')");
      if (B[i].contains("directed")) {
        if (!B[i]["directed"].is_boolean()) fail(p + ".directed", "expected true or false, got " + type_name(B[i]["directed"]));
        b.directed = B[i]["directed"].get<bool>();
      }
      if (B[i].contains("shape")) {
        const std::string sh = string_at(B[i]["shape"], p + ".shape");
        if (sh == "segment") b.shape = Beam::Shape::Segment;
        else if (sh == "ray") b.shape = Beam::Shape::Ray;
        else if (sh == "line") b.shape = Beam::Shape::Line;
        else fail(p + ".shape", "expected \"segment\", \"ray\" or \"line\", got \"" + sh + "\"");
      }
      if (b.from == b.to) fail(p, "beam endpoints coincide");
      out.push_back(std::move(b));
    }
  }
  return s;
}

Scene load_scene(const std::string& path) { return parse_scene(read_file(path), path); }

json to_json(const Scene& s) {
  json doc = json::object();
  if (!s.name.empty()) doc["name"] = s.name;
  if (!s.description.empty()) doc["description"] = s.description;
  if (s.environment) {
    const auto& env = *s.environment;
    json env_j;
    json outer = json::array();
    for (auto& p : env.ring(0)) outer.push_back(point_json(p));
    env_j["boundary"] = outer;
    json obs = json::array();
    for (std::size_t r = 1; r < env.num_rings(); ++r) {
      json h = json::array();
      for (auto& p : env.ring(r)) h.push_back(point_json(p));
      obs.push_back(h);
    }
    if (!obs.empty()) env_j["obstacles"] = obs;
    doc["environment"] = env_j;
  }
  if (s.start) doc["start"] = point_json(*s.start);
  if (s.goal) doc["goal"] = point_json(*s.goal);
  if (s.robot_radius) doc["robot"] = {{"radius", *s.robot_radius}};
  if (!s.landmarks.empty()) {
    json L = json::array();
    for (auto& l : s.landmarks) L.push_back({{"label", l.label}, {"at", point_json(l.at)}});
    doc["landmarks"] = L;
  }
  if (s.tracking) {
    const auto& t = *s.tracking;
    json T = {{"heading", t.heading}, {"target_radius", t.target_radius}, {"target_speed", t.target_speed}};
    if (t.observer) T["observer"] = point_json(*t.observer);
    if (t.target) T["target"] = point_json(*t.target);
    if (!t.target_path.empty()) {
      json P = json::array();
      for (auto& p : t.target_path) P.push_back(point_json(p));
      T["target_path"] = P;
    }
    doc["tracking"] = T;
  }
  for (const auto* list : {&s.beams, &s.imaginary_beams}) {
    if (list->empty()) continue;
    json B = json::array();
    for (auto& b : *list) {
      json j = {{"label", b.label}, {"from", point_json(b.from)}, {"to", point_json(b.to)}, {"directed", b.directed}};
      if (b.shape != Beam::Shape::Segment) j["shape"] = to_string(b.shape);
      B.push_back(std::move(j));
    }
    doc[list == &s.beams ? "beams" : "imaginary_beams"] = B;
  }
  return doc;
}

void save_scene(const Scene& s, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot write file");
  out << format_json(to_json(s), JsonLayout::Pretty) << "\n";
  if (!out) throw InputError(path + ": write error");
}

}  // namespace preimage::scene
