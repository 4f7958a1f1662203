// SPDX-License-Identifier: Apache-2.0
// GeoJSON polygon: import_geojson (text form), then the scene round trip.
#include "fuzz.hpp"

#include <preimage/scene/import.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace preimage;
  fuzz::expect_only_input_errors(
      [&] { fuzz::check_round_trip(scene::import_geojson(fuzz::text_of(data, size), "fuzz.geojson")); });
  return 0;
}
