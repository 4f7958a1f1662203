// SPDX-License-Identifier: Apache-2.0
// Figures of the decompose module, on the shared SVG canvas.
#pragma once
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/decompose/brushfire.hpp>
#include <preimage/decompose/morse.hpp>
#include <preimage/decompose/planner.hpp>
#include <preimage/decompose/wavefront.hpp>
#include <preimage/render/svg.hpp>

namespace preimage::decompose {

/// Cells (alternating light fills), vertical extensions (dashed) and, when a planner is
/// given, the adjacency graph drawn through cell centroids and extension midpoints.
void draw_decomposition(render::SvgCanvas& canvas, const TrapezoidalDecomposition& d,
                        const TrapezoidalPlanner* graph = nullptr);

/// Boustrophedon cells, critical slices and the Reeb graph (nodes at slice midpoints,
/// one edge per cell drawn through the cell's centre).
void draw_boustrophedon(render::SvgCanvas& canvas, const BoustrophedonDecomposition& b);

/// Morse cells (light fills), the critical slice intervals as true circle arcs, rays or
/// diamond pieces, critical points (filled: split/merge, open: birth/death) and the centre.
void draw_morse(render::SvgCanvas& canvas, const MorseDecomposition& m);

/// Brushfire cells (each band filled with its cell's colour), the medial axis (grey), the
/// GVD between different obstacles (blue), saddles (filled) and maxima (open) of D.
void draw_brushfire(render::SvgCanvas& canvas, const BrushfireDecomposition& b);

/// The wave-front decomposition: `levels` fronts (the computed arcs) evenly spaced up to
/// the largest h, each coloured by its cell, the critical slices' points and the start.
void draw_wavefront(render::SvgCanvas& canvas, const WavefrontDecomposition& w, int levels = 24);


}  // namespace preimage::decompose
