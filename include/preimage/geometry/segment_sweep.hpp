// SPDX-License-Identifier: Apache-2.0
// Shamos–Hoey sweep: the first improper contact among a set of segments, O(n log n).
#pragma once
#include <preimage/geometry/kernel.hpp>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace preimage::geometry {

/// A segment between two points of a shared point array, by index.
struct IndexedSegment {
  std::uint32_t a, b;
};

/// Two segments that touch where they may not, and a point near the contact.
struct SegmentContact {
  std::size_t first, second;  // indices into the segment list, first < second
  Point near;                 // a contact point (approximate when constructed)
};

/// Finds a pair of segments that intersect anywhere except at an endpoint *index*
/// they share (two segments sharing an endpoint index may meet exactly there and
/// nowhere else; collinear overlap is a contact). Distinct indices with equal
/// coordinates are contacts. Exact predicates; O(n log n).
std::optional<SegmentContact> find_segment_contact(const std::vector<Point>& points,
                                                   const std::vector<IndexedSegment>& segments);

/// The O(n^2) definition of the above, for tests and tiny inputs.
std::optional<SegmentContact> find_segment_contact_brute_force(
    const std::vector<Point>& points, const std::vector<IndexedSegment>& segments);

}  // namespace preimage::geometry
