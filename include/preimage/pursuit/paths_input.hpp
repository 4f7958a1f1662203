// SPDX-License-Identifier: Apache-2.0
// Pursuer paths as `pursuit check --path` reads them (docs/cli.md): one polyline
// [[x, y], ...], several [[[x, y], ...], ...], or an object with "paths" (or "pursuers"),
// also under "plan" (what `pursuit plan --json` and `wallfollow pursue --json` write). A
// coordinate is a JSON number (its double) or an exact string ("-7/2", "0.1" = 1/10).
#pragma once
#include <preimage/pursuit/checker.hpp>

#include <string>

namespace preimage::pursuit {

struct PathsInput {
  ExactPaths exact;            // every coordinate as read, without rounding
  bool exact_strings = false;  // some coordinate was a string
  Paths rounded() const;       // the nearest doubles
};

/// Throws InputError "<source>: <JSON path>: <what>" ("$.paths[0][3][1]: expected a number
/// or a rational string \"p/q\", got \"1/0\"").
PathsInput parse_paths(const std::string& text, const std::string& source);

/// check_exact_paths when some coordinate was a string (V at the exact positions), else
/// check_paths on the doubles, as before exact input existed.
CheckResult check_paths(const geometry::Environment& env, const PathsInput& paths, const CheckOptions& options = {});

}  // namespace preimage::pursuit
