// SPDX-License-Identifier: Apache-2.0
// Several pursuers: the evader must hide from all of them, in the intersection of their
// shadows. The free edges of all their visibility polygons, overlaid with the shared
// segment arrangement, cut free space into faces; each face lies in V of some pursuers
// and in one shadow component of each of the others. A "unit" is a tuple of components,
// one per pursuer, whose intersection is not empty (a face hidden from everybody).
//
// The k-pursuer search labels units. It is sound: while pursuer i moves and the others
// hold still, an evader stays in one component of each still pursuer's shadow, and its
// component for pursuer i follows the exact one-pursuer transition; so a unit can be
// contaminated only from a unit equal in the still coordinates and related in
// coordinate i. It treats all faces of a unit as one region (an evader in one part is
// assumed able to reach the other): it may miss plans, never accept a wrong one.
#pragma once
#include <preimage/geometry/segment_arrangement.hpp>
#include <preimage/pursuit/shadows.hpp>

#include <span>
#include <vector>

namespace preimage::pursuit {

struct ShadowOverlay {
  geometry::SegmentArrangement arrangement;
  /// component[r][l]: shadow component of pursuer l holding region r, kNone if r is in V.
  std::vector<std::vector<std::uint32_t>> component;
};

/// Overlays the gaps of pursuers at `at` (doubles) with shadows `shadows` (of V(at[l])).
ShadowOverlay overlay_shadows(const geometry::Environment& env, std::span<const geometry::Point> at,
                              std::span<const Shadows* const> shadows);

/// The non-empty units (sorted, distinct) of an overlay.
std::vector<std::vector<std::uint32_t>> joint_units(const ShadowOverlay& overlay);

}  // namespace preimage::pursuit
