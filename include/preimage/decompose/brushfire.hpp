// SPDX-License-Identifier: Apache-2.0
// The brushfire decomposition (section 6.2.3, Figs. 6.15–6.17): the Morse decomposition of
// free space by D, the distance to the nearest obstacle. Its slices D = λ are the wave
// fronts that grow from every obstacle; cells are what one front sweeps between the
// critical points where fronts first collide (saddles of D) or vanish (maxima).
//
// Built on the medial axis (geometry::GeneralizedVoronoiDiagram with medial_axis): free
// space deformation-retracts onto it along the flow lines of D (the segments from each
// point of the axis to its nearest obstacle points), so the slice D = λ is the boundary of
// a thickening of the axis' part where D >= λ, and its topology changes only where D,
// restricted to the axis, has a maximum (a vertex with no rising branch) or a saddle (two
// or more rising branches: the minimum of an edge, a vertex, or a plateau between parallel
// walls). Fronts of one obstacle colliding (a corridor, a doorway) are saddles as much as
// fronts of two: the GVD between different obstacles alone would leave a floor plan
// without pillars one cell.
//
// Construction: every medial-axis sheet (the region between an axis edge and one of its
// two sites) is cut at the levels of the critical slices crossing it; the bands are glued
// across flow lines and across the axis wherever they meet off a critical slice; the
// classes are the cells. Decided in double on the diagram of the snapped environment
// (geometry::GeneralizedVoronoiDiagram::resolution()): critical values are compared
// exactly as doubles, so equal values found by different sites at a symmetric point may
// give two nodes an infinitesimal cell apart.
#pragma once
#include <preimage/geometry/gvd.hpp>

#include <cstdint>
#include <vector>

namespace preimage::decompose {

using geometry::Environment;
using geometry::Point;

struct BrushfireCriticalPoint {
  enum class Kind : std::uint8_t { Saddle, Maximum };
  Kind kind = Kind::Saddle;
  Point p;
  double level = 0;               // D there
  std::uint32_t node = 0;         // the critical slice it lies on
  std::uint32_t rising = 0;       // branches of the axis along which D rises from it
};

/// A critical slice: the component of D = level through one or more critical points.
struct BrushfireNode {
  double level = 0;
  std::vector<std::uint32_t> critical_points;
};

struct BrushfireCell {
  static constexpr std::uint32_t kNone = UINT32_MAX;
  double lo = 0, hi = 0;                 // the range of D over the cell
  std::uint32_t lower = kNone;           // the slice it starts from (kNone: an obstacle's boundary)
  std::uint32_t upper = kNone;           // the slice it ends at
  std::uint32_t obstacle = kNone;        // the obstacle whose boundary it starts from (lower == kNone)
  double area = 0;                       // of the sampled bands (within the sampling bound)
  std::vector<std::uint32_t> bands;      // its pieces (ids for band_polygon)
};

class BrushfireDecomposition {
 public:
  /// Throws InputError for environments the GVD refuses (finer than its grid).
  explicit BrushfireDecomposition(const Environment& env, const geometry::GvdOptions& options = {});

  const Environment& environment() const { return *env_; }
  const geometry::GeneralizedVoronoiDiagram& gvd() const { return gvd_; }
  const std::vector<BrushfireCriticalPoint>& critical_points() const { return critical_; }
  const std::vector<BrushfireNode>& nodes() const { return nodes_; }
  const std::vector<BrushfireCell>& cells() const { return cells_; }
  std::size_t num_nodes() const { return nodes_.size(); }
  /// Cells sharing a critical slice (sorted, no repeats).
  std::vector<std::vector<std::uint32_t>> adjacency() const;

  /// A band (a piece of one sheet between two consecutive cuts) as a polygon; arcs around
  /// vertex sites sampled so that no chord is farther than `sag` from its arc.
  std::vector<Point> band_polygon(std::uint32_t band, double sag) const;
  std::size_t num_bands() const { return band_sheet_.size(); }
  std::uint32_t band_cell(std::uint32_t band) const { return band_cell_[band]; }

  /// The slice D = lambda (lambda > 0): its components, each a closed curve, with the cell
  /// it runs through (a non-critical level lies in one cell per component). Arcs sampled
  /// within `sag`; points are exactly at distance lambda from their site (to rounding).
  struct LevelCurve {
    std::vector<Point> points;  // closed: the last point joins the first
    std::uint32_t cell = BrushfireCell::kNone;
  };
  std::vector<LevelCurve> level_curves(double lambda, double sag) const;

  /// The medial axis inside each cell: the axis pieces between consecutive cuts, with the
  /// cell whose bands border them on both sides.
  struct AxisPiece {
    std::vector<Point> points;
    std::vector<double> clearance;
    std::uint32_t cell = BrushfireCell::kNone;
  };
  std::vector<AxisPiece> axis_pieces() const;

  /// Area of free space (shoelace of the environment).
  double free_area() const { return free_area_; }

 private:
  struct Cut {
    double level;
    std::uint32_t node;
  };
  const Environment* env_;
  geometry::GeneralizedVoronoiDiagram gvd_;
  std::vector<double> dv_;                       // D at medial vertices (plateau runs made equal)
  std::vector<std::uint32_t> prev_sheet_;
  std::vector<std::vector<Cut>> cuts_;           // per sheet, ascending
  std::vector<std::uint32_t> band_start_;        // per sheet: first band id (size sheets + 1)
  std::vector<std::uint32_t> band_sheet_, band_cell_;
  std::vector<BrushfireCriticalPoint> critical_;
  std::vector<BrushfireNode> nodes_;
  std::vector<BrushfireCell> cells_;
  double free_area_ = 0;

  double d_start(std::uint32_t sheet) const;
  double d_end(std::uint32_t sheet) const;
  double d_lo(std::uint32_t edge) const;
  double d_hi(std::uint32_t edge) const;
  double band_lo(std::uint32_t band) const;
  double band_hi(std::uint32_t band) const;  // +inf for the top band
  std::uint32_t band_at(std::uint32_t sheet, double level) const;
  // Points of the sheet's edge, in the sheet's direction, where D >= level, with D.
  void sheet_run(std::uint32_t sheet, double level, std::vector<Point>& m, std::vector<double>& d) const;
  Point crossing(std::uint32_t edge, const Point& q, const Point& p, double dq, double dp, double level) const;
  // p on the flow line from the site's nearest point to m, at distance lambda.
  Point on_flow_line(std::uint32_t sheet, const Point& m, double dm, double lambda) const;
  // Appends points at distance lambda over m's (arcs around vertex sites subdivided).
  void offset_run(std::uint32_t sheet, const std::vector<Point>& m, const std::vector<double>& d, double lambda, double sag,
                  std::vector<Point>& out) const;
};

}  // namespace preimage::decompose
