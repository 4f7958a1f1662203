// SPDX-License-Identifier: Apache-2.0
// preimage: the command line. Each module registers its subcommands here.
#include "common.hpp"
#include "suggest.hpp"

#include <preimage/error.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"preimage: exact combinatorial planning and filtering in the plane"};
  app.set_version_flag("--version", std::string("preimage ") + PREIMAGE_VERSION);
  app.require_subcommand(1);
  app.option_defaults()->always_capture_default();  // every --help shows every default
  preimage::cli::add_geometry_commands(app);
  preimage::cli::add_visibility_commands(app);
  preimage::cli::add_decompose_commands(app);
  preimage::cli::add_gvd_commands(app);
  preimage::cli::add_beams_commands(app);
  preimage::cli::add_wallfollow_commands(app);
  preimage::cli::add_landmarks_commands(app);
  preimage::cli::add_track_commands(app);
  preimage::cli::add_pursuit_commands(app);
  preimage::cli::add_demo_command(app);
  if (const auto unknown = preimage::cli::unknown_command(app, argc, argv)) {
    std::cerr << "preimage: " << *unknown << " (see preimage --help)\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, naming what was wrong; usage is one --help away.
    std::cerr << "preimage: " << e.what() << " (see preimage --help)\n";
    return 2;  // every usage error alike (CLI11's own codes run from 105 to 115)
  } catch (const preimage::InputError& e) {
    std::cerr << "preimage: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "preimage: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
