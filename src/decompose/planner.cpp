// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/planner.hpp>
#include <preimage/geometry/clearance.hpp>
#include <preimage/geometry/local_frame.hpp>


#include <preimage/error.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility_graph.hpp>


#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <stdexcept>

namespace preimage::decompose {

TrapezoidalPlanner::TrapezoidalPlanner(const TrapezoidalDecomposition& d) : d_(&d), locator_(d) {
  const Environment& E = d.environment();
  contact_off_.assign(1, 0);
  if (!E.has_contacts()) return;
  // A cell holds a contact point in its closure iff its floor or ceiling edge ends there at
  // one of the cell's sides (cells are bounded by vertical lines through vertices).
  std::vector<std::uint32_t> contact_of(E.num_vertices(), UINT32_MAX);
  for (std::size_t v = 0; v < E.num_vertices(); ++v) {
    if (!E.is_contact(v) || contact_of[v] != UINT32_MAX) continue;
    for (std::size_t w = v;;) {
      contact_of[w] = static_cast<std::uint32_t>(contacts_.size());
      w = E.same_point_next(w);
      if (w == v) break;
    }
    contacts_.push_back(E.vertex(v));
  }
  std::vector<std::vector<std::uint32_t>> cells_at(contacts_.size());
  cell_contacts_.resize(d.cells().size());
  for (std::uint32_t c = 0; c < d.cells().size(); ++c) {
    const auto& t = d.cells()[c];
    for (std::uint32_t e : {t.floor, t.ceiling})
      for (std::size_t w : {std::size_t(e), E.next(e)}) {
        const std::uint32_t k = contact_of[w];
        if (k == UINT32_MAX || (E.vertex(w).x() != t.x_left && E.vertex(w).x() != t.x_right)) continue;
        if (std::find(cell_contacts_[c].begin(), cell_contacts_[c].end(), k) != cell_contacts_[c].end()) continue;
        cell_contacts_[c].push_back(k);
        cells_at[k].push_back(c);
      }
  }
  for (const auto& cs : cells_at) {
    contact_cells_.insert(contact_cells_.end(), cs.begin(), cs.end());
    contact_off_.push_back(static_cast<std::uint32_t>(contact_cells_.size()));
  }
}

Point TrapezoidalPlanner::extension_midpoint(std::size_t x) const {
  auto [a, b] = d_->segment(x);
  return Point(d_->extensions()[x].x, (CGAL::to_double(a.y()) + CGAL::to_double(b.y())) / 2);
}

Point TrapezoidalPlanner::centroid(std::size_t cell) const {
  double sx = 0, sy = 0;
  auto poly = d_->polygon(cell);
  for (auto& p : poly) sx += CGAL::to_double(p.x()), sy += CGAL::to_double(p.y());
  return Point(sx / static_cast<double>(poly.size()), sy / static_cast<double>(poly.size()));
}

Plan TrapezoidalPlanner::plan(const Point& start, const Point& goal, bool shorten,
                              const geometry::VisibilityIndex* index) const {
  const Environment& env = d_->environment();
  auto locate_or_throw = [&](const Point& p, const char* what) {
    if (auto c = locator_.locate(p)) return *c;
    const auto loc = geometry::locate(env, p);
    throw InputError(std::string(what) + " " + geometry::format_point(p) + " is not in free space: it lies " +
                     (loc.kind == geometry::Location::Kind::InHole ? "inside " + env.ring_name(loc.index + 1)
                                                                   : "outside " + env.ring_name(0)));
  };
  const std::uint32_t cs = locate_or_throw(start, "start"), cg = locate_or_throw(goal, "goal");
  Plan out;

  // Dijkstra over cells, entering each through an extension (or a contact point); cost =
  // distance between the entry points (portals), which the unshortened path will travel.
  const std::size_t m = d_->cells().size();
  std::vector<double> dist(m, std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> from(m, UINT32_MAX);  // cell the cell was entered from
  std::vector<Point> entry(m, start);              // its portal
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> pq;
  dist[cs] = 0;
  pq.push({0, cs});
  auto gap = [](const Point& a, const Point& b) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))); };
  auto relax = [&](std::uint32_t c, std::uint32_t o, const Point& portal) {
    const double nd = dist[c] + gap(entry[c], portal);
    if (nd < dist[o]) dist[o] = nd, from[o] = c, entry[o] = portal, pq.push({nd, o});
  };
  while (!pq.empty()) {
    auto [dcur, c] = pq.top();
    pq.pop();
    if (dcur > dist[c]) continue;
    if (c == cg) break;
    for (auto x : d_->extensions_of(c)) {
      const auto& ext = d_->extensions()[x];
      relax(c, ext.left_cell == c ? ext.right_cell : ext.left_cell, extension_midpoint(x));
    }
    if (!cell_contacts_.empty())
      for (std::uint32_t k : cell_contacts_[c])
        for (std::uint32_t i = contact_off_[k]; i < contact_off_[k + 1]; ++i)
          if (contact_cells_[i] != c) relax(c, contact_cells_[i], contacts_[k]);
  }
  if (!std::isfinite(dist[cg])) return out;

  // Cells back from the goal; the path as in the text: start, then per cell crossed its
  // portal (extension midpoint or contact point) and the next cell's centroid, then the goal.
  for (std::uint32_t c = cg; c != cs; c = from[c]) out.cells.push_back(c);
  out.cells.push_back(cs);
  std::reverse(out.cells.begin(), out.cells.end());
  out.path.push_back(start);
  for (std::size_t k = 1; k < out.cells.size(); ++k) {
    out.path.push_back(entry[out.cells[k]]);
    if (out.cells[k] != cg) out.path.push_back(centroid(out.cells[k]));
  }
  out.path.push_back(goal);
  if (shorten && out.path.size() > 2) {
    // String pulling: from each kept point jump to a later point it sees (exact), found by
    // doubling the jump while the point there is visible and then halving back to the
    // last visible one. Consecutive points see each other, so every jump is a segment in
    // free space; galloping asks O(log m) questions per jump where trying each point in
    // turn asked one per point skipped (24 s on a 64,000-point path in a 10^5-vertex square).
    std::optional<geometry::VisibilityIndex> own;
    if (!index) index = &own.emplace(env);
    if (&index->environment() != &env) throw std::logic_error("plan: the visibility index is of another environment");
    const std::vector<Point>& p = out.path;
    std::vector<Point> s{p.front()};
    for (std::size_t i = 0; i + 1 < p.size();) {
      std::size_t good = i + 1, step = 1;
      while (good + step < p.size() && index->visible(p[i], p[good + step])) good += step, step *= 2;
      for (std::size_t bad = std::min(p.size(), good + step); bad - good > 1;) {
        const std::size_t mid = good + (bad - good) / 2;
        (index->visible(p[i], p[mid]) ? good : bad) = mid;
      }
      s.push_back(p[good]);
      i = good;
    }
    out.path.swap(s);
  }
  for (std::size_t k = 0; k + 1 < out.path.size(); ++k) out.length += gap(out.path[k], out.path[k + 1]);
  out.found = true;
  return out;
}

namespace {

RobotPlan plan_in_frame(const Environment& env, const Point& start, const Point& goal, double radius, PlanMethod method, bool shorten) {
  const geometry::ConfigurationSpace cs(env, radius);
  auto join = [&](const Point& p, const char* what) {
    const auto loc = geometry::locate(env, p);
    if (!loc.in_free_space())
      throw InputError(std::string(what) + " " + geometry::format_point(p) + " is not in free space: it lies " +
                       (loc.kind == geometry::Location::Kind::InHole ? "inside " + env.ring_name(loc.index + 1) : "outside " + env.ring_name(0)));
    if (!cs.admits(p))
      throw InputError(std::string(what) + " " + geometry::format_point(p) + " is " + geometry::format_number(cs.clearance(p)) +
                       " from an obstacle: a robot of radius " + geometry::format_number(radius) + " does not fit there");
    const auto in = cs.entry(p);
    if (!in)
      throw InputError(std::string(what) + " " + geometry::format_point(p) + " is within " + geometry::format_number(cs.approximation_error()) +
                       " of the configuration space's boundary and cannot be joined to it: move it inwards");
    return *in;
  };
  const auto s = join(start, "start"), g = join(goal, "goal");
  RobotPlan out;
  if (s.component != g.component) {
    out.why_not = "start and goal are in different components of the configuration space: a robot of radius " +
                  geometry::format_number(radius) + " cannot pass between them";
    return out;
  }
  const Environment& E = cs.components()[s.component];
  const geometry::VisibilityIndex index(E);
  std::vector<Point> middle;
  if (method == PlanMethod::Shortest) {
    const geometry::VisibilityGraph graph(index);
    const auto sp = graph.shortest_path(s.at, g.at);
    if (!sp.found) throw std::logic_error("plan: no path inside one component of the configuration space");
    middle = sp.points;
  } else {
    const TrapezoidalDecomposition d(E);
    const TrapezoidalPlanner planner(d);
    const Plan p = planner.plan(s.at, g.at, shorten, &index);
    if (!p.found) throw std::logic_error("plan: the cell graph of one component is not connected");
    middle = p.path, out.decomposition_cells = d.cells().size(), out.cells_crossed = p.cells.size();
  }
  if (start != s.at) out.path.push_back(start);
  for (const Point& p : middle)
    if (out.path.empty() || out.path.back() != p) out.path.push_back(p);
  if (goal != out.path.back()) out.path.push_back(goal);
  // Certified: inside the component (exact walk) or, for the joins from the thin band, and
  // for every segment with a footprint, r away from every obstacle (exact arithmetic).
  for (std::size_t i = 0; i + 1 < out.path.size(); ++i) {
    const Point &a = out.path[i], &z = out.path[i + 1];
    const bool join_segment = (i == 0 && start != s.at) || (i + 2 == out.path.size() && goal != g.at);
    if (!(join_segment ? cs.admits(a, z) : index.visible(a, z)) || (radius > 0 && !cs.admits(a, z)))
      throw std::logic_error("plan: segment " + geometry::format_point(a) + " -> " + geometry::format_point(z) + " failed certification");
    out.length += std::sqrt(CGAL::to_double(CGAL::squared_distance(a, z)));
  }
  out.found = true;
  return out;
}

}  // namespace

RobotPlan plan_path(const Environment& env, const Point& start, const Point& goal, double radius, PlanMethod method,
                    bool shorten) {
  const geometry::LocalFrame frame = geometry::LocalFrame::of(env);
  if (frame.identity()) return plan_in_frame(env, start, goal, radius, method, shorten);
  // Far from the origin: plan in the local frame (the configuration space's offset keeps its
  // digits there), then round the path back and certify it in input coordinates.
  const geometry::Clearance clear(env, radius);
  RobotPlan out = plan_in_frame(frame.to_local(env), frame.to_local(start), frame.to_local(goal), radius, method, shorten);
  if (!out.found) return out;
  if (const std::size_t bad = frame.to_input_certified(out.path, clear); bad < out.path.size())
    throw std::logic_error("plan: segment " + geometry::format_point(out.path[bad]) + " -> " + geometry::format_point(out.path[bad + 1]) +
                           " failed certification in input coordinates");
  return out;
}

}  // namespace preimage::decompose
