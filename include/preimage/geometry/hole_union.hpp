// SPDX-License-Identifier: Apache-2.0
// Merging holes that overlap (share an edge, cross, or nest) into their union, for maps
// drawn as overlapping wall rectangles or tiles: `preimage import --merge-holes`.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <vector>

namespace preimage::geometry {

struct MergedHoles {
  std::vector<Ring> holes;   // the union's polygons; ones touching at a vertex stay apart (contacts)
  std::size_t input = 0;     // number of holes given
  double grid = 0;           // coordinates were snapped to multiples of this power of two
};

/// The union of the holes, by Clipper (Boost licence) on an integer grid: a power of two
/// chosen so every coordinate is below 2^51 grid steps, hence exact for input coordinates
/// that are multiples of it (all the coordinates of a map in metres with a few decimals
/// are, to within the grid, 2^-49 of the largest coordinate). Strictly simple output: two
/// pieces that touch at a point stay two polygons. Throws InputError when the union
/// encloses free space (a ring of walls around an empty room: it would be a hole in a
/// hole), naming a point of it.
MergedHoles merge_overlapping_holes(const std::vector<Ring>& holes);

}  // namespace preimage::geometry
