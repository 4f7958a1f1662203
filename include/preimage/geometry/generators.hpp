// SPDX-License-Identifier: Apache-2.0
// Environments for tests, benchmarks, examples and the demo. All are deterministic in
// their seed and valid by construction (tests re-validate them exactly).
#pragma once
#include <preimage/geometry/environment.hpp>

#include <cstdint>

namespace preimage::geometry::generators {

/// Random simple polygon on n random points in [0, size]^2 by space partitioning
/// (Auer & Held, "RPG"): recursive splits by random lines make disjoint convex regions,
/// one chain in each. O(n log n) expected; fine up to 10^5 vertices and beyond.
Ring random_simple_polygon(std::size_t n, std::uint64_t seed, double size = 1.0);

/// n vertices in all: a star-shaped outer boundary (half the vertices) around `holes`
/// random simple polygons placed in disjoint grid cells. holes == 0 gives a random
/// simple polygon of n vertices.
Environment random_environment(std::size_t n, std::size_t holes, std::uint64_t seed);

/// Star with `points` tips, alternating radii r_out and r_in around (0, 0).
Ring star(std::size_t points, double r_in = 0.4, double r_out = 1.0);
/// Comb: a base bar with `teeth` vertical teeth (vertical edges, equal x everywhere).
Ring comb(std::size_t teeth, double tooth_width = 1.0, double gap = 1.0, double height = 4.0);
/// Spiral corridor with `turns` turns.
Ring spiral(double turns, double corridor = 1.0, std::size_t samples_per_turn = 36);
/// Office floor plan: rows x cols rooms of side `room` with axis-aligned walls as
/// obstacles, door gaps, and collinear vertices on every long wall.
Environment office(std::size_t rows, std::size_t cols, double room = 4.0);

/// Random rectilinear environment: a random polyomino grown cell by cell on a cols x rows
/// grid (never two cells touching only at a corner), its bounded gaps as holes when
/// `holes` is true (otherwise they are filled), columns and rows of random integer widths,
/// and a random share of the collinear grid points kept as straight vertices. Every
/// degeneracy of a real floor plan is there: equal x and y everywhere, vertical and
/// horizontal edges, several vertices on one vertical line, collinear runs.
Environment random_rectilinear(std::size_t cols, std::size_t rows, bool holes, std::uint64_t seed);

/// The union of the filled unit cells of a cols x rows grid (filled[y * cols + x], cell
/// (x, y) = [x, x + 1] x [y, y + 1]); no two filled cells may touch at a corner only.
/// Unfilled cells enclosed by filled ones are holes; straight vertices are dropped.
Environment from_cells(const std::vector<char>& filled, std::size_t cols, std::size_t rows);

/// Holes that touch at vertices (Environment contacts): an m x m grid in [0, m]^2 whose
/// inner black cells ((i + j) even, not on the border) are unit-square holes with
/// probability `fill`, so diagonal neighbours touch at corners; and triangles whose apex
/// touches the bottom wall at a boundary vertex (the wall has a vertex at every integer).
/// `sheared` maps everything by the integer matrix [[2, 1], [1, 3]] (exact in doubles), so
/// no edge is axis-aligned. Valid by construction for m >= 3.
Environment touching_squares(std::size_t m, double fill, std::uint64_t seed, bool sheared = false);

}  // namespace preimage::geometry::generators
