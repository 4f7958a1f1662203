// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/landmarks/strategies.hpp>
#include <preimage/union_find.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <stdexcept>

namespace preimage::landmarks {
namespace {

std::string name(std::uint32_t k, const std::vector<std::string>& labels) {
  return k < labels.size() ? labels[k] : std::to_string(k);
}

std::vector<bool> hull_flags(std::size_t n, std::span<const std::uint32_t> hull) {
  std::vector<bool> on(n, false);
  for (auto h : hull) on[h] = true;
  return on;
}

// The hull edge (a, b) through which the swap line starting at interior p_i and pointing
// away from p_j leaves the hull: a and b on either side of line ij (Lemma 11), and the
// crossing beyond p_i, i.e. p_i inside triangle a b j.
std::pair<std::uint32_t, std::uint32_t> exit_edge(const Chirotope& chi, std::span<const std::uint32_t> hull, std::uint32_t i,
                                                  std::uint32_t j) {
  const std::size_t m = hull.size();
  for (std::size_t q = 0; q < m; ++q) {
    const std::uint32_t a = hull[q], b = hull[(q + 1) % m];
    if (a == j || b == j) continue;
    if (chi(i, j, a) != chi(i, j, b) && chi(b, j, i) > 0 && chi(j, a, i) > 0) return {a, b};
  }
  throw std::logic_error("landmark strategy: a swap line of an interior landmark leaves the hull nowhere");
}

// From anywhere inside the hull (or at a landmark): onto the swap line starting at
// interior p_i away from p_j, where it crosses the hull boundary. Two tracks.
void enter_swap_line(RobotInterface& robot, const Chirotope& chi, std::span<const std::uint32_t> hull, std::uint32_t i,
                     std::uint32_t j) {
  const auto [a, b] = exit_edge(chi, hull, i, j);
  robot.track(a);
  if (!robot.track(b, StopRule::aligned(i, j)).halted) throw std::logic_error("landmark strategy: missed a swap line on the hull");
}

}  // namespace

std::vector<std::uint32_t> LearnedOrderType::Lambda(std::uint32_t i, std::uint32_t j) const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t k = 0; k < n_; ++k)
    if (chi(i, j, k) > 0) out.push_back(k);
  return out;
}

void LearnedOrderType::set(std::uint32_t i, std::uint32_t j, std::span<const std::uint32_t> left) {
  for (std::uint32_t k = 0; k < n_; ++k) {
    if (k == i || k == j) continue;
    const bool l = std::find(left.begin(), left.end(), k) != left.end();
    left_[(std::size_t(i) * n_ + j) * n_ + k] = l;
    left_[(std::size_t(j) * n_ + i) * n_ + k] = !l;
  }
  known_[std::size_t(i) * n_ + j] = known_[std::size_t(j) * n_ + i] = 1;
}

bool LearnedOrderType::complete() const {
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t j = 0; j < n_; ++j)
      if (i != j && !known_[i * n_ + j]) return false;
  return true;
}

HullTour learn_by_hull_tour(RobotInterface& robot) {
  const std::size_t n = robot.num_landmarks();
  HullTour tour{learn_hull(robot), LearnedOrderType(n), {}};
  const auto& hull = tour.hull;
  // learn_hull ends at hull.back(): each track below runs along one hull edge.
  for (const std::uint32_t target : hull) {
    const MotionTrace tr = robot.track(target, StopRule::arrive());
    // Each reading as a linear order: the tracked landmark first, the one left last.
    const std::size_t first = tour.permutations.size();
    for (const auto& r : tr.readings) tour.permutations.push_back(rotated_to(r, target));
    const std::span<const Reading> linear(tour.permutations.data() + first, tr.readings.size());
    for (std::size_t t = 0; t < tr.events.size(); ++t)
      for (auto [a, b] : tr.events[t].swaps) {
        // Before the swap a comes right before b: the robot is left of p_a -> p_b, on the
        // side of the landmark it left, i.e. of the landmarks after the pair.
        const Reading& r = linear[t];
        if (!follows(r, a, b)) std::swap(a, b);
        const auto p = static_cast<std::size_t>(std::find(r.begin(), r.end(), a) - r.begin());
        tour.order_type.set(a, b, std::span<const std::uint32_t>(r).subspan(p + 2));
      }
    // Arriving at a hull landmark: the rest lie counter-clockwise from the direction of
    // travel within a half-turn, so Lambda(target, x) is what follows x.
    const Reading& last = linear.back();
    for (std::size_t q = 1; q < last.size(); ++q) tour.order_type.set(target, last[q], std::span<const std::uint32_t>(last).subspan(q + 1));
  }
  if (!tour.order_type.complete()) throw std::logic_error("hull tour: some pair of landmarks was never seen to swap");
  return tour;
}

PatrolPlan patrol_route(std::size_t n, const Chirotope& chi, std::span<const std::uint32_t> hull,
                        std::span<const std::uint32_t> W, const std::vector<std::string>& labels) {
  if (W.empty()) throw InputError("patrol: no landmark to watch");
  std::vector<bool> in_w(n, false);
  const auto on_hull = hull_flags(n, hull);
  for (auto w : W) {
    if (w >= n) throw InputError("patrol: no landmark " + std::to_string(w));
    if (in_w[w]) throw InputError("patrol: landmark '" + name(w, labels) + "' is listed twice");
    if (on_hull[w])
      throw InputError("patrol: landmark '" + name(w, labels) +
                       "' is on the convex hull of all landmarks, so no route of landmarks can keep it inside");
    in_w[w] = true;
  }
  // Edges a -> b with every watched landmark strictly left; a shortest cycle (BFS from
  // every start) is a smallest route. Such a cycle turns by a positive angle at every
  // edge as seen from each w, so it winds around W at least once.
  std::vector<std::vector<std::uint32_t>> next(n);
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = 0; b < n; ++b) {
      if (a == b || in_w[a] || in_w[b]) continue;
      if (std::all_of(W.begin(), W.end(), [&](std::uint32_t w) { return chi(a, b, w) > 0; })) next[a].push_back(b);
    }
  std::vector<std::uint32_t> best;
  std::vector<std::uint32_t> dist(n), parent(n);
  for (std::uint32_t s = 0; s < n; ++s) {
    if (in_w[s]) continue;
    std::fill(dist.begin(), dist.end(), UINT32_MAX);
    dist[s] = 0;
    std::vector<std::uint32_t> queue{s};
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const std::uint32_t a = queue[q];
      if (!best.empty() && dist[a] + 1 >= best.size()) break;
      for (auto b : next[a]) {
        if (b == s) {  // closes a cycle of dist[a] + 1 edges
          std::vector<std::uint32_t> cycle;
          for (std::uint32_t x = a; x != s; x = parent[x]) cycle.push_back(x);
          cycle.push_back(s);
          std::reverse(cycle.begin(), cycle.end());
          if (best.empty() || cycle.size() < best.size()) best = cycle;
          break;
        }
        if (dist[b] == UINT32_MAX) dist[b] = dist[a] + 1, parent[b] = a, queue.push_back(b);
      }
    }
  }
  if (best.empty()) throw std::logic_error("patrol: the hull itself should enclose the watched landmarks");
  std::rotate(best.begin(), std::min_element(best.begin(), best.end()), best.end());
  PatrolPlan plan{best, best};
  plan.M.insert(plan.M.end(), W.begin(), W.end());
  std::sort(plan.M.begin(), plan.M.end());
  return plan;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> polar_pairs(std::size_t n, const Chirotope& chi, const Reading& g) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::size_t q = 0; q < g.size(); ++q) {
    const std::uint32_t a = g[q], b = g[(q + 1) % n];
    std::size_t lam = 0;
    for (std::uint32_t k = 0; k < n; ++k) lam += chi(a, b, k) > 0;
    // g = [a, b, X, Y] with X = Lambda(a, b) or X = Lambda(b, a) (as sets).
    auto prefix_left_of = [&](std::uint32_t x, std::uint32_t y, std::size_t size) {
      for (std::size_t s = 0; s < size; ++s)
        if (chi(x, y, g[(q + 2 + s) % n]) <= 0) return false;
      return true;
    };
    if (prefix_left_of(a, b, lam) || prefix_left_of(b, a, n - 2 - lam)) out.emplace_back(a, b);
  }
  return out;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> meeting_polar_lines(std::size_t n, const Chirotope& chi, const Reading& g) {
  const auto polar = polar_pairs(n, chi, g);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& ij : polar) {
    const std::uint32_t i = ij.first, j = ij.second;  // not a structured binding: clang 14 cannot capture those
    const bool met = std::any_of(polar.begin(), polar.end(), [&](const auto& o) {
      const auto [k, l] = o;
      if (std::minmax(i, j) == std::minmax(k, l)) return false;
      if (k == i || k == j || l == i || l == j) return true;  // both swap lines start at the shared landmark
      // Lines ij and kl cross outside both segments iff k, l lie on one side of line ij
      // and i, j on one side of line kl (Lemmas 11-12); parallel lines pass too, which
      // only keeps more lines.
      return chi(i, j, k) == chi(i, j, l) && chi(k, l, i) == chi(k, l, j);
    });
    if (met) out.emplace_back(i, j);
  }
  return out;
}

std::optional<std::string> unrealizable_reason(std::size_t n, const Chirotope& chi, std::span<const std::uint32_t> hull,
                                               const Reading& g, const std::vector<std::string>& labels) {
  // Lemma 3: inside the hull its landmarks keep their counter-clockwise order, and a cell
  // meeting the hull meets its interior.
  Reading sub;
  const auto on_hull = hull_flags(n, hull);
  for (auto k : g)
    if (on_hull[k]) sub.push_back(k);
  if (normalized(sub) != normalized(Reading(hull.begin(), hull.end())))
    return std::string("the hull landmarks are out of their counter-clockwise order (Lemma 3)");
  if (n <= 3) return std::nullopt;  // then the hull order is the whole reading: the inside cell reads it
  // Lemma 10 as it holds: the boundary of any cell has at least two swap lines, all on
  // polar lines (Lemma 9), and where it turns from one line to the next the two meet on
  // their swap lines (at a crossing, or at the landmark both start from). So some two
  // polar lines meet. (The paper asks it of every polar line; that is false: a polar
  // line need not bound the cell. docs/landmarks.md gives the counterexample.)
  if (meeting_polar_lines(n, chi, g).size() < 2) {
    const auto polar = polar_pairs(n, chi, g);
    std::string list;
    for (std::size_t q = 0; q < polar.size() && q < 8; ++q)
      list += (q ? ", " : "") + name(polar[q].first, labels) + "-" + name(polar[q].second, labels);
    if (polar.size() > 8) list += ", ...";
    if (polar.size() < 2)
      return "it has " + std::string(polar.empty() ? "no polar line" : "one polar line (" + list + ")") +
             "; a cell's boundary lies on at least two (Lemmas 9-10)";
    return "no two of its " + std::to_string(polar.size()) + " polar lines (" + list +
           ") meet on their swap lines, as two lines of a cell's boundary do (Lemmas 9-12)";
  }
  return std::nullopt;
}

NavigationResult navigate(RobotInterface& robot, const Chirotope& chi, std::span<const std::uint32_t> hull, const Reading& goal,
                          const std::vector<std::string>& labels) {
  const std::size_t n = robot.num_landmarks();
  const Reading g = normalized(goal);
  NavigationResult res;
  res.polar = polar_pairs(n, chi, g);
  if (auto why = unrealizable_reason(n, chi, hull, g, labels)) {
    res.reason = *why;
    return res;
  }
  auto reading_g = [&] { return robot.lcd().size() == n && normalized(robot.lcd()) == g; };
  // The search concludes only on what the robot reads: every motion below runs along the
  // hull boundary or inside the hull, so a reading on the way is that of a cell meeting
  // the hull (Theorem 14 makes it the only cell reading g). A robot not at a landmark may
  // be outside the hull, where g could be read in another cell: it first moves in.
  if (robot.lcd().size() == n) robot.track(hull.back());
  // Cells meeting the hull boundary: one tour of its edges.
  if (robot.track(hull.back(), StopRule::reads({g})).halted) return res.reached = true, res;
  for (auto h : hull)
    if (robot.track(h, StopRule::reads({g})).halted) return res.reached = true, res;
  // A cell inside the hull that misses its boundary is bounded by pieces of swap lines of
  // interior landmarks inside the hull, on polar lines that meet another (Lemma 9, as in
  // unrealizable_reason). The robot reads both sides of each such piece when it tracks
  // the whole part of that swap line inside the hull.
  const auto on_hull = hull_flags(n, hull);
  for (auto [p, q] : meeting_polar_lines(n, chi, g))
    for (auto [i, j] : {std::pair{p, q}, std::pair{q, p}}) {
      if (on_hull[i]) continue;
      ++res.swap_lines_searched;
      enter_swap_line(robot, chi, hull, i, j);
      if (!robot.track(i, StopRule::reads({g, transposed(g, i, j)})).halted) continue;
      // On the line, one side reads g: step off to it. With i right before j in g the
      // robot must be left of p_i -> p_j (swap the pair for the other side).
      const bool left = follows(g, i, j);
      std::uint32_t m = 0;
      while (m == i || m == j || chi(left ? i : j, left ? j : i, m) <= 0) ++m;
      robot.track(m, StopRule::reads({g}));
      if (!reading_g()) throw std::logic_error("navigate: stepped off a swap line into the wrong cell");
      return res.reached = true, res;
    }
  res.reason = "no cell meeting the hull reads it (the robot searched the hull boundary and the " +
               std::to_string(res.swap_lines_searched) + " swap lines inside the hull of its polar lines that meet another)";
  return res;
}

namespace {

using EdgeKey = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>;

// The edges of a learned swap graph: one per pair of distinct cells, labelled by the pair
// of landmarks whose swap line separates them. With three landmarks a cell outside the
// hull borders the inside cell along both swap lines of its landmark (either
// transposition gives the same cyclic order): one edge, labelled by the least pair, as
// in SwapCellDecomposition::swap_graph.
struct EdgeSet {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>> edges;
  void add(std::uint32_t a, std::uint32_t b, std::uint32_t i, std::uint32_t j) {
    if (a == b) return;
    if (a > b) std::swap(a, b);
    const auto pair = std::minmax(i, j);
    auto [it, fresh] = edges.emplace(std::pair{a, b}, pair);
    if (!fresh) it->second = std::min(it->second, std::pair{pair.first, pair.second});
  }
  std::vector<LearnedSwapGraph::Edge> list() const {
    std::vector<LearnedSwapGraph::Edge> out;
    for (const auto& [cells, pair] : edges) out.push_back({cells.first, cells.second, pair.first, pair.second});
    return out;
  }
};

// Along a traced swap line of (i, j) each reading shows the cell on one side, and its
// transposition of i and j the cell on the other (Lemma 6): the line separates them. A
// single swap of k and l on the way is a crossing with line kl, which separates
// consecutive cells on either side. cell(reading, piece) names a cell; edge(a, b, k, l)
// records one.
template <class CellOf, class EdgeOf>
void walk_swap_line(const MotionTrace& tr, std::uint32_t i, std::uint32_t j, CellOf&& cell, EdgeOf&& edge) {
  std::vector<std::uint32_t> side, other;
  for (std::size_t t = 0; t < tr.readings.size(); ++t) {
    side.push_back(cell(tr.readings[t], t));
    other.push_back(cell(transposed(tr.readings[t], i, j), t));
    edge(side[t], other[t], i, j);
  }
  for (std::size_t t = 0; t < tr.events.size(); ++t)
    if (tr.events[t].swaps.size() == 1) {
      const auto [k, l] = tr.events[t].swaps[0];
      edge(side[t], side[t + 1], k, l);
      edge(other[t], other[t + 1], k, l);
    }
}

}  // namespace

LearnedSwapGraph learn_inside_swap_graph(RobotInterface& robot, const Chirotope& chi, std::span<const std::uint32_t> hull) {
  const std::size_t n = robot.num_landmarks();
  const auto on_hull = hull_flags(n, hull);
  LearnedSwapGraph g;
  std::map<Reading, std::uint32_t> id;  // Theorem 7: inside the hull a reading names its cell
  auto cell = [&](const Reading& r, std::size_t) {
    const Reading p = normalized(r);
    auto [it, fresh] = id.emplace(p, static_cast<std::uint32_t>(g.cells.size()));
    if (fresh) g.cells.push_back({p, {}});
    return it->second;
  };
  EdgeSet E;
  if (hull.size() == n) {  // no swap line enters the hull: its interior is one cell
    robot.track(hull[0]);
    cell(robot.track(hull[1], StopRule::arrive()).readings.front(), 0);
    return g;
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    if (on_hull[i]) continue;
    for (std::uint32_t j = 0; j < n; ++j) {
      if (j == i) continue;
      enter_swap_line(robot, chi, hull, i, j);
      walk_swap_line(robot.track(i, StopRule::arrive()), i, j, cell,
                     [&](std::uint32_t a, std::uint32_t b, std::uint32_t k, std::uint32_t l) { E.add(a, b, k, l); });
    }
  }
  g.edges = E.list();
  return g;
}

LearnedSwapGraph learn_swap_graph(RobotInterface& robot, const LearnedSwapGraph& inside, const std::function<void(double)>& progress) {
  const std::uint32_t n = static_cast<std::uint32_t>(robot.num_landmarks());
  struct Record {
    Reading p;
    std::vector<std::vector<std::uint32_t>> keys;
  };
  std::vector<Record> rec;
  std::vector<EdgeKey> raw_edges;  // between records
  auto line = [n](std::uint32_t a, std::uint32_t b) { return std::min(a, b) * n + std::max(a, b); };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j) {
      if (i == j) continue;
      if (progress) progress(double(i * n + j) / (double(n) * n));
      robot.track(i);
      const MotionTrace tr = robot.repel(i, j, StopRule::arrive());
      // Arrangement vertices the robot passes: p_i, then one per sensor event, named by
      // the lines through it (its own and those of the pairs that swap there).
      std::vector<std::vector<std::uint32_t>> vertex{{n * n + i}};
      for (const auto& e : tr.events) {
        if (e.passed) throw std::logic_error("repel passed over a landmark");
        std::vector<std::uint32_t> key{line(i, j)};
        for (auto [k, l] : e.swaps) key.push_back(line(k, l));
        std::sort(key.begin(), key.end());
        vertex.push_back(std::move(key));
      }
      // One record per side of each piece, with the vertices at the piece's ends.
      auto record = [&](const Reading& r, std::size_t t) {
        std::vector<std::vector<std::uint32_t>> keys{vertex[t]};
        if (t + 1 < vertex.size()) keys.push_back(vertex[t + 1]);
        rec.push_back({normalized(r), std::move(keys)});
        return static_cast<std::uint32_t>(rec.size() - 1);
      };
      walk_swap_line(tr, i, j, record,
                     [&](std::uint32_t a, std::uint32_t b, std::uint32_t k, std::uint32_t l) { raw_edges.emplace_back(a, b, k, l); });
    }
  // Merge: same reading and a shared vertex (Lemma 6: distinct cells on one swap line,
  // or around one vertex, read differently), or a reading of a cell meeting the hull
  // (Theorem 14: that reading names one cell of the whole plane).
  UnionFind same(rec.size());
  std::map<std::pair<Reading, std::vector<std::uint32_t>>, std::uint32_t> by_vertex;
  std::map<Reading, std::uint32_t> by_inside;
  std::set<Reading> inside_cells;
  for (const auto& c : inside.cells) inside_cells.insert(c.permutation);
  for (std::uint32_t r = 0; r < rec.size(); ++r) {
    for (const auto& k : rec[r].keys) {
      auto [it, fresh] = by_vertex.emplace(std::pair{rec[r].p, k}, r);
      if (!fresh) same.join(r, it->second);
    }
    if (inside_cells.count(rec[r].p)) {
      auto [it, fresh] = by_inside.emplace(rec[r].p, r);
      if (!fresh) same.join(r, it->second);
    }
  }
  LearnedSwapGraph g;
  std::vector<std::uint32_t> cell_of(rec.size()), root_cell(rec.size(), UINT32_MAX);
  for (std::uint32_t r = 0; r < rec.size(); ++r) {
    const std::uint32_t root = same.find(r);
    if (root_cell[root] == UINT32_MAX) {
      root_cell[root] = static_cast<std::uint32_t>(g.cells.size());
      g.cells.push_back({rec[r].p, {}});
    }
    cell_of[r] = root_cell[root];
    auto& keys = g.cells[cell_of[r]].vertex_keys;
    keys.insert(keys.end(), rec[r].keys.begin(), rec[r].keys.end());
  }
  for (auto& c : g.cells) {
    std::sort(c.vertex_keys.begin(), c.vertex_keys.end());
    c.vertex_keys.erase(std::unique(c.vertex_keys.begin(), c.vertex_keys.end()), c.vertex_keys.end());
  }
  EdgeSet E;
  for (auto [a, b, i, j] : raw_edges) E.add(cell_of[a], cell_of[b], i, j);
  g.edges = E.list();
  return g;
}

}  // namespace preimage::landmarks
