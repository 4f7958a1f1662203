// SPDX-License-Identifier: Apache-2.0
#include <preimage/coverage/figures.hpp>

#include <cmath>
#include <numbers>

namespace preimage::coverage {

void draw_coverage(render::SvgCanvas& c, const CoverageReport& rep) {
  if (rep.path.size() < 2) return;
  const render::Style lap{"none", "#d93025", 1.6, 0.9, ""}, follow{"none", "#1a73e8", 1.6, 0.9, ""}, transit{"none", "#188038", 2.2, 0.95, "6 4"};
  const render::Style turn{"none", "#9334e6", 2.2, 0.95, ""};
  // Runs of one kind of move as one polyline each.
  std::size_t i = 0;
  while (i < rep.moves.size()) {
    std::size_t j = i;
    while (j < rep.moves.size() && rep.moves[j] == rep.moves[i]) ++j;
    const std::vector<Point> run(rep.path.begin() + static_cast<long>(i), rep.path.begin() + static_cast<long>(j + 1));
    const auto& st = rep.moves[i] == Move::Lap ? lap : rep.moves[i] == Move::Follow ? follow : rep.moves[i] == Move::Turn ? turn : transit;
    c.path(run, st, "", 90, 4, i);
    i = j;
  }
  c.legend("laps along the slice", lap);
  c.legend("boundary following between laps", follow);
  c.legend(rep.min_turn_radius > 0 ? "transits (straight parts of turns)" : "transits (shortest collision-free paths)", transit);
  if (rep.min_turn_radius > 0) c.legend("arcs of the turning radius (certified)", turn);
  const render::Style start{"#ffffff", "#202124", 2.5, 1.0, ""}, end{"#202124", "#202124", 1.0, 1.0, ""};
  c.point(rep.path.front(), 6, start, "start");
  c.point(rep.path.back(), 5, end, "end");
  c.legend("start (ring) and end (dot)", start);
}

void draw_online_coverage(render::SvgCanvas& c, const OnlineReport& rep, std::size_t upto) {
  upto = std::min(upto, rep.path.size());
  if (upto >= 2) {
    CoverageReport part;
    part.path.assign(rep.path.begin(), rep.path.begin() + static_cast<long>(upto));
    part.moves.assign(rep.moves.begin(), rep.moves.begin() + static_cast<long>(upto - 1));
    draw_coverage(c, part);
  }
  const render::Style edge{"none", "#7b1fa2", 3.0, 0.85, ""}, stub{"none", "#7b1fa2", 2.0, 0.6, "3 3"};
  const render::Style node{"#f9ab00", "#202124", 1.5, 1.0, ""};
  const double rad = std::numbers::pi / 180 * rep.angle, ux = std::cos(rad), uy = std::sin(rad);
  std::vector<char> seen(rep.nodes.size(), 0);
  for (std::size_t i = 0; i < rep.nodes.size(); ++i) seen[i] = rep.nodes[i].sensed_at < upto;
  for (std::size_t k = 0; k < rep.edges.size(); ++k) {
    const auto& e = rep.edges[k];
    if (e.path_end >= upto) continue;
    // Through the middle of the cell's sweep.
    const Point mid = rep.path[(e.path_begin + e.path_end) / 2];
    c.polyline({rep.nodes[e.from].at, mid, rep.nodes[e.to].at}, edge, "cell " + std::to_string(e.from) + " - " + std::to_string(e.to));
  }
  const double len = 2.5 * rep.width;
  for (std::size_t i = 0; i < rep.nodes.size(); ++i) {
    if (!seen[i]) continue;
    const auto& n = rep.nodes[i];
    for (std::size_t p = 0; p < n.ports.size(); ++p) {
      const bool explored = n.ports[p] >= 0 && rep.edges[static_cast<std::size_t>(n.ports[p])].path_end < upto;
      if (explored) continue;
      // Port directions: left or right along the sweep, tilted from down to up by their
      // order on the slice.
      const bool right = p >= n.left;
      const std::size_t k = right ? n.ports.size() - n.left : n.left, j = right ? p - n.left : p;
      const double tilt = k > 1 ? -0.6 + 1.2 * static_cast<double>(j) / static_cast<double>(k - 1) : 0.0;
      const double sx = right ? 1 : -1;
      const Point q(n.at.x() + len * (sx * ux - tilt * uy), n.at.y() + len * (sx * uy + tilt * ux));
      c.segment(n.at, q, stub, "unexplored port");
    }
  }
  std::size_t order = 0;
  for (std::size_t i = 0; i < rep.nodes.size(); ++i)
    if (seen[i]) {
      c.point(rep.nodes[i].at, 6, node, std::to_string(i) + ": " + std::string(to_string(rep.nodes[i].kind)));
      c.label(rep.nodes[i].at, std::to_string(i), 12);
      ++order;
    }
  c.legend("Reeb graph edges: cells covered", edge);
  c.legend("unexplored ports", stub);
  c.legend("critical points sensed", node);
}

}  // namespace preimage::coverage
