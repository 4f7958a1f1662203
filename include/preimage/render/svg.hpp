// SPDX-License-Identifier: Apache-2.0
// SVG drawing of environments with overlays, reused by every module's figures.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <string>
#include <vector>

namespace preimage::render {

using geometry::Point;

/// One step of a region's boundary (SvgCanvas::region): to `to`, straight, or along a
/// circle of radius `arc_radius` (world units), sweeping `arc_span` radians counter-clockwise
/// in the world (clockwise when negative), less than 2 pi in size (SVG cannot draw an arc
/// between equal ends: give a full circle as two half-turns).
struct RegionStep {
  Point to;
  double arc_radius = 0;  // 0: a straight step
  double arc_span = 0;
};

struct Style {
  std::string fill = "none";
  std::string stroke = "#222";
  double stroke_width = 1.5;  // pixels
  double opacity = 1.0;
  std::string dash;           // SVG dasharray, e.g. "4 3"
};

/// A canvas mapping a world box (y up) onto pixels (y down), with a legend.
class SvgCanvas {
 public:
  explicit SvgCanvas(CGAL::Bbox_2 world, double width_px = 720, double margin_px = 16);

  /// Free space white, obstacles and outside grey, walls dark.
  void environment(const geometry::Environment& env);
  void polygon(const std::vector<Point>& pts, const Style& style, const std::string& title = "");
  /// Several rings filled together with the even-odd rule (a region with holes).
  void rings(const std::vector<std::vector<Point>>& rings, const Style& style, const std::string& title = "");
  void polyline(const std::vector<Point>& pts, const Style& style, const std::string& title = "");
  /// A closed region bounded by segments and circular arcs (real SVG arcs, not polygons):
  /// from `start` through each step, closed back to `start` (left open if not `closed`:
  /// a stroke only, e.g. one arc).
  void region(const Point& start, const std::vector<RegionStep>& steps, const Style& style, const std::string& title = "",
              bool closed = true);
  void segment(const Point& a, const Point& b, const Style& style, const std::string& title = "");
  void point(const Point& p, double radius_px, const Style& style, const std::string& title = "");
  void label(const Point& p, const std::string& text, double size_px = 12, const std::string& colour = "#222");
  /// Small arrowheads along a polyline, one every `spacing_px` of drawn length, pointing the
  /// way it runs. A spacing that is not a positive finite number draws none.
  void arrows(const std::vector<Point>& pts, const std::string& colour, double spacing_px = 70, double size_px = 5);
  /// A path something follows (a robot, a pursuer, a sample path of a body): the polyline
  /// with arrowheads in its stroke colour, tagged `data-path` so the interactive report
  /// can step along it (render::HtmlReport). `first_step`: the step of the figure's
  /// timeline at which pts[0] is reached (pieces of one path drawn in several styles).
  void path(const std::vector<Point>& pts, const Style& style, const std::string& title = "", double arrow_spacing_px = 70,
            double arrow_size_px = 5, std::size_t first_step = 0);
  /// Drops the legend (small multiples: one panel carries it for all).
  void clear_legend() { legend_.clear(); }
  /// Adds a legend entry drawn with the given style.
  void legend(const std::string& text, const Style& style);

  /// The SVG: the drawing with axes in world units along its left and bottom edges (ticks
  /// and a scale bar), and the legend below it.
  std::string str() const;
  void save(const std::string& path) const;

  double scale() const { return scale_; }

 private:
  std::string px(const Point& p) const;
  std::string axes() const;
  std::string style_attr(const Style& s) const;
  CGAL::Bbox_2 world_;
  double scale_, margin_, width_, height_;
  std::string body_;
  std::vector<std::pair<std::string, Style>> legend_;
};

/// Small multiples: whole SVG documents (SvgCanvas::str() or any "<svg ... width= height=")
/// nested side by side in rows of `columns`, with `note` as a line of text beneath. One
/// panel per query where drawings would otherwise overlap.
std::string panel_grid(const std::vector<std::string>& panels, std::size_t columns, const std::string& note = "");

/// XML/HTML text escaping.
std::string escape(const std::string& text);

}  // namespace preimage::render
