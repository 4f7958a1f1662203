// SPDX-License-Identifier: Apache-2.0
// GeoJSON and WKT in and out (issue 22): round trips on real floor plans, closed rings,
// and errors that name the element.
#include <gtest/gtest.h>
#include <preimage/error.hpp>
#include <preimage/scene/geojson.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/wkt.hpp>

#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

using namespace preimage;

namespace {
// The environment's rings as vertex lists (boundary first), for comparisons.
std::vector<std::vector<geometry::Point>> rings_of(const geometry::Environment& env) {
  std::vector<std::vector<geometry::Point>> out;
  for (std::size_t r = 0; r < env.num_rings(); ++r) {
    out.emplace_back();
    for (std::size_t v = env.ring_begin(r); v < env.ring_end(r); ++v) out.back().push_back(env.vertex(v));
  }
  return out;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(Formats, GeoJsonAndWktRoundTripRealFloorPlans) {
  // A real plan written as GeoJSON by GeoJsonWriter and as WKT by to_wkt (what `preimage
  // export` writes), read back: the same vertices, bit for bit (both write doubles exactly).
  // The HouseExpo houses, a room with a pillar, and the office floors with holes from shared
  // data when present (a checkout beside ../shared, as CI's).
  std::vector<std::pair<std::string, geometry::Environment>> plans;
  for (const char* name : {"house_expo_room_0000.json", "house_expo_room_1451.json"})
    plans.emplace_back(name, *scene::import_houseexpo(std::string(PREIMAGE_FLOORPLANS) + "/" + name).environment);
  plans.emplace_back("pillar.json", scene::load_scene(std::string(PREIMAGE_EXAMPLES) + "/pursuit/pillar.json").require_environment());
  ASSERT_EQ(plans.back().second.num_holes(), 1u);  // a shipped plan with a hole, on every clone
  for (const char* name : {"mlstruct_302.json", "mlstruct_848.json"}) {
    const std::string path = std::string(PREIMAGE_SOURCE) + "/../shared/data/floorplans/" + name;
    if (std::ifstream(path)) plans.emplace_back(name, scene::load_scene(path).require_environment());
  }
  for (const auto& [name, env] : plans) {
    const auto gj = scene::GeoJsonWriter().environment(env, {{"name", name}}).json();
    const auto from_geojson = scene::import_geojson(gj.dump(), "plan.geojson");
    EXPECT_EQ(rings_of(*from_geojson.environment), rings_of(env)) << name;
    EXPECT_EQ(from_geojson.name, name);
    const std::string wkt = scene::to_wkt(env);
    EXPECT_EQ(wkt.rfind("POLYGON ((", 0), 0u) << name;
    const auto from_wkt = scene::import_wkt(wkt, "plan.wkt");
    EXPECT_EQ(rings_of(*from_wkt.environment), rings_of(env)) << name;
  }
}

TEST(Formats, WktWritesTheShortestExactNumbers) {
  // 0.1 is not 0.1000000000000000055511151231257827 in the text (%.17g would say so), and
  // 1/3 reads back to the same double; a negative zero is written as 0.
  const auto env = geometry::Environment::make({{0.1, -0.0}, {1.0 / 3, 0}, {1.0 / 3, 2e-7}, {0.1, 1e11}}, {}, "outer", "holes");
  const std::string wkt = scene::to_wkt(env);
  EXPECT_NE(wkt.find("0.1 0"), std::string::npos) << wkt;
  EXPECT_EQ(wkt.find("(-0"), std::string::npos) << wkt;
  EXPECT_EQ(wkt.find(" -0"), std::string::npos) << wkt;
  EXPECT_EQ(rings_of(*scene::import_wkt(wkt, "t.wkt").environment), rings_of(env)) << wkt;
}

TEST(Formats, WktAndGeoJsonOfTheExampleAreTheSameRoom) {
  const auto a = scene::import_wkt(std::string(PREIMAGE_EXAMPLES) + "/formats/l_room.wkt");
  const auto b = scene::import_geojson(std::string(PREIMAGE_EXAMPLES) + "/formats/l_room.geojson");
  EXPECT_EQ(rings_of(*a.environment), rings_of(*b.environment));
  EXPECT_EQ(a.environment->num_holes(), 1u);
  EXPECT_EQ(b.name, "L-shaped room with a pillar");
}

TEST(Formats, SceneLoaderAcceptsClosedRings) {
  const std::string open = R"({"environment":{"boundary":[[0,0],[4,0],[4,3],[0,3]],"obstacles":[[[1,1],[2,1],[2,2]]]}})";
  const std::string closed = R"({"environment":{"boundary":[[0,0],[4,0],[4,3],[0,3],[0,0]],"obstacles":[[[1,1],[2,1],[2,2],[1,1]]]}})";
  EXPECT_EQ(rings_of(*scene::parse_scene(closed, "closed.json").environment), rings_of(*scene::parse_scene(open, "open.json").environment));
}

TEST(Formats, GeoJsonErrorsNameTheJsonPath) {
  EXPECT_EQ(error_of([] { scene::import_geojson(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1]]]})", "a.geojson"); }),
            "a.geojson: $.coordinates[0]: the ring is not closed (its last position must equal the first, RFC 7946 3.1.6)");
  EXPECT_EQ(error_of([] { scene::import_geojson(R"({"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],["x",1],[0,0]]]}})", "b.geojson"); }),
            "b.geojson: $.geometry.coordinates[0][2][0]: expected a number, got string");
  EXPECT_EQ(error_of([] { scene::import_geojson(R"({"type":"FeatureCollection","features":[]})", "c.geojson"); }),
            "c.geojson: $.features: expected exactly one feature (one floor plan), got 0");
  EXPECT_EQ(error_of([] { scene::import_geojson(R"({"type":"LineString","coordinates":[[0,0],[1,1]]})", "d.geojson"); }),
            "d.geojson: $.type: expected Polygon, MultiPolygon, Feature or FeatureCollection, got \"LineString\"");
  EXPECT_EQ(error_of([] { scene::import_geojson(R"({"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,0]]],[[[2,2],[3,2],[3,3],[2,2]]]]})", "e.geojson"); }),
            "e.geojson: $.coordinates: expected a MultiPolygon of exactly one polygon, got 2");
}

TEST(Formats, WktErrorsNameTheCharacter) {
  EXPECT_EQ(error_of([] { scene::import_wkt("POLYGON ((0 0, 1 0, a 1, 0 0))", "a.wkt"); }), "a.wkt: character 21: expected a number, got 'a'");
  EXPECT_EQ(error_of([] { scene::import_wkt("LINESTRING (0 0, 1 1)", "b.wkt"); }), "b.wkt: character 11: expected POLYGON or MULTIPOLYGON, got 'LINESTRING'");
  EXPECT_EQ(error_of([] { scene::import_wkt("POLYGON Z ((0 0 1, 1 0 1, 1 1 1, 0 0 1))", "c.wkt"); }), "c.wkt: character 10: only 2-D coordinates are read, got 'Z'");
  EXPECT_EQ(error_of([] { scene::import_wkt("POLYGON ((0 0, 1 0, 1 1, 0 0)", "d.wkt"); }), "d.wkt: character 30: expected ')', got the end of the text");
  // A hole crossing the boundary: the environment's own check, in WKT's ring names.
  EXPECT_EQ(error_of([] { scene::import_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4), (1 1, 5 1, 5 2, 1 1))", "e.wkt"); }),
            "e.wkt: holes[0] edge 0 touches ring 1 (boundary) edge 1 near (4, 1)");
}
