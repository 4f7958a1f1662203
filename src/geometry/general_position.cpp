// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/general_position.hpp>

#include <preimage/error.hpp>

#include <algorithm>
#include <numeric>

namespace preimage::geometry {

std::optional<std::array<std::size_t, 3>> find_collinear_triple(const std::vector<Point>& pts) {
  const std::size_t n = pts.size();
  std::vector<std::size_t> others;
  std::vector<signed char> side(n);
  for (std::size_t c = 0; c < n; ++c) {
    const Point& o = pts[c];
    others.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (i != c && pts[i] != o) others.push_back(i);
    // Direction folded into the upper half-plane (plus the +x ray), so a line through o
    // is one direction; sort by exact orientation, neighbours on one line are adjacent.
    for (std::size_t i : others) side[i] = pts[i].y() > o.y() || (pts[i].y() == o.y() && pts[i].x() > o.x()) ? 1 : -1;
    auto before = [&](std::size_t a, std::size_t b) { return side[a] * side[b] * orientation(o, pts[a], pts[b]) > 0; };
    std::sort(others.begin(), others.end(), before);
    for (std::size_t k = 0; k + 1 < others.size(); ++k)
      if (orientation(o, pts[others[k]], pts[others[k + 1]]) == 0) {
        std::array<std::size_t, 3> t{c, others[k], others[k + 1]};
        std::sort(t.begin(), t.end());
        return t;
      }
  }
  return std::nullopt;
}

std::optional<std::array<std::size_t, 2>> find_equal_x(const std::vector<Point>& pts) {
  std::vector<std::size_t> ord(pts.size());
  std::iota(ord.begin(), ord.end(), 0);
  std::sort(ord.begin(), ord.end(), [&](auto a, auto b) { return pts[a].x() < pts[b].x() || (pts[a].x() == pts[b].x() && a < b); });
  for (std::size_t k = 0; k + 1 < ord.size(); ++k)
    if (pts[ord[k]].x() == pts[ord[k + 1]].x()) return std::array<std::size_t, 2>{ord[k], ord[k + 1]};
  return std::nullopt;
}

std::vector<std::size_t> straight_vertices(const Environment& env) {
  std::vector<std::size_t> out;
  for (std::size_t v = 0; v < env.num_vertices(); ++v)
    if (env.turn(v) == 0) out.push_back(v);
  return out;
}

std::string describe_vertex(const Environment& env, std::size_t v) {
  return env.ring_name(env.ring_of(v)) + " vertex " + std::to_string(env.input_index(v));
}

void require_no_collinear_vertices(const Environment& env, const std::string& what) {
  if (auto t = find_collinear_triple(env.vertices()))
    throw InputError(what + " needs vertices in general position: " + describe_vertex(env, (*t)[0]) + ", " +
                     describe_vertex(env, (*t)[1]) + " and " + describe_vertex(env, (*t)[2]) + " are collinear");
}

void require_distinct_x(const Environment& env, const std::string& what) {
  if (auto p = find_equal_x(env.vertices()))
    throw InputError(what + " needs distinct x-coordinates: " + describe_vertex(env, (*p)[0]) + " and " +
                     describe_vertex(env, (*p)[1]) + " share x = " + format_number(env.vertex((*p)[0]).x()));
}

}  // namespace preimage::geometry
