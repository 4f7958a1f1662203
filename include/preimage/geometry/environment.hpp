// SPDX-License-Identifier: Apache-2.0
// Environment = bounded outer boundary with polygonal holes that may touch one another or
// the outer boundary at single vertices (a weakly simple domain, as maps built from tiles
// or wall rectangles are).
#pragma once
#include <preimage/geometry/kernel.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace preimage::geometry {

using Ring = std::vector<Point>;

/// A validated environment. Vertices of all rings are stored flat: ring r occupies
/// [ring_begin(r), ring_end(r)); ring 0 is the outer boundary (counter-clockwise),
/// rings 1.. are holes (clockwise), so free space is always to the left of every
/// directed edge v -> next(v). Edge e is identified with its start vertex e.
///
/// Contacts. Rings may meet at a *contact*: one point where vertices of two or more rings
/// coincide (never a vertex on another ring's edge, never a shared edge, never a ring
/// touching itself). Free space is closed, so it contains the contact point and a segment
/// may pass through it. Around a contact the rings' material sectors alternate with *free
/// wedges*: the wedge that starts (counter-clockwise) at the out-edge v -> next(v) of one
/// ring vertex v ends at the in-edge prev(u) -> u of another, u = wedge_end(v). Without
/// contacts wedge_end(v) == v. Vertex ids stay one per ring vertex: a contact point has as
/// many ids as rings meeting there, linked by same_point_next().
class Environment {
 public:
  /// Validates and normalises orientation. Throws InputError naming the element
  /// ("obstacles[2]: edges 3 and 7 intersect near (1.5, 2)"); `outer_name` and
  /// `hole_prefix` let callers put the element in their own terms (e.g. JSON paths).
  static Environment make(Ring outer, std::vector<Ring> holes,
                          const std::string& outer_name = "boundary",
                          const std::string& hole_prefix = "obstacles");

  std::size_t num_vertices() const { return pts_.size(); }
  std::size_t num_rings() const { return ring_begin_.size() - 1; }
  std::size_t num_holes() const { return num_rings() - 1; }
  const std::vector<Point>& vertices() const { return pts_; }
  const Point& vertex(std::size_t v) const { return pts_[v]; }
  /// The same vertex as a lazy-exact point (shared handle, no construction per call).
  const ExactPoint& exact_vertex(std::size_t v) const { return exact_pts_[v]; }
  /// Supporting line of edge e, lazy-exact, built once (ray hits are constructed against it).
  const ExactKernel::Line_2& exact_edge_line(std::size_t e) const { return exact_lines_[e]; }

  std::size_t ring_begin(std::size_t r) const { return ring_begin_[r]; }
  std::size_t ring_end(std::size_t r) const { return ring_begin_[r + 1]; }
  std::size_t ring_size(std::size_t r) const { return ring_end(r) - ring_begin(r); }
  std::size_t ring_of(std::size_t v) const { return ring_of_[v]; }
  std::size_t next(std::size_t v) const { return v + 1 == ring_end(ring_of_[v]) ? ring_begin(ring_of_[v]) : v + 1; }
  std::size_t prev(std::size_t v) const { return v == ring_begin(ring_of_[v]) ? ring_end(ring_of_[v]) - 1 : v - 1; }
  Segment edge(std::size_t e) const { return Segment(pts_[e], pts_[next(e)]); }

  /// Vertices of ring r in stored (normalised) order.
  Ring ring(std::size_t r) const;
  /// Vertex index in the caller's input ring (before orientation was normalised).
  std::size_t input_index(std::size_t v) const { return input_index_[v]; }
  /// Edge e as the caller wrote it: edge k of its ring runs from input vertex k to k + 1.
  std::size_t input_edge_index(std::size_t e) const {
    const std::size_t a = input_index_[e], b = input_index_[next(e)], n = ring_size(ring_of(e));
    return b == (a + 1) % n ? a : b;  // the ring was reversed when b precedes a
  }
  /// "boundary" / "obstacles[k]" (as given to make()).
  const std::string& ring_name(std::size_t r) const { return ring_names_[r]; }

  /// Turn at v: +1 convex, 0 straight (collinear neighbours), -1 reflex (w.r.t. free space).
  /// At a contact this is the turn of v's own ring (its material sector), not of a wedge.
  int turn(std::size_t v) const { return orientation(pts_[prev(v)], pts_[v], pts_[next(v)]); }
  bool is_reflex(std::size_t v) const { return turn(v) < 0; }

  /// Number of contact points (0 for an environment with disjoint rings).
  std::size_t num_contacts() const { return num_contacts_; }
  bool has_contacts() const { return num_contacts_ != 0; }
  /// Sum over contact points of (rings there - 1): vertices minus distinct points. It
  /// enters Euler's formula: a contact of k rings unglued into k points raises the Euler
  /// characteristic of free space by k - 1, so the boustrophedon Reeb graph has
  /// N_cells = N_critical + N_holes - 1 - contact_merges() (docs/decompose.md).
  std::size_t contact_merges() const { return contact_merges_; }
  /// Is v at a contact (another ring has a vertex at the same point)?
  bool is_contact(std::size_t v) const { return same_next_[v] != v; }
  /// The next vertex id at the same point (cyclic; v itself when v is not at a contact).
  std::size_t same_point_next(std::size_t v) const { return same_next_[v]; }
  /// The vertex whose in-edge ends the free wedge starting at v's out-edge (v if none).
  std::size_t wedge_end(std::size_t v) const { return wedge_end_[v]; }
  /// The inverse: the vertex whose out-edge starts the free wedge ending at u's in-edge.
  std::size_t wedge_start(std::size_t u) const { return wedge_start_[u]; }
  /// Turn of the free wedge starting at v: orientation(prev(wedge_end(v)), v, next(v)).
  int wedge_turn(std::size_t v) const { return orientation(pts_[prev(wedge_end_[v])], pts_[v], pts_[next(v)]); }
  /// The neighbour before the free wedge starting at v (the tail of the in-edge ending it);
  /// the one after it is next(v). Without contacts prev(v).
  std::size_t wedge_prev(std::size_t v) const { return prev(wedge_end_[v]); }
  /// Is there an environment edge from the point of a to the point of b? Its id, or
  /// SIZE_MAX. O(1) without contacts (next(a) == b), O(rings at the point) with.
  std::size_t edge_between(std::size_t a, std::size_t b) const;

  /// Free area (outer minus holes), computed in double for reports; exact value: exact_area().
  double area() const;
  ExactFT exact_area() const;
  /// The same environment moved by (-dx, -dy). Only for exact translations (every
  /// difference representable: geometry::LocalFrame checks it); rings, names and indices
  /// are kept.
  Environment translated(double dx, double dy) const;
  /// Bounding box of the outer boundary.
  CGAL::Bbox_2 bbox() const;

 private:
  void link_contacts(const std::vector<std::string>& names, const std::vector<std::uint32_t>& input_rep);

  std::vector<Point> pts_;
  std::vector<ExactPoint> exact_pts_;
  std::vector<ExactKernel::Line_2> exact_lines_;
  std::vector<std::size_t> ring_begin_;
  std::vector<std::uint32_t> ring_of_;
  std::vector<std::size_t> input_index_;
  std::vector<std::string> ring_names_;
  std::vector<std::uint32_t> same_next_, wedge_end_, wedge_start_;
  std::size_t num_contacts_ = 0, contact_merges_ = 0;
};

}  // namespace preimage::geometry
