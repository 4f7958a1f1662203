// SPDX-License-Identifier: Apache-2.0
// Scene JSON (docs/scene-format.md): parse_scene, then the round trip through to_json.
#include "fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace preimage;
  fuzz::expect_only_input_errors([&] { fuzz::check_round_trip(scene::parse_scene(fuzz::text_of(data, size), "fuzz.json")); });
  return 0;
}
