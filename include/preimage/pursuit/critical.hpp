// SPDX-License-Identifier: Apache-2.0
// The critical boundaries of the conservative cells (Choset et al. 6.3, Fig. 6.35):
//   - from every reflex vertex of free space, the extensions of its two edges beyond it;
//   - for every pair of mutually visible reflex vertices whose line is tangent at both
//     (a bitangent), the rays beyond each vertex, away from the other;
// each clipped at its first boundary contact (shoot_ray). A ray through another vertex
// stops there; the line goes on as the ray of that vertex's bitangent, so nothing is lost.
// Rays that coincide (an edge both of whose ends are reflex, a doorway between two
// aligned walls, collinear bitangents) are one segment with several generators.
//
// Along a critical segment's line the pursuer sees a sequence of vertices edge-on or
// grazing ("contacts"): `SightLine` records them, walls included, for the exact gap
// transitions (transitions.cpp).
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/geometry/segment_arrangement.hpp>

#include <cstdint>
#include <vector>

namespace preimage::pursuit {

using geometry::Environment;
using geometry::ExactPoint;
using geometry::Point;
using geometry::kNone;

/// Why a critical segment exists.
struct CriticalGenerator {
  enum class Kind : std::uint8_t { Extension, Bitangent, Contact };
  Kind kind;
  std::uint32_t vertex;  // the reflex vertex the ray leaves
  std::uint32_t other;   // Extension: the other end of the extended edge; Bitangent: the partner vertex;
                         // Contact: a vertex at the contact point whose visibility changes on the ray
};

/// What the line of sight meets, from a point of a critical segment looking along it past
/// one of its ends: vertices it passes edge-on or grazing, then the stop.
struct SightLine {
  struct Contact {
    std::uint32_t vertex;
    int side;             // +1: the obstacle at the vertex lies left of the look direction, -1: right
    bool wall_after;      // the boundary runs along the line from this contact to the next (or to the stop)
  };
  std::vector<Contact> contacts;  // empty: the sight line enters an obstacle right at the segment's end
};

/// A critical ray clipped to a segment. `from` is vertex `origin` (reflex); the segment's
/// interior lies in open free space and `to` is its first boundary contact.
struct CriticalSegment {
  std::uint32_t origin;
  std::uint32_t partner;  // the carrier is the line through vertices `partner` and `origin`
  ExactPoint from, to;
  geometry::SegmentEnd end;  // where `to` lies: at a vertex or inside an edge
  std::vector<CriticalGenerator> generators;
  SightLine backward;  // looking from a point of the segment towards `from` and beyond
  SightLine forward;   // looking towards `to` and beyond
};

/// Is reflex vertex v's boundary tangent to the line through v and p (both neighbours on
/// one closed side)? Exact. At a contact, v names the free wedge starting at its out-edge,
/// and the neighbours are that wedge's (Environment::wedge_prev, next).
bool tangent_at(const Environment& env, std::size_t v, const Point& p);
/// Is the free wedge starting at v (v's own at a vertex that is no contact) reflex?
bool is_reflex_wedge(const Environment& env, std::size_t v);

/// All critical segments of the environment, duplicates merged, with their sight lines.
/// O(r^2 n) for r reflex vertices (bitangent candidates are tested with exact visibility).
std::vector<CriticalSegment> critical_segments(const Environment& env);

}  // namespace preimage::pursuit
