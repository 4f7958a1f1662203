// SPDX-License-Identifier: Apache-2.0
// "unknown command 'visiblity'; did you mean 'visibility'?" — CLI11 only says that a
// subcommand is required, or that an argument was not expected.
#pragma once
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace preimage::cli {

/// The message for the first command word (in the positions where `app` and its command
/// groups expect a subcommand) that names no subcommand, with the closest names offered.
std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv);

}  // namespace preimage::cli
