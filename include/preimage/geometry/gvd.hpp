// SPDX-License-Identifier: Apache-2.0
// The generalized Voronoi diagram (GVD) of an environment: the points of free space
// equidistant to two or more different obstacles (section 6.2.3, Fig. 6.15), with the
// distance function D (clearance) and its critical points on the GVD.
//
// Built on Boost.Polygon's Voronoi diagram of segments (Boost licence; exact predicates on
// int32 input): the environment is snapped to a power-of-two grid (the *resolution*),
// the snapped segments are checked exactly to meet only at shared endpoints, and the
// output is checked before it is returned (docs/geometry.md, "Generalized Voronoi
// diagram").
#pragma once
#include <preimage/geometry/environment.hpp>

#include <cstdint>
#include <vector>

namespace preimage::geometry {

class LocalFrame;

/// A site of the Voronoi diagram: an environment vertex (a point site) or an environment
/// edge (the open segment), with the obstacle it belongs to.
struct GvdSite {
  enum class Kind : std::uint8_t { Vertex, Edge };
  Kind kind = Kind::Vertex;
  std::uint32_t index = 0;     // environment vertex id or edge id
  std::uint32_t obstacle = 0;  // GeneralizedVoronoiDiagram::obstacle_of_ring(ring of index)
};

struct GvdVertex {
  Point p;                  // world coordinates (doubles)
  double clearance = 0;     // distance to the nearest obstacle (of the snapped environment)
  std::uint32_t degree = 0; // number of GVD edges at the vertex (2: the sites change, not the obstacles)
};

/// A GVD edge: a piece of the bisector of two sites of different obstacles, from vertex
/// `from` to vertex `to`. Straight for point-point and segment-segment sites, a parabolic
/// arc for a point and a segment.
struct GvdEdge {
  GvdSite sites[2];
  std::uint32_t from = 0, to = 0;   // GvdVertex ids
  bool curved = false;
  double clearance_from = 0, clearance_to = 0;
  double min_clearance = 0;          // the minimum of D along the edge
  std::vector<Point> polyline;       // from .. to; a curved edge sampled within max_deviation()
};

/// A critical point of D on the GVD.
struct GvdCriticalPoint {
  /// Saddle kinds: Interior (the apex of a parabolic arc or the midpoint of two vertices,
  /// inside an edge), Vertex (a degree-2 vertex where D has a local minimum along the GVD
  /// and is critical), Plateau (the middle of an edge between two parallel walls, D
  /// constant along it and rising on both sides). Maxima are GVD vertices (kind Vertex).
  enum class Kind : std::uint8_t { Interior, Vertex, Plateau };
  Kind kind = Kind::Interior;
  Point p;
  double clearance = 0;
  std::uint32_t edge = UINT32_MAX;    // the edge it lies on (Interior, Plateau), else UINT32_MAX
  std::uint32_t vertex = UINT32_MAX;  // the vertex it is (Vertex), else UINT32_MAX
  Point nearest[2];                   // nearest points of two obstacles: opposite for Interior and Plateau
                                      // saddles; at a vertex the most nearly opposite pair
};

/// A vertex of the medial axis: a Voronoi vertex, or the minimum of D inside a Voronoi edge.
struct MedialVertex {
  Point p;
  double clearance = 0;  // D there
};

/// An edge of the medial axis (GvdOptions::medial_axis): a piece of a primary Voronoi edge
/// in free space — between sites of one obstacle too —, split at the minimum of D so that D
/// is monotone (or constant) from `from` to `to`.
///
/// Its two *sheets* tile free space with all the others: sheet 2e + s is swept by the
/// segments from the edge's points to their nearest points on sites[s]. D grows linearly
/// along each such segment (the flow lines of the brushfire), so a level curve of D crosses
/// a sheet once, above the points of the edge where D is at least its level. Sheet 2e runs
/// from -> to with sites[0] on its left; sheet 2e + 1 runs to -> from with sites[1] on its left.
struct MedialEdge {
  static constexpr std::uint32_t kNoSheet = UINT32_MAX;
  GvdSite sites[2];
  std::uint32_t from = 0, to = 0;  // MedialVertex ids
  std::vector<Point> polyline;     // from .. to (curved edges sampled within max_deviation())
  std::vector<double> clearance;   // D at each polyline point: monotone, or constant (plateau)
  bool plateau = false;            // between parallel walls: D constant
  /// The sheet beyond the flow line at the end of sheet 2e + s (the next one along the same
  /// obstacle boundary); kNoSheet where that end lies on an obstacle (D = 0).
  std::uint32_t next_sheet[2] = {kNoSheet, kNoSheet};
};

struct GvdOptions {
  /// Curved edges are sampled so that the polyline stays within this distance of the
  /// arc; 0 means 1/1000 of the larger side of the bounding box.
  double max_deviation = 0;
  /// Snapping: every |coordinate| is below 2^grid_bits grid steps (16..30). Fewer bits, a
  /// coarser grid but a faster diagram: Boost's exact fallback works on shorter numbers.
  int grid_bits = 29;
  /// Also build the medial axis (medial_vertices(), medial_edges()).
  bool medial_axis = false;
};

class GeneralizedVoronoiDiagram {
 public:
  /// Throws InputError when snapping to the grid makes segments meet other than at shared
  /// endpoints (naming the elements), std::logic_error when Boost's output fails the checks.
  static GeneralizedVoronoiDiagram build(const Environment& env, const GvdOptions& options = {});

  const std::vector<GvdVertex>& vertices() const { return vertices_; }
  const std::vector<GvdEdge>& edges() const { return edges_; }
  const std::vector<GvdCriticalPoint>& saddles() const { return saddles_; }
  const std::vector<GvdCriticalPoint>& maxima() const { return maxima_; }

  /// The medial axis (empty unless GvdOptions::medial_axis): every primary Voronoi edge in
  /// free space, the GVD's and those between two sites of one obstacle.
  const std::vector<MedialVertex>& medial_vertices() const { return medial_vertices_; }
  const std::vector<MedialEdge>& medial_edges() const { return medial_edges_; }
  /// The nearest point of a site (of the snapped environment) to p.
  Point nearest_on_site(const GvdSite& s, const Point& p) const;

  /// Obstacles are the rings joined by contacts (the connected components of the
  /// obstacle region, the text's QO_i): without contacts, the outer ring (obstacle 0) and
  /// one per hole. Obstacle ids are numbered by their first ring.
  std::size_t num_obstacles() const { return obstacle_rings_.size(); }
  std::uint32_t obstacle_of_ring(std::size_t r) const { return ring_obstacle_[r]; }
  const std::vector<std::uint32_t>& obstacle_rings(std::size_t o) const { return obstacle_rings_[o]; }

  /// The grid the input was snapped to: a power of two, 2^resolution_exponent(). The GVD
  /// is the exact GVD of the snapped environment; reported coordinates are within
  /// resolution() of it, and the snapped vertices within resolution() / 2 (per
  /// coordinate) of the input. Far from the origin the grid is laid in the environment's
  /// local frame (geometry::LocalFrame), so its resolution follows the plan's size, not
  /// its distance from the origin; points are then moved back and rounded.
  double resolution() const { return resolution_; }
  int resolution_exponent() const { return resolution_exponent_; }
  /// Vertex v after snapping (exactly a multiple of resolution() in the local frame).
  const Point& snapped_vertex(std::size_t v) const { return snapped_[v]; }
  const std::vector<Point>& snapped_vertices() const { return snapped_; }
  /// The sampling bound of curved edges actually used.
  double max_deviation() const { return max_deviation_; }

  /// D(p): distance from p to the nearest obstacle point (the input environment's edges;
  /// for p in free space). Uniform-grid search, exact-enough doubles.
  double clearance(const Point& p) const;
  /// The same by brute force over all edges (the reference).
  double clearance_brute_force(const Point& p) const;
  /// Distance from p to obstacle o alone (input coordinates), brute force.
  double distance_to_obstacle(const Point& p, std::size_t o) const;

  /// Sorted (a < b) obstacle pairs with at least one GVD edge, with their edge counts.
  std::vector<std::pair<std::pair<std::uint32_t, std::uint32_t>, std::size_t>> obstacle_pairs() const;

 private:
  // Moves a diagram built in env's local frame back to env's coordinates (rounded).
  void to_input(const LocalFrame& frame, const Environment& env);

  std::vector<GvdVertex> vertices_;
  std::vector<GvdEdge> edges_;
  std::vector<GvdCriticalPoint> saddles_, maxima_;
  std::vector<MedialVertex> medial_vertices_;
  std::vector<MedialEdge> medial_edges_;
  std::vector<std::uint32_t> next_;       // env.next(e)
  std::vector<std::uint32_t> ring_obstacle_;
  std::vector<std::vector<std::uint32_t>> obstacle_rings_;
  std::vector<Point> snapped_;
  std::vector<Segment> segments_;         // input edges (edge id order)
  std::vector<std::uint32_t> edge_obstacle_;
  double resolution_ = 1, max_deviation_ = 0;
  int resolution_exponent_ = 0;
  // Uniform grid over the edges for clearance().
  double grid_x0_ = 0, grid_y0_ = 0, grid_cell_ = 1;
  std::size_t grid_nx_ = 1, grid_ny_ = 1;
  std::vector<std::uint32_t> grid_start_, grid_items_;
};

}  // namespace preimage::geometry
