// SPDX-License-Identifier: Apache-2.0
// Exact clearance tests for a disc robot: is a point, or every point of a segment, in free
// space and at distance >= r from every obstacle edge? A uniform grid of the edges finds
// the candidates, a double filter settles the clear cases, and exact (rational)
// arithmetic the rest. It builds no polygon, so it certifies paths anywhere in the
// supported range (ConfigurationSpace builds its polygonal approximation on top of it).
#pragma once
#include <preimage/geometry/environment.hpp>

#include <memory>

namespace preimage::geometry {

class Clearance {
 public:
  /// Throws InputError if r is negative or not finite.
  Clearance(const Environment& workspace, double radius);
  Clearance(Environment&&, double) = delete;  // keeps a pointer to the workspace
  ~Clearance();
  Clearance(Clearance&&) noexcept;
  Clearance& operator=(Clearance&&) noexcept;

  double radius() const { return radius_; }
  /// Exact: p is in free space at distance >= r from every obstacle edge.
  bool admits(const Point& p) const;
  /// Exact: every point of segment pq is (for r == 0: pq lies in closed free space).
  bool admits(const Point& p, const Point& q) const;
  /// Exact: segment pq is at distance >= r from every workspace edge (it may lie outside).
  bool clear(const Point& p, const Point& q, double r) const;
  /// Distance from p to the nearest obstacle edge, in double (for messages, not decisions).
  double distance(const Point& p) const;
  /// The nearest point of the obstacle edges to p, in double (a direction to move away, not
  /// a decision).
  Point nearest(const Point& p) const;

 private:
  struct EdgeGrid;
  const Environment* workspace_;
  double radius_;
  std::unique_ptr<EdgeGrid> grid_;
};

}  // namespace preimage::geometry
