// SPDX-License-Identifier: Apache-2.0
// Escape risk (section III.C, equation 3) and its gradient with respect to the observer's
// position, and the two ways of aggregating it (section III.B).
//
//   phi^e = c r_o^2 (1/h)^(m+2),  h = SDE(q^t, e),  r_o = |q^o - corner|.
//
// The target is a disc of radius delta (section III.C: with delta > 0 the gradient exists
// in every case). The free edge of an occluding corner k is the line of sight from q^o
// past k, with direction u = (k - q^o)/r_o; moving the observer turns it about k. The
// escape path is fixed up to its last pivot w (at geodesic distance P from the target);
// its last leg leaves in one of two ways:
//  * Perpendicular ("through a vertex of V"): with s = (w - k).u >= delta, straight from
//    w to the line: h = P + |d|, d = u x (w - k), and grad h = sign(d) (s / r_o) t,
//    t = u rotated by +90 deg;
//  * Corner ("through the occluding corner"): with s < delta the disc's centre wraps the
//    corner on a circle of radius delta to k + delta u: h = P + sqrt(|w-k|^2 - delta^2) +
//    delta alpha, alpha the arc angle, and grad h = sign(d) (delta / r_o) t — equation
//    (4) of the paper for m = 0.
// Both give grad r_o = -u, and grad phi = c [2 r_o h^-(m+2) grad r_o - (m+2) r_o^2
// h^-(m+3) grad h]. The two cases meet with equal value and gradient at s = delta.
#pragma once
#include <preimage/tracking/escape_path_tree.hpp>

#include <cmath>
#include <vector>

namespace preimage::tracking {

struct Vec2 {
  double x = 0, y = 0;
  Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  Vec2 operator*(double k) const { return {x * k, y * k}; }
  double dot(Vec2 o) const { return x * o.x + y * o.y; }
  double cross(Vec2 o) const { return x * o.y - y * o.x; }
  // sqrt, not hypot: lengths here are metres, far from overflow, and hypot is ~10x slower.
  double norm() const { return std::sqrt(x * x + y * y); }
};
inline Vec2 vec(const Point& p) { return {p.x(), p.y()}; }

struct RiskParams {
  double c = 0.1;       // scale of equation (3)
  int m = 0;            // exponent of the reactive component, m >= 0
  double delta = 0.2;   // target radius
  double min_h = 1e-6;  // h is floored here (a target touching its free edge has escaped)
};

/// One occlusion edge's risk.
struct EdgeRisk {
  enum class Exit { Perpendicular, Corner };
  std::uint32_t path = 0;  // index into EscapePathTree::paths
  Exit exit = Exit::Corner;
  double r_o = 0, h = 0, phi = 0;
  double d = 0, s = 0;     // last pivot w relative to the corner k: d = u x (w - k), s = u . (w - k)
  Vec2 gradient;           // grad phi^e with respect to the observer position
};

/// An average of the edges' risks: phi-bar and grad phi-bar (the same weights for both,
/// so the gradient is the gradient of the value while the tree keeps its structure).
struct RiskAverage {
  double phi = 0;
  Vec2 gradient;
};

/// Risk and gradient of one corner, as a function of the observer position alone (the
/// combinatorial structure — last pivot w at geodesic distance P — held fixed).
EdgeRisk corner_risk(const Point& observer, const Point& corner, const Point& pivot, double pivot_distance,
                     const RiskParams& params);

/// phi^e and grad phi^e for every occlusion edge of the tree (range edges carry no risk:
/// as in section V.A, the distance regulator handles the sensor's range).
std::vector<EdgeRisk> escape_risks(const LocalMap& map, const EscapePathTree& tree, const RiskParams& params);

/// The plain average of phi^e and grad phi^e over the occlusion edges (zero if none).
RiskAverage plain_average(const std::vector<EdgeRisk>& risks);
/// The recursive average over the escape-path tree (III.B): each node averages its
/// children (subtrees that hold an occlusion edge, and the edges hanging from it), and the
/// result is passed up to its parent; the root's value is returned.
RiskAverage recursive_average(const EscapePathTree& tree, const std::vector<EdgeRisk>& risks);

}  // namespace preimage::tracking
