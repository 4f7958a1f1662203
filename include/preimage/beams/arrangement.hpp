// SPDX-License-Identifier: Apache-2.0
// The planar subdivision of free space by obstacles and beams (beams paper, 2 and 4.1):
// vertices (environment vertices, beam endpoints, exact beam crossings), half-edges
// with faces on their left, regions (the free 2-cells) each with an exact sample
// point strictly inside, and the directed labelled multigraph G whose edge r1 -> r2
// carries the observation made when a body crosses from r1 into r2.
//
// The subdivision itself is geometry::SegmentArrangement (shared with the pursuit
// module's conservative cells); this class validates the beams, feeds them to it and
// builds G. CGAL's Arrangement_2 serves only as a test oracle. A scene without an
// environment is the unbounded plane with point landmarks: the subdivision is then
// built inside a box that strictly contains every landmark and beam crossing, which
// changes no region's combinatorics.
#pragma once
#include <preimage/beams/alphabet.hpp>
#include <preimage/filter/transition_system.hpp>
#include <preimage/geometry/environment.hpp>
#include <preimage/geometry/segment_arrangement.hpp>
#include <preimage/scene/scene.hpp>

#include <optional>
#include <string>
#include <vector>

namespace preimage::beams {

using geometry::ExactPoint;
inline constexpr std::uint32_t kNone = UINT32_MAX;
/// The outer boundary (or, for a landmark scene, infinity) where an obstacle index goes.
inline constexpr std::uint32_t kOuter = UINT32_MAX - 1;

/// One validated beam, clipped to a segment from `from` to `to`.
struct BeamGeometry {
  std::uint32_t label;
  bool directed;
  scene::Beam::Shape shape;
  ExactPoint from, to;
  bool unbounded_from = false, unbounded_to = false;  // clipped by the box, not a real end
  // What each end is attached to: an obstacle index, or kOuter (the outer boundary,
  // or infinity for an unbounded end).
  std::uint32_t from_obstacle = kOuter, to_obstacle = kOuter;
};

struct HalfEdge {
  std::uint32_t origin, target;
  std::uint32_t next = kNone;  // next half-edge around the face on the left
  std::uint32_t face = kNone;
  std::uint32_t beam = kNone;  // kNone: a piece of the boundary
};

/// A crossing of G: from region `from` into region `to` across beam piece `half_edge`
/// (a half-edge whose face is `to`), observing `symbol`. G is a multigraph (4.1): every
/// beam piece gives two crossings, one per direction, even where another piece with
/// the same label joins the same two regions.
struct Crossing {
  std::uint32_t from, to;
  Symbol symbol;
  std::uint32_t half_edge;
};

struct Region {
  ExactPoint sample;                   // strictly inside
  std::vector<std::uint32_t> cycles;   // one half-edge per boundary cycle (outer first)
};

class BeamArrangement {
 public:
  /// Validates the scene's beams and builds the subdivision and G. Throws InputError
  /// naming the beam ("$.beams[3] ('a'): ...") for every violated condition: endpoints
  /// off the boundary, interior touching an obstacle, through a vertex, a landmark or
  /// another beam's crossing, overlapping beams, mixed directedness of one label.
  static BeamArrangement build(const scene::Scene& scene);

  const Alphabet& alphabet() const { return alphabet_; }
  const std::vector<BeamGeometry>& beams() const { return beams_; }
  /// The environment the subdivision lives in (the box for a landmark scene).
  const geometry::Environment& environment() const { return env_; }
  bool unbounded() const { return unbounded_; }
  const std::vector<geometry::Point>& landmarks() const { return landmarks_; }

  /// The obstacles o_1..o_n of the paper (section 2): the environment's holes, or the
  /// point landmarks of a scene without an environment. Indices are 0-based.
  std::size_t num_obstacles() const { return unbounded_ ? landmarks_.size() : env_.num_holes(); }
  /// "o2 ($.environment.obstacles[1])" or "o2 (landmark 'b')".
  std::string obstacle_name(std::uint32_t obstacle) const;
  /// A point of obstacle i's boundary (a landmark itself): what winding numbers wind around.
  ExactPoint obstacle_point(std::uint32_t obstacle) const;
  /// The obstacle a vertex lies on, kOuter for the outer boundary, kNone for a crossing of beams.
  std::uint32_t vertex_obstacle(std::uint32_t vertex) const { return vertex_obstacle_[vertex]; }

  const std::vector<ExactPoint>& vertices() const { return arr_.vertices(); }
  const std::vector<HalfEdge>& half_edges() const { return half_edges_; }
  static std::uint32_t twin(std::uint32_t h) { return h ^ 1u; }
  /// Half-edges of beam i's pieces, in order from -> to: [first, last), even ids (step 2).
  std::pair<std::uint32_t, std::uint32_t> beam_pieces(std::uint32_t i) const { return arr_.segment_pieces(i); }
  /// Half-edges of a region (all its boundary cycles).
  std::span<const std::uint32_t> region_half_edges(std::uint32_t r) const { return arr_.region_half_edges(r); }
  /// Region on the left of half-edge h, kNone for obstacle interiors and the outside.
  std::uint32_t region_of(std::uint32_t h) const { return arr_.region_of(h); }

  std::size_t num_regions() const { return regions_.size(); }
  const std::vector<Region>& regions() const { return regions_; }
  std::size_t num_crossings() const { return arr_.num_crossings(); }  // beam-beam crossing points
  /// The subdivision (shared representation).
  const geometry::SegmentArrangement& subdivision() const { return arr_; }

  /// G's transition relation over regions: one transition per distinct (from, symbol,
  /// to), which is all a region filter or a region sequence can tell apart.
  const filter::TransitionSystem& graph() const { return graph_; }
  /// The multigraph G itself: one edge per beam piece and direction (2 per piece),
  /// sorted by (from, symbol, to, half_edge).
  const std::vector<Crossing>& edges() const { return edges_; }
  /// The first edge from -> to observing y (the lowest half-edge), or nullptr.
  const Crossing* find_edge(std::uint32_t from, Symbol y, std::uint32_t to) const;
  /// Number of beam pieces: maximal parts of beams between crossings and ends.
  std::size_t num_pieces() const {
    return beams_.empty() ? 0 : (arr_.segment_pieces(beams_.size() - 1).second - arr_.segment_pieces(0).first) / 2;
  }
  /// Which piece half-edge h (of a beam) is: its beam and its index along the beam,
  /// counted from 0 at the beam's `from` end.
  struct Piece {
    std::uint32_t beam, index;
  };
  Piece piece(std::uint32_t h) const;

  /// Region strictly containing p, or nullopt if p is on a beam, on the boundary or
  /// outside free space. O(edges).
  std::optional<std::uint32_t> locate(const ExactPoint& p) const { return arr_.locate(p); }

 private:
  Alphabet alphabet_;
  std::vector<BeamGeometry> beams_;
  geometry::Environment env_;
  bool unbounded_ = false;
  std::vector<geometry::Point> landmarks_;
  geometry::SegmentArrangement arr_;
  std::vector<HalfEdge> half_edges_;  // arr_'s half-edges with beam ids
  std::vector<std::uint32_t> vertex_obstacle_;
  std::vector<std::string> landmark_labels_;
  std::vector<Region> regions_;
  filter::TransitionSystem graph_;
  std::vector<Crossing> edges_;

  friend class ArrangementBuilder;
};

}  // namespace preimage::beams
