// SPDX-License-Identifier: Apache-2.0
// Laser range scans (section V): a simulated range finder in a scene, and the local-map
// construction of section V.A — scan -> ordered points -> polylines split at occlusion
// gaps (successive points too far apart) and out-of-range gaps (saturated readings) ->
// V(q^o) closed by occlusion edges, and by occlusion-range-occlusion edges across
// out-of-range gaps. Scans and maps are in the sensor frame: observer at the origin,
// heading along +x, angles counter-clockwise.
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/tracking/local_map.hpp>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

namespace preimage::tracking {

/// One scan: ranges[i] is measured along angle_min + i * angle_increment.
struct Scan {
  double timestamp = 0;
  double angle_min = 0;
  double angle_increment = 0;
  double max_range = 8;
  std::vector<double> ranges;
  double angle(std::size_t i) const { return angle_min + static_cast<double>(i) * angle_increment; }
  /// The field of view the beams cover (for n beams: (n - 1) increments, or 2 pi when
  /// they go all the way round).
  bool full_circle() const;
  /// Throws InputError naming the reading if a range is not finite or negative, or if the
  /// beams are not counter-clockwise within one turn.
  void validate(const std::string& what = "scan") const;
  /// The checks of validate() that do not read every range (count, increment, span).
  void validate_layout(const std::string& what = "scan") const;
};

struct LaserSpec {
  double fov = 2 * M_PI;          // 2 pi, or a cone of at most pi centred on the heading
  std::size_t beams = 360;
  double max_range = 8.0;
  double noise_sigma = 0.0;       // Gaussian range noise (metres), seeded by the caller's rng
};

struct Pose {
  Point position;
  double heading = 0;  // radians
};
struct Disc {
  Point center;
  double radius = 0.2;
};

/// A scan from `pose` in `env`; the target disc, if given, occludes like an obstacle.
/// Readings that hit nothing within range read max_range.
Scan simulate_scan(const geometry::Environment& env, const Pose& pose, const LaserSpec& spec,
                   const std::optional<Disc>& target, std::mt19937_64* noise_rng = nullptr);

struct MapParams {
  double gap = 0.3;            // occlusion gap: successive points further apart than gap + 2 r dtheta
  double simplify = 0.02;      // polyline fitting tolerance (Douglas-Peucker), metres
  double range_margin = 0.05;  // a reading within this of max_range is out of range
  double min_range = 0.01;     // readings at or below this are invalid (treated as no return)
  double arc_step = 0.2;       // range edges approximate the range circle in steps of at most this (rad)
};

/// V(q^o) from a scan (section V.A, technique of [10]). Vertices are the fitted polylines'
/// points in angular order; occlusion edges get the nearer endpoint as their corner.
/// With a cone of view the observer (origin) closes the polygon between two
/// field-of-view edges. Throws InputError for a scan that is not valid.
LocalMap local_map_from_scan(const Scan& scan, const MapParams& params = {});

/// cos and sin of every beam angle, cached per thread for the last two beam layouts seen
/// (a sensor keeps one layout, so TRACK computes no trigonometry per scan).
struct BeamDirections { std::vector<double> cos, sin; };
const BeamDirections& beam_directions(const Scan& scan);

}  // namespace preimage::tracking
