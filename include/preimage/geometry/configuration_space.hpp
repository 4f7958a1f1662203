// SPDX-License-Identifier: Apache-2.0
// The configuration space of a disc robot of radius r: the points of free space at
// distance at least r from every obstacle (free space eroded by the disc).
//
// Its exact boundary has straight pieces (edges offset by r) and circular arcs around the
// convex corners of obstacles. The planners work on a polygonal approximation that is
// *certified to lie inside* the exact set: Clipper (Boost licence) offsets the boundary
// inwards by r plus a margin covering its arc chords and its integer grid, and the result
// is then checked with exact arithmetic (every edge at distance >= r from every obstacle
// edge, every ring in free space, no obstacle inside). What the approximation gives away
// is at most `approximation_error()` next to the exact boundary.
//
// Components that meet only where the exact set pinches to a point are kept apart: a
// disc of positive radius cannot pass such a point.
#pragma once
#include <preimage/geometry/clearance.hpp>
#include <preimage/geometry/environment.hpp>

#include <memory>
#include <optional>
#include <vector>

namespace preimage::geometry {

class ConfigurationSpace {
 public:
  /// r >= 0; r == 0 gives the free space itself (one component, the environment). Throws
  /// InputError if r is negative or not finite.
  ConfigurationSpace(const Environment& workspace, double radius);
  ConfigurationSpace(Environment&&, double) = delete;  // keeps a pointer to the workspace
  ~ConfigurationSpace();
  ConfigurationSpace(ConfigurationSpace&&) noexcept;
  ConfigurationSpace& operator=(ConfigurationSpace&&) noexcept;

  const Environment& workspace() const { return *workspace_; }
  double radius() const { return radius_; }
  /// Polygonal components, largest area first (none when the robot fits nowhere).
  const std::vector<Environment>& components() const { return components_; }
  /// Largest distance by which the polygonal boundary may lie inside the exact one.
  double approximation_error() const { return error_; }
  /// The component whose closed region holds p, if any.
  std::optional<std::size_t> component_of(const Point& p) const;
  /// Where an admitted point p joins the polygonal components: p itself inside one, else
  /// (p in the thin band the approximation gives away) the nearest boundary point q of a
  /// component with segment pq admitted. None if p is not admitted or no such q exists.
  struct Entry {
    std::size_t component;
    Point at;
  };
  std::optional<Entry> entry(const Point& p) const;

  /// Exact: p is in free space at distance >= r from every obstacle edge.
  bool admits(const Point& p) const { return clearance_.admits(p); }
  /// Exact: every point of segment pq is (the segment stays r away from all obstacles).
  bool admits(const Point& p, const Point& q) const { return clearance_.admits(p, q); }
  /// Distance from p to the nearest obstacle edge, in double (for messages, not decisions).
  double clearance(const Point& p) const { return clearance_.distance(p); }

 private:
  const Environment* workspace_;
  double radius_;
  Clearance clearance_;
  double error_ = 0;
  std::vector<Environment> components_;
};

}  // namespace preimage::geometry
