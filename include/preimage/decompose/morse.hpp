// SPDX-License-Identifier: Apache-2.0
// Morse decompositions with variable slices (Choset et al., 6.2.2 and 6.2.3): the slices
// are the level sets of h, and the cells are the connected components of the free space
// minus the critical slice intervals I* (Definition 6.2.1).
//
//   circular  h = |p - c|            slices are circles around c        (Fig. 6.12)
//   spike     h = angle of p - c     slices are rays from c ("pie")      (Fig. 6.13)
//   squarel   h = |x-cx| + |y-cy|    slices are diamonds around c        (Fig. 6.14)
//
// Construction (one algorithm for the three): every boundary point where h restricted to
// the boundary may have an extremum is an *event* — each vertex, and inside an edge the foot
// of the perpendicular from c (circular) or a crossing of the axes through c (squarel, where
// the diamond has its corners and h its generalised gradient, 5.5.2). At an event the slice
// leaves in two directions; counting how many of them enter the free space classifies it:
// one is a regular point, none is a critical point where a slice interval is born or dies,
// two is a critical point where slice intervals split or merge. From a split/merge point the
// slice is followed both ways to the first point of the closed obstacle set: those arcs are
// the critical slice intervals. The boundary cut at their ends, plus the arcs, is a plane
// graph; its faces (traced with the free space on the left, inner components assigned to the
// innermost face around them) are the cells, and two cells are adjacent when they share an
// arc. Critical slices (arcs joined at critical points of the same level, or a lone
// birth/death point, or the centre when it is a minimum) are the Reeb graph's nodes.
//
// Exactness: event classification, the order of points along edges and where every arc ends
// are decided exactly. Vertices, feet of perpendiculars, axis crossings, ray and diamond hits
// are rational; circle hits are a + b*sqrt(d) with rational a, b, d and are ordered around
// the circle by a double filter with an exact fallback (RootNumber). Which face encloses an
// inner component is decided in double with a certified margin, and an input too close to
// call is rejected with an error, never guessed. Edges lying along a slice (spike: on a line
// through c; squarel: parallel to the diamond's side in its quadrant; h = x: vertical) form
// flat runs, each one critical event. Holes touching at a vertex are one graph point with a
// critical point per free wedge. Rejected with a one-line error: the centre on the boundary,
// a whole ring on one slice, a flat run ending at a contact.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace preimage::decompose {

using geometry::Environment;
using geometry::ExactFT;
using geometry::ExactPoint;
using geometry::Point;

/// Linear is h = x (vertical slices): the boustrophedon decomposition through this generic
/// construction, kept to check one against the other.
enum class SliceFamily : std::uint8_t { Circular, Spike, Squarel, Linear };
std::string_view to_string(SliceFamily f);
std::optional<SliceFamily> parse_slice_family(std::string_view s);

/// An exact real a + b * sqrt(d) with rational a, b and d >= 0.
struct RootNumber {
  ExactFT a = 0, b = 0, d = 0;
  int sign() const;
  double approx() const;
};
/// Sign of the cross product (p - o) x (q - o) of points with RootNumber coordinates (each
/// point's two coordinates share one d); exact.
int root_orientation(const RootNumber& ox, const RootNumber& oy, const RootNumber& px, const RootNumber& py,
                     const RootNumber& qx, const RootNumber& qy);

/// A vertex of the decomposition's plane graph.
struct MorsePoint {
  enum class Kind : std::uint8_t { Vertex, OnEdge, Centre };
  Kind kind = Kind::Vertex;
  std::uint32_t id = 0;   // environment vertex or edge id (unused for the centre)
  RootNumber x, y;        // exact coordinates (b == 0 unless a circle hit inside an edge)
  Point approx;
};

enum class CriticalKind : std::uint8_t {
  SplitMerge,  // the slice passes through with free space both ways: intervals split or merge
  BirthDeath,  // the slice only touches: an interval is born or dies here
  Minimum,     // the centre, inside the free space (circular, squarel)
};

struct MorseCritical {
  std::uint32_t point;   // into points()
  CriticalKind kind;
  double level;          // h there (radians for spike, in [0, 2 pi))
  std::uint32_t node;    // Reeb graph node
};

/// A critical slice interval between two points of the graph, along the slice.
struct MorseArc {
  std::uint32_t from, to;
  bool ccw;              // circular/squarel: counter-clockwise around c; spike: outwards
  ExactFT level;         // circular: squared radius; squarel: L1 level; spike: 0
  std::uint32_t node;
  /// Drawing: the arc as points (circle arcs sampled; squarel includes its corners).
  std::vector<Point> polyline(double max_error) const;
  SliceFamily family = SliceFamily::Circular;
  Point centre, a, b;          // approximations of the centre and the two ends
  std::vector<Point> corners;  // squarel: the diamond's corners passed, in order (exact values rounded)
  /// Signed angle swept around the centre (circular: in (-2 pi, 2 pi], the sign is the direction).
  double span = 0;
};

/// A piece of a cell's boundary: a piece of an environment edge (arc < 0) or an arc, run
/// from `from` to `to` (an arc may be run backwards).
struct MorsePiece {
  std::uint32_t from, to;
  std::int32_t arc = -1;      // index into arcs(), or -1
  std::uint32_t edge = 0;     // environment edge (boundary pieces)
  bool forward = true;        // an arc run from its `from` to its `to`
};

struct MorseCell {
  /// Boundary cycles: the first counter-clockwise (outer), then clockwise ones around the
  /// obstacles and critical slices inside the cell (annular cells of 6.2.3).
  std::vector<std::vector<MorsePiece>> cycles;
  std::vector<std::uint32_t> nodes;  // Reeb nodes on its closure (2 in general position)
  double area = 0;                   // circular pieces integrated exactly, summed in double
};

class MorseDecomposition {
 public:
  /// Throws InputError for a degenerate input (see above). `centre` is ignored for Linear.
  MorseDecomposition(const Environment& env, SliceFamily family, const Point& centre);
  MorseDecomposition(Environment&&, SliceFamily, const Point&) = delete;  // keeps a pointer

  SliceFamily family() const { return family_; }
  const Point& centre() const { return centre_; }
  const Environment& environment() const { return *env_; }
  bool centre_in_free_space() const { return centre_free_; }
  const std::vector<MorsePoint>& points() const { return points_; }
  const std::vector<MorseCritical>& critical_points() const { return critical_; }
  const std::vector<MorseArc>& arcs() const { return arcs_; }
  const std::vector<MorseCell>& cells() const { return cells_; }
  std::size_t num_nodes() const { return num_nodes_; }
  /// Reeb graph: per cell, the nodes it joins; cells adjacent when they share an arc.
  std::vector<std::vector<std::uint32_t>> adjacency() const;
  /// h at a point (double; radians in [0, 2 pi) for spike).
  double level(const Point& p) const;
  /// A cell's cycles as closed polylines (circle arcs sampled within max_error).
  std::vector<std::vector<Point>> cell_rings(std::size_t cell, double max_error) const;
  /// The cell containing p (double test; nullopt outside the free space or on a boundary).
  std::optional<std::size_t> cell_of(const Point& p) const;
  /// First Betti number of the domain h is defined on: holes, plus one for spike when the
  /// centre is in the free space (h is undefined there).
  std::size_t domain_loops() const;

 private:
  void build();
  const Environment* env_;
  SliceFamily family_;
  Point centre_;
  bool centre_free_ = false;
  std::vector<MorsePoint> points_;
  std::vector<MorseCritical> critical_;
  std::vector<MorseArc> arcs_;
  std::vector<MorseCell> cells_;
  std::size_t num_nodes_ = 0;
};

}  // namespace preimage::decompose
