// SPDX-License-Identifier: Apache-2.0
// Standard figures: a scene with its slots, a triangulation, a visibility polygon.
#pragma once
#include <preimage/geometry/triangulation.hpp>
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

}  // namespace preimage::render
