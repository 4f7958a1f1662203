// SPDX-License-Identifier: Apache-2.0
// Exact gap transitions across a critical segment (rules 1-4 of 6.3, and any combination
// of them at a degenerate line).
//
// Let b be a point of the boundary and x_A, x_B points infinitely close to b on either
// side. The evader, caught on V(b), must be in a component K of the shadow at b at the
// moment the pursuer crosses; K lies inside one component of S(x_A) and one of S(x_B)
// (their limits), so components C_A, C_B correspond iff they contain a common K.
//   - Every gap of V(b) off the line is a gap on both sides (the same reflex vertex),
//     and the K behind it lies in that gap's component on both sides.
//   - The K touching the line are found locally. Looking along the line past one end of
//     the segment, the sight line passes contacts v_1..v_k (vertices seen edge-on or
//     grazing; obstacle on side o_i; maybe walls along the line between them). Near the
//     line the free space splits into strips (v_i, v_i+1) on each side. For x on side s
//     the strip on side s is hidden iff some o_m = s (m <= i); a point of the strip on
//     the other side t is seen along a line crossing the line of sight at c, passing
//     v_1..v_j (c in interval j) on side s and v_j+1..v_i on side t: so the strip splits
//     into pieces W(i, j), j = 0..i, by the gap rays through the contacts. Pieces are
//     joined across the line, across rays that are not gaps, and along a side unless a
//     contact's obstacle stands there; the far piece W(i, 0) (and the strip on side s)
//     touches the region K(i, side) of the shadow at b. Each K lands in the class of a
//     gap ray through some contact: that gap's component holds it.
#include <preimage/pursuit/cells.hpp>

#include <preimage/union_find.hpp>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace preimage::pursuit {

namespace {

// For x on side s of the sight line: the gap contacts, and for each strip i (1-based)
// and side (index 0: side s, 1: side t) that is hidden from b, the gap vertices whose
// class holds the region K(i, side) (empty: not hidden at b).
using Local = SightSide;

Local analyse(const SightLine& line, int s) {
  const int t = -s;
  const std::size_t k = line.contacts.size();
  // 1-based arrays: o[i], wall[i] (interval i runs from contact i to contact i + 1 or the stop).
  std::vector<int> o(k + 1, 0);
  std::vector<char> wall(k + 1, 0);
  for (std::size_t i = 1; i <= k; ++i) o[i] = line.contacts[i - 1].side, wall[i] = line.contacts[i - 1].wall_after;
  std::vector<char> has_s(k + 1, 0), has_t(k + 1, 0);
  std::vector<std::size_t> last_t(k + 1, 0);
  for (std::size_t i = 1; i <= k; ++i) {
    has_s[i] = has_s[i - 1] || o[i] == s;
    has_t[i] = has_t[i - 1] || o[i] == t;
    last_t[i] = o[i] == t ? i : last_t[i - 1];
  }
  // Node ids: N(i) for side s, W(i, j) for side t, D(i, side), G(j).
  auto N = [&](std::size_t i) { return static_cast<std::uint32_t>(i - 1); };
  std::vector<std::uint32_t> wbase(k + 2, 0);
  wbase[1] = static_cast<std::uint32_t>(k);
  for (std::size_t i = 1; i <= k; ++i) wbase[i + 1] = wbase[i] + static_cast<std::uint32_t>(i + 1);
  auto W = [&](std::size_t i, std::size_t j) { return wbase[i] + static_cast<std::uint32_t>(j); };
  const std::uint32_t dbase = wbase[k + 1];
  auto D = [&](std::size_t i, int side) { return dbase + static_cast<std::uint32_t>(2 * (i - 1) + (side == s ? 0 : 1)); };
  const std::uint32_t gbase = dbase + static_cast<std::uint32_t>(2 * k);
  auto G = [&](std::size_t j) { return gbase + static_cast<std::uint32_t>(j - 1); };
  UnionFind uf(gbase + k);

  auto n_exists = [&](std::size_t i) { return !(wall[i] && o[i] == s); };
  auto w_exists = [&](std::size_t i) { return !(wall[i] && o[i] == t); };
  auto n_hidden = [&](std::size_t i) { return bool(has_s[i]); };
  auto w_hidden = [&](std::size_t i, std::size_t j) { return has_s[j] || last_t[i] > j || (j >= 1 && wall[j]); };
  auto n_ok = [&](std::size_t i) { return n_exists(i) && n_hidden(i); };
  auto w_ok = [&](std::size_t i, std::size_t j) { return w_exists(i) && w_hidden(i, j); };

  for (std::size_t i = 1; i <= k; ++i) {
    if (n_ok(i) && !wall[i] && w_ok(i, i)) uf.join(N(i), W(i, i));  // across the line
    for (std::size_t j = 1; j <= i; ++j)
      if (w_ok(i, j) && w_ok(i, j - 1)) uf.join(W(i, j), W(i, j - 1));  // across a ray that is no gap
    if (i < k) {
      if (o[i + 1] != s && n_ok(i) && n_ok(i + 1)) uf.join(N(i), N(i + 1));
      if (o[i + 1] != t)
        for (std::size_t j = 0; j <= i; ++j)
          if (w_ok(i, j) && w_ok(i + 1, j)) uf.join(W(i, j), W(i + 1, j));
    }
    if (n_ok(i)) uf.join(D(i, s), N(i));
    if (w_ok(i, 0)) uf.join(D(i, t), W(i, 0));
  }
  // A degenerate line: a wall on side s runs along strip i right after a contact whose
  // gap ray bounds the near piece W(i, i), and strip i on side t was hidden at b. In exact
  // terms the near piece is new (cleared): an evader could reach it only through the
  // line, which b sees along the wall. That separation has no width; moving the wall by
  // any amount to side t makes the piece split off K(i, t), and the independent checker
  // (which drops free edges along walls) cannot tell it either. The piece is joined to
  // K(i, t), so plans never rely on a sight line along a wall
  // (tests/fixtures/pursuit/aligned_notch.json).
  for (std::size_t i = 1; i <= k; ++i)
    if (!n_exists(i) && has_t[i] && w_ok(i, i)) uf.join(W(i, i), D(i, t));
  Local out;
  for (std::size_t j = 1; j <= k; ++j) {
    const bool visible = !has_s[j - 1];
    const bool back = j >= 2 && wall[j - 1], fwd = wall[j];
    const bool tangent = back && fwd ? false : back ? o[j] == t : fwd ? o[j] == s : true;
    if (!visible || !tangent) continue;
    out.gaps.push_back(line.contacts[j - 1].vertex);
    // The gap ray crosses the line at v_j; behind it lies the near piece (obstacle on s)
    // or the far piece (obstacle on t) of strip j on side t.
    const std::size_t piece = o[j] == s ? j : j - 1;
    if (!w_ok(j, piece))
      throw std::logic_error("pursuit: the gap of vertex " + std::to_string(line.contacts[j - 1].vertex) +
                             " has no hidden piece behind it");
    uf.join(G(j), W(j, piece));
  }
  out.tokens.resize(k + 1);
  for (std::size_t i = 1; i <= k; ++i)
    for (int side : {s, t}) {
      const bool exists = side == s ? n_exists(i) : w_exists(i);
      const bool hidden_at_b = side == s ? has_s[i] : has_t[i];
      if (!exists || !hidden_at_b) continue;
      auto& tok = out.tokens[i][side == s ? 0 : 1];
      const std::uint32_t root = uf.find(D(i, side));
      for (std::size_t j = 1; j <= k; ++j)
        if (uf.find(G(j)) == root) tok.push_back(line.contacts[j - 1].vertex);
      if (tok.empty())
        throw std::logic_error("pursuit: a shadow region along the sight line from vertex " +
                               std::to_string(line.contacts[0].vertex) + " has no gap");
    }
  return out;
}

std::uint32_t component(const Shadows& sh, std::uint32_t v, const char* side) {
  const std::uint32_t c = sh.component_of(v);
  if (c == kNone)
    throw std::logic_error(std::string("pursuit: vertex ") + std::to_string(v) + " is a gap on the " + side +
                           " side of a critical line but not in the cell's shadows");
  return c;
}

// The components holding `gaps` (one, unless a degenerate line joined a near piece to K).
std::vector<std::uint32_t> components(const Shadows& sh, const std::vector<std::uint32_t>& gaps, const char* side) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t v : gaps) out.push_back(component(sh, v, side));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

SegmentSight analyse_sight(const CriticalSegment& seg) {
  // Relative to the forward look (the segment's direction) a pursuer on the left is on
  // side +1; looking backward the sides swap.
  SegmentSight out;
  for (int i = 0; i < 2; ++i) {
    const int side = i == 0 ? +1 : -1;
    out.forward[i] = analyse(seg.forward, side);
    out.backward[i] = analyse(seg.backward, -side);
  }
  return out;
}

filter::ShadowEvent gap_transition(const SegmentSight& sight, int side_a, const Shadows& a, const Shadows& b) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  // Gaps on both sides: the region behind the same reflex vertex.
  for (const Gap& g : a.gaps)
    if (const std::uint32_t cb = b.component_of(g.reflex); cb != kNone) pairs.push_back({g.component, cb});
  // Regions touching the line, looking past each end.
  const int ia = side_a > 0 ? 0 : 1, ib = 1 - ia;
  for (const auto* dir : {&sight.forward, &sight.backward}) {
    const Local &la = (*dir)[ia], &lb = (*dir)[ib];
    for (std::uint32_t v : la.gaps) component(a, v, "A");
    for (std::uint32_t v : lb.gaps) component(b, v, "B");
    for (std::size_t i = 1; i < la.tokens.size(); ++i)
      for (int side = 0; side < 2; ++side) {
        // Side index 0 is "the pursuer's own side" in each analysis: A's side is B's other.
        const auto& ta = la.tokens[i][side];
        const auto& tb = lb.tokens[i][1 - side];
        if (ta.empty() != tb.empty()) throw std::logic_error("pursuit: sides disagree on the shadow at a critical line");
        if (ta.empty()) continue;
        for (std::uint32_t ca : components(a, ta, "A"))
          for (std::uint32_t cb : components(b, tb, "B")) pairs.push_back({ca, cb});
      }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return {a.num_components, b.num_components, std::move(pairs)};
}

}  // namespace preimage::pursuit
