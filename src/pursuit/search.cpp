// SPDX-License-Identifier: Apache-2.0
// Dijkstra over information states (see search.hpp). A state is a sorted tuple of cells
// (interned) and one label per unit of that tuple; transitions are compiled once per
// (tuple, moving slot, boundary) into a filter::ShadowTransition.
#include <preimage/pursuit/search.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/pursuit/joint.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace preimage::pursuit {

const char* to_string(SearchResult::Outcome o) {
  switch (o) {
    case SearchResult::Outcome::Plan: return "plan";
    case SearchResult::Outcome::NoPlan: return "no plan";
    case SearchResult::Outcome::Budget: return "budget exhausted";
  }
  return "?";
}

namespace {

double dist(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

// Tuples of cells (sorted), their units and compiled transitions.
class JointSpace {
 public:
  struct Step {
    std::uint32_t to;                   // new tuple
    std::vector<std::uint32_t> slot_of; // new sorted slot of each old slot
    filter::ShadowTransition tr;
  };

  JointSpace(const ConservativeCells& C, std::size_t k) : C_(C), k_(k) {}

  std::uint32_t intern(const std::vector<std::uint32_t>& cells) {
    auto [it, fresh] = id_.try_emplace(cells, static_cast<std::uint32_t>(tuples_.size()));
    if (fresh) {
      tuples_.push_back(cells);
      units_.push_back(compute_units(cells));
    }
    return it->second;
  }
  const std::vector<std::uint32_t>& cells(std::uint32_t t) const { return tuples_[t]; }
  std::size_t num_units(std::uint32_t t) const { return units_[t].size(); }

  const Step& step(std::uint32_t t, std::uint32_t slot, std::uint32_t b) {
    const std::uint64_t key = (std::uint64_t{t} * k_ + slot) * C_.boundaries().size() + b;
    auto it = steps_.find(key);
    if (it != steps_.end()) return it->second;
    const CellBoundary& B = C_.boundaries()[b];
    std::vector<std::uint32_t> moved = tuples_[t];
    const std::uint32_t c = moved[slot];
    const bool rightward = c == B.left;
    if (!rightward && c != B.right) throw std::logic_error("pursuit: a move across a boundary of another cell");
    moved[slot] = rightward ? B.right : B.left;
    const filter::ShadowEvent& ev = rightward ? B.to_right : B.to_left;
    std::vector<std::uint32_t> order(k_);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](auto a, auto b2) { return moved[a] < moved[b2]; });
    Step s;
    s.slot_of.assign(k_, 0);
    std::vector<std::uint32_t> sorted(k_);
    for (std::uint32_t p = 0; p < k_; ++p) sorted[p] = moved[order[p]], s.slot_of[order[p]] = p;
    s.to = intern(sorted);
    const auto& U = units_[t];
    const auto& U2 = units_[s.to];
    filter::ShadowEvent e{U.size(), U2.size(), {}};
    if (k_ == 1) {
      e.pairs = ev.pairs;
    } else {
      std::map<std::vector<std::uint32_t>, std::uint32_t> index;
      for (std::uint32_t u = 0; u < U.size(); ++u) index.emplace(U[u], u);
      for (std::uint32_t j = 0; j < U2.size(); ++j) {
        std::vector<std::uint32_t> old(k_);
        for (std::uint32_t l = 0; l < k_; ++l) old[l] = U2[j][s.slot_of[l]];
        const std::uint32_t mine = old[slot];
        for (auto [a, a2] : ev.pairs) {
          if (a2 != mine) continue;
          old[slot] = a;
          if (auto f = index.find(old); f != index.end()) e.pairs.push_back({f->second, j});
        }
      }
    }
    s.tr = filter::ShadowTransition(e);
    return steps_.emplace(key, std::move(s)).first->second;
  }

 private:
  std::vector<std::vector<std::uint32_t>> compute_units(const std::vector<std::uint32_t>& cells) const {
    std::vector<std::vector<std::uint32_t>> units;
    if (k_ == 1) {
      for (std::uint32_t c = 0; c < C_.cell(cells[0]).shadows.num_components; ++c) units.push_back({c});
      return units;
    }
    std::vector<Point> at;
    std::vector<const Shadows*> sh;
    for (auto c : cells) at.push_back(C_.cell(c).sample), sh.push_back(&C_.cell(c).shadows);
    return joint_units(overlay_shadows(C_.environment(), at, sh));
  }

  const ConservativeCells& C_;
  std::size_t k_;
  std::map<std::vector<std::uint32_t>, std::uint32_t> id_;
  std::vector<std::vector<std::uint32_t>> tuples_;
  std::vector<std::vector<std::vector<std::uint32_t>>> units_;
  std::unordered_map<std::uint64_t, Step> steps_;
};

struct StateKey {
  std::uint32_t tuple;
  filter::ShadowLabels labels;
  bool operator==(const StateKey& o) const { return tuple == o.tuple && labels == o.labels; }
};
struct StateHash {
  std::size_t operator()(const StateKey& k) const { return k.labels.hash() ^ (std::size_t{k.tuple} * 0x9e3779b97f4a7c15ull); }
};

struct Node {
  StateKey key;
  double dist;
  std::uint32_t parent;
  std::uint32_t slot, boundary;
  bool closed = false;
};

std::uint32_t start_cell_of(const ConservativeCells& C, const Point& p) {
  const auto loc = geometry::locate(C.environment(), p);
  if (!loc.in_free_space())
    throw InputError("--start " + geometry::format_point(p) + " is not in free space (it is " + geometry::to_string(loc.kind) + ")");
  const auto c = C.locate(p);
  if (!c) throw std::logic_error("pursuit: a free-space point in no cell");
  return *c;
}

void certify(const geometry::Environment& env, const std::vector<Point>& path, std::size_t pursuer) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (path[i] != path[i + 1] && !geometry::visible(env, path[i], path[i + 1]))
      throw std::logic_error("pursuit: plan segment " + std::to_string(i) + " of pursuer " + std::to_string(pursuer) +
                             " leaves free space");
}

// Cost of moving from c across b (the walk between the cells' samples).
double move_cost(const ConservativeCells& C, std::uint32_t c, std::uint32_t b) {
  const CellBoundary& B = C.boundaries()[b];
  const bool right = c == B.left;
  const Point &near_from = right ? B.near_left : B.near_right, &near_to = right ? B.near_right : B.near_left;
  return dist(C.cell(c).sample, near_from) + dist(near_from, near_to) + dist(near_to, C.cell(right ? B.right : B.left).sample);
}

// Double points strictly inside cell c approaching the middle of boundary b's piece (the
// last ones closest to it), for crossings next to cells too thin for near points.
std::vector<Point> toward(const ConservativeCells& C, std::uint32_t c, std::uint32_t b) {
  const auto& A = C.arrangement();
  const auto& H = A.half_edges();
  const std::uint32_t h = C.boundaries()[b].half_edge;
  const Point &a = A.approx_vertices()[H[h].origin], &z = A.approx_vertices()[H[h].target];
  const Point s = C.cell(c).sample;
  std::vector<Point> out;
  for (double f : {0.5, 0.3, 0.7}) {
    const Point m(a.x() + f * (z.x() - a.x()), a.y() + f * (z.y() - a.y()));
    std::vector<Point> inside;
    double t = 0.5;
    for (int k = 1; k <= 52; ++k, t = 1 - (1 - t) / 2) {
      const Point x(s.x() + t * (m.x() - s.x()), s.y() + t * (m.y() - s.y()));
      if (A.strictly_inside(c, geometry::to_exact(x))) inside.push_back(x);
    }
    for (std::size_t i = inside.size(); i-- > 0 && inside.size() - i <= 4;) out.push_back(inside[i]);
  }
  return out;
}

bool at_most(const filter::ShadowLabels& a, const filter::ShadowLabels& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] && !b[i]) return false;
  return true;
}

// One pursuer: the walk through cells `cells` (boundaries `bs`) drawn as a polyline. A
// boundary with near points is crossed through them; a stretch through cells too thin for
// double points is crossed by one straight segment whose exact crossings (walk) leave
// labels no worse than planned (the transitions are monotone, so the plan still clears).
Plan build_single(const ConservativeCells& C, const Point& start, std::vector<std::uint32_t> cells, std::vector<std::uint32_t> bs) {
  auto next_cell = [&](std::uint32_t c, std::uint32_t b) {
    const auto& B = C.boundaries()[b];
    return c == B.left ? B.right : B.left;
  };
  auto apply = [&](const filter::ShadowLabels& l, std::uint32_t c, std::uint32_t b) {
    const auto& B = C.boundaries()[b];
    return filter::update(l, c == B.left ? B.to_right : B.to_left);
  };
  // A plan ending in a thin cell walks on (labels all clear stay clear) to a wider one.
  if (C.cell(cells.back()).tiny) {
    std::vector<std::uint32_t> from(C.size(), kNone), via(C.size(), kNone);
    std::vector<std::uint32_t> queue{cells.back()};
    from[cells.back()] = cells.back();
    std::uint32_t found = kNone;
    for (std::size_t q = 0; q < queue.size() && found == kNone; ++q)
      for (std::uint32_t b : C.boundaries_of(queue[q])) {
        const std::uint32_t n = next_cell(queue[q], b);
        if (from[n] != kNone) continue;
        from[n] = queue[q], via[n] = b, queue.push_back(n);
        if (!C.cell(n).tiny) {
          found = n;
          break;
        }
      }
    std::vector<std::uint32_t> tail;
    for (std::uint32_t n = found; n != cells.back(); n = from[n]) tail.push_back(via[n]);
    for (auto it = tail.rbegin(); it != tail.rend(); ++it) cells.push_back(next_cell(cells.back(), *it)), bs.push_back(*it);
  }
  std::vector<filter::ShadowLabels> planned{filter::ShadowLabels(C.cell(cells[0]).shadows.num_components, true)};
  for (std::size_t i = 0; i < bs.size(); ++i) planned.push_back(apply(planned.back(), cells[i], bs[i]));
  Plan plan;
  plan.start_cell = cells[0];
  plan.paths.assign(1, {start});
  filter::ShadowLabels now = planned[0];
  for (std::size_t i = 0; i < bs.size();) {
    const CellBoundary& B = C.boundaries()[bs[i]];
    const bool right = cells[i] == B.left;
    if (B.drawable && !C.cell(cells[i + 1]).tiny) {
      plan.paths[0].push_back(right ? B.near_left : B.near_right);
      plan.paths[0].push_back(right ? B.near_right : B.near_left);
      now = apply(now, cells[i], bs[i]);
      ++i;
      plan.moves.push_back({0, bs[i - 1], cells[i - 1], cells[i]});
      continue;
    }
    std::size_t j = i + 1;
    while (C.cell(cells[j]).tiny) ++j;
    std::vector<Point> ps, qs = toward(C, cells[j], bs[j - 1]);
    const Point here = plan.paths[0].back();
    if (C.arrangement().strictly_inside(cells[i], geometry::to_exact(here))) ps.push_back(here);
    if (B.drawable) ps.push_back(right ? B.near_left : B.near_right);
    if (!C.cell(cells[i]).tiny)
      for (auto& p : toward(C, cells[i], bs[i])) ps.push_back(p);
    if (C.boundaries()[bs[j - 1]].drawable) {
      const auto& E = C.boundaries()[bs[j - 1]];
      qs.insert(qs.begin(), cells[j] == E.right ? E.near_right : E.near_left);
    }
    bool done = false;
    for (const Point& p : ps) {
      for (const Point& q : qs) {
        const auto seq = C.walk(p, q);
        if (!seq || seq->empty()) continue;
        filter::ShadowLabels l = now;
        std::uint32_t c = cells[i];
        for (auto [b, rightward] : *seq) {
          const auto& X = C.boundaries()[b];
          l = filter::update(l, rightward ? X.to_right : X.to_left);
          plan.moves.push_back({0, b, c, rightward ? X.right : X.left});
          c = rightward ? X.right : X.left;
        }
        if (c != cells[j] || !at_most(l, planned[j])) {
          plan.moves.resize(plan.moves.size() - seq->size());
          continue;
        }
        if (p != here) plan.paths[0].push_back(p);
        plan.paths[0].push_back(q);
        now = l, i = j, done = true;
        break;
      }
      if (done) break;
    }
    if (!done)
      throw std::runtime_error("pursuit: the plan crosses cells thinner than double precision near " +
                               geometry::format_point(C.cell(cells[i + 1]).sample) +
                               " in an order no straight double-precision segment realizes");
  }
  if (!now.all_clear()) throw std::logic_error("pursuit: a drawn plan does not clear");
  return plan;
}

Plan build_plan(const ConservativeCells& C, std::size_t k, const Point& start, std::uint32_t c0,
                const std::vector<std::pair<std::uint32_t, std::uint32_t>>& moves, JointSpace& J, std::uint32_t t0) {
  if (k == 1) {
    std::vector<std::uint32_t> cells{c0}, bs;
    for (auto [slot, b] : moves) {
      const auto& B = C.boundaries()[b];
      cells.push_back(cells.back() == B.left ? B.right : B.left);
      bs.push_back(b);
    }
    Plan plan = build_single(C, start, std::move(cells), std::move(bs));
    certify(C.environment(), plan.paths[0], 0);
    for (std::size_t i = 0; i + 1 < plan.paths[0].size(); ++i) plan.length += dist(plan.paths[0][i], plan.paths[0][i + 1]);
    return plan;
  }
  Plan plan;
  plan.start_cell = c0;
  plan.paths.assign(k, {start});
  std::vector<std::uint32_t> phys(k);
  std::iota(phys.begin(), phys.end(), 0u);
  std::vector<std::uint32_t> cell(k, c0);
  if (start != C.cell(c0).sample)
    for (auto& p : plan.paths) p.push_back(C.cell(c0).sample);
  std::uint32_t t = t0;
  for (auto [slot, b] : moves) {
    const CellBoundary& B = C.boundaries()[b];
    const std::uint32_t who = phys[slot], from = cell[who];
    const bool right = from == B.left;
    const std::uint32_t to = right ? B.right : B.left;
    const Point &nf = right ? B.near_left : B.near_right, &nt = right ? B.near_right : B.near_left;
    plan.moves.push_back({who, b, from, to});
    for (std::uint32_t p = 0; p < k; ++p) {
      const Point here = plan.paths[p].back();
      if (p == who) {
        plan.paths[p].push_back(nf);
        plan.paths[p].push_back(nt);
        plan.paths[p].push_back(C.cell(to).sample);
      } else {
        for (int r = 0; r < 3; ++r) plan.paths[p].push_back(here);
      }
    }
    cell[who] = to;
    const auto& s = J.step(t, slot, b);
    std::vector<std::uint32_t> np(k);
    for (std::uint32_t l = 0; l < k; ++l) np[s.slot_of[l]] = phys[l];
    phys = np;
    t = s.to;
  }
  for (std::size_t p = 0; p < k; ++p) {
    certify(C.environment(), plan.paths[p], p);
    for (std::size_t i = 0; i + 1 < plan.paths[p].size(); ++i) plan.length += dist(plan.paths[p][i], plan.paths[p][i + 1]);
  }
  return plan;
}

}  // namespace

SearchResult search(const ConservativeCells& C, std::size_t k, const SearchOptions& o) {
  if (k == 0) throw InputError("--pursuers: at least one pursuer is needed");
  SearchResult res;
  res.pursuers = k;
  JointSpace J(C, k);
  std::vector<Node> nodes;
  std::unordered_map<StateKey, std::uint32_t, StateHash> seen;
  // Queue key: the distance (shortest plan), or the number of contaminated components
  // first (any plan, found sooner); entries carry the distance they were pushed with.
  using QItem = std::tuple<double, double, std::uint32_t>;
  std::priority_queue<QItem, std::vector<QItem>, std::greater<>> queue;
  auto priority = [&](const filter::ShadowLabels& l, double d) { return o.shortest ? d : static_cast<double>(l.contaminated()); };
  // Dominance: labels are monotone under every transition, so a state whose contaminated
  // components include those of a state already settled in the same cells (at no larger
  // distance) can do nothing that one cannot; it is not explored.
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> settled;
  auto dominated = [&](const StateKey& key) {
    auto it = settled.find(key.tuple);
    if (it == settled.end()) return false;
    const auto& w = key.labels.words();
    for (std::uint32_t s : it->second) {
      const auto& v = nodes[s].key.labels.words();
      bool subset = true;
      for (std::size_t i = 0; i < w.size() && subset; ++i) subset = (v[i] & ~w[i]) == 0;
      if (subset) return true;
    }
    return false;
  };
  // Memory of one stored state: the node with its label words, its hash-table entry (key
  // copy, value, bucket and node overhead) and a queue entry.
  const auto t_start = std::chrono::steady_clock::now();
  std::size_t label_bytes = 0;
  auto state_bytes = [&] { return 2 * (sizeof(Node) + label_bytes) + 48 + sizeof(std::tuple<double, double, std::uint32_t>); };
  auto over_budget = [&]() -> const char* {
    if (nodes.size() >= o.max_states) return "states";
    if (o.max_mb && (nodes.size() + 1) * state_bytes() > o.max_mb * std::size_t{1} << 20) return "memory";
    if (o.time_limit > 0 && (nodes.size() & 1023) == 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count() > o.time_limit)
      return "time";
    return nullptr;
  };
  const char* stopped_by = nullptr;
  auto offer = [&](StateKey key_state, double d, std::uint32_t parent, std::uint32_t slot, std::uint32_t b) -> bool {
    if (dominated(key_state)) return true;
    auto [it, fresh] = seen.try_emplace(key_state, static_cast<std::uint32_t>(nodes.size()));
    if (fresh) {
      label_bytes = key_state.labels.words().size() * sizeof(key_state.labels.words()[0]);
      if ((stopped_by = over_budget())) {
        seen.erase(it);
        return false;
      }
      const double pr = priority(key_state.labels, d);
      nodes.push_back({std::move(key_state), d, parent, slot, b});
      queue.push({pr, d, it->second});
    } else if (d < nodes[it->second].dist && !nodes[it->second].closed) {
      nodes[it->second].dist = d, nodes[it->second].parent = parent, nodes[it->second].slot = slot, nodes[it->second].boundary = b;
      queue.push({priority(nodes[it->second].key.labels, d), d, it->second});
    }
    return true;
  };
  std::vector<std::uint32_t> sources;
  std::optional<std::uint32_t> c0;
  if (o.start) c0 = start_cell_of(C, *o.start);
  for (std::uint32_t c = 0; c < C.size(); ++c) {
    if (c0 ? c != *c0 : C.cell(c).tiny) continue;
    const std::uint32_t t = J.intern(std::vector<std::uint32_t>(k, c));
    const double d0 = o.start && k > 1 ? k * dist(*o.start, C.cell(c).sample) : 0;
    offer({t, filter::ShadowLabels(J.num_units(t), true)}, d0, kNone, 0, 0);
  }
  std::optional<std::uint32_t> goal;
  bool budget = false;
  std::vector<char> done;
  while (!queue.empty() && !goal && !budget) {
    const auto [prio, d, id] = queue.top();
    (void)prio;
    queue.pop();
    if (d > nodes[id].dist || nodes[id].closed) continue;
    nodes[id].closed = true;  // (with the greedy order a closed state may be offered again, shorter)
    if (dominated(nodes[id].key)) continue;
    settled[nodes[id].key.tuple].push_back(id);
    ++res.states;
    if (nodes[id].key.labels.all_clear()) {
      goal = id;
      break;
    }
    const StateKey key = nodes[id].key;  // copy: nodes may grow
    const auto tuple = J.cells(key.tuple);
    for (std::uint32_t slot = 0; slot < k && !budget; ++slot) {
      if (slot > 0 && tuple[slot] == tuple[slot - 1]) continue;  // interchangeable pursuers in one cell
      for (std::uint32_t b : C.boundaries_of(tuple[slot])) {
        if (k > 1) {  // several pursuers wait at sample points and cross through near points
          const auto& B = C.boundaries()[b];
          if (!B.drawable || C.cell(B.left).tiny || C.cell(B.right).tiny) continue;
        }
        const auto& s = J.step(key.tuple, slot, b);
        ++res.transitions;
        if (!offer({s.to, s.tr.apply(key.labels)}, d + move_cost(C, tuple[slot], b), id, slot, b)) {
          budget = true;
          break;
        }
      }
    }
  }
  res.stored = nodes.size();
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  res.bytes = nodes.size() * state_bytes();
  if (!goal) {
    res.outcome = budget ? SearchResult::Outcome::Budget : SearchResult::Outcome::NoPlan;
    if (budget && stopped_by) res.budget = stopped_by;
    return res;
  }
  res.outcome = SearchResult::Outcome::Plan;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> moves;
  std::uint32_t id = *goal;
  while (nodes[id].parent != kNone) moves.push_back({nodes[id].slot, nodes[id].boundary}), id = nodes[id].parent;
  std::reverse(moves.begin(), moves.end());
  const std::uint32_t t0 = nodes[id].key.tuple, start_cell = J.cells(t0)[0];
  const Point start = o.start ? *o.start : C.cell(start_cell).sample;
  res.plan = build_plan(C, k, start, start_cell, moves, J, t0);
  return res;
}

SearchResult least_pursuers(const ConservativeCells& C, std::size_t max_pursuers, const SearchOptions& o,
                            std::vector<SearchResult>* results) {
  SearchResult last;
  for (std::size_t k = 1; k <= max_pursuers; ++k) {
    last = search(C, k, o);
    if (results) results->push_back(last);
    if (last.outcome == SearchResult::Outcome::Plan) break;
  }
  return last;
}

namespace {
filter::ShadowLabels cross(const ConservativeCells& C, std::uint32_t c, std::uint32_t b, const filter::ShadowLabels& l,
                           std::uint32_t& to) {
  const CellBoundary& B = C.boundaries()[b];
  const bool right = c == B.left;
  to = right ? B.right : B.left;
  return filter::update(l, right ? B.to_right : B.to_left);
}
}  // namespace

std::optional<std::size_t> fewest_crossings(const ConservativeCells& C, std::uint32_t start_cell, std::size_t* reached) {
  std::unordered_set<StateKey, StateHash> seen;
  std::vector<StateKey> layer{{start_cell, filter::ShadowLabels(C.cell(start_cell).shadows.num_components, true)}};
  seen.insert(layer[0]);
  for (std::size_t depth = 0; !layer.empty(); ++depth) {
    std::vector<StateKey> next;
    if (reached) *reached = seen.size();
    for (auto& s : layer) {
      if (s.labels.all_clear()) return depth;
      for (std::uint32_t b : C.boundaries_of(s.tuple)) {
        std::uint32_t to;
        StateKey n{0, cross(C, s.tuple, b, s.labels, to)};
        n.tuple = to;
        if (seen.insert(n).second) next.push_back(std::move(n));
      }
    }
    layer.swap(next);
  }
  return std::nullopt;
}

std::optional<std::size_t> search_without_merging(const ConservativeCells& C, std::uint32_t start_cell, std::size_t max_depth,
                                                  std::size_t max_nodes, std::size_t& nodes, bool& complete) {
  nodes = 0;
  complete = true;
  std::optional<std::size_t> best;
  std::unordered_set<StateKey, StateHash> on_path;
  // Branch and bound over walks; no table of visited states across walks.
  auto dfs = [&](auto&& self, const StateKey& s, std::size_t depth) -> void {
    if (!complete) return;
    if (++nodes > max_nodes) {
      complete = false;
      return;
    }
    if (s.labels.all_clear()) {
      if (!best || depth < *best) best = depth;
      return;
    }
    if (depth == max_depth || (best && depth + 1 >= *best)) return;
    on_path.insert(s);
    for (std::uint32_t b : C.boundaries_of(s.tuple)) {
      std::uint32_t to;
      StateKey n{0, cross(C, s.tuple, b, s.labels, to)};
      n.tuple = to;
      if (on_path.count(n)) continue;
      self(self, n, depth + 1);
    }
    on_path.erase(s);
  };
  dfs(dfs, {start_cell, filter::ShadowLabels(C.cell(start_cell).shadows.num_components, true)}, 0);
  return best;
}

}  // namespace preimage::pursuit
