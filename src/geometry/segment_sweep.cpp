// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/segment_sweep.hpp>

#include <algorithm>
#include <numeric>
#include <set>

namespace preimage::geometry {
namespace {

struct Found {
  std::size_t s, t;
};

// Oriented copy of a segment: lo before hi in lexicographic (x, y) order.
struct Oriented {
  std::uint32_t lo, hi;
};

Point contact_point(const Point& a, const Point& b, const Point& c, const Point& d) {
  auto r = CGAL::intersection(Segment(a, b), Segment(c, d));
  if (r) {
    if (const Point* p = boost::get<Point>(&*r)) return *p;
    if (const Segment* s = boost::get<Segment>(&*r)) return s->source();
  }
  return a;
}

// Do segments s and t (by endpoint indices) touch improperly?
bool improper(const std::vector<Point>& P, const IndexedSegment& s, const IndexedSegment& t) {
  std::uint32_t shared = UINT32_MAX, os = 0, ot = 0;
  if (s.a == t.a) shared = s.a, os = s.b, ot = t.b;
  else if (s.a == t.b) shared = s.a, os = s.b, ot = t.a;
  else if (s.b == t.a) shared = s.b, os = s.a, ot = t.b;
  else if (s.b == t.b) shared = s.b, os = s.a, ot = t.a;
  if (shared != UINT32_MAX) {
    if (os == ot) return true;  // the same segment twice
    // Sharing an endpoint, they meet elsewhere only if they overlap collinearly.
    const Point &c = P[shared], &u = P[os], &w = P[ot];
    return orientation(c, u, w) == 0 && ((u - c) * (w - c)) > 0;
  }
  return CGAL::do_intersect(Segment(P[s.a], P[s.b]), Segment(P[t.a], P[t.b]));
}

}  // namespace

std::optional<SegmentContact> find_segment_contact(const std::vector<Point>& P,
                                                   const std::vector<IndexedSegment>& segs) {
  const std::size_t m = segs.size();
  auto make = [&](std::size_t s, std::size_t t) {
    const auto &A = segs[s], &B = segs[t];
    return SegmentContact{std::min(s, t), std::max(s, t),
                          contact_point(P[A.a], P[A.b], P[B.a], P[B.b])};
  };
  for (std::size_t s = 0; s < m; ++s)
    if (P[segs[s].a] == P[segs[s].b]) return SegmentContact{s, s, P[segs[s].a]};

  std::vector<Oriented> o(m);
  for (std::size_t s = 0; s < m; ++s) {
    auto [a, b] = segs[s];
    o[s] = lex_less_xy(P[a], P[b]) ? Oriented{a, b} : Oriented{b, a};
  }

  // Events: every endpoint index once, in lexicographic order of its point.
  std::vector<std::uint32_t> ev;
  ev.reserve(2 * m);
  for (auto& s : o) ev.push_back(s.lo), ev.push_back(s.hi);
  std::sort(ev.begin(), ev.end());
  ev.erase(std::unique(ev.begin(), ev.end()), ev.end());
  std::stable_sort(ev.begin(), ev.end(), [&](auto i, auto j) { return lex_less_xy(P[i], P[j]); });

  // Segments starting / ending at each event index (CSR layout).
  std::vector<std::uint32_t> slot(P.size(), UINT32_MAX);
  for (std::size_t k = 0; k < ev.size(); ++k) slot[ev[k]] = static_cast<std::uint32_t>(k);
  std::vector<std::uint32_t> start_off(ev.size() + 1, 0), end_off(ev.size() + 1, 0);
  for (auto& s : o) ++start_off[slot[s.lo] + 1], ++end_off[slot[s.hi] + 1];
  std::partial_sum(start_off.begin(), start_off.end(), start_off.begin());
  std::partial_sum(end_off.begin(), end_off.end(), end_off.begin());
  std::vector<std::uint32_t> starts(m), ends(m);
  {
    auto sf = start_off, ef = end_off;
    for (std::uint32_t s = 0; s < m; ++s) starts[sf[slot[o[s].lo]]++] = s, ends[ef[slot[o[s].hi]]++] = s;
  }

  // Status: active segments bottom to top. The comparator decides with one exact
  // orientation test; a collinear answer *is* a contact, reported by throwing.
  auto below = [&](std::uint32_t s, std::uint32_t t) -> bool {
    if (s == t) return false;
    const Point &ls = P[o[s].lo], &hs = P[o[s].hi], &lt = P[o[t].lo], &ht = P[o[t].hi];
    if (o[s].lo == o[t].lo) {
      int r = orientation(ls, hs, ht);
      if (r == 0) throw Found{s, t};
      return r > 0;
    }
    if (!lex_less_xy(ls, lt)) {  // s starts at or after t: locate s's start against t
      int r = orientation(lt, ht, ls);
      if (r == 0) throw Found{s, t};
      return r < 0;
    }
    int r = orientation(ls, hs, lt);
    if (r == 0) throw Found{s, t};
    return r > 0;
  };
  using Status = std::set<std::uint32_t, decltype(below)>;
  Status status(below);
  std::vector<Status::iterator> where(m, status.end());

  try {
    for (std::size_t k = 0; k < ev.size(); ++k) {
      // Distinct indices at equal coordinates always touch.
      if (k + 1 < ev.size() && P[ev[k]] == P[ev[k + 1]]) {
        auto any_seg = [&](std::size_t kk) {
          return start_off[kk] < start_off[kk + 1] ? starts[start_off[kk]] : ends[end_off[kk]];
        };
        return make(any_seg(k), any_seg(k + 1));
      }
      for (auto i = end_off[k]; i < end_off[k + 1]; ++i) {
        auto s = ends[i];
        auto it = where[s];
        auto up = std::next(it);
        if (it != status.begin() && up != status.end()) {
          auto dn = std::prev(it);
          if (improper(P, segs[*dn], segs[*up])) return make(*dn, *up);
        }
        status.erase(it);
        where[s] = status.end();
      }
      for (auto i = start_off[k]; i < start_off[k + 1]; ++i) {
        auto s = starts[i];
        auto [it, ok] = status.insert(s);
        where[s] = it;
        if (it != status.begin()) {
          auto dn = std::prev(it);
          if (improper(P, segs[*dn], segs[s])) return make(*dn, s);
        }
        auto up = std::next(it);
        if (up != status.end() && improper(P, segs[s], segs[*up])) return make(s, *up);
      }
    }
  } catch (const Found& f) {
    return make(f.s, f.t);
  }
  return std::nullopt;
}

std::optional<SegmentContact> find_segment_contact_brute_force(
    const std::vector<Point>& P, const std::vector<IndexedSegment>& segs) {
  for (std::size_t s = 0; s < segs.size(); ++s) {
    if (P[segs[s].a] == P[segs[s].b]) return SegmentContact{s, s, P[segs[s].a]};
    for (std::size_t t = s + 1; t < segs.size(); ++t) {
      const auto &A = segs[s], &B = segs[t];
      bool touch = improper(P, A, B);
      // Distinct indices at equal coordinates count as a contact even when shared-index logic passed.
      for (auto i : {A.a, A.b})
        for (auto j : {B.a, B.b})
          if (i != j && P[i] == P[j]) touch = true;
      if (touch) return SegmentContact{s, t, contact_point(P[A.a], P[A.b], P[B.a], P[B.b])};
    }
  }
  return std::nullopt;
}

}  // namespace preimage::geometry
