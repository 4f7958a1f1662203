// SPDX-License-Identifier: Apache-2.0
// CARMEN (FLASER, ROBOTLASER1) and plain-text laser logs (`track replay`): each line through
// parse_log_line, and every scan it accepts through replay_scan, as the command does.
#include "fuzz.hpp"

#include <preimage/tracking/replay.hpp>

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace preimage;
  std::istringstream in(fuzz::text_of(data, size));
  const tracking::TrackerParams params;
  std::size_t line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    fuzz::expect_only_input_errors([&] {
      const auto scan = tracking::parse_log_line(line, 8.0, "fuzz.log:" + std::to_string(line_no));
      if (scan) tracking::replay_scan(*scan, params, 1.0);
    });
  }
  return 0;
}
