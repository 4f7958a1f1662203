// SPDX-License-Identifier: Apache-2.0
// A local frame for the floating steps (offsets, rasters, snapping, areas, angles).
//
// Predicates are exact wherever an environment sits, but a floating step is not: a plan in
// UTM or Web Mercator coordinates (5e5 .. 2e7, up to kMaxCoordinate) loses in a raster, a
// Clipper grid or a sum of cross products the digits that its own size keeps near the origin.
// An environment much farther from the origin than it is large is translated so its bounding
// box starts at 0 along each such axis. The translation is exact (Sterbenz: x and x0 of the same
// sign within a factor 2 have an exact difference), so the local environment is the input one,
// moved, and every decision on it is the decision on the input. Only mapping constructed points
// back rounds: by at most half an ulp of the input's largest coordinate per axis. A path is
// therefore certified again in input coordinates (to_input_certified), where points that
// rounding took within r of a wall are pushed `margin()` away; a configuration space's rings
// get `margin()` more erosion when their rounded copy fails its certificate.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <vector>

namespace preimage::geometry {

class Clearance;

class LocalFrame {
 public:
  LocalFrame() = default;
  /// The frame for env: a translation along each axis whose coordinates all lie more than 16
  /// times the environment's extent from 0, else the identity along it.
  static LocalFrame of(const Environment& env) { return make(env, false); }
  /// The frame a whole plan is answered in: the box's low end along every axis where the
  /// translation is exact (always far from 0; near 0 for a plan on a binary grid such as a
  /// snapped or georeferenced one), else of(env) along it. Every exact translate of env gets
  /// the same local environment, so floating steps round alike and the answer is the same,
  /// moved: a plan at its own coordinates and shifted by 4e6 used to get different merged
  /// bends, as only the shifted one was translated. Used where a command's answer starts
  /// (plan_coverage, measure_coverage); derived environments inside (a configuration space's
  /// components) keep of(), whose identity near 0 maps back without rounding.
  static LocalFrame canonical(const Environment& env) { return make(env, true); }

  bool identity() const { return dx_ == 0 && dy_ == 0; }
  double dx() const { return dx_; }
  double dy() const { return dy_; }
  /// How far to_input() may move a constructed point, with a factor of safety (0 for the
  /// identity); at least 2^-36 of the extent, so an erosion by it is representable.
  double margin() const { return margin_; }

  /// The environment translated into the frame (exact; std::logic_error if it were not).
  Environment to_local(const Environment& env) const;
  /// A point into the frame: exact for points within the environment's box, rounded
  /// otherwise (a centre given outside it).
  Point to_local(const Point& p) const { return Point(p.x() - dx_, p.y() - dy_); }
  /// A constructed point back to input coordinates, rounded to the nearest double.
  Point to_input(const Point& p) const { return Point(p.x() + dx_, p.y() + dy_); }
  /// A path certified in the frame, mapped back to input coordinates and certified there
  /// (clear.admits, exact). Rounding moves each point by under an ulp; where that brings a
  /// segment within r of an obstacle (a transit along a chord of a configuration space's
  /// arcs lies a few grid units outside the circle of radius r), the segment's ends are
  /// pushed margin() (up to 8 margins) away from the nearest obstacle. Returns the first
  /// segment still failing, or path.size() when all are certified.
  std::size_t to_input_certified(std::vector<Point>& path, const Clearance& clear) const;

 private:
  static LocalFrame make(const Environment& env, bool canonical);
  double dx_ = 0, dy_ = 0, margin_ = 0;
};

}  // namespace preimage::geometry
