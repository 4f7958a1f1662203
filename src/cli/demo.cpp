// SPDX-License-Identifier: Apache-2.0
#include "demo.hpp"

#include "common.hpp"

#include <preimage/error.hpp>

#include <fstream>
#include <iostream>

namespace preimage::cli {

void DemoContext::figure(const std::string& file, const std::string& svg, const std::string& caption) {
  std::ofstream f(out_dir + "/" + file);
  f << svg;
  if (!f) throw InputError(out_dir + "/" + file + ": cannot write file");
  report.figure(svg, caption + " (" + file + ")");
}

namespace {
// One entry per module, in architecture order; later modules append theirs.
using Section = void (*)(DemoContext&);
constexpr Section kSections[] = {demo_geometry, demo_beams, demo_beams_homotopy, demo_decompose, demo_coverage, demo_morse, demo_brushfire, demo_online, demo_wallfollow, demo_wallfollow_pursuit, demo_landmarks, demo_tracking, demo_pursuit};

void run_demo(const std::string& out) {
  make_dirs(out);
  render::HtmlReport report("preimage demo");
  report.paragraph("Every figure below was computed by preimage with exact predicates on a built-in scene; "
                   "each line states a result the test suite also checks.");
  DemoContext ctx{out, report};
  for (Section s : kSections) s(ctx);
  const std::string index = out + "/index.html";
  report.save(index);
  std::cout << index << "\n";
}
}  // namespace

void add_demo_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("demo", "Run every module on built-in scenes and write an HTML report");
  set_examples(cmd, {"preimage demo --out report"});
  auto out = std::make_shared<std::string>("preimage-demo");
  cmd->add_option("--out", *out, "Folder for the report (created if missing)")->capture_default_str();
  cmd->callback([=] { run_demo(*out); });
}

}  // namespace preimage::cli
