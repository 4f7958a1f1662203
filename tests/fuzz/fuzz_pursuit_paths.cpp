// SPDX-License-Identifier: Apache-2.0
// Pursuer paths (`pursuit check --path`, what `pursuit plan --json` and `wallfollow pursue
// --json` write): parse_paths, then every exact coordinate written as a rational string
// must read back to the same number, and small accepted paths go through the independent
// checker in the room with a pillar (bad paths must end in InputError, nothing else).
#include "fuzz.hpp"

#include <preimage/pursuit/paths_input.hpp>

namespace {
using namespace preimage;

const geometry::Environment& pillar_room() {
  static const geometry::Environment env = geometry::Environment::make(
      {{0, 0}, {6, 0}, {6, 6}, {0, 6}}, {{{2, 2}, {2, 4}, {4, 4}, {4, 2}}});
  return env;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  pursuit::PathsInput paths;
  try {
    paths = pursuit::parse_paths(fuzz::text_of(data, size), "fuzz-paths.json");
  } catch (const InputError&) {
    return 0;
  }
  std::size_t points = 0;
  for (const auto& path : paths.exact) {
    points += path.size();
    for (const auto& p : path)
      for (const auto& c : {p.x(), p.y()}) {
        const auto again = geometry::parse_exact_number(geometry::exact_string(c));
        if (!again || *again != c) fuzz::fail("an exact coordinate does not read back from its rational string");
      }
  }
  // The checker's time grows with the waypoints and pursuers: only small inputs go through it.
  if (paths.exact.size() <= 3 && points <= 12)
    fuzz::expect_only_input_errors([&] { (void)pursuit::check_paths(pillar_room(), paths); });
  return 0;
}
