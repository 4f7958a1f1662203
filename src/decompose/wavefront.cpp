// SPDX-License-Identifier: Apache-2.0
#include <preimage/decompose/wavefront.hpp>

#include <preimage/parallel_for.hpp>
#include <preimage/union_find.hpp>

#include "cell_graph.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <limits>
#include <map>
#include <numeric>
#include <thread>
#include <tuple>

namespace preimage::decompose {

namespace {

using geometry::ShortestPathMap;
constexpr double kFullTurn = 2 * std::numbers::pi;
constexpr std::uint32_t kNoSlot = UINT32_MAX;

double wf_length(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }
double wf_angle(const Point& from, const Point& to) { return std::atan2(to.y() - from.y() + 0.0, to.x() - from.x() + 0.0); }  // + 0.0: no -0.0, so no -pi
// Angle reduced to [0, 2pi) relative to `base`.
double wf_offset(double angle, double base) {
  double d = std::fmod(angle - base, kFullTurn);
  return d < 0 ? d + kFullTurn : d;
}

// What an end of a front piece is: an obstacle edge (a free end), the extension of the
// shortest path through a root (glued to that root's piece), or one of the two crossings of
// two roots' circles (glued to the other root's piece). Packed so both sides agree exactly.
enum : std::uint64_t { kEdgeEnd = 0, kExtensionEnd = 1, kCrossingEnd = 2, kTieEnd = 3 };
std::uint64_t wf_label(std::uint64_t kind, std::uint64_t a, std::uint64_t b = 0, std::uint64_t side = 0) {
  return (kind << 62) | (a << 31) | (b << 1) | side;
}
bool wf_free_end(std::uint64_t label) { return (label >> 62) == kEdgeEnd; }
std::uint32_t wf_edge_of(std::uint64_t label) { return static_cast<std::uint32_t>((label >> 31) & 0x7fffffff); }  // of a free end

struct WfSplit {
  double angle;
  std::uint64_t label;
};

}  // namespace

struct WavefrontDecomposition::Level {
  double lambda = 0;
  std::vector<WavefrontArc> arcs;           // grouped by slot
  std::vector<std::uint32_t> arc_slot;
  std::vector<std::uint32_t> first;         // per slot: first arc (size slots + 1)
  std::vector<std::uint32_t> front;         // per arc: its front
  std::vector<std::int64_t> link;           // per arc end (2 a + e): the glued end, or -1 (free)
  std::vector<char> closed;                 // per front
  std::vector<std::vector<std::uint32_t>> end_rings;  // per front: the rings its free ends lie on, sorted
  std::size_t fronts = 0, unmatched = 0, snapped = 0;

  // The arc of `slot` whose angular range contains `angle` (-1 if none).
  // A point followed back along a path that runs along a wall (into a contact, or down a
  // notch) lands on an arc's end, whose angle is a rounded cut: ends within 1e-9 rad count.
  std::int64_t arc_at(std::uint32_t slot, double angle) const {
    std::int64_t near = -1;
    for (std::uint32_t a = first[slot]; a < first[slot + 1]; ++a) {
      const double off = wf_offset(angle, arcs[a].from);
      if (arcs[a].sweep >= kFullTurn || off <= arcs[a].sweep) return a;
      if (off - arcs[a].sweep < 1e-9 || kFullTurn - off < 1e-9) near = a;
    }
    return near;
  }
};

bool WavefrontDecomposition::taut(std::uint32_t s, const Point& m) const {
  // A path into m can end with a bend at reflex root v only if the segment v m is tangent
  // there (both neighbours on one side) and the turn from the predecessor wraps the
  // obstacle: m not on the far side of the line from the predecessor through v. Without
  // the second test a sliver just across the extension would be claimed by v. Exact
  // orientation tests on input points and m; any alias of the root may be the bend.
  const Environment& env = spm_->environment();
  const Point& P = slot_point_[slot_pred_[s]];
  const Point& V = slot_point_[s];
  const int turn = geometry::orientation(P, V, m);
  for (const std::uint32_t v : slot_alias_[s]) {
    if (!geometry::tangent_at(env, v, m)) continue;
    if (turn == 0) return true;
    const int a = geometry::orientation(P, V, env.vertex(env.prev(v)));
    const int b = geometry::orientation(P, V, env.vertex(env.next(v)));
    if (turn == (a != 0 ? a : b) || (a == 0 && b == 0)) return true;
  }
  return false;
}

WavefrontDecomposition::Level WavefrontDecomposition::compute(double lambda) const {
  const std::size_t slots = slot_root_.size();
  Level L;
  L.lambda = lambda;
  L.first.assign(slots + 1, 0);
  std::vector<double> radius(slots, 0);
  std::vector<std::uint32_t> live;
  for (std::uint32_t s = 0; s < slots; ++s)
    if (slot_live_[s] && slot_dist_[s] < lambda) radius[s] = lambda - slot_dist_[s], live.push_back(s);
  std::vector<std::vector<WfSplit>> splits(slots);

  // Obstacle edges crossing each circle (the front ends there).
  const Environment& env = spm_->environment();
  const geometry::VisibilityIndex& index = spm_->index();
  for (const std::uint32_t s : live) {
    const Point& c = slot_point_[s];
    const double r = radius[s];
    for (std::size_t e = 0; e < env.num_vertices(); ++e) {
      const Point& a = env.vertex(e);
      const Point& b = env.vertex(env.next(e));
      if (std::min(a.x(), b.x()) > c.x() + r || std::max(a.x(), b.x()) < c.x() - r || std::min(a.y(), b.y()) > c.y() + r ||
          std::max(a.y(), b.y()) < c.y() - r)
        continue;
      // An edge at the root's own point (its ring edges, a contact's other rings): the
      // circle meets it in the edge's direction (the quadratic loses a small radius).
      if (a == c || b == c) {
        const Point& o = a == c ? b : a;
        if (wf_length(c, o) >= r) splits[s].push_back({wf_angle(c, o), wf_label(kEdgeEnd, e)});
        continue;
      }
      const double dx = b.x() - a.x(), dy = b.y() - a.y(), fx = a.x() - c.x(), fy = a.y() - c.y();
      const double qa = dx * dx + dy * dy, qb = 2 * (fx * dx + fy * dy), qc = fx * fx + fy * fy - r * r;
      const double disc = qb * qb - 4 * qa * qc;
      if (qa == 0 || disc < 0) continue;
      const double root = std::sqrt(disc);
      for (const double t : {(-qb - root) / (2 * qa), (-qb + root) / (2 * qa)})
        if (t >= 0 && t <= 1) splits[s].push_back({std::atan2(fy + t * dy + 0.0, fx + t * dx + 0.0), wf_label(kEdgeEnd, e)});
    }
  }
  // The extension of each root's shortest path: where its circle starts, and where its
  // predecessor's circle passes behind it (the same angle from both, so the same label).
  for (const std::uint32_t s : live) {
    const std::uint32_t p = slot_pred_[s];
    if (p == kNoSlot) continue;
    const double angle = ext_angle_[s];
    splits[s].push_back({angle, wf_label(kExtensionEnd, s)});
    // (whenever s's own circle has the cut: p's radius exceeds |ps| by exactly s's radius,
    // but not always once rounded, and a cut on one side only leaves an end alone)
    for (const std::uint32_t w : collinear_chain_[s]) splits[p].push_back({angle, wf_label(kExtensionEnd, w)});
  }
  for (const Tie& t : ties_) {
    if (radius[t.w] <= 0) continue;
    const std::uint64_t label = wf_label(kTieEnd, t.s, t.w);
    splits[t.w].push_back({t.angle, label});
    splits[t.s].push_back({t.angle, label});  // (as for extensions)
  }
  // Crossings of two circles, computed once per pair (lower slot first) so both agree.
  for (std::size_t i = 0; i < live.size(); ++i) {
    const std::uint32_t a = live[i];
    const Point& pa = slot_point_[a];
    for (std::size_t j = i + 1; j < live.size(); ++j) {
      const std::uint32_t b = live[j];
      if (slot_pred_[a] == b || slot_pred_[b] == a) continue;  // tangent along the extension
      const Point& pb = slot_point_[b];
      const double ra = radius[a], rb = radius[b];
      const double dx = pb.x() - pa.x(), dy = pb.y() - pa.y();
      if (std::fabs(dx) > ra + rb || std::fabs(dy) > ra + rb) continue;
      const double d = std::hypot(dx, dy);
      if (d == 0 || d >= ra + rb || d <= std::fabs(ra - rb) * (1 + 1e-12)) continue;
      const double x = (d * d + ra * ra - rb * rb) / (2 * d), h = std::sqrt(std::max(0.0, ra * ra - x * x));
      const double ux = dx / d, uy = dy / d;
      for (int side = 0; side < 2; ++side) {
        const double sgn = side == 0 ? 1 : -1;
        const Point q(pa.x() + x * ux - sgn * h * uy, pa.y() + x * uy + sgn * h * ux);
        const std::uint64_t label = wf_label(kCrossingEnd, a, b, static_cast<std::uint64_t>(side));
        splits[a].push_back({wf_angle(pa, q), label});
        splits[b].push_back({wf_angle(pb, q), label});
      }
    }
  }

  // Pieces between consecutive cuts; a piece is on the front when its midpoint m is (see
  // on_front). Runs of pieces on the front become arcs.
  struct End {
    std::vector<std::uint64_t> labels;
  };
  std::vector<std::array<End, 2>> ends;
  for (std::uint32_t s = 0; s < slots; ++s) {
    L.first[s] = static_cast<std::uint32_t>(L.arcs.size());
    if (radius[s] <= 0) continue;
    auto& cut = splits[s];
    const Point& c = slot_point_[s];
    const std::uint32_t root = slot_root_[s];
    auto on_front = [&](double angle) {
      const Point m(c.x() + radius[s] * std::cos(angle), c.y() + radius[s] * std::sin(angle));
      // m must be seen from the root (a walk from the root, which also rejects an m outside
      // free space without locating it), with the path taut there at a reflex root
      if (root != ShortestPathMap::kSource && !taut(s, m)) return false;
      auto sees = [&](std::uint32_t slot) {
        const std::uint32_t r = slot_root_[slot];
        return r == ShortestPathMap::kSource ? index.visible(slot_point_[slot], m) : index.visible_from_vertex(r, m);  // a walk from a contact tries each wedge
      };
      if (!sees(s)) return false;
      // A root tied with s (ties_) is as near at s's point and nearer wherever it sees:
      // the ray through s bounds s's share exactly, whatever distances round to.
      for (const std::uint32_t t : tie_sources_[s])
        if (radius[t] > 0 && sees(t)) return false;
      // m is on the front unless a root that sees m is nearer through its own path:
      // h(m) = min over the roots m sees (any visible root's path bounds h from above).
      // Only roots whose disc of radius λ - D(u) holds m can be; each costs one walk.
      for (const std::uint32_t u : live) {
        if (u == s) continue;
        const double ru = radius[u] * (1 - 1e-12);
        const Point& pu = slot_point_[u];
        if (std::fabs(pu.x() - m.x()) >= ru || std::fabs(pu.y() - m.y()) >= ru) continue;
        if (wf_length(pu, m) < ru && sees(u)) return false;
      }
      return true;
    };
    if (cut.empty()) {
      if (on_front(0)) {
        L.arcs.push_back({root, radius[s], -std::numbers::pi, kFullTurn});
        L.arc_slot.push_back(s);
        ends.push_back({});
      }
      continue;
    }
    std::sort(cut.begin(), cut.end(), [](const WfSplit& x, const WfSplit& y) { return x.angle < y.angle || (x.angle == y.angle && x.label < y.label); });
    // Distinct angles, with every label at each. Cuts within 1e-12 rad are one: the same
    // point reached two ways (a wall lying on the ray of an extension through a contact,
    // whose crossing is solved, not taken from the ray), which would leave a sliver between.
    std::vector<double> angle;
    std::vector<std::vector<std::uint64_t>> labels;
    for (const auto& sp : cut) {
      if (angle.empty() || sp.angle - angle.back() > 1e-12) angle.push_back(sp.angle), labels.emplace_back();
      labels.back().push_back(sp.label);
    }
    if (angle.size() > 1 && angle.front() + kFullTurn - angle.back() <= 1e-12) {  // across -pi
      labels.front().insert(labels.front().end(), labels.back().begin(), labels.back().end());
      angle.pop_back(), labels.pop_back();
    }
    const std::size_t k = angle.size();
    std::vector<char> on(k);  // piece i: from angle[i] to angle[i + 1] (cyclically)
    for (std::size_t i = 0; i < k; ++i) {
      const double a0 = angle[i], span = k == 1 ? kFullTurn : wf_offset(angle[(i + 1) % k], a0);
      on[i] = on_front(a0 + span / 2);
    }
    const std::size_t all = static_cast<std::size_t>(std::count(on.begin(), on.end(), 1));
    if (all == k) {  // the whole circle (every cut spurious)
      L.arcs.push_back({root, radius[s], -std::numbers::pi, kFullTurn});
      L.arc_slot.push_back(s);
      ends.push_back({});
      continue;
    }
    std::size_t start = 0;
    while (on[start]) ++start;  // an off piece: runs start after it
    for (std::size_t step = 1; step <= k; ++step) {
      const std::size_t i = (start + step) % k;
      if (!on[i] || on[(i + k - 1) % k]) continue;  // not the first piece of a run
      std::size_t j = i;
      double sweep = 0;
      while (on[j]) {
        sweep += k == 1 ? kFullTurn : wf_offset(angle[(j + 1) % k], angle[j]);
        j = (j + 1) % k;
      }
      L.arcs.push_back({root, radius[s], angle[i], sweep});
      L.arc_slot.push_back(s);
      ends.push_back({End{labels[i]}, End{labels[j]}});
    }
  }
  L.first[slots] = static_cast<std::uint32_t>(L.arcs.size());

  // Glue ends that carry the same label; an end with an edge label is free.
  const std::size_t n = L.arcs.size();
  L.link.assign(2 * n, -1);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> reg;  // (label, arc end)
  std::vector<char> free_end(2 * n, 0);
  for (std::size_t a = 0; a < n; ++a)
    for (int e = 0; e < 2; ++e) {
      const auto& lab = ends[a][static_cast<std::size_t>(e)].labels;
      if (L.arcs[a].sweep >= kFullTurn) continue;
      if (std::any_of(lab.begin(), lab.end(), wf_free_end)) {
        free_end[2 * a + static_cast<std::size_t>(e)] = 1;
        continue;
      }
      for (const auto l : lab) reg.emplace_back(l, static_cast<std::uint32_t>(2 * a + static_cast<std::size_t>(e)));
    }
  std::sort(reg.begin(), reg.end());
  UnionFind uf(n);
  for (auto it = reg.begin(); it != reg.end();) {
    auto jt = it;
    while (jt != reg.end() && jt->first == it->first) ++jt;
    for (auto mt = it + 1; mt < jt; ++mt) {
      const std::uint32_t x = it->second, y = mt->second;
      if (x / 2 == y / 2) continue;
      uf.join(x / 2, y / 2);
      if (L.link[x] < 0) L.link[x] = y;
      if (L.link[y] < 0) L.link[y] = x;
    }
    it = jt;
  }
  // Ends left without a partner: where the cuts of one circle come closer than double
  // resolution can order (bends so nearly on one ray from their predecessor, as on the
  // staircase walls of rasterised plans; three circles nearly through one point, a level
  // close to a collision on an extension), the sliver between them changes hands. A front
  // has no end in open free space, so such an end is joined to the nearest other such end
  // (the closest pairs first) if it lies within 1e-6 of the map's size; the count is
  // reported (snapped_ends), and ends left over are counted as unmatched.
  auto end_point = [&](std::size_t x) {
    const auto& A = L.arcs[x / 2];
    const double t = (x % 2) ? A.from + A.sweep : A.from;
    const Point& o = slot_point_[L.arc_slot[x / 2]];
    return Point(o.x() + A.radius * std::cos(t), o.y() + A.radius * std::sin(t));
  };
  std::vector<std::size_t> loose;
  for (std::size_t x = 0; x < 2 * n; ++x)
    if (!free_end[x] && L.link[x] < 0 && L.arcs[x / 2].sweep < kFullTurn) loose.push_back(x);
  std::vector<std::tuple<double, std::size_t, std::size_t>> close;
  for (std::size_t i = 0; i < loose.size(); ++i)
    for (std::size_t j = i + 1; j < loose.size(); ++j)
      if (const double d = wf_length(end_point(loose[i]), end_point(loose[j])); loose[i] / 2 != loose[j] / 2 && d <= 1e-6 * top_)
        close.emplace_back(d, loose[i], loose[j]);
  std::sort(close.begin(), close.end());
  for (const auto& [d, x, y] : close) {
    if (L.link[x] >= 0 || L.link[y] >= 0) continue;
    L.link[x] = static_cast<std::int64_t>(y), L.link[y] = static_cast<std::int64_t>(x);
    uf.join(static_cast<std::uint32_t>(x / 2), static_cast<std::uint32_t>(y / 2));
    L.snapped += 2;
  }
  for (const std::size_t x : loose) L.unmatched += L.link[x] < 0;
  L.front.assign(n, 0);
  std::vector<std::uint32_t> id(n, UINT32_MAX);
  for (std::size_t a = 0; a < n; ++a) {
    const std::uint32_t r = uf.find(static_cast<std::uint32_t>(a));
    if (id[r] == UINT32_MAX) id[r] = static_cast<std::uint32_t>(L.fronts++), L.closed.push_back(1);
    L.front[a] = id[r];
  }
  L.end_rings.assign(L.fronts, {});
  for (std::size_t x = 0; x < 2 * n; ++x)
    if (L.link[x] < 0 && L.arcs[x / 2].sweep < kFullTurn) {
      L.closed[L.front[x / 2]] = 0;
      std::uint32_t ring = UINT32_MAX;  // the obstacle the end lies on (the lowest ring at a vertex)
      for (const auto l : ends[x / 2][x % 2].labels)
        if (wf_free_end(l)) ring = std::min(ring, static_cast<std::uint32_t>(env.ring_of(wf_edge_of(l))));
      L.end_rings[L.front[x / 2]].push_back(ring);
    }
  for (auto& r : L.end_rings) std::sort(r.begin(), r.end());
  return L;
}

std::int64_t WavefrontDecomposition::arc_on_path(const Level& A, std::uint32_t s, double angle) const {
  // Back along the path's bends while they are not below A's level; the point is then on
  // the circle of the last bend below it, in the direction of the next bend.
  if (slot_dist_[s] >= A.lambda) {
    std::uint32_t child = s, x = slot_pred_[s];
    while (x != kNoSlot && slot_dist_[x] >= A.lambda) child = x, x = slot_pred_[x];
    if (x == kNoSlot) return -1;
    s = x;
    angle = ext_angle_[child];
  }
  // The circles of the roots behind s on the same ray touch s's there and the front may be
  // theirs: on a straight chain of bends (p -> s -> child in line) p's, and beyond a root
  // tied with s (ties_) the tie's source's (compute() gives it what it sees beyond s).
  std::uint32_t todo[16] = {s};
  std::size_t n = 1;
  auto add = [&](std::uint32_t y) {
    if (n < 16 && std::find(todo, todo + n, y) == todo + n) todo[n++] = y;
  };
  // (in line to 1e-9 rad: a start collinear with a chain only to rounding bends by 1e-16)
  auto in_line = [&](double a) {
    const double d = wf_offset(a, angle);
    return d < 1e-9 || d > kFullTurn - 1e-9;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t x = todo[i];
    if (const std::int64_t a = A.arc_at(x, angle); a >= 0) return a;
    if (x != 0 && slot_pred_[x] != kNoSlot && in_line(ext_angle_[x])) add(slot_pred_[x]);
    for (const std::uint32_t t : tie_sources_[x])
      if (in_line(wf_angle(slot_point_[t], slot_point_[x]))) add(t);
  }
  return -1;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> WavefrontDecomposition::relation(const Level& A, const Level& B) const {
  // Each arc of B, from its midpoint, back along its shortest path to the level of A.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::uint32_t b = 0; b < B.arcs.size(); ++b) {
    const std::int64_t a = arc_on_path(A, B.arc_slot[b], B.arcs[b].from + B.arcs[b].sweep / 2);
    if (a >= 0) pairs.emplace_back(A.front[static_cast<std::size_t>(a)], B.front[b]);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

namespace {

// Fronts of two levels grouped by the correspondence: per group, its fronts below and above.
struct WfGroup {
  std::vector<std::uint32_t> below, above;
};
std::vector<WfGroup> wf_groups(std::size_t na, std::size_t nb, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                               const std::vector<std::pair<std::uint32_t, std::uint32_t>>& below_joins = {}) {
  UnionFind uf(na + nb);
  for (const auto& [a, b] : pairs) uf.join(a, static_cast<std::uint32_t>(na + b));
  for (const auto& [a, b] : below_joins) uf.join(a, b);
  std::vector<std::uint32_t> id(na + nb, UINT32_MAX);
  std::vector<WfGroup> groups;
  for (std::uint32_t x = 0; x < na + nb; ++x) {
    const std::uint32_t r = uf.find(x);
    if (id[r] == UINT32_MAX) id[r] = static_cast<std::uint32_t>(groups.size()), groups.emplace_back();
    auto& g = groups[id[r]];
    if (x < na) g.below.push_back(x);
    else g.above.push_back(static_cast<std::uint32_t>(x - na));
  }
  return groups;
}

}  // namespace

bool WavefrontDecomposition::continues(const Level& A, std::uint32_t a, const Level& B, std::uint32_t b) const {
  // The same topology: closed or open, and an open chain's ends on the same obstacles (two
  // events at one level can close a chain and open it elsewhere: its ends move rings).
  return A.closed[a] == B.closed[b] && A.end_rings[a] == B.end_rings[b];
}

std::int64_t WavefrontDecomposition::front_on_path(const Level& A, std::uint32_t s, double angle) const {
  const std::int64_t a = arc_on_path(A, s, angle);
  return a < 0 ? -1 : static_cast<std::int64_t>(A.front[static_cast<std::size_t>(a)]);
}

void WavefrontDecomposition::step(const Level& A, const Level& B, int depth) {
  const auto pairs = relation(A, B);
  // Fronts that reach one root at one level along tied paths (ties_) meet there: at a
  // contact they may touch only at that point (a kiss through the contact) and part again,
  // one to one on both sides, which following back cannot see. Joined below.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> kisses;
  for (const Tie& t : ties_) {
    if (!(A.lambda < slot_dist_[t.w] && slot_dist_[t.w] <= B.lambda)) continue;
    const std::uint32_t p = slot_pred_[t.w];
    const std::int64_t x = front_on_path(A, p, wf_angle(slot_point_[p], slot_point_[t.w]));
    const std::int64_t y = front_on_path(A, t.s, t.angle);
    if (x >= 0 && y >= 0 && x != y) kisses.emplace_back(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
  }
  const auto groups = wf_groups(A.fronts, B.fronts, pairs, kisses);
  // (a kiss is one slice whatever the interval: it does not call for bisection)
  const auto plain = kisses.empty() ? groups : wf_groups(A.fronts, B.fronts, pairs);
  const bool compound = std::any_of(plain.begin(), plain.end(), [](const WfGroup& g) { return g.below.size() >= 2 && g.above.size() >= 2; });
  // A front that merges into another and whose part of the merged front is then overrun
  // within the interval looks like a death beside a change of the other front (nothing at B
  // follows back to it). Seen where a front comes through a contact into a corner. A finer
  // level between the two shows the merge.
  std::size_t deaths = 0, changes = 0;
  for (const auto& g : plain) {
    if (g.above.empty()) ++deaths;
    else if (!(g.below.size() == 1 && g.above.size() == 1 && continues(A, g.below[0], B, g.above[0]))) ++changes;
  }
  const bool overrun = deaths > 0 && changes > 0 && B.lambda - A.lambda > 1e-9 * top_;
  if ((compound || overrun) && depth < 40 && B.lambda - A.lambda > 1e-12 * top_) {
    const Level M = compute((A.lambda + B.lambda) / 2);
    step(A, M, depth + 1);
    step(M, B, depth + 1);
    return;
  }
  const std::vector<std::uint32_t> below_cells = level_cells_.back();
  std::vector<std::uint32_t> above_cells(B.fronts, WavefrontCell::kNone);
  const auto c = std::upper_bound(candidates_.begin(), candidates_.end(), A.lambda);
  const bool has_candidate = c != candidates_.end() && *c <= B.lambda;
  for (const auto& g : groups) {
    if (g.below.size() == 1 && g.above.size() == 1 && continues(A, g.below[0], B, g.above[0])) {
      above_cells[g.above[0]] = below_cells[g.below[0]];
      continue;
    }
    WavefrontNode node;
    node.lo = A.lambda, node.hi = B.lambda;
    node.level = has_candidate ? *c : (A.lambda + B.lambda) / 2;
    // Its point: the candidate critical point in (lo, hi] nearest to the fronts taking part
    // (midpoints of their arcs on both sides), else one of those midpoints.
    std::vector<Point> near;
    for (int side = 0; side < 2; ++side) {
      const Level& L = side == 0 ? A : B;
      const auto& fs = side == 0 ? g.below : g.above;
      for (std::uint32_t a = 0; a < L.arcs.size(); ++a)
        if (std::find(fs.begin(), fs.end(), L.front[a]) != fs.end()) {
          const auto& arc = L.arcs[a];
          const double t = arc.from + arc.sweep / 2;
          const Point& o = slot_point_[L.arc_slot[a]];
          near.emplace_back(o.x() + arc.radius * std::cos(t), o.y() + arc.radius * std::sin(t));
        }
    }
    double best = std::numeric_limits<double>::infinity();
    auto it = std::upper_bound(all_candidates_.begin(), all_candidates_.end(), A.lambda, [](double x, const auto& y) { return x < y.first; });
    for (; it != all_candidates_.end() && it->first <= B.lambda; ++it)
      for (const Point& q : near)
        if (const double d = wf_length(q, it->second); d < best) best = d, node.point = it->second;
    if (!std::isfinite(best) && !near.empty()) node.point = near.front();
    const auto id = static_cast<std::uint32_t>(nodes_.size());
    for (const std::uint32_t f : g.below) {
      const std::uint32_t cell = below_cells[f];
      cells_[cell].upper = id, cells_[cell].hi = node.level;
      node.below.push_back(cell);
    }
    for (const std::uint32_t f : g.above) {
      const auto cell = static_cast<std::uint32_t>(cells_.size());
      cells_.push_back({id, WavefrontCell::kNone, node.level, node.level});
      above_cells[f] = cell;
      node.above.push_back(cell);
    }
    nodes_.push_back(std::move(node));
  }
  unmatched_ += B.unmatched, snapped_ += B.snapped;
  levels_.push_back(B.lambda);
  level_cells_.push_back(std::move(above_cells));
}

WavefrontDecomposition::WavefrontDecomposition(const geometry::ShortestPathMap& spm) : spm_(&spm) {
  const Environment& env = spm.environment();
  // Holes touching at a vertex (contacts) need no case of their own: the ring vertices at
  // a contact are one root (aliases, below); a front that reaches the contact goes on
  // into the far wedges as that root's circle (found by following back through it); paths
  // along walls on both sides of a contact are straight chains of bends; fronts arriving
  // from two wedges at once kiss there (ties_, joined in step()).
  // Roots: the start (slot 0) and every reached reflex vertex.
  root_slot_.assign(env.num_vertices(), kNoSlot);
  slot_root_.push_back(ShortestPathMap::kSource);
  slot_point_.push_back(spm.source());
  slot_dist_.push_back(0);
  for (const std::uint32_t v : spm.graph().reflex_vertices())
    if (spm.reached(v)) {
      root_slot_[v] = static_cast<std::uint32_t>(slot_root_.size());
      slot_root_.push_back(v);
      slot_point_.push_back(env.vertex(v));
      slot_dist_.push_back(spm.vertex_distance(v));
    }
  // Roots at one point (the start at a reflex vertex; the ring vertices of a contact) are
  // one root: the first slot there; the others are its aliases (their wedges all count
  // for tangency), never a circle of their own, and paths through them go through it.
  slot_alias_.assign(slot_root_.size(), {});
  std::vector<std::uint32_t> canon(slot_root_.size());
  {
    std::map<std::pair<double, double>, std::uint32_t> at;
    for (std::uint32_t s = 0; s < slot_root_.size(); ++s) {
      const auto [it, fresh] = at.emplace(std::make_pair(slot_point_[s].x(), slot_point_[s].y()), s);
      canon[s] = it->second;
      if (slot_root_[s] != ShortestPathMap::kSource) slot_alias_[canon[s]].push_back(slot_root_[s]);
      if (!fresh) slot_dist_[canon[s]] = std::min(slot_dist_[canon[s]], slot_dist_[s]);
    }
  }
  slot_pred_.assign(slot_root_.size(), kNoSlot);
  slot_live_.assign(slot_root_.size(), 1);
  for (std::uint32_t s = 0; s < slot_root_.size(); ++s) {
    if (canon[s] != s) {
      slot_live_[s] = 0;
      root_slot_[slot_root_[s]] = canon[s];
      continue;
    }
    if (s == 0) continue;
    // the predecessor of the point: an alias's predecessor may be another alias (a step of
    // length 0 through the contact), so take the first that is elsewhere
    for (const std::uint32_t v : slot_alias_[s]) {
      const std::uint32_t p = spm.vertex_predecessor(v);
      const std::uint32_t c = p == ShortestPathMap::kSource ? 0 : canon[root_slot_[p]];
      if (c != s) {
        slot_pred_[s] = c;
        break;
      }
    }
    if (slot_pred_[s] == kNoSlot) slot_pred_[s] = 0;  // (every alias reached through the point itself: cannot be)
  }
  // A root lying on the segment from another root's predecessor to it (siblings on one
  // ray: a sight line along two walls through a contact, or grazing a notch) is where that
  // path passes, at the same distance: it becomes the predecessor, so that the circles
  // along the ray are glued by the chain of extensions below (which follows predecessors).
  for (std::uint32_t s = 1; s < slot_root_.size(); ++s) {
    if (!slot_live_[s]) continue;
    const std::uint32_t p = slot_pred_[s];
    const Point &P = slot_point_[p], &S = slot_point_[s];
    std::uint32_t via = p;
    // (any root on the segment, not only p's children: the map may have hung it on
    // another root of the same line, the rounding of a tie)
    const double x0 = std::min(P.x(), S.x()), x1 = std::max(P.x(), S.x()), y0 = std::min(P.y(), S.y()), y1 = std::max(P.y(), S.y());
    for (std::uint32_t c = 1; c < slot_root_.size(); ++c) {
      const Point& C = slot_point_[c];
      if (!slot_live_[c] || c == p || c == s || C.x() < x0 || C.x() > x1 || C.y() < y0 || C.y() > y1) continue;
      if (geometry::orientation(P, C, S) != 0 || CGAL::compare_distance_to_point(P, C, S) != CGAL::SMALLER) continue;
      if ((C.x() - P.x()) * (S.x() - P.x()) + (C.y() - P.y()) * (S.y() - P.y()) <= 0) continue;  // behind p
      if (via == p || CGAL::compare_distance_to_point(P, slot_point_[via], C) == CGAL::SMALLER) via = c;
    }
    slot_pred_[s] = via;
  }
  // Each root's visibility polygon as segments (double: they only say where to look for
  // the feet of perpendiculars, each confirmed by a query).
  sight_.resize(slot_root_.size());
  {
    const geometry::VisibilityIndex& index = spm.index();
    const unsigned threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
    parallel_for(slot_root_.size(), threads, [&](std::size_t s) {
      const auto V = index.compute(slot_point_[s]);
      auto& vb = sight_[s];
      for (std::size_t i = 0; i < V.edges.size(); ++i) {
        vb.a.push_back(V.approx_point(i));
        vb.b.push_back(V.approx_point((i + 1) % V.vertices.size()));
        vb.edge.push_back(V.edges[i].kind == geometry::VisibilityEdge::Kind::Solid ? V.edges[i].edge : geometry::kNone);
      }
    });
  }
  // Bends in a straight line (p -> s -> w with w's predecessor s, all collinear: real
  // floor plans have them): beyond the last of them p's circle meets the circle of any of
  // them, so p's cut there carries all their labels.
  collinear_chain_.resize(slot_root_.size());
  for (std::uint32_t s = 0; s < slot_root_.size(); ++s) collinear_chain_[s].push_back(s);
  {
    std::vector<std::vector<std::uint32_t>> children(slot_root_.size());
    for (std::uint32_t s = 1; s < slot_root_.size(); ++s)
      if (slot_pred_[s] != kNoSlot) children[slot_pred_[s]].push_back(s);
    for (std::uint32_t s = 1; s < slot_root_.size(); ++s) {
      if (slot_pred_[s] == kNoSlot) continue;  // an alias
      const Point& p = slot_point_[slot_pred_[s]];
      for (std::size_t i = 0; i < collinear_chain_[s].size(); ++i) {  // every bend straight beyond s
        const std::uint32_t cur = collinear_chain_[s][i];
        for (const std::uint32_t w : children[cur])
          if (geometry::orientation(p, slot_point_[cur], slot_point_[w]) == 0 &&
              (slot_point_[w].x() - slot_point_[cur].x()) * (slot_point_[cur].x() - p.x()) + (slot_point_[w].y() - slot_point_[cur].y()) * (slot_point_[cur].y() - p.y()) > 0)
            collinear_chain_[s].push_back(w);
      }
    }
    // The direction of each extension: the same double for every bend of one straight
    // chain (p -> s -> w collinear), so that the cuts they put on one circle coincide;
    // taken from the chain's first step. Nearer roots first (a predecessor is nearer).
    ext_angle_.assign(slot_root_.size(), 0);
    std::vector<std::uint32_t> order;
    for (std::uint32_t s = 1; s < slot_root_.size(); ++s)
      if (slot_pred_[s] != kNoSlot) order.push_back(s);
    std::sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return slot_dist_[x] < slot_dist_[y]; });
    for (const std::uint32_t s : order) {
      const std::uint32_t p = slot_pred_[s];
      const std::uint32_t pp = slot_pred_[p];
      const Point &o = slot_point_[p], &S = slot_point_[s];
      if (p != 0 && pp != kNoSlot && geometry::orientation(slot_point_[pp], o, S) == 0 &&
          (o.x() - slot_point_[pp].x()) * (S.x() - o.x()) + (o.y() - slot_point_[pp].y()) * (S.y() - o.y()) > 0)
        ext_angle_[s] = ext_angle_[p];
      else
        ext_angle_[s] = wf_angle(o, S);
    }
  }
  const auto box = env.bbox();
  for (std::size_t s = 0; s < slot_root_.size(); ++s) {
    const Point& o = slot_point_[s];
    const double far = std::hypot(std::max(o.x() - box.xmin(), box.xmax() - o.x()), std::max(o.y() - box.ymin(), box.ymax() - o.y()));
    top_ = std::max(top_, slot_dist_[s] + far);
  }
  top_ = top_ * (1 + 1e-6) + 1e-9;
  // Ties (see ties_): every root s that sees root w with the segment tangent at w (a
  // visibility-graph edge, or the start seeing w) and D(s) + |sw| = D(w) to within 1e-12
  // of the range of h, other than w's predecessor (its extension is cut already).
  tie_sources_.assign(slot_root_.size(), {});
  for (std::uint32_t w = 1; w < slot_root_.size(); ++w) {
    if (!slot_live_[w]) continue;
    std::vector<std::uint32_t> from;
    if (slot_pred_[w] != 0 && spm.index().visible_from_vertex(slot_root_[w], spm.source())) from.push_back(0);
    for (const std::uint32_t v : slot_alias_[w])
      for (const std::uint32_t u : spm.graph().neighbours(v))
        if (root_slot_[u] != kNoSlot) from.push_back(root_slot_[u]);
    std::sort(from.begin(), from.end());
    from.erase(std::unique(from.begin(), from.end()), from.end());
    for (const std::uint32_t s : from) {
      if (s == w || s == slot_pred_[w] || slot_pred_[s] == w) continue;
      if (std::fabs(slot_dist_[s] + wf_length(slot_point_[s], slot_point_[w]) - slot_dist_[w]) > 1e-12 * top_) continue;
      ties_.push_back({s, w, wf_angle(slot_point_[s], slot_point_[w])});
      tie_sources_[w].push_back(s);
    }
  }

  // Candidate critical values.
  std::vector<std::pair<double, Point>> cand{{0.0, spm.source()}};
  for (std::uint32_t v = 0; v < env.num_vertices(); ++v) {
    const double d = root_slot_[v] != kNoSlot ? spm.vertex_distance(v) : spm.distance(env.vertex(v));
    if (std::isfinite(d)) cand.emplace_back(d, env.vertex(v));
  }
  // Fronts tangent to a wall: the foot of the perpendicular from a root to an edge, where
  // that root is the point's root (a local minimum of h along the edge).
  std::vector<std::vector<double>> minima(env.num_vertices(), std::vector<double>{0.0, 1.0});
  auto nudged = [&](std::size_t e, double t) {  // 1e-7 of the edge's length into free space (left)
    const Point& a = env.vertex(e);
    const Point& b = env.vertex(env.next(e));
    const double dx = b.x() - a.x(), dy = b.y() - a.y();
    return Point(a.x() + t * dx - 1e-7 * dy, a.y() + t * dy + 1e-7 * dx);
  };
  for (std::size_t s = 0; s < slot_root_.size(); ++s) {
    if (!slot_live_[s]) continue;
    const Point& o = slot_point_[s];
    const auto& vb = sight_[s];
    for (std::size_t k = 0; k < vb.edge.size(); ++k) {
      const std::uint32_t e = vb.edge[k];
      if (e == geometry::kNone) continue;
      const Point& a = env.vertex(e);
      const Point& b = env.vertex(env.next(e));
      if (geometry::orientation(a, b, o) <= 0) continue;  // free space is left of every edge
      const double dx = b.x() - a.x(), dy = b.y() - a.y();
      const double t = ((o.x() - a.x()) * dx + (o.y() - a.y()) * dy) / (dx * dx + dy * dy);
      if (!(t > 0 && t < 1)) continue;
      const Point f(a.x() + t * dx, a.y() + t * dy);
      // only where this root sees the edge (the piece of V(root) on it)
      const Point &pa = vb.a[k], &pb = vb.b[k];
      const double u = ((f.x() - pa.x()) * (pb.x() - pa.x()) + (f.y() - pa.y()) * (pb.y() - pa.y())) / std::max(1e-300, wf_length(pa, pb) * wf_length(pa, pb));
      if (u < -1e-9 || u > 1 + 1e-9) continue;
      const double d = slot_dist_[s] + wf_length(o, f);
      if (d >= top_) continue;
      // (the foot rounded to double may lie just inside the obstacle: ask a point nudged
      // into free space; this only places a candidate level)
      // It is a minimum of h when this root's path is a shortest one there: the point's
      // root, an alias of it (one point, several ring vertices), or a root tied with it
      // (on lattice maps two paths often reach a wall's foot at once).
      const Point n = nudged(e, t);
      const auto q = spm.query(n);
      const auto& al = slot_alias_[s];
      if (q.root == slot_root_[s] || std::find(al.begin(), al.end(), q.root) != al.end() ||
          q.distance >= slot_dist_[s] + wf_length(o, n) - 1e-12 * top_)
        cand.emplace_back(d, f), minima[e].push_back(t);
    }
  }
  // Between two consecutive minima along an edge h (a minimum of convex functions of the
  // position) has one maximum: where two fronts reach the wall from both sides, or a front
  // leaves it. Golden-section search on h, to 1e-9 of the edge.
  for (std::size_t e = 0; e < env.num_vertices(); ++e) {
    auto& m = minima[e];
    std::sort(m.begin(), m.end());
    auto h = [&](double t) {
      const double d = spm.distance(nudged(e, t));
      return std::isfinite(d) ? d : -1.0;
    };
    for (std::size_t i = 0; i + 1 < m.size(); ++i) {
      double lo = m[i], hi = m[i + 1];
      if (hi - lo < 1e-9) continue;
      const double g = (std::sqrt(5.0) - 1) / 2;
      double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = h(x1), f2 = h(x2);
      while (hi - lo > 1e-9) {
        if (f1 < f2) lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = h(x2);
        else hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = h(x1);
      }
      const double t = (lo + hi) / 2, d = h(t);
      if (d > 0) {
        const Point& a = env.vertex(e);
        const Point& b = env.vertex(env.next(e));
        cand.emplace_back(d, Point(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y())));
      }
    }
  }
  for (const auto& m : spm.collisions()) cand.emplace_back(m.distance, m.point);
  for (const auto& e : spm.extensions()) {
    const Point& v = env.vertex(e.vertex);
    cand.emplace_back(spm.vertex_distance(e.vertex) + wf_length(v, e.end), e.end);
    const Point hit = geometry::to_double(e.hit);
    cand.emplace_back(spm.vertex_distance(e.vertex) + wf_length(v, hit), hit);
  }
  std::stable_sort(cand.begin(), cand.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [d, p] : cand) {
    if (candidates_.empty() || d > candidates_.back() + 1e-9 * top_) candidates_.push_back(d);
    all_candidates_.emplace_back(d, p);
  }

  // Levels between consecutive candidates, and one above every front.
  std::vector<double> initial;
  for (std::size_t i = 0; i + 1 < candidates_.size(); ++i) initial.push_back((candidates_[i] + candidates_[i + 1]) / 2);
  initial.push_back(top_);
  // The first level: the start's own front, one cell from node 0 (a minimum of h).
  Level prev = compute(initial[0]);
  WavefrontNode start;
  start.level = 0, start.lo = 0, start.hi = initial[0], start.point = spm.source();
  std::vector<std::uint32_t> first_cells;
  for (std::uint32_t f = 0; f < prev.fronts; ++f) {
    first_cells.push_back(static_cast<std::uint32_t>(cells_.size()));
    start.above.push_back(static_cast<std::uint32_t>(cells_.size()));
    cells_.push_back({0, WavefrontCell::kNone, 0, 0});
  }
  nodes_.push_back(std::move(start));
  unmatched_ += prev.unmatched, snapped_ += prev.snapped;
  levels_.push_back(initial[0]);
  level_cells_.push_back(std::move(first_cells));
  // Later levels, computed a batch at a time on every core, then followed in order.
  const unsigned threads = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
  const std::size_t batch = 8 * threads;
  for (std::size_t i = 1; i < initial.size(); i += batch) {
    const std::size_t m = std::min(batch, initial.size() - i);
    std::vector<Level> next(m);
    parallel_for(m, threads, [&](std::size_t k) { next[k] = compute(initial[i + k]); });
    for (auto& L : next) {
      step(prev, L, 0);
      prev = std::move(L);
    }
  }
}

std::vector<std::vector<std::uint32_t>> WavefrontDecomposition::adjacency() const {
  std::vector<std::vector<std::uint32_t>> groups;
  for (const auto& n : nodes_) {
    groups.push_back(n.below);
    groups.back().insert(groups.back().end(), n.above.begin(), n.above.end());
  }
  return detail::adjacency_from_groups(groups, cells_.size());
}

std::vector<std::uint32_t> WavefrontDecomposition::cells_of(const Level& C) const {
  std::vector<std::uint32_t> out(C.fronts, WavefrontCell::kNone);
  const auto it = std::upper_bound(levels_.begin(), levels_.end(), C.lambda);
  const std::size_t k = static_cast<std::size_t>(it - levels_.begin());  // levels_[k - 1] <= lambda < levels_[k]
  if (k > 0 && levels_[k - 1] == C.lambda) return level_cells_[k - 1];
  auto follow = [&](const Level& A, const Level& B, bool from_below) {
    const auto pairs = relation(A, B);
    std::vector<std::uint32_t> na(A.fronts, 0), nb(B.fronts, 0);
    for (const auto& [a, b] : pairs) ++na[a], ++nb[b];
    for (const auto& [a, b] : pairs)
      if (na[a] == 1 && nb[b] == 1 && continues(A, a, B, b)) {
        if (from_below && out[b] == WavefrontCell::kNone) out[b] = level_cells_[k - 1][a];
        if (!from_below && out[a] == WavefrontCell::kNone) out[a] = level_cells_[k][b];
      }
  };
  if (k > 0) follow(compute(levels_[k - 1]), C, true);
  if (k < levels_.size()) follow(C, compute(levels_[k]), false);
  return out;
}

std::vector<WavefrontFront> WavefrontDecomposition::fronts(double lambda) const {
  const Level C = compute(lambda);
  const auto cell = cells_of(C);
  std::vector<WavefrontFront> out(C.fronts);
  std::vector<char> seen(C.arcs.size(), 0);
  auto walk = [&](std::uint32_t a, int enter) {
    auto& f = out[C.front[a]];
    while (!seen[a]) {
      seen[a] = 1;
      WavefrontArc arc = C.arcs[a];
      if (enter == 1) arc.from += arc.sweep, arc.sweep = -arc.sweep;
      f.arcs.push_back(arc);
      const std::int64_t next = C.link[2 * a + static_cast<std::uint32_t>(1 - enter)];
      if (next < 0) break;
      a = static_cast<std::uint32_t>(next / 2), enter = static_cast<int>(next % 2);
    }
  };
  for (std::uint32_t a = 0; a < C.arcs.size(); ++a)  // chains from their free ends first
    if (!seen[a] && C.arcs[a].sweep < kFullTurn && (C.link[2 * a] < 0 || C.link[2 * a + 1] < 0)) walk(a, C.link[2 * a] < 0 ? 0 : 1);
  for (std::uint32_t a = 0; a < C.arcs.size(); ++a)
    if (!seen[a]) walk(a, 0);
  for (std::uint32_t f = 0; f < C.fronts; ++f) out[f].closed = C.closed[f], out[f].cell = cell[f];
  return out;
}

std::uint32_t WavefrontDecomposition::cell_at(const Point& p) const {
  const auto q = spm_->query(p);
  if (q.root == geometry::kNone || q.distance <= 0) return WavefrontCell::kNone;
  const Level C = compute(q.distance);
  const std::uint32_t s = q.root == ShortestPathMap::kSource ? 0 : root_slot_[q.root];
  const std::int64_t a = C.arc_at(s, wf_angle(slot_point_[s], p));
  if (a < 0) return WavefrontCell::kNone;
  return cells_of(C)[C.front[static_cast<std::size_t>(a)]];
}

std::vector<Point> WavefrontDecomposition::arc_points(const WavefrontArc& arc, double sag) const {
  const Point& o = arc.root == ShortestPathMap::kSource ? spm_->source() : spm_->environment().vertex(arc.root);
  const double r = arc.radius;
  const double step = sag >= r ? std::numbers::pi / 2 : std::max(1e-4, 2 * std::acos(1 - sag / r));
  const auto pieces = static_cast<std::size_t>(std::ceil(std::fabs(arc.sweep) / step)) + 1;
  std::vector<Point> out;
  for (std::size_t i = 0; i <= pieces; ++i) {
    const double t = arc.from + arc.sweep * static_cast<double>(i) / static_cast<double>(pieces);
    out.emplace_back(o.x() + r * std::cos(t), o.y() + r * std::sin(t));
  }
  return out;
}

}  // namespace preimage::decompose
