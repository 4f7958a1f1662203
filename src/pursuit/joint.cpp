// SPDX-License-Identifier: Apache-2.0
// Overlay of several pursuers' gaps. A gap's interior lies in open free space and its ends
// on the boundary (the pursuers stand inside conservative cells), so two gaps either
// coincide (pursuers in line with the occluding vertex) or share no interior point: equal
// gaps are merged and remember every pursuer they belong to.
#include <preimage/pursuit/joint.hpp>

#include <preimage/union_find.hpp>

#include <algorithm>
#include <stdexcept>

namespace preimage::pursuit {

using geometry::ExactPoint;

namespace {

geometry::SegmentEnd end_of(const geometry::VisibilityVertex& v) {
  using K = geometry::VisibilityVertex::Kind;
  if (v.kind == K::EnvironmentVertex) return {geometry::SegmentEnd::Kind::AtVertex, v.vertex};
  if (v.kind == K::RayHit) return {geometry::SegmentEnd::Kind::OnEdge, v.edge};
  throw std::logic_error("pursuit: a gap ends at the pursuer (the pursuer stands on the boundary)");
}

}  // namespace

ShadowOverlay overlay_shadows(const geometry::Environment& env, std::span<const geometry::Point> at,
                              std::span<const Shadows* const> shadows) {
  struct Owner {
    std::uint32_t pursuer, component;
    bool v_left_of_even;  // V(pursuer) lies left of the segment's from -> to
  };
  struct Item {
    geometry::ArrangementSegment seg;
    Owner owner;
  };
  std::vector<Item> items;
  for (std::uint32_t l = 0; l < shadows.size(); ++l)
    for (const Gap& g : shadows[l]->gaps) {
      if (g.pinch) continue;  // no edge: labelled by its wedge's face below
      // Canonical direction: lexicographically smaller end first, so equal gaps compare equal.
      const ExactPoint pa = shadows[l]->end(env, g.a), pb = shadows[l]->end(env, g.b);
      const bool fwd = CGAL::compare_xy(pa, pb) == CGAL::SMALLER;
      geometry::ArrangementSegment s{fwd ? pa : pb, fwd ? pb : pa, end_of(fwd ? g.a : g.b), end_of(fwd ? g.b : g.a),
                                     std::make_pair(at[l], env.vertex(g.reflex))};
      items.push_back({std::move(s), {l, g.component, fwd}});
    }
  std::sort(items.begin(), items.end(), [](const Item& x, const Item& y) {
    const auto c = CGAL::compare_xy(x.seg.from, y.seg.from);
    if (c != CGAL::EQUAL) return c == CGAL::SMALLER;
    return CGAL::compare_xy(x.seg.to, y.seg.to) == CGAL::SMALLER;
  });
  std::vector<geometry::ArrangementSegment> segs;
  std::vector<std::vector<Owner>> owners;
  for (auto& it : items) {
    if (!segs.empty() && segs.back().from == it.seg.from && segs.back().to == it.seg.to) {
      owners.back().push_back(it.owner);
      continue;
    }
    segs.push_back(std::move(it.seg));
    owners.push_back({it.owner});
  }
  ShadowOverlay out{geometry::SegmentArrangement::build(env, std::move(segs), {}, nullptr, true), {}};
  const auto& A = out.arrangement;
  const auto& H = A.half_edges();
  const std::size_t nr = A.num_regions(), k = shadows.size();
  out.component.assign(nr, std::vector<std::uint32_t>(k, kNone));
  for (std::uint32_t l = 0; l < k; ++l) {
    // Regions joined across everything but pursuer l's gaps are one side of them: V(l)
    // or one component of its shadow, told by any gap of l on the class's boundary.
    UnionFind uf(nr);
    auto owns = [&](std::uint32_t seg) -> const Owner* {
      for (auto& o : owners[seg])
        if (o.pursuer == l) return &o;
      return nullptr;
    };
    for (std::uint32_t h = 0; h < H.size(); h += 2) {
      if (H[h].segment == kNone || owns(H[h].segment)) continue;
      uf.join(A.region_of(h), A.region_of(h + 1));
    }
    std::vector<std::uint32_t> label(nr, kNone);
    std::vector<char> known(nr, 0);
    for (std::uint32_t h = 0; h < H.size(); ++h) {
      if (H[h].segment == kNone) continue;
      const Owner* o = owns(H[h].segment);
      if (!o) continue;
      const std::uint32_t root = uf.find(A.region_of(h));
      // Even half-edges run from -> to; V(l) is on the left of from -> to iff v_left_of_even.
      const bool in_v = (h % 2 == 0) == o->v_left_of_even;
      const std::uint32_t c = in_v ? kNone : o->component;
      if (known[root] && label[root] != c) throw std::logic_error("pursuit: a face is on both sides of a pursuer's gaps");
      known[root] = 1, label[root] = c;
    }
    // A shadow region pinched at a contact point (or a wedge of a hidden one) starts at the
    // face beside its wedge's first edge.
    for (const Gap& g : shadows[l]->gaps) {
      if (!g.pinch) continue;
      const std::uint32_t root = uf.find(A.region_of(A.first_piece(g.reflex)));
      if (known[root] && label[root] != g.component)
        throw std::logic_error("pursuit: a face beside contact vertex " + std::to_string(g.reflex) + " is in two components");
      known[root] = 1, label[root] = g.component;
    }
    for (std::uint32_t r = 0; r < nr; ++r) out.component[r][l] = label[uf.find(r)];  // no gap at all: all visible
  }
  return out;
}

std::vector<std::vector<std::uint32_t>> joint_units(const ShadowOverlay& overlay) {
  std::vector<std::vector<std::uint32_t>> units;
  for (auto& c : overlay.component)
    if (std::find(c.begin(), c.end(), kNone) == c.end()) units.push_back(c);
  std::sort(units.begin(), units.end());
  units.erase(std::unique(units.begin(), units.end()), units.end());
  return units;
}

}  // namespace preimage::pursuit
