// SPDX-License-Identifier: Apache-2.0
// Axis-aligned rooms with rectangular obstacles, for tests that need a small known scene.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <utility>
#include <vector>

namespace preimage::test {

/// The rectangle [0, w] x [0, h], counter-clockwise.
inline geometry::Environment rect_room(double w, double h, std::vector<geometry::Ring> holes = {}) {
  return geometry::Environment::make({{0, 0}, {w, 0}, {w, h}, {0, h}}, std::move(holes));
}
/// A rectangular obstacle [x0, x1] x [y0, y1].
inline geometry::Ring box(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

}  // namespace preimage::test
