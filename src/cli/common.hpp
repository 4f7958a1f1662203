// SPDX-License-Identifier: Apache-2.0
// Shared pieces of the preimage command line.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace preimage::cli {

/// "1.5,2" -> point; InputError "<flag>: expected X,Y, got '...'".
geometry::Point parse_point(const std::string& text, const std::string& flag);
/// Creates a directory (and parents); InputError if impossible.
void make_dirs(const std::string& dir);
/// {"ring": "<ring name>", "index": k}: environment edge e in the caller's terms.
nlohmann::json edge_json(const geometry::Environment& env, std::size_t e);
/// [x, y] of an exact point, rounded to doubles.
nlohmann::json point_json(const geometry::ExactPoint& p);
/// [[x, y], ...]: a polyline or polygon as JSON.
nlohmann::json points_json(const std::vector<geometry::Point>& pts);
/// "(2, -3)": a winding vector or any integer tuple.
std::string tuple_string(std::span<const std::int64_t> v);
/// Validator for an integer flag in [lo, hi]: anything else ("-1" for a count, "1e3", "7x",
/// out of range) is a usage error naming the flag and the range, before the value is
/// converted (so a negative count never wraps to a huge one).
CLI::Validator integer_in(std::int64_t lo, std::int64_t hi);
/// Validator for a finite number in [lo, hi] (lo_open / hi_open exclude the ends).
CLI::Validator number_in(double lo, double hi, bool lo_open = false, bool hi_open = false);

/// An integer option checked by integer_in(lo, hi), its default shown in --help.
template <class T>
CLI::Option* add_count(CLI::App* cmd, const std::string& name, T& value, std::int64_t lo, std::int64_t hi,
                       const std::string& help) {
  return cmd->add_option(name, value, help)->check(integer_in(lo, hi))->capture_default_str();
}

/// "Examples:" closing the command's --help, each a command line that runs from the source
/// checkout on shipped files (tests/cli/help_examples.sh runs every one).
void set_examples(CLI::App* cmd, const std::vector<std::string>& lines);

/// --json (bound to `json`) and --pretty (implies --json; indented output) on a command.
CLI::Option* add_json_flag(CLI::App* cmd, bool& json, const std::string& help);
/// Prints JSON to stdout: one compact line, or indented after --pretty. JSON Lines
/// outputs (one record per observation or scan) stay one line per record.
void print_json(const nlohmann::json& j);
/// "1 obstacle", "3 obstacles"; "1 vertex", "2 vertices" with the plural given.
std::string count_of(std::size_t n, const std::string& singular, const std::string& plural = "");

/// Registration of each command group.
void add_geometry_commands(CLI::App& app);
void add_visibility_commands(CLI::App& app);  // visibility, visibility-graph
void add_decompose_commands(CLI::App& app);
void add_gvd_commands(CLI::App& app);  // gvd
void add_beams_commands(CLI::App& app);
void add_beams_homotopy_commands(CLI::App* beams_cmd);  // homotopy, winding
void add_wallfollow_commands(CLI::App& app);
void add_landmarks_commands(CLI::App& app);
void add_track_commands(CLI::App& app);
void add_pursuit_commands(CLI::App& app);
void add_demo_command(CLI::App& app);

}  // namespace preimage::cli
