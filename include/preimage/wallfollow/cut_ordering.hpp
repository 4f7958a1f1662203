// SPDX-License-Identifier: Apache-2.0
// The cut ordering (wall-following paper, V.A): the cyclic order along the boundary,
// counter-clockwise, of all vertices and of the endpoints l_i, r_i of the left and right
// cuts of every reflex vertex v_i. True ordering from geometry (exact ray shooting),
// canonical form up to relabelling, the cut diagram, Proposition 4, and the reflex-chain
// realizability rule.
#pragma once
#include <preimage/geometry/environment.hpp>
#include <preimage/render/svg.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace preimage::wallfollow {

/// v_i, l_i or r_i (0-based vertex; printed 1-based as in the paper).
struct CutPoint {
  enum class Kind : std::uint8_t { Vertex, Left, Right } kind;
  std::uint32_t vertex;
  bool operator==(const CutPoint&) const = default;
  auto operator<=>(const CutPoint&) const = default;
};

/// A cyclic sequence, counter-clockwise along the boundary; vertices appear in order
/// v_1 .. v_n and each edge's cut endpoints follow its start vertex.
struct CutOrdering {
  std::size_t n = 0;                // vertices
  std::vector<bool> reflex;         // per vertex
  std::vector<CutPoint> points;     // |M| = n + 2m

  /// Relabelled so that v_1 is vertex `first` (indices shift by -first mod n).
  CutOrdering relabelled(std::size_t first) const;
  /// The representative of the equivalence class of V.A: the lexicographically least
  /// relabelling, written from v_1.
  CutOrdering canonical() const;
  bool operator==(const CutOrdering&) const = default;
  /// "(v1, v2, v3, l5, r2, v4, v5, v6, l2, r5)".
  std::string str() const;
};

/// A cut as geometry gives it.
struct Cut {
  std::uint32_t vertex;
  bool left;                      // left cut (arrived by LFOLLOW, clockwise)
  geometry::ExactPoint end;       // endpoint on the boundary
  std::uint32_t edge;             // edge holding the endpoint
};

/// The cut of reflex vertex v by exact ray shooting along the edge arriving at v
/// (from next(v) for a left cut, from prev(v) for a right cut). InputError if it ends
/// at a vertex or runs along an edge (no general position).
Cut shoot_cut(const geometry::Environment& env, std::uint32_t v, bool left);

struct TrueCuts {
  std::vector<Cut> cuts;  // two per reflex vertex: left then right
  CutOrdering ordering;
};

/// Every cut by exact ray shooting, and their order along each edge. InputError when
/// two cut endpoints coincide (excluded in V.A), naming both cuts.
/// The environment must pass require_general_position.
TrueCuts true_cut_ordering(const geometry::Environment& env);

/// A cut as a chord of the cut diagram: its two points and their positions in the ordering.
struct CutChord {
  CutPoint from, to;       // v_i and l_i or r_i
  std::size_t at_from, at_to;
};
std::vector<CutChord> chords(const CutOrdering& o);
/// Do two chords cross in the cut diagram (their endpoints alternate around the
/// circle)? Chords sharing an endpoint do not.
bool chords_cross(const CutChord& a, const CutChord& b);

/// Reflex-chain rule (V.B): the cut endpoint of a vertex of a reflex chain (maximal run
/// of consecutive reflex vertices) cannot lie between vertices of that chain. Returns
/// one message per violation; empty for every realizable ordering.
std::vector<std::string> reflex_chain_violations(const CutOrdering& o);

/// Fig. 4(a): the points of M around a circle in cyclic order, each reflex vertex joined
/// to its two cut endpoints (left cuts blue, right cuts red).
render::SvgCanvas cut_diagram(const CutOrdering& o, const std::string& title = "");
/// The environment with its cuts drawn (Fig. 3): vertices numbered v1.., cuts from each
/// reflex vertex to l_i and r_i.
render::SvgCanvas cuts_figure(const geometry::Environment& env, const TrueCuts& cuts);

}  // namespace preimage::wallfollow
