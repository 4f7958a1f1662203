// SPDX-License-Identifier: Apache-2.0
// Shared by the libFuzzer harnesses (docs/reliability.md). A harness feeds its bytes to one
// public parsing entry point of the library. Bad input must end in preimage::InputError;
// any other exception escapes to std::terminate and libFuzzer reports it as a crash, as it
// does a sanitizer report, a timeout or a failed check below.
#pragma once
#include <preimage/error.hpp>
#include <preimage/scene/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace preimage::fuzz {

inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// A property the input broke: print it and abort, so libFuzzer keeps the input.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz check failed: %s\n", what.c_str());
  std::abort();
}

/// Runs fn; an InputError is the expected answer to bad input and is swallowed.
template <class Fn>
void expect_only_input_errors(Fn&& fn) {
  try {
    fn();
  } catch (const InputError&) {
  }
}

/// A scene the library accepted is written as JSON and read back: it must be accepted
/// again and write the same JSON (what `preimage import` and `save_scene` rely on).
inline void check_round_trip(const scene::Scene& s) {
  const std::string once = scene::to_json(s).dump();
  scene::Scene again;
  try {
    again = scene::parse_scene(once, "round-trip");
  } catch (const InputError& e) {
    fail(std::string("an accepted scene is rejected when read back: ") + e.what());
  }
  if (scene::to_json(again).dump() != once) fail("a scene read back writes other JSON");
}

}  // namespace preimage::fuzz
