// SPDX-License-Identifier: Apache-2.0
// Path planning on the trapezoidal decomposition (section 6.1): locate start and goal,
// search the adjacency graph, and connect extension midpoints and cell centroids into
// a collision-free polyline; optionally shortened with exact visibility checks.
#pragma once
#include <preimage/decompose/cell_locator.hpp>
#include <preimage/geometry/visibility.hpp>

#include <optional>
#include <string>

namespace preimage::decompose {

struct Plan {
  bool found = false;
  std::vector<Point> path;           // start ... goal (empty when not found)
  std::vector<std::uint32_t> cells;  // cells crossed, in order
  double length = 0;
};

class TrapezoidalPlanner {
 public:
  explicit TrapezoidalPlanner(const TrapezoidalDecomposition& d);
  TrapezoidalPlanner(TrapezoidalDecomposition&&) = delete;  // keeps a pointer to the decomposition
  /// Throws InputError when start or goal is not in free space (naming which and where).
  /// Cells are joined through extensions and, where rings touch, through the contact point
  /// (cells meeting only there: free space is closed, a point robot passes). `found` is
  /// false when nothing connects them (never for a valid Environment, whose free space is
  /// connected).
  /// Shortening asks exact visibility of `index` (of the same environment) when given,
  /// else of one it builds: O(k) per segment for the k triangles it crosses, not O(n).
  Plan plan(const Point& start, const Point& goal, bool shorten = true, const geometry::VisibilityIndex* index = nullptr) const;

  const CellLocator& locator() const { return locator_; }
  /// Double approximations used for the path (midpoint of an extension, cell centroid).
  Point extension_midpoint(std::size_t x) const;
  Point centroid(std::size_t cell) const;

 private:
  const TrapezoidalDecomposition* d_;
  CellLocator locator_;
  // Cells whose closure holds each contact point (CSR: contact k's cells are
  // contact_cells_[contact_off_[k] .. contact_off_[k + 1]), and the contacts of each cell.
  std::vector<Point> contacts_;
  std::vector<std::uint32_t> contact_off_, contact_cells_;
  std::vector<std::vector<std::uint32_t>> cell_contacts_;
};

enum class PlanMethod { Shortest, Trapezoidal };

struct RobotPlan {
  bool found = false;
  std::vector<Point> path;            // start ... goal, certified
  double length = 0;
  std::size_t decomposition_cells = 0, cells_crossed = 0;  // Trapezoidal only
  std::string why_not;                // when not found
};

/// A collision-free path for a disc robot of radius r (r = 0: a point) from start to goal:
/// the shortest one (visibility graph of the configuration space), or through the
/// trapezoidal decomposition of the configuration space (6.1; `shorten` pulls the string).
/// Every segment is certified: inside the polygonal configuration space (exact) and at
/// distance >= r from every obstacle (exact arithmetic). Throws InputError when start or
/// goal is not a place the robot fits; `found` is false, with the reason, when they are in
/// different components (a passage narrower than 2r between them).
RobotPlan plan_path(const Environment& env, const Point& start, const Point& goal, double radius,
                    PlanMethod method = PlanMethod::Shortest, bool shorten = true);

}  // namespace preimage::decompose
