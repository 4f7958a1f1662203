// SPDX-License-Identifier: Apache-2.0
// Figures of the coverage module, on the shared SVG canvas.
#pragma once
#include <preimage/coverage/coverage.hpp>
#include <preimage/coverage/online_coverage.hpp>
#include <preimage/render/svg.hpp>

#include <cstddef>

namespace preimage::coverage {

/// A coverage path: laps, boundary following and transits in three styles, arrows along
/// it, start and end markers.
void draw_coverage(render::SvgCanvas& canvas, const CoverageReport& report);

/// Online coverage as it stood after the first `upto` path points (Fig. 6.21): the path so
/// far, the critical points sensed by then (numbered in order) and the Reeb graph edges of
/// the cells covered by then; ports still unexplored drawn as short stubs.
void draw_online_coverage(render::SvgCanvas& canvas, const OnlineReport& report, std::size_t upto);

}  // namespace preimage::coverage
