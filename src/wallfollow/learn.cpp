// SPDX-License-Identifier: Apache-2.0
// Strategy 1 (V.C). The learner keeps its own combinatorial picture of where the robot
// and the pebble are (vertex labels counted from the pebble's first vertex, edges, cut
// ids) and drives the robot through RobotInterface alone. Every expectation it relies on
// is checked against the observation; a mismatch means the robot is not the model of
// III.A (or the environment breaks general position) and is reported, not ignored.
#include <preimage/wallfollow/learn.hpp>

#include <algorithm>
#include <random>
#include <stdexcept>

namespace preimage::wallfollow {
namespace {

class Learner {
 public:
  Learner(RobotInterface& r, const LearnOptions& o) : R(r), opt(o), rng(o.seed) {}
  LearnReport run();

 private:
  using CutId = std::size_t;  // 2 * vertex + (right ? 1 : 0)
  static std::size_t vertex_of(CutId c) { return c / 2; }
  static bool is_left(CutId c) { return c % 2 == 0; }
  static int dir_of(CutId c) { return is_left(c) ? -1 : +1; }  // arrival direction before the JUMP

  Observation act(Action u) {
    ++rep.actions;
    ++rep.phase_actions[phase];
    return R.apply(u);
  }
  [[noreturn]] void lost(const std::string& what) const {
    throw std::runtime_error("cut-ordering strategy: " + what + " (the robot does not behave as the model of III.A)");
  }
  std::size_t mod(long k) const { return static_cast<std::size_t>(((k % static_cast<long>(n)) + static_cast<long>(n)) % static_cast<long>(n)); }

  // One follow in direction d (+1 RFOLLOW, -1 LFOLLOW) to the next vertex, following on
  // when it stops at the lying pebble in the middle of an edge.
  void step(int d) {
    Observation y;
    do {
      y = act(d > 0 ? Action::RFollow : Action::LFollow);
    } while (y.touch == Touch::Edge);
    const std::size_t next = on_edge ? (d > 0 ? mod(static_cast<long>(at) + 1) : at) : mod(static_cast<long>(at) + d);
    if ((y.touch == Touch::Reflex) != reflex[next]) lost(std::string("vertex v").append(std::to_string(next + 1)).append(" reads differently"));
    at = next, on_edge = false, arrived = d, at_cut = -1;
  }
  // To vertex v arriving in direction d (the JUMP from v then gives that cut).
  void goto_arriving(std::size_t v, int d) {
    if (on_edge) step(d);
    if (at == v && arrived == d) return;
    // Either walk in direction d all the way, or go the other way to v's neighbour
    // behind it and take one step in d: whichever is shorter.
    const long c = static_cast<long>(at), t = static_cast<long>(v);
    std::size_t along = mod(d > 0 ? t - c : c - t);
    if (along == 0) along = n;
    const std::size_t behind = mod(d > 0 ? c - (t - 1) : (t + 1) - c) + 1;
    if (along <= behind) {
      for (std::size_t k = 0; k < along; ++k) step(d);
    } else {
      for (std::size_t k = 0; k + 1 < behind; ++k) step(-d);
      step(d);
    }
  }
  void goto_vertex(std::size_t v) {
    if (on_edge) step(+1);
    const long c = static_cast<long>(at), t = static_cast<long>(v);
    const std::size_t ccw = mod(t - c), cw = mod(c - t);
    for (std::size_t k = 0, s = std::min(ccw, cw); k < s; ++k) step(ccw <= cw ? +1 : -1);
  }
  Observation jump(CutId c) {
    goto_arriving(vertex_of(c), dir_of(c));
    const Observation y = act(Action::Jump);
    if (y.touch != Touch::Edge) lost("a JUMP did not end inside an edge");
    // Inside the endpoint's edge; during phase 2 that edge is what is being measured and
    // the caller resets the position once the pebble is found.
    on_edge = true, at = edge_of[c], arrived = 0, at_cut = static_cast<long>(c);
    return y;
  }

  void learn_vertices();
  void locate_cut_endpoints();
  std::vector<CutId> sort_edge(std::vector<CutId> cuts);
  void put_pebble_at(CutId c);
  bool test_before(CutId pivot, CutId c);  // is the pebble's endpoint (pivot) before c?

  RobotInterface& R;
  LearnOptions opt;
  std::mt19937_64 rng;
  LearnReport rep;
  int phase = 0;
  std::size_t n = 0;
  std::vector<bool> reflex;
  std::vector<std::size_t> edge_of;  // per cut id
  // Where the robot is: vertex `at`, or inside edge `at` (from vertex at to at + 1), at
  // cut endpoint at_cut when known; the direction of the last follow.
  std::size_t at = 0;
  bool on_edge = false;
  long at_cut = -1;
  int arrived = 0;
  // Where the pebble is: held, at vertex v_1 (label 0), or at a cut endpoint.
  bool holding = true;
  long pebble_cut = -1;
};

// Phase 1: INIT, DROP, LFOLLOW around to the pebble. The k-th step lands on label n - k.
void Learner::learn_vertices() {
  Observation y = act(Action::Init);
  if (y.touch != Touch::Convex && y.touch != Touch::Reflex) lost("INIT did not end at a vertex");
  const bool first_reflex = y.touch == Touch::Reflex;
  y = act(Action::Drop);
  holding = false;
  std::vector<bool> seen;
  do {
    y = act(Action::LFollow);
    if (y.touch != Touch::Convex && y.touch != Touch::Reflex) lost("LFOLLOW did not end at a vertex");
    seen.push_back(y.touch == Touch::Reflex);
  } while (!y.pebble);
  n = seen.size();
  if (n < 3) lost("fewer than three vertices");
  reflex.assign(n, false);
  for (std::size_t k = 1; k <= n; ++k) reflex[(n - k) % n] = seen[k - 1];
  if (reflex[0] != first_reflex) lost("the pebble's vertex reads differently");
  at = 0, on_edge = false, arrived = -1;
}

// Phase 2: the edge of every cut endpoint, by counting follows back to the pebble at v_1.
void Learner::locate_cut_endpoints() {
  edge_of.assign(2 * n, 0);
  for (std::size_t v = 0; v < n; ++v) {
    if (!reflex[v]) continue;
    for (CutId c : {2 * v, 2 * v + 1}) {
      jump(c);
      const int d = dir_of(c);
      std::size_t m = 0;
      Observation y;
      do {
        y = act(d > 0 ? Action::RFollow : Action::LFollow);
        ++m;
        if (m > n) lost("the pebble was not found after a JUMP");
      } while (!y.pebble);
      // Landing inside edge (j, j+1): going clockwise meets j, j-1, ..., 0 (m = j + 1);
      // counter-clockwise meets j+1, ..., n-1, 0 (m = n - j).
      edge_of[c] = d < 0 ? m - 1 : n - m;
      at = 0, on_edge = false, arrived = d, at_cut = -1;
    }
  }
}

void Learner::put_pebble_at(CutId c) {
  if (!holding && pebble_cut == static_cast<long>(c)) return;
  if (!holding) {
    if (!(on_edge && at_cut == pebble_cut)) {
      if (pebble_cut < 0) {
        goto_vertex(0);
      } else {
        // The pebble lies inside edge j: from vertex j, RFOLLOW stops at it.
        goto_vertex(edge_of[static_cast<std::size_t>(pebble_cut)]);
        const Observation y = act(Action::RFollow);
        if (y.touch != Touch::Edge || !y.pebble) lost("the pebble was not where it was dropped");
        on_edge = true, at = edge_of[static_cast<std::size_t>(pebble_cut)], at_cut = pebble_cut, arrived = +1;
      }
    }
    act(Action::Grab);
    holding = true;
  }
  jump(c);
  act(Action::Drop);
  holding = false, pebble_cut = static_cast<long>(c);
}

bool Learner::test_before(CutId pivot, CutId c) {
  put_pebble_at(pivot);
  jump(c);
  ++rep.comparisons;
  const Observation y = act(Action::RFollow);
  if (y.touch == Touch::Edge) {
    if (!y.pebble) lost("RFOLLOW stopped inside an edge without the pebble");
    at_cut = static_cast<long>(pivot), arrived = +1;  // the pebble lies ahead of c
    return false;
  }
  at = mod(static_cast<long>(edge_of[c]) + 1), on_edge = false, at_cut = -1, arrived = +1;
  return true;
}

std::vector<Learner::CutId> Learner::sort_edge(std::vector<CutId> cuts) {
  if (cuts.size() <= 1) return cuts;
  if (opt.sort == LearnOptions::Sort::AllPairs) {
    // The paper's comparison of every pair: rank = number of endpoints before it.
    std::vector<std::size_t> rank(cuts.size(), 0);
    for (std::size_t a = 0; a < cuts.size(); ++a)
      for (std::size_t b = a + 1; b < cuts.size(); ++b) ++rank[test_before(cuts[a], cuts[b]) ? b : a];
    std::vector<CutId> out(cuts.size());
    for (std::size_t k = 0; k < cuts.size(); ++k) out[rank[k]] = cuts[k];
    return out;
  }
  const CutId pivot = cuts[rng() % cuts.size()];
  std::vector<CutId> before, after;
  for (CutId c : cuts)
    if (c != pivot) (test_before(pivot, c) ? after : before).push_back(c);
  std::vector<CutId> out = sort_edge(std::move(before));
  out.push_back(pivot);
  for (CutId c : sort_edge(std::move(after))) out.push_back(c);
  return out;
}

LearnReport Learner::run() {
  learn_vertices();
  phase = 1;
  locate_cut_endpoints();
  phase = 2;
  std::vector<std::vector<CutId>> on(n);
  std::size_t m = 0;
  for (std::size_t v = 0; v < n; ++v)
    if (reflex[v]) {
      ++m;
      on[edge_of[2 * v]].push_back(2 * v);
      on[edge_of[2 * v + 1]].push_back(2 * v + 1);
    }
  std::size_t pivots = 0;
  for (std::size_t e = 0; e < n; ++e) {
    rep.max_edge_load = std::max(rep.max_edge_load, on[e].size());
    pivots += on[e].size() >= 2 ? on[e].size() : 0;
    on[e] = sort_edge(std::move(on[e]));
  }
  CutOrdering& o = rep.ordering;
  o.n = n;
  o.reflex = reflex;
  for (std::size_t e = 0; e < n; ++e) {
    o.points.push_back({CutPoint::Kind::Vertex, static_cast<std::uint32_t>(e)});
    for (CutId c : on[e])
      o.points.push_back({is_left(c) ? CutPoint::Kind::Left : CutPoint::Kind::Right, static_cast<std::uint32_t>(vertex_of(c))});
  }
  rep.action_bound = (n + 2) + 2 * m * (2 * n + 3) + pivots * (2 * n + 8) + rep.comparisons * (n + 6);
  auto index_of = [&](CutPoint p) {
    return static_cast<std::uint32_t>(std::find(o.points.begin(), o.points.end(), p) - o.points.begin());
  };
  auto cut_point = [&](CutId c) {
    return CutPoint{is_left(c) ? CutPoint::Kind::Left : CutPoint::Kind::Right, static_cast<std::uint32_t>(vertex_of(c))};
  };
  if (on_edge && at_cut < 0) lost("the robot's place inside an edge is not a cut endpoint");
  rep.robot_at = index_of(on_edge ? cut_point(static_cast<CutId>(at_cut)) : CutPoint{CutPoint::Kind::Vertex, static_cast<std::uint32_t>(at)});
  rep.arrived = arrived;
  if (!holding)
    rep.pebble_at = index_of(pebble_cut < 0 ? CutPoint{CutPoint::Kind::Vertex, 0} : cut_point(static_cast<CutId>(pebble_cut)));
  return rep;
}

}  // namespace

LearnReport learn_cut_ordering(RobotInterface& robot, const LearnOptions& options) { return Learner(robot, options).run(); }

}  // namespace preimage::wallfollow
