// SPDX-License-Identifier: Apache-2.0
// Standard figures: a scene with its slots, a triangulation, a visibility polygon.
#pragma once
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/triangulation.hpp>
#include <preimage/geometry/range_visibility.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/render/svg.hpp>
#include <preimage/scene/scene.hpp>

namespace preimage::render {

/// World box of a scene (environment, landmarks, beams, start/goal), padded by 3%.
CGAL::Bbox_2 scene_box(const scene::Scene& s);
/// Environment, start/goal, landmarks and beams, with legend entries.
void draw_scene(SvgCanvas& canvas, const scene::Scene& s);
void draw_triangulation(SvgCanvas& canvas, const geometry::Triangulation& t);
/// Filled polygon, solid edges along walls, dashed free (occlusion) edges, the query point.
void draw_visibility(SvgCanvas& canvas, const geometry::VisibilityPolygon& v, const std::string& colour = "#f4b400",
                     const std::string& label = "visibility polygon (thick edges lie on walls)");
/// Range-limited visibility V(q) within radius R: the region with its circle arcs as SVG
/// arcs, pieces on walls thick, free pieces dashed, the range circle dotted, the query point.
void draw_range_visibility(SvgCanvas& canvas, const geometry::RangeVisibility& r, const std::string& colour = "#f4b400",
                           const std::string& label = "visible within range (arcs: the range limit)");

/// A robot's route: the polyline with arrows showing the way it runs, and start and end
/// markers (each with a legend entry).
void draw_route(SvgCanvas& canvas, const std::vector<Point>& path, const std::string& label, const std::string& colour,
                double stroke_px = 2.5, const std::string& dash = "");
/// The configuration space of a disc robot: its components shaded, the band it cannot
/// reach along the walls left plain.
void draw_configuration_space(SvgCanvas& canvas, const geometry::ConfigurationSpace& cs);

}  // namespace preimage::render
