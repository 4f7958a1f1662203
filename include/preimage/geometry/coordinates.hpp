// SPDX-License-Identifier: Apache-2.0
// The range of coordinates the library supports (docs/scene-format.md, "Numbers").
//
// Predicates on input points are exact for any double, but constructions, grids, angles and
// the simulations work in floating point: with magnitudes near 1e308 differences overflow to
// infinity, and subnormal values lose their precision. Inside this range every construction
// of degree up to 8 stays finite, so the library refuses what it cannot handle rather than
// crash on it.
#pragma once
#include <cmath>
#include <cstdio>
#include <string>

namespace preimage::geometry {

/// Largest supported magnitude of a coordinate or length (1e12: a million km in metres).
inline constexpr double kMaxCoordinate = 1e12;

/// Empty if v is a supported coordinate: finite, |v| <= kMaxCoordinate, and zero or normal
/// (no subnormal). Otherwise why not, as the end of an error message.
inline std::string coordinate_problem(double v) {
  if (!std::isfinite(v)) return "number is not finite";
  if (std::fabs(v) > kMaxCoordinate) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return "coordinate " + std::string(buf) + " is outside the supported range [-1e12, 1e12]";
  }
  if (v != 0 && !std::isnormal(v)) return "coordinate is subnormal (smaller in magnitude than 2.2e-308): not supported";
  return {};
}

/// Degrees to radians for any finite angle: reduced modulo 360 first (fmod is exact), since
/// 1e308 degrees in radians overflows to infinity, whose sine and cosine are NaN.
inline double radians_from_degrees(double degrees) { return std::fmod(degrees, 360.0) * (M_PI / 180); }

}  // namespace preimage::geometry
