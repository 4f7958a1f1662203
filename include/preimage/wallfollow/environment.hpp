// SPDX-License-Identifier: Apache-2.0
// Environments of the wall-following robot (wall-following paper, III.A): a simply
// connected polygon in general position, i.e. no three vertices collinear. Collinear
// triples would let a cut end at a vertex or run along an edge, which the model
// excludes, so they are rejected rather than handled.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <string>

namespace preimage::wallfollow {

/// Throws InputError naming the element: obstacles present, or the first collinear
/// triple found ("<where>: vertices 3, 7 and 12 are collinear ..."; input indices).
/// O(n^2 log n): an exact angular sort of the other vertices around each vertex.
void require_general_position(const geometry::Environment& env, const std::string& where = "$.environment.boundary");

}  // namespace preimage::wallfollow
