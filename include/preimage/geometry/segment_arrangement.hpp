// SPDX-License-Identifier: Apache-2.0
// The planar subdivision of free space by segments among obstacles: vertices (environment
// vertices, segment ends, exact crossings of any multiplicity), half-edges with faces on
// their left, and the free faces ("regions") each with an exact sample point strictly
// inside. Shared by the beams module (sensor beams) and the pursuit module (critical rays
// of the conservative cells); CGAL's Arrangement_2 serves only as a test oracle.
//
// Input segments end on the boundary (inside an edge or at a vertex) or at isolated points
// of free space (landmarks), and their interiors lie in free space. Any number of segments
// may cross at one point; a segment may not end on another's interior nor overlap one:
// such contacts are reported to the caller's policy (which throws its own message) and are
// otherwise a logic error. Decisions use exact predicates on the input coordinates and
// lazy-exact crossing points.
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/geometry/triangulation.hpp>  // kNone

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace preimage::geometry {

/// Where a segment ends: inside boundary edge `index`, at environment vertex `index`, or
/// at isolated point `index` of the arrangement's point list.
struct SegmentEnd {
  enum class Kind : std::uint8_t { OnEdge, AtVertex, AtPoint };
  Kind kind;
  std::uint32_t index;
};

struct ArrangementSegment {
  ExactPoint from, to;
  SegmentEnd from_end, to_end;
  /// Two input points on the segment's supporting line: crossings are then constructed
  /// from lines of input doubles (one lazy node per crossing). Without them the line
  /// through the exact ends is used.
  std::optional<std::pair<Point, Point>> carrier;
};

struct ArrangementHalfEdge {
  std::uint32_t origin, target;
  std::uint32_t next = kNone;     // next half-edge around the face on the left
  std::uint32_t face = kNone;
  std::uint32_t segment = kNone;  // kNone: a piece of the boundary
};

/// How two segments touch without crossing properly.
enum class SegmentContactKind : std::uint8_t { Overlap, FirstEndsOnSecond, SecondEndsOnFirst };

/// Validation hooks; each may throw the caller's own error. A policy that returns from
/// `contact` leaves a logic error (the arrangement cannot represent the contact).
struct ArrangementPolicy {
  virtual ~ArrangementPolicy() = default;
  /// Segments i < j (or j < i, in the order found) touch as `kind` (first = i).
  virtual void contact(std::size_t i, std::size_t j, SegmentContactKind kind) const = 0;
  /// Segment i meets segments a and b at one point p (three or more through a point).
  /// The default accepts it: the crossing becomes one vertex.
  virtual void multiple(std::size_t /*i*/, std::size_t /*a*/, std::size_t /*b*/, const ExactPoint& /*p*/) const {}
};

class SegmentArrangement {
 public:
  /// `points`: isolated points segments may end at (SegmentEnd::AtPoint); one vertex is made
  /// for each point some segment uses. Throws std::logic_error on contacts the policy accepts.
  ///
  /// Where rings touch at a point (Environment contacts) each ring's vertex there is its own
  /// arrangement vertex by default: the rings are unglued, and the free wedges around the
  /// point belong to faces that pass it (right for a sensor that sees nothing there, e.g.
  /// beams). With `glue_contacts` every edge and segment at the point meets at one vertex
  /// (the smallest id there), so each wedge's faces end at the point; the vertices of the
  /// other ids there are left without edges.
  static SegmentArrangement build(Environment env, std::vector<ArrangementSegment> segments,
                                  const std::vector<ExactPoint>& points = {}, const ArrangementPolicy* policy = nullptr,
                                  bool glue_contacts = false);

  /// The environment the subdivision lives in (a copy owned by the arrangement).
  const Environment& environment() const { return env_; }
  const std::vector<ArrangementSegment>& segments() const { return segments_; }
  const std::vector<ExactPoint>& vertices() const { return vertices_; }
  /// Vertex coordinates rounded from their intervals (for drawing, sorting, reports).
  const std::vector<Point>& approx_vertices() const { return approx_; }
  const std::vector<ArrangementHalfEdge>& half_edges() const { return half_edges_; }
  static std::uint32_t twin(std::uint32_t h) { return h ^ 1u; }

  /// Vertex at each end of segment i.
  std::uint32_t from_vertex(std::size_t i) const { return end_vertex_[2 * i]; }
  std::uint32_t to_vertex(std::size_t i) const { return end_vertex_[2 * i + 1]; }
  /// Half-edges of segment i's pieces, in order from -> to: [first, last), even ids (step 2);
  /// the even half-edge of a piece runs from -> to.
  std::pair<std::uint32_t, std::uint32_t> segment_pieces(std::size_t i) const { return {seg_he_[i], seg_he_[i + 1]}; }
  /// Outgoing half-edges of vertex v, counter-clockwise from east.
  std::span<const std::uint32_t> outgoing(std::uint32_t v) const {
    return {out_.data() + out_begin_[v], out_.data() + out_begin_[v + 1]};
  }

  /// Free faces (regions), numbered by sample point left to right.
  std::size_t num_regions() const { return sample_.size(); }
  /// An exact point strictly inside region r.
  const ExactPoint& sample(std::size_t r) const { return sample_[r]; }
  /// One half-edge per boundary cycle of region r, the outer cycle first.
  const std::vector<std::uint32_t>& region_cycles(std::size_t r) const { return cycles_[r]; }
  /// All half-edges of region r.
  std::span<const std::uint32_t> region_half_edges(std::size_t r) const {
    return {region_he_.data() + region_he_begin_[r], region_he_.data() + region_he_begin_[r + 1]};
  }
  /// The even half-edge of boundary edge e's first piece (from vertex e, or from the glued
  /// vertex at its point): the region on its left is the face of e's free wedge there.
  std::uint32_t first_piece(std::size_t e) const { return edge_he_[e]; }
  /// Region on the left of half-edge h, kNone for obstacle interiors and the outside.
  std::uint32_t region_of(std::uint32_t h) const { return face_region_[half_edges_[h].face]; }
  /// Number of vertices where two or more segments cross.
  std::size_t num_crossings() const { return crossings_; }

  /// Region strictly containing p, or nullopt if p is on a segment, on the boundary or
  /// outside free space. O(edges).
  std::optional<std::uint32_t> locate(const ExactPoint& p) const { return locate(p, false); }
  /// A region whose closure holds p (for p on a segment or at a crossing: one of the regions
  /// around it), nullopt if p is on the environment's boundary or outside free space.
  std::optional<std::uint32_t> locate_closed(const ExactPoint& p) const { return locate(p, true); }
  /// Is p strictly inside region r? Exact, O(size of the region).
  bool strictly_inside(std::size_t r, const ExactPoint& p) const;

 private:
  std::optional<std::uint32_t> locate(const ExactPoint& p, bool closed) const;

  Environment env_;
  std::vector<ArrangementSegment> segments_;
  std::vector<ExactPoint> vertices_;
  std::vector<Point> approx_;
  std::vector<double> xlo_, xhi_;  // each vertex's x interval: locate's filter
  std::vector<ArrangementHalfEdge> half_edges_;
  std::vector<std::uint32_t> end_vertex_;
  std::vector<std::uint32_t> edge_he_;
  std::vector<std::uint32_t> seg_he_;
  std::vector<std::uint32_t> out_begin_, out_;
  std::vector<std::uint32_t> face_region_;
  std::vector<ExactPoint> sample_;
  std::vector<std::vector<std::uint32_t>> cycles_;
  std::vector<std::uint32_t> region_he_begin_, region_he_;
  std::size_t crossings_ = 0;

  friend class SegmentArrangementBuilder;
};

}  // namespace preimage::geometry
