// SPDX-License-Identifier: Apache-2.0
// The ray sweep of section IV.A. Every decision (sides of l(q^o, q^t), pivot-list
// updates, where the nearest point of a free edge lies, whether a pivot blocks it) is an
// exact predicate on the map's points; only lengths and escape points are computed in
// doubles. The one constructed point that is decided on is where a free edge crosses the
// line l behind the observer (a 360-deg map), splitting it between the two sweeps.
#include <preimage/error.hpp>
#include <preimage/tracking/escape_path_tree.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace preimage::tracking {

double EscapePathTree::sde() const {
  return shortest == kNone ? std::numeric_limits<double>::infinity() : paths[shortest].length;
}

std::vector<Point> EscapePathTree::polyline(std::size_t i) const {
  std::vector<Point> out{paths[i].escape_point};
  for (std::uint32_t v = paths[i].node; v != kNone; v = nodes[v].parent) out.push_back(nodes[v].at);
  std::reverse(out.begin(), out.end());
  return out;
}

std::vector<std::vector<std::uint32_t>> EscapePathTree::child_nodes() const {
  std::vector<std::vector<std::uint32_t>> c(nodes.size());
  for (std::uint32_t i = 1; i < nodes.size(); ++i) c[nodes[i].parent].push_back(i);
  return c;
}

std::vector<std::vector<std::uint32_t>> EscapePathTree::child_paths() const {
  std::vector<std::vector<std::uint32_t>> c(nodes.size());
  for (std::uint32_t i = 0; i < paths.size(); ++i) c[paths[i].node].push_back(i);
  return c;
}

namespace {

double dist(const Point& a, const Point& b) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))); }

// Rank of a vertex in counter-clockwise order starting at the ray q^o -> q^t.
enum Rank : std::uint8_t { Front = 0, Left = 1, Back = 2, Right = 3 };

// The pivot list: vertex (kNone = target), geodesic distance and tree node, both lazy (-1,
// kNone until needed: most pivots are popped before any escape path uses them).
struct Pivot { std::uint32_t vertex; double distance; std::uint32_t node; };

struct Sweep {
  const LocalMap& map;
  EscapePathTree& tree;
  std::vector<double>& best;             // per edge: best SDE so far (+inf)
  std::vector<Pivot>& stack;
  std::vector<std::uint32_t>& index_of;  // edge -> index in tree.paths

  const Point& at(const Pivot& p) const { return p.vertex == kNone ? tree.target : map.vertices[p.vertex]; }

  // Geodesic distance of stack entry j, filling in the entries below it first.
  double distance(std::size_t j) {
    std::size_t k = j;
    while (stack[k].distance < 0) --k;  // the root has distance 0
    for (++k; k <= j; ++k) stack[k].distance = stack[k - 1].distance + dist(at(stack[k - 1]), at(stack[k]));
    return stack[j].distance;
  }

  void reset() { stack.assign(1, Pivot{kNone, 0.0, 0}); }

  // Tree node for stack entry j, creating the nodes below it first (parents precede children).
  std::uint32_t node_of(std::size_t j, int side) {
    std::size_t k = j;
    while (stack[k].node == kNone) --k;
    for (++k; k <= j; ++k) {
      EscapeNode n{stack[k].vertex, stack[k - 1].node, at(stack[k]), distance(k), side};
      stack[k].node = static_cast<std::uint32_t>(tree.nodes.size());
      tree.nodes.push_back(n);
    }
    return stack[j].node;
  }

  // Pivot list UPDATE (IV.A) for the next vertex of the sweep. side = +1 for L_l, -1 for
  // L_r: escape paths wrap obstacles by turning clockwise on the left of l, so a pivot
  // whose turn is counter-clockwise or straight is no longer on the shortest path.
  void push(std::uint32_t v, int side) {
    const Point& p = map.vertices[v];
    while (stack.size() >= 2 &&
           side * geometry::orientation(at(stack[stack.size() - 2]), at(stack.back()), p) >= 0)
      stack.pop_back();
    stack.push_back(Pivot{v, -1.0, kNone});
  }

  // Nearest point of segment [a, b] to w, as a point and as "which": 0 a, 1 b, 2 interior.
  static int nearest_kind(const Point& a, const Point& b, const Point& w) {
    if (geometry::dot_sign(a, b, a, w) <= 0) return 0;
    if (geometry::dot_sign(b, a, b, w) <= 0) return 1;
    return 2;
  }
  static Point foot(const Point& a, const Point& b, const Point& w) {
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    const double t = ((w.x() - a.x()) * dx + (w.y() - a.y()) * dy) / (dx * dx + dy * dy);
    return Point(a.x() + t * dx, a.y() + t * dy);
  }

  // The escape through free edge `edge`, restricted to its part [a, b], reached from the
  // pivot list whose top is the path to a (case 3 of IV.A: the escape point slides along
  // the edge towards the nearest point). Walking down the list never makes the path
  // longer (triangle inequality), so the answer is the lowest pivot that still sees its
  // nearest point of [a, b]; the pivot above it blocks it when it lies strictly on the
  // obstacle side (the side the path wraps) of the segment from the pivot to that point.
  void escape(std::uint32_t edge, const Point& a, const Point& b, int side) {
    std::size_t j = stack.size() - 1;  // the top: a itself, or the target for the edge across l
    const int top = nearest_kind(a, b, at(stack[j]));
    Point q = top == 0 ? a : top == 1 ? b : foot(a, b, at(stack[j]));
    double len = distance(j) + dist(at(stack[j]), q);
    for (std::size_t k = j; k-- > 0;) {
      const Point& w = at(stack[k]);
      const Point& nxt = at(stack[k + 1]);
      const int kind = nearest_kind(a, b, w);
      int turn;  // sign of cross(q - w, nxt - w)
      if (kind < 2) {
        // nxt is often that very endpoint (the corner pushed last): skip the predicate,
        // whose filters cannot certify a zero determinant and fall back to exact arithmetic.
        const Point& end = kind == 0 ? a : b;
        turn = end == nxt ? 0 : geometry::orientation(w, end, nxt);
      } else {
        // q - w is the normal of ab pointing from w to the line: cross(sigma perp(d), v)
        // = -sigma dot(d, v), with sigma = +1 when w is right of a -> b.
        const int sigma = -geometry::orientation(a, b, w);
        const int dot = geometry::dot_sign(a, b, w, nxt);
        turn = -sigma * dot;
      }
      if (side * turn > 0) break;  // blocked
      j = k;
      q = kind == 0 ? a : kind == 1 ? b : foot(a, b, w);
      len = distance(k) + dist(w, q);
    }
    if (len < best[edge]) {
      best[edge] = len;
      EscapePath& path = tree.paths[index_of[edge]];
      path.node = node_of(j, side);
      path.escape_point = q;
      path.length = len;
      path.side = j == 0 ? 0 : side;
    }
  }
};

}  // namespace

EscapePathTree escape_path_tree(const LocalMap& map, const Point& t) {
  if (auto tree = try_escape_path_tree(map, t)) return std::move(*tree);
  throw InputError("target at (" + std::to_string(t.x()) + ", " + std::to_string(t.y()) +
                   ") is not strictly inside the observer's visibility polygon");
}

std::optional<EscapePathTree> try_escape_path_tree(const LocalMap& map, const Point& t) {
  if (!map.strictly_contains(t)) return std::nullopt;
  const std::size_t n = map.size();
  const Point& o = map.observer;
  if (t == o) throw InputError("target and observer coincide");
  EscapePathTree tree;
  tree.target = t;
  tree.nodes.push_back(EscapeNode{kNone, kNone, t, 0.0, 0});
  // Scratch kept per thread: TRACK builds one tree per scan.
  thread_local std::vector<double> best;
  thread_local std::vector<Pivot> stack;
  thread_local std::vector<std::uint32_t> index_of;
  thread_local std::vector<Rank> rank;
  best.assign(n, std::numeric_limits<double>::infinity());
  index_of.assign(n, kNone);
  Sweep s{map, tree, best, stack, index_of};
  std::size_t escapes = 0;
  for (auto k : map.edges) escapes += is_escape(k);
  tree.paths.reserve(escapes);
  tree.nodes.reserve(tree.paths.capacity() + 8);
  for (std::uint32_t e = 0; e < n; ++e)
    if (is_escape(map.edges[e])) {
      s.index_of[e] = static_cast<std::uint32_t>(tree.paths.size());
      tree.paths.push_back(EscapePath{e, map.edges[e], kNone, Point(), 0.0, 0});
    }

  // Rank every vertex about the ray from the observer through the target.
  rank.assign(n, Front);
  for (std::size_t i = 0; i < n; ++i) {
    if (i == map.observer_vertex) continue;
    const int side = geometry::orientation(o, t, map.vertices[i]);
    rank[i] = side > 0 ? Left : side < 0 ? Right : geometry::dot_sign(o, t, o, map.vertices[i]) > 0 ? Front : Back;
  }
  // Start of the counter-clockwise order at the ray: after the observer (cone), or at the
  // first Front/Left vertex that follows a Back/Right one (360 deg).
  std::size_t start = kNone;
  if (map.observer_vertex != kNone) {
    start = map.next(map.observer_vertex);
  } else {
    for (std::size_t i = 0; i < n && start == kNone; ++i)
      if ((rank[i] == Front || rank[i] == Left) && (rank[map.prev(i)] == Back || rank[map.prev(i)] == Right)) start = i;
    if (start == kNone) throw InputError("local map: the observer does not see around itself (no vertex on one side of the target's line)");
  }
  auto in_left = [&](std::size_t i) { return i != map.observer_vertex && rank[i] != Right; };
  auto in_right = [&](std::size_t i) { return i != map.observer_vertex && rank[i] != Left; };

  // The edge l(q^o, q^t) crosses beyond the target when no vertex lies on the ray: the
  // target sees all of it, so its escape point is simply the nearest point.
  std::size_t first = start;
  while (first != map.observer_vertex && rank[first] == Right) first = map.next(first);  // cone: skip L_r
  if (rank[first] != Front) {
    const std::uint32_t e = static_cast<std::uint32_t>(map.prev(first));
    if (is_escape(map.edges[e])) {
      s.reset();
      s.escape(e, map.vertices[map.prev(first)], map.vertices[first], +1);
    }
  }

  for (int side : {+1, -1}) {
    s.reset();
    // L_l runs counter-clockwise from the first vertex at or left of the ray; L_r runs
    // clockwise from the last vertex at or right of it.
    std::size_t cur = first;
    if (side < 0) {
      cur = map.prev(first);
      std::size_t f = first;
      while (rank[f] == Front) { cur = f; f = map.next(f); }  // Front vertices belong to both lists
    }
    auto member = [&](std::size_t i) { return side > 0 ? in_left(i) : in_right(i); };
    auto step = [&](std::size_t i) { return side > 0 ? map.next(i) : map.prev(i); };
    std::size_t prev = kNone;
    for (std::size_t count = 0; count < n && member(cur); ++count) {
      if (prev != kNone) {
        const std::uint32_t e = static_cast<std::uint32_t>(side > 0 ? prev : cur);
        if (is_escape(map.edges[e])) s.escape(e, map.vertices[prev], map.vertices[cur], side);
      }
      s.push(static_cast<std::uint32_t>(cur), side);
      prev = cur;
      cur = step(cur);
      if (cur == first && side > 0) break;
    }
    // Behind the observer (360 deg, no vertex on the ray): the edge from the last vertex of
    // this list to the first of the other crosses l; by Property 2 this sweep may use only
    // its part on this side.
    if (prev != kNone && map.observer_vertex == kNone && rank[prev] != Back && rank[cur] != Back &&
        rank[cur] != rank[prev]) {
      const std::uint32_t e = static_cast<std::uint32_t>(side > 0 ? prev : cur);
      if (is_escape(map.edges[e])) {
        const Point& a = map.vertices[prev];
        const Point& b = map.vertices[cur];
        // Where ab crosses l: a and b lie strictly on opposite sides, so the ratio is in (0, 1).
        auto side_area = [&](const Point& p) { return (t.x() - o.x()) * (p.y() - o.y()) - (t.y() - o.y()) * (p.x() - o.x()); };
        const double da = side_area(a), db = side_area(b);
        const double r = da != db ? std::clamp(da / (da - db), 0.0, 1.0) : 0.5;  // rounding may tie them
        s.escape(e, a, Point(a.x() + r * (b.x() - a.x()), a.y() + r * (b.y() - a.y())), side);
      }
    }
  }
  double shortest = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < tree.paths.size(); ++i) {
    if (tree.paths[i].node == kNone)
      throw InputError("local map: escape edge " + std::to_string(tree.paths[i].edge) + " was not reached by the sweep");
    if (tree.paths[i].length < shortest) { shortest = tree.paths[i].length; tree.shortest = i; }
  }
  return tree;
}

}  // namespace preimage::tracking
