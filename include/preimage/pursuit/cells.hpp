// SPDX-License-Identifier: Apache-2.0
// The conservative cell decomposition of section 6.3: the arrangement of the critical
// segments (critical.hpp) with the environment. Every cell is convex; inside a cell the
// gaps of V(x) and the shadow components they bound do not change (a cell is
// "conservative"), so each cell stores them once, computed at a sample point. Every
// boundary between two cells (a piece of a critical segment) carries the exact gap
// transition: which shadow components on one side share evader positions with which on
// the other (appear, disappear, split, merge: rules 1-4), as a filter::ShadowEvent.
//
// The transition at a boundary is the limit of the shadows on both sides at a point b of
// it: a component on side A corresponds to one on side B iff both contain a component of
// the shadow at b. Components behind gaps that persist across the line keep their
// correspondence; the ones touching the line are found from the sight line along it
// (contacts and walls, critical.hpp) by a case-free local analysis (transitions.cpp).
#pragma once
#include <preimage/filter/shadow_labels.hpp>
#include <preimage/geometry/segment_arrangement.hpp>
#include <preimage/pursuit/critical.hpp>
#include <preimage/pursuit/shadows.hpp>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace preimage::geometry {
class VisibilityIndex;
}

namespace preimage::pursuit {

struct Cell {
  Point sample;                 // strictly inside, representable in doubles
  Shadows shadows;              // gaps and components of V(sample), the same at every point of the cell
  std::vector<Point> polygon;   // boundary, counter-clockwise (rounded, for drawing and reports)
  bool tiny = false;            // no double point lies inside: `sample` is only the rounding of an exact one
};

/// A boundary between two cells: a piece of critical segment `segment`, with `left` on
/// the left of the segment's direction (from its origin). `to_right` / `to_left` are the
/// exact transitions of the shadow components crossing it either way.
struct CellBoundary {
  std::uint32_t half_edge;  // even arrangement half-edge of the piece (left of it: `left`)
  std::uint32_t segment;
  std::uint32_t left, right;
  Point near_left, near_right;  // doubles strictly inside each cell; the segment between them crosses only this piece
  bool drawable = true;         // near_left / near_right exist (not so next to a tiny cell)
  filter::ShadowEvent to_right, to_left;
};

class ConservativeCells {
 public:
  /// Throws InputError for an environment the cells cannot be sampled in doubles (a cell
  /// thinner than double precision resolves), naming the critical rays near it.
  static ConservativeCells build(const Environment& env);

  const Environment& environment() const { return arr_->environment(); }
  const std::vector<CriticalSegment>& critical() const { return critical_; }
  const geometry::SegmentArrangement& arrangement() const { return *arr_; }
  const geometry::VisibilityIndex& visibility() const { return *vis_; }

  std::size_t size() const { return cells_.size(); }
  const Cell& cell(std::size_t c) const { return cells_[c]; }
  const std::vector<Cell>& cells() const { return cells_; }
  const std::vector<CellBoundary>& boundaries() const { return boundaries_; }
  /// Boundaries of cell c (indices into boundaries()).
  const std::vector<std::uint32_t>& boundaries_of(std::size_t c) const { return adjacent_[c]; }
  /// Shadows of V(p) (p in free space), as the cells' are computed.
  Shadows shadows_at(const Point& p) const;
  /// Number of reflex vertices of free space.
  std::size_t reflex_vertices() const { return reflex_; }
  /// Number of cells no double-precision point lies in (see Cell::tiny).
  std::size_t tiny_cells() const { return tiny_; }

  /// The cell strictly containing p, else one whose closure contains p (p on a critical
  /// segment or a vertex of the arrangement), else nullopt (p outside free space).
  std::optional<std::uint32_t> locate(const Point& p) const;
  /// Is p in the closed convex cell c? Exact.
  bool in_closed_cell(std::size_t c, const ExactPoint& p) const;
  /// Boundary a half-edge of the arrangement lies on, kNone for the environment's boundary.
  std::uint32_t boundary_of(std::uint32_t half_edge) const { return boundary_of_[half_edge]; }

  /// The boundaries the segment from p to q crosses, in order, each with its direction
  /// (true: from `left` to `right`), exactly; nullopt if p or q is not strictly inside a
  /// cell, or the segment passes through a vertex of the arrangement or leaves free space.
  struct Crossing {
    std::uint32_t boundary;
    bool rightward;
  };
  std::optional<std::vector<Crossing>> walk(const Point& p, const Point& q) const;

 private:
  std::vector<CriticalSegment> critical_;
  std::shared_ptr<const geometry::SegmentArrangement> arr_;
  std::shared_ptr<const geometry::VisibilityIndex> vis_;
  std::vector<Cell> cells_;
  std::vector<CellBoundary> boundaries_;
  std::vector<std::vector<std::uint32_t>> adjacent_;
  std::vector<std::uint32_t> boundary_of_;
  std::vector<std::uint32_t> pieces_;  // per environment edge: its piece of free space (contacts)
  std::size_t reflex_ = 0, tiny_ = 0;
};

/// What a pursuer infinitely close to a critical segment, on one side, sees along it
/// looking past one end: the contacts that are gaps for it, and for each strip beside the
/// line that is hidden from the segment itself, the gap vertices whose shadow holds it.
struct SightSide {
  std::vector<std::uint32_t> gaps;
  std::vector<std::array<std::vector<std::uint32_t>, 2>> tokens;  // [strip][0: the pursuer's side, 1: the other]
};
/// Both look directions for a pursuer left (index 0) or right (1) of the segment's direction.
struct SegmentSight {
  std::array<SightSide, 2> forward, backward;
};
SegmentSight analyse_sight(const CriticalSegment& s);

/// The gap transition across a boundary on critical segment s, from the cell with shadows
/// `a` on side `side_a` (+1: left of the segment's direction) to the cell with shadows `b`
/// on the other side. Throws std::logic_error when the cells' shadows disagree with the
/// sight line (a bug: the decomposition would not be conservative).
filter::ShadowEvent gap_transition(const SegmentSight& sight, int side_a, const Shadows& a, const Shadows& b);
inline filter::ShadowEvent gap_transition(const CriticalSegment& s, int side_a, const Shadows& a, const Shadows& b) {
  return gap_transition(analyse_sight(s), side_a, a, b);
}

}  // namespace preimage::pursuit
