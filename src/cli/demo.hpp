// SPDX-License-Identifier: Apache-2.0
// `preimage demo`: every module adds one section (figures + a line of text per result).
#pragma once
#include <preimage/render/html.hpp>

#include <string>

namespace preimage::cli {

struct DemoContext {
  std::string out_dir;
  render::HtmlReport& report;
  /// Writes an SVG next to the report and inlines it as a figure.
  void figure(const std::string& file, const std::string& svg, const std::string& caption);
};

void demo_geometry(DemoContext& ctx);
void demo_decompose(DemoContext& ctx);
void demo_coverage(DemoContext& ctx);
void demo_morse(DemoContext& ctx);
void demo_brushfire(DemoContext& ctx);
void demo_online(DemoContext& ctx);
void demo_beams(DemoContext& ctx);
void demo_beams_homotopy(DemoContext& ctx);
void demo_wallfollow(DemoContext& ctx);
void demo_wallfollow_pursuit(DemoContext& ctx);
void demo_landmarks(DemoContext& ctx);
void demo_tracking(DemoContext& ctx);
void demo_pursuit(DemoContext& ctx);

}  // namespace preimage::cli
