// SPDX-License-Identifier: Apache-2.0
// Test support for the landmark robot: a start point on no line through two landmarks.
#pragma once
#include <preimage/geometry/kernel.hpp>
#include <preimage/geometry/random_point.hpp>

#include <random>
#include <vector>

namespace preimage::testing {

inline geometry::Point generic_start(const std::vector<geometry::Point>& P, std::uint64_t seed, double range = 1500) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-range, range);
  for (;;) {
    const geometry::Point s = geometry::random_point(rng, u);
    bool ok = true;
    for (std::size_t i = 0; i < P.size() && ok; ++i)
      for (std::size_t j = i + 1; j < P.size() && ok; ++j) ok = geometry::orientation(P[i], P[j], s) != 0;
    if (ok) return s;
  }
}

}  // namespace preimage::testing
