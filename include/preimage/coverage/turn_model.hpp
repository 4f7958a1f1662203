// SPDX-License-Identifier: Apache-2.0
// Turn models: how a robot that cannot turn in place gets from one pose to the next.
//
// A car-like robot drives forward with a turning radius of at least R. Between two poses
// the shortest such path is one of Dubins' six words (Dubins 1957; LaValle, Planning
// Algorithms 15.3.1): two arcs of radius R joined by a straight segment (LSL, RSR, LSR,
// RSL) or by a third arc (RLR, LRL); where none fits, coverage searches with reverse steps
// too (src/coverage/car_search.hpp). The curves here are computed in double: they are
// choices, never decisions. Whether a curve may be driven is decided by ArcCertifier,
// with exact clearance tests on a capsule that provably contains every arc piece.
#pragma once
#include <preimage/geometry/clearance.hpp>
#include <preimage/geometry/environment.hpp>

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace preimage::coverage {

using geometry::Point;

/// Where a robot stands and where it heads (radians, counter-clockwise from +x).
struct Pose {
  Point at;
  double heading = 0;
};

enum class DubinsWord : std::uint8_t { LSL, RSR, LSR, RSL, RLR, LRL };
std::string_view to_string(DubinsWord w);

/// One piece of a drivable path: an arc of radius `radius` turning by `turn` radians
/// (positive: left, counter-clockwise), or a straight segment of length `length` (turn 0).
struct DrivePiece {
  double turn = 0;
  double length = 0;  // arc length or segment length
};

/// A Dubins curve from `from`: three pieces, each an arc of radius `radius` or a segment.
struct DubinsCurve {
  Pose from;
  double radius = 0;
  DubinsWord word = DubinsWord::LSL;
  std::array<DrivePiece, 3> pieces{};
  double length() const { return pieces[0].length + pieces[1].length + pieces[2].length; }
  /// The pose after driving `s` along the curve (0 <= s <= length()).
  Pose at(double s) const;
};

/// Every Dubins word that joins `a` to `b` with turning radius `radius` (> 0), shortest
/// first. The shortest is the shortest forward path of bounded curvature (Dubins' theorem).
std::vector<DubinsCurve> dubins_curves(const Pose& a, const Pose& b, double radius);

/// The pose after driving a piece from `p` with turning radius `radius`.
Pose drive(const Pose& p, const DrivePiece& piece, double radius);

/// Certifies drivable pieces for a disc robot of radius r in a workspace. A piece starts
/// where a certified one ended (or at a certified start), so in free space: a segment is
/// certified when it keeps r from every obstacle edge (r = 0: lies in free space); an arc
/// when the capsule of radius r + s around the chord of each run of its samples is clear,
/// s bounding (with slack for rounding) how far the arc bulges from that chord — so the
/// exact arc, not only its samples, keeps r from every obstacle; being connected to free
/// space and never that close to an edge, it stays in free space. Every test is exact
/// (geometry::Clearance).
class ArcCertifier {
 public:
  /// Chords of an arc turn by at most this much (the polyline drawn and measured).
  static constexpr double kChordTurn = 0.06;  // radians, about 3.4 degrees
  ArcCertifier(const geometry::Environment& workspace, double robot_radius);
  ArcCertifier(geometry::Environment&&, double) = delete;  // keeps a pointer to the workspace
  /// Exact, for p in free space: segment pq keeps r from every obstacle and lies in free space.
  bool segment(const Point& p, const Point& q) const;
  /// Exact, for p in free space: the arc from `p` turning by `turn` (radius `radius`),
  /// sampled at `samples` (the chord ends after p, the last one the arc's end), keeps r.
  bool arc(const Point& p, const std::vector<Point>& samples, double radius, double turn) const;
  /// The chord ends of the arc piece from pose p (not including p), at most kChordTurn apart.
  static std::vector<Point> sample_arc(const Pose& p, double radius, double turn);
  /// The exact clearance tests it decides with (radius r).
  const geometry::Clearance& clearance() const { return clearance_; }

 private:
  double r_;
  geometry::Clearance clearance_;
};

}  // namespace preimage::coverage
