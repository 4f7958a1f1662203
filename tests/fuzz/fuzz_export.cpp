// SPDX-License-Identifier: Apache-2.0
// Export round trip: a scene the library accepts, written as GeoJSON (GeoJsonWriter, what
// `preimage export --to geojson` and every --geojson writes) and as WKT (to_wkt), must read
// back through import_geojson / import_wkt to the same environment, vertex for vertex.
#include "fuzz.hpp"

#include <preimage/scene/geojson.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/scene/wkt.hpp>

namespace {
using namespace preimage;

void expect_same(const geometry::Environment& a, const geometry::Environment& b, const char* format) {
  const std::string what = std::string("an exported environment read back through ") + format + " ";
  if (a.num_rings() != b.num_rings()) fuzz::fail(what + "has another number of rings");
  for (std::size_t r = 0; r < a.num_rings(); ++r) {
    if (a.ring_size(r) != b.ring_size(r)) fuzz::fail(what + "has a ring of another size");
    for (std::size_t i = 0; i < a.ring_size(r); ++i)
      if (a.vertex(a.ring_begin(r) + i) != b.vertex(b.ring_begin(r) + i)) fuzz::fail(what + "has another vertex");
  }
}

template <class Import>
void read_back(const geometry::Environment& env, const std::string& text, const char* format, Import import) {
  scene::Scene again;
  try {
    again = import(text);
  } catch (const InputError& e) {
    fuzz::fail(std::string("an exported environment is rejected by the ") + format + " importer: " + e.what());
  }
  expect_same(env, again.require_environment(), format);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scene::Scene s;
  try {
    s = scene::parse_scene(fuzz::text_of(data, size), "fuzz.json");
  } catch (const InputError&) {
    return 0;
  }
  if (!s.environment) return 0;
  const auto& env = *s.environment;
  read_back(env, scene::GeoJsonWriter().environment(env).json().dump(), "GeoJSON",
            [](const std::string& t) { return scene::import_geojson(t, "export.geojson"); });
  read_back(env, scene::to_wkt(env), "WKT", [](const std::string& t) { return scene::import_wkt(t, "export.wkt"); });
  return 0;
}
