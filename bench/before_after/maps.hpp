// SPDX-License-Identifier: Apache-2.0
// bench_visibility's maps by name, for the standalone before/after programs here. Uses only
// API that commit 73df79e already had, so the programs build against either library.
// Floor plans are read from $PREIMAGE_EXAMPLES/floorplans (default: examples/floorplans).
#pragma once
#include <preimage/geometry/generators.hpp>
#include <preimage/scene/import.hpp>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

namespace before_after {
inline std::string env_or(const char* k, const char* d) {
  const char* v = std::getenv(k);
  return v ? v : d;
}
inline std::string floorplan(const char* n) { return env_or("PREIMAGE_EXAMPLES", "examples") + "/floorplans/" + n; }
inline std::map<std::string, std::function<preimage::geometry::Environment()>> maps() {
  using preimage::geometry::Environment;
  namespace gen = preimage::geometry::generators;
  return {
      {"houseexpo-0000", [] { return *preimage::scene::import_houseexpo(floorplan("house_expo_room_0000.json")).environment; }},
      {"houseexpo-1451", [] { return *preimage::scene::import_houseexpo(floorplan("house_expo_room_1451.json")).environment; }},
      {"office-3x3", [] { return gen::office(3, 3); }},
      {"office-5x5", [] { return gen::office(5, 5); }},
      {"comb-25", [] { return Environment::make(gen::comb(25), {}); }},
      {"comb-120", [] { return Environment::make(gen::comb(120), {}); }},
      {"random-1000-h20", [] { return gen::random_environment(1000, 20, 1062); }},
      {"office-35x35", [] { return gen::office(35, 35); }},
      {"comb-7500", [] { return Environment::make(gen::comb(7500), {}); }},
  };
}
}  // namespace before_after
