// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/visibility_graphs.hpp>

#include <preimage/error.hpp>

#include <algorithm>
#include <string>
#include <thread>

namespace preimage::geometry {

namespace vis_graphs_detail {

// Runs row(i, out) for i in [0, rows) on `threads` threads, rows interleaved (the rows of a
// triangle of pairs shrink), and concatenates the outputs in row order.
template <class Row>
GraphEdges by_rows(std::size_t rows, unsigned threads, Row&& row) {
  std::size_t t = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  t = std::clamp<std::size_t>(t, 1, std::max<std::size_t>(1, rows));
  std::vector<GraphEdges> per_row(rows);
  auto work = [&](std::size_t begin) {
    for (std::size_t i = begin; i < rows; i += t) row(i, per_row[i]);
  };
  if (t == 1) {
    work(0);
  } else {
    std::vector<std::thread> pool;
    for (std::size_t k = 0; k < t; ++k) pool.emplace_back(work, k);
    for (auto& th : pool) th.join();
  }
  GraphEdges out;
  std::size_t total = 0;
  for (auto& r : per_row) total += r.size();
  out.reserve(total);
  for (auto& r : per_row) out.insert(out.end(), r.begin(), r.end());
  return out;
}

void require_free_points(const VisibilityIndex& index, std::span<const Point> points) {
  const Environment& env = index.environment();
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (index.in_free_space(points[i])) continue;
    const Location loc = index.locate(points[i]);
    throw InputError("visibility graph: point " + std::to_string(i) + " " + format_point(points[i]) + " is not in free space: it lies " +
                     (loc.kind == Location::Kind::InHole ? "inside " + env.ring_name(loc.index + 1) : "outside " + env.ring_name(0)));
  }
}

}  // namespace vis_graphs_detail

GraphEdges vertex_visibility_graph(const VisibilityIndex& index, unsigned threads) {
  const Environment& env = index.environment();
  return vis_graphs_detail::by_rows(env.num_vertices(), threads, [&](std::size_t u, GraphEdges& out) {
    for (std::uint32_t w : index.visible_vertices(env.vertex(u)))  // ascending
      if (w > u) out.emplace_back(static_cast<std::uint32_t>(u), w);
  });
}

GraphEdges point_visibility_graph(const VisibilityIndex& index, std::span<const Point> points, unsigned threads) {
  vis_graphs_detail::require_free_points(index, points);
  return vis_graphs_detail::by_rows(points.size(), threads, [&](std::size_t i, GraphEdges& out) {
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (index.visible(points[i], points[j])) out.emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
  });
}

GraphEdges point_vertex_visibility_graph(const VisibilityIndex& index, std::span<const Point> points, unsigned threads) {
  vis_graphs_detail::require_free_points(index, points);
  return vis_graphs_detail::by_rows(points.size(), threads, [&](std::size_t i, GraphEdges& out) {
    for (std::uint32_t w : index.visible_vertices(points[i])) out.emplace_back(static_cast<std::uint32_t>(i), w);
  });
}

}  // namespace preimage::geometry
