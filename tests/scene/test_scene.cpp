// Scene files and importers: JSON-path errors, round trips, and the real floor plans.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/import.hpp>

#include "support/cgal_oracle.hpp"

#include <fstream>

using namespace preimage;

namespace {
std::string error_of(const std::string& text) {
  try {
    scene::parse_scene(text, "t.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
std::string fixture(const std::string& rel) { return std::string(PREIMAGE_FIXTURES) + "/" + rel; }
std::string load_error(const std::string& path) {
  try {
    scene::load_scene(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Scene, ErrorsNameTheJsonPath) {
  EXPECT_EQ(error_of(R"({"environment": {"boundary": [[0,0],[1,0],[1,1]], "walls": 1}})"),
            "$.environment.walls: unknown key (expected one of: boundary, obstacles)");
  EXPECT_EQ(error_of(R"({"environment": {"boundary": [[0,0],[1,0],[1,"x"]]}})"),
            "$.environment.boundary[2][1]: expected a number, got string");
  EXPECT_EQ(error_of(R"({"environment": {"boundary": [[0,0],[1,0],[1]]}})"),
            "$.environment.boundary[2]: expected [x, y], got an array of 1");
  EXPECT_EQ(error_of(R"({"environment": {}})"), "$.environment: missing key \"boundary\"");
  EXPECT_EQ(error_of(R"({"start": [0, 1e999]})"), "t.json: $.start[1]: number 1e999 is outside the range of doubles");
  EXPECT_EQ(error_of(R"({"robot": {"radius": -1}})"), "$.robot.radius: must not be negative");
  EXPECT_EQ(error_of(R"({"beams": [{"label": "a", "from": [0,0]}]})"), "$.beams[0]: missing key \"to\"");
  EXPECT_EQ(error_of(R"({"beams": [{"label": "a", "from": [0,0], "to": [1,1], "directed": "yes"}]})"),
            "$.beams[0].directed: expected true or false, got string");
  EXPECT_EQ(error_of("{\n  \"name\": \"x\",\n  oops\n}").rfind("t.json:3:3: JSON syntax error", 0), 0u);
}

// A beam label no observation word can name (white space splits tokens, a trailing prime
// means the negative crossing) was accepted, and the beam could never be reported.
TEST(Scene, BeamLabelsThatNoWordCanNameAreRejected) {
  const std::string why = "cannot be written in an observation word (a label is one or more characters, no white space, not ending in ')";
  EXPECT_EQ(load_error(fixture("scenes/beam_label_with_space.json")), "$.beams[1].label: 'a b' " + why);
  EXPECT_EQ(error_of(R"({"beams": [{"label": "", "from": [0,0], "to": [1,1]}]})"), "$.beams[0].label: '' " + why);
  EXPECT_EQ(error_of(R"({"beams": [{"label": "b'", "from": [0,0], "to": [1,1]}]})"), "$.beams[0].label: 'b'' " + why);
  EXPECT_EQ(error_of(R"({"imaginary_beams": [{"label": "x\ty", "from": [0,0], "to": [1,1]}]})"),
            "$.imaginary_beams[0].label: 'x\ty' " + why);
  // Primes inside a label, and any other character, stay allowed.
  EXPECT_EQ(error_of(R"({"beams": [{"label": "b'2", "from": [0,0], "to": [1,1]}, {"label": "1/2", "from": [0,0], "to": [1,1]}]})"), "");
}

TEST(Scene, GeometryErrorsCarryTheJsonPath) {
  EXPECT_EQ(load_error(fixture("scenes/self_intersecting.json")),
            "$.environment.boundary: edges 1 and 3 intersect near (1, 1)");
  // Holes touching at a vertex are accepted (a contact); overlapping there is an error.
  EXPECT_EQ(load_error(fixture("scenes/touching_obstacles.json")), "");
  EXPECT_EQ(load_error(fixture("contacts/overlap_at_contact.json")),
            "$.environment.obstacles[1] vertex 0 and $.environment.obstacles[0] vertex 2 overlap at (4, 4): rings may "
            "touch at a contact, not cross or overlap there");
  EXPECT_EQ(load_error(fixture("scenes/bad_coordinate.json")),
            "$.environment.obstacles[0][2][1]: expected a number, got string");
  EXPECT_EQ(load_error(fixture("scenes/missing.json")), fixture("scenes/missing.json") + ": cannot open file");
}

TEST(Scene, RoundTripsThroughJson) {
  auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/../../examples/gallery.json");
  ASSERT_TRUE(s.environment);
  EXPECT_EQ(s.environment->num_holes(), 3u);
  EXPECT_EQ(s.landmarks.size(), 2u);
  EXPECT_EQ(s.beams.size(), 1u);
  auto again = scene::parse_scene(scene::to_json(s).dump());
  EXPECT_EQ(scene::to_json(again), scene::to_json(s));
  EXPECT_EQ(again.environment->exact_area(), s.environment->exact_area());
}

TEST(Import, VisiLibityFiles) {
  auto s = scene::import_visilibity(scene::read_file(fixture("visilibity/room_with_pillar.txt")), "room.txt");
  ASSERT_TRUE(s.environment);
  EXPECT_EQ(s.environment->num_holes(), 1u);
  EXPECT_EQ(s.environment->exact_area(), geometry::ExactFT(56));
  try {
    scene::import_visilibity(scene::read_file(fixture("visilibity/bad_token.txt")), "bad.txt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "bad.txt:3: expected 'x y', got '10 zero'");
  }
  try {
    scene::import_visilibity(scene::read_file(fixture("visilibity/hole_crossing_wall.txt")), "h.txt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("h.txt: holes[0] edge", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("(holes[0] starts at line 7)"), std::string::npos) << e.what();
  }
}

// The two real HouseExpo plans (vertices 1 cm apart, many near-collinear runs): they
// import, triangulate, and give the same visibility polygons as CGAL.
TEST(Import, RealHouseExpoFloorPlansMatchCgalVisibility) {
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"}) {
    const std::string path = std::string(PREIMAGE_FLOORPLANS) + "/" + name;
    if (!std::ifstream(path)) GTEST_SKIP() << "shared data not found beside the checkout: " << path;
    auto s = scene::import_houseexpo(scene::read_file(path), path);
    ASSERT_TRUE(s.environment) << name;
    const auto& env = *s.environment;
    EXPECT_GT(env.num_vertices(), 100u);
    geometry::VisibilityIndex index(env);
    EXPECT_NO_THROW(index.triangulation().check());
    preimage::testing::CgalVisibility cgal(env);
    int compared = 0;
    for (auto& q : preimage::testing::random_queries(env, 150, 0, 80, 42)) {
      auto mine = geometry::canonical_cycle(index.compute(q.p).points());
      auto theirs = geometry::canonical_cycle(cgal.compute(q.p, q.loc));
      EXPECT_EQ(mine, theirs) << name << " query " << geometry::format_point(q.p);
      ++compared;
    }
    EXPECT_EQ(compared, 230);
  }
}

// A number beyond the range of doubles is found by the JSON parser, which gives no path:
// parse_json finds it (issue 26: "internal error: number overflow parsing '1e400'").
TEST(Scene, NumberOverflowNamesTheJsonPath) {
  auto error = [](const std::string& text) {
    try {
      scene::parse_json(text, "t.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("1e400"), "t.json: $: number 1e400 is outside the range of doubles");
  EXPECT_EQ(error("[1e400]"), "t.json: $[0]: number 1e400 is outside the range of doubles");
  EXPECT_EQ(error(R"({"x": -1e999})"), "t.json: $.x: number -1e999 is outside the range of doubles");
  EXPECT_EQ(error(R"({"a": {"b": [1, [2, 1.5e308, 1e309]]}})"), "t.json: $.a.b[1][2]: number 1e309 is outside the range of doubles");
  EXPECT_EQ(error(R"({"a": [{"b": 1}, {"c": [], "d": 2E+400}]})"), "t.json: $.a[1].d: number 2E+400 is outside the range of doubles");
  EXPECT_EQ(error(R"([[], {}, "1e400", null, true, 7, -1, 1e400])"), "t.json: $[7]: number 1e400 is outside the range of doubles");
  EXPECT_EQ(error("{\n  \"a\": 1,\n  oops\n}").rfind("t.json:3:3: JSON syntax error", 0), 0u);
  EXPECT_EQ(scene::parse_json("[1e308, 1e-400]", "t.json")[0].get<double>(), 1e308);
}

TEST(Import, HouseExpoNumberOverflowNamesTheJsonPath) {
  const std::string path = fixture("houseexpo/number_overflow.json");
  try {
    scene::import_houseexpo(path);
    ADD_FAILURE() << "imported " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": $.verts[2][1]: number 1e400 is outside the range of doubles");
  }
}

// The one-argument importers read the file (issue 25, defect 6: a path given to the text
// form was "JSON syntax error at byte 1").
TEST(Import, HouseExpoFromAPath) {
  const auto s = scene::import_houseexpo(fixture("houseexpo/l_shape.json"));
  ASSERT_TRUE(s.environment);
  EXPECT_EQ(s.name, "l_shape");
  EXPECT_EQ(s.description, "HouseExpo floor plan (kitchen)");
  EXPECT_EQ(s.environment->num_vertices(), 6u);  // the repeated closing vertex dropped
  EXPECT_EQ(s.environment->exact_area(), geometry::ExactFT(12));
  EXPECT_EQ(scene::import_houseexpo(scene::read_file(fixture("houseexpo/l_shape.json")), "x").environment->vertices(),
            s.environment->vertices());
}
