// SPDX-License-Identifier: Apache-2.0
#include "progress.hpp"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace preimage::cli {

Progress::Progress(std::string what, std::string unit)
    : what_(std::move(what)), unit_(std::move(unit)), tty_(isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
  if (shown_) std::fprintf(stderr, "\r\033[K"), std::fflush(stderr);
}

bool Progress::due() {
  if (!tty_) return false;
  const auto now = Clock::now();
  if (now - start_ < std::chrono::seconds(1) || now - last_ < std::chrono::milliseconds(250)) return false;
  last_ = now;
  return true;
}

void Progress::draw(const std::string& line) {
  shown_ = true;
  std::fprintf(stderr, "\r\033[K%s", line.c_str());
  std::fflush(stderr);
}

void Progress::operator()(std::size_t done, std::size_t total) {
  if (!due()) return;
  const double t = std::chrono::duration<double>(Clock::now() - start_).count();
  const double f = total ? static_cast<double>(done) / static_cast<double>(total) : 0;
  char tail[96];
  if (done > 0 && done < total)
    std::snprintf(tail, sizeof tail, " (%.0f%%), %.0f s, about %.0f s left", 100 * f, t, t * (1 - f) / f);
  else
    std::snprintf(tail, sizeof tail, " (%.0f%%), %.0f s", 100 * f, t);
  draw(what_ + ": " + std::to_string(done) + " of " + std::to_string(total) + (unit_.empty() ? "" : " " + unit_) + tail);
}

void Progress::note(const std::string& line) {
  if (shown_) std::fprintf(stderr, "\r\033[K"), shown_ = false;
  std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
}

void Progress::operator()(double fraction) {
  if (!due()) return;
  char line[32];
  std::snprintf(line, sizeof line, ": %3.0f%%", 100 * std::clamp(fraction, 0.0, 1.0));
  draw(what_ + line);
}

}  // namespace preimage::cli
