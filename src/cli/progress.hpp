// SPDX-License-Identifier: Apache-2.0
// A status line on stderr for CLI work that runs longer than a second.
#pragma once
#include <chrono>
#include <cstddef>
#include <string>

namespace preimage::cli {

/// Drawn only when stderr is a terminal (pipes, logs and tests see nothing), first after
/// one second, redrawn at most four times a second and erased when the work ends. Holds
/// no signal handler: Ctrl-C interrupts as usual.
class Progress {
 public:
  /// Shows "<what>: <done> of <total> <unit> (p%), t s, about s left" or "<what>: p%".
  explicit Progress(std::string what, std::string unit = "");
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  ~Progress();

  void operator()(std::size_t done, std::size_t total);
  void operator()(double fraction);
  /// Prints a line of its own on stderr (always, terminal or not), erasing the status line
  /// first; the status is drawn again at the next update.
  void note(const std::string& line);

 private:
  bool due();
  void draw(const std::string& line);
  using Clock = std::chrono::steady_clock;
  std::string what_, unit_;
  bool tty_, shown_ = false;
  Clock::time_point start_ = Clock::now(), last_{};
};

}  // namespace preimage::cli
