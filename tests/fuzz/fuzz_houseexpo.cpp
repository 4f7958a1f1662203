// SPDX-License-Identifier: Apache-2.0
// HouseExpo floor plan JSON: import_houseexpo (text form), then the scene round trip.
#include "fuzz.hpp"

#include <preimage/scene/import.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace preimage;
  fuzz::expect_only_input_errors(
      [&] { fuzz::check_round_trip(scene::import_houseexpo(fuzz::text_of(data, size), "fuzz.json")); });
  return 0;
}
