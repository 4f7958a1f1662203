// SPDX-License-Identifier: Apache-2.0
// The brushfire decomposition on the medial axis (see the header). Steps:
//  1. the medial axis with its sheets (geometry::GeneralizedVoronoiDiagram);
//  2. D at its vertices, runs of constant D (plateaus) merged to one level;
//  3. critical points of D on the axis: no rising branch (maximum), two or more (saddle);
//  4. for each critical level, the slice through its critical points: a search over the
//     sheets whose part of the slice meets (a flow line shared with the next sheet, or the
//     axis point where the slice turns from one side to the other); each component a node;
//  5. every sheet cut at the levels of the slices crossing it into bands; bands glued
//     where they meet off a slice; the classes are the cells.
#include <preimage/decompose/brushfire.hpp>

#include <preimage/error.hpp>
#include <preimage/union_find.hpp>

#include "cell_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace preimage::decompose {

namespace {

constexpr std::uint32_t kNoId = UINT32_MAX;
constexpr double kInf = std::numeric_limits<double>::infinity();

geometry::GvdOptions with_medial_axis(geometry::GvdOptions o, const Environment& env) {
  o.medial_axis = true;
  // the axis bounds the bands drawn and the laps' turns: finer than the GVD's default
  if (o.max_deviation == 0) o.max_deviation = 1e-5 * std::max(env.bbox().xmax() - env.bbox().xmin(), env.bbox().ymax() - env.bbox().ymin());
  return o;
}

double span(const Point& a, const Point& b) { return std::hypot(a.x() - b.x(), a.y() - b.y()); }

}  // namespace

double BrushfireDecomposition::d_start(std::uint32_t s) const {
  const auto& e = gvd_.medial_edges()[s / 2];
  return dv_[s % 2 == 0 ? e.from : e.to];
}
double BrushfireDecomposition::d_end(std::uint32_t s) const {
  const auto& e = gvd_.medial_edges()[s / 2];
  return dv_[s % 2 == 0 ? e.to : e.from];
}
double BrushfireDecomposition::d_lo(std::uint32_t e) const {
  return std::min(dv_[gvd_.medial_edges()[e].from], dv_[gvd_.medial_edges()[e].to]);
}
double BrushfireDecomposition::d_hi(std::uint32_t e) const {
  return std::max(dv_[gvd_.medial_edges()[e].from], dv_[gvd_.medial_edges()[e].to]);
}

double BrushfireDecomposition::band_lo(std::uint32_t b) const {
  const std::uint32_t s = band_sheet_[b], j = b - band_start_[s];
  return j == 0 ? 0.0 : cuts_[s][j - 1].level;
}
double BrushfireDecomposition::band_hi(std::uint32_t b) const {
  const std::uint32_t s = band_sheet_[b], j = b - band_start_[s];
  return j < cuts_[s].size() ? cuts_[s][j].level : kInf;
}
std::uint32_t BrushfireDecomposition::band_at(std::uint32_t s, double level) const {
  const auto& c = cuts_[s];
  const auto j = static_cast<std::uint32_t>(std::lower_bound(c.begin(), c.end(), level, [](const Cut& k, double l) { return k.level < l; }) - c.begin());
  const std::uint32_t b = band_start_[s] + j;
  if (b >= band_start_[s + 1]) throw std::logic_error("brushfire: a level above the sheet's bands");
  return b;
}

BrushfireDecomposition::BrushfireDecomposition(const Environment& env, const geometry::GvdOptions& options)
    : env_(&env), gvd_(geometry::GeneralizedVoronoiDiagram::build(env, with_medial_axis(options, env))) {
  const auto& V = gvd_.medial_vertices();
  const auto& E = gvd_.medial_edges();
  const std::size_t nv = V.size(), ne = E.size(), ns = 2 * ne;
  free_area_ = env.area();

  // ---- D at the vertices; runs of constant D (plateaus, equal ends) share one level
  dv_.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) dv_[v] = V[v].clearance;
  UnionFind runs(nv);
  for (int pass = 0; pass < 4; ++pass) {
    bool changed = false;
    for (const auto& e : E)
      if ((e.plateau || dv_[e.from] == dv_[e.to]) && runs.find(e.from) != runs.find(e.to)) runs.join(e.from, e.to), changed = true;
    std::vector<double> level(nv, kInf);
    for (std::uint32_t v = 0; v < nv; ++v) level[runs.find(v)] = std::min(level[runs.find(v)], dv_[v]);
    for (std::uint32_t v = 0; v < nv; ++v) dv_[v] = level[runs.find(v)];
    if (!changed) break;
  }

  // ---- sheets' predecessors
  prev_sheet_.assign(ns, kNoId);
  for (std::uint32_t s = 0; s < ns; ++s) {
    const std::uint32_t n = E[s / 2].next_sheet[s % 2];
    if (n != kNoId) prev_sheet_[n] = s;
  }

  // ---- critical points: per run, how many axis branches rise from it
  std::vector<std::vector<std::uint32_t>> incident(nv);  // edges
  for (std::uint32_t e = 0; e < ne; ++e) incident[E[e].from].push_back(e), incident[E[e].to].push_back(e);
  std::vector<std::uint32_t> up(nv, 0), down(nv, 0);
  std::vector<std::vector<std::uint32_t>> members(nv);
  for (std::uint32_t v = 0; v < nv; ++v) members[runs.find(v)].push_back(v);
  for (const auto& e : E) {
    if (dv_[e.from] == dv_[e.to]) continue;
    const std::uint32_t lo = dv_[e.from] < dv_[e.to] ? e.from : e.to, hi = lo == e.from ? e.to : e.from;
    ++up[runs.find(lo)], ++down[runs.find(hi)];
  }
  std::vector<std::uint32_t> crit_root;  // the run of each critical point
  for (std::uint32_t r = 0; r < nv; ++r) {
    if (members[r].empty() || !(dv_[r] > 0)) continue;
    bool any_edge = false;
    for (const std::uint32_t v : members[r]) any_edge = any_edge || !incident[v].empty();
    if (!any_edge) continue;
    if (up[r] != 0 && up[r] < 2) continue;
    BrushfireCriticalPoint c;
    c.kind = up[r] == 0 ? BrushfireCriticalPoint::Kind::Maximum : BrushfireCriticalPoint::Kind::Saddle;
    // a run's middle vertex stands for it (a plateau's points are all critical)
    c.p = V[members[r][members[r].size() / 2]].p;
    c.level = dv_[r];
    c.rising = up[r];
    critical_.push_back(c);
    crit_root.push_back(r);
  }
  std::vector<std::uint32_t> order(critical_.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return critical_[a].level < critical_[b].level; });

  // ---- critical slices, ascending: the search over sheets at each level
  cuts_.assign(ns, {});
  std::vector<std::uint32_t> seen_group(ns, kNoId), seen_node(ns, kNoId), queue;
  for (std::size_t g0 = 0; g0 < order.size();) {
    std::size_t g1 = g0;
    const double lambda = critical_[order[g0]].level;
    while (g1 < order.size() && critical_[order[g1]].level == lambda) ++g1;
    const auto group = static_cast<std::uint32_t>(g0);
    for (std::size_t k = g0; k < g1; ++k) {
      const std::uint32_t c = order[k];
      std::vector<std::uint32_t> start;
      for (const std::uint32_t v : members[crit_root[c]])
        for (const std::uint32_t e : incident[v]) start.push_back(2 * e), start.push_back(2 * e + 1);
      std::uint32_t node = kNoId;
      for (const std::uint32_t s : start)
        if (seen_group[s] == group) node = seen_node[s];
      if (node == kNoId) {
        node = static_cast<std::uint32_t>(nodes_.size());
        nodes_.push_back({lambda, {}});
      }
      nodes_[node].critical_points.push_back(c);
      critical_[c].node = node;
      queue.clear();
      auto push = [&](std::uint32_t s) {
        if (s == kNoId || seen_group[s] == group || d_hi(s / 2) < lambda) return;
        seen_group[s] = group, seen_node[s] = node;
        cuts_[s].push_back({lambda, node});
        queue.push_back(s);
      };
      for (const std::uint32_t s : start) push(s);
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const std::uint32_t s = queue[q];
        if (d_end(s) >= lambda) push(E[s / 2].next_sheet[s % 2]);
        if (d_start(s) >= lambda) push(prev_sheet_[s]);
        if (d_lo(s / 2) <= lambda) push(s ^ 1u);
      }
    }
    g0 = g1;
  }

  // ---- bands: each sheet cut at its slices' levels (the part below D on the axis)
  band_start_.assign(ns + 1, 0);
  for (std::uint32_t s = 0; s < ns; ++s) {
    std::uint32_t count = 0;
    const double top = d_hi(s / 2);
    if (top > 0) {
      count = 1;
      for (const Cut& c : cuts_[s]) count += c.level < top;
    }
    band_start_[s + 1] = band_start_[s] + count;
  }
  const std::uint32_t nb = band_start_[ns];
  band_sheet_.resize(nb);
  for (std::uint32_t s = 0; s < ns; ++s)
    for (std::uint32_t b = band_start_[s]; b < band_start_[s + 1]; ++b) band_sheet_[b] = s;

  // ---- glue bands that meet off a slice: across flow lines, across the axis
  UnionFind cells(nb);
  for (std::uint32_t s = 0; s < ns; ++s) {
    const std::uint32_t n = E[s / 2].next_sheet[s % 2];
    const double at = d_end(s);
    if (n != kNoId && at > 0 && band_start_[n + 1] > band_start_[n])
      for (std::uint32_t b = band_start_[s]; b < band_start_[s + 1]; ++b)
        if (band_lo(b) < at) cells.join(b, band_at(n, (band_lo(b) + std::min(band_hi(b), at)) / 2));
    if (s % 2 == 0) {
      const double lo = d_lo(s / 2), hi = d_hi(s / 2);
      if (hi > lo)
        for (std::uint32_t b = band_start_[s]; b < band_start_[s + 1]; ++b) {
          const double a = std::max(band_lo(b), lo), z = std::min(band_hi(b), hi);
          if (a < z) cells.join(b, band_at(s + 1, (a + z) / 2));
        }
    }
  }
  band_cell_.assign(nb, kNoId);
  for (std::uint32_t b = 0; b < nb; ++b) {
    const std::uint32_t root = cells.find(b);
    if (band_cell_[root] == kNoId) {
      band_cell_[root] = static_cast<std::uint32_t>(cells_.size());
      BrushfireCell c;
      c.lo = kInf, c.hi = 0;
      cells_.push_back(c);
    }
    band_cell_[b] = band_cell_[root];
  }
  // Each cell's slices: one below (or an obstacle), one above. Anything else would mean a
  // cell reaching two slices on one side: a bug, not an answer.
  for (std::uint32_t b = 0; b < nb; ++b) {
    BrushfireCell& c = cells_[band_cell_[b]];
    const std::uint32_t s = band_sheet_[b], j = b - band_start_[s];
    c.bands.push_back(b);
    c.lo = std::min(c.lo, band_lo(b));
    c.hi = std::max(c.hi, std::min(band_hi(b), d_hi(s / 2)));
    const std::uint32_t lower = j == 0 ? BrushfireCell::kNone : cuts_[s][j - 1].node;
    const std::uint32_t upper = j < cuts_[s].size() ? cuts_[s][j].node : BrushfireCell::kNone;
    const std::uint32_t obstacle = j == 0 ? E[s / 2].sites[s % 2].obstacle : BrushfireCell::kNone;
    if (c.bands.size() == 1) {
      c.lower = lower, c.upper = upper, c.obstacle = obstacle;
    } else {
      if (c.lower != lower || c.obstacle != obstacle)
        throw std::logic_error("brushfire: a cell starts from two slices (bands of sheets " + std::to_string(band_sheet_[c.bands.front()]) + " and " +
                               std::to_string(s) + ")");
      if (upper != BrushfireCell::kNone) {
        if (c.upper != BrushfireCell::kNone && c.upper != upper) throw std::logic_error("brushfire: a cell ends at two slices");
        c.upper = upper;
      }
    }
  }
  const double sag = 1e-5 * std::max(env.bbox().xmax() - env.bbox().xmin(), env.bbox().ymax() - env.bbox().ymin());
  for (std::uint32_t b = 0; b < nb; ++b) {
    const auto poly = band_polygon(b, sag);
    double a = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Point& p = poly[i];
      const Point& q = poly[(i + 1) % poly.size()];
      a += p.x() * q.y() - q.x() * p.y();
    }
    cells_[band_cell_[b]].area += std::fabs(a) / 2;
  }
}

std::vector<std::vector<std::uint32_t>> BrushfireDecomposition::adjacency() const {
  std::vector<std::vector<std::uint32_t>> at_node(nodes_.size());
  for (std::uint32_t c = 0; c < cells_.size(); ++c) {
    if (cells_[c].lower != BrushfireCell::kNone) at_node[cells_[c].lower].push_back(c);
    if (cells_[c].upper != BrushfireCell::kNone) at_node[cells_[c].upper].push_back(c);
  }
  return detail::adjacency_from_groups(at_node, cells_.size());
}

// The point of segment qp (a piece of the axis edge e) where D = level, D going from dq to
// dp: on a circle around a vertex site when the edge has one (D is not linear along a
// bisector of points), else linear (D is linear along a line between two segments).
Point BrushfireDecomposition::crossing(std::uint32_t e, const Point& q, const Point& p, double dq, double dp, double level) const {
  const auto& me = gvd_.medial_edges()[e];
  for (const auto& site : me.sites) {
    if (site.kind != geometry::GvdSite::Kind::Vertex) continue;
    const Point c = gvd_.nearest_on_site(site, q);
    const double ux = p.x() - q.x(), uy = p.y() - q.y(), wx = q.x() - c.x(), wy = q.y() - c.y();
    const double A = ux * ux + uy * uy, B = 2 * (ux * wx + uy * wy), C = wx * wx + wy * wy - level * level;
    if (!(A > 0)) return q;
    const double disc = std::max(0.0, B * B - 4 * A * C), sq = std::sqrt(disc);
    // the root in [0, 1] nearer the linear guess
    const double guess = dp != dq ? std::clamp((level - dq) / (dp - dq), 0.0, 1.0) : 0.0;
    double best = guess, gap = kInf;
    for (const double t : {(-B - sq) / (2 * A), (-B + sq) / (2 * A)})
      if (t >= -1e-9 && t <= 1 + 1e-9 && std::fabs(t - guess) < gap) best = std::clamp(t, 0.0, 1.0), gap = std::fabs(t - guess);
    return {q.x() + best * ux, q.y() + best * uy};
  }
  const double t = dp != dq ? std::clamp((level - dq) / (dp - dq), 0.0, 1.0) : 0.0;
  return {q.x() + t * (p.x() - q.x()), q.y() + t * (p.y() - q.y())};
}

void BrushfireDecomposition::sheet_run(std::uint32_t s, double level, std::vector<Point>& m, std::vector<double>& d) const {
  m.clear(), d.clear();
  const auto& e = gvd_.medial_edges()[s / 2];
  const std::size_t n = e.polyline.size();
  const bool forward = s % 2 == 0;
  // D along the sheet, made monotone between the run-equalised ends (sampled values may
  // wobble by rounding)
  const double a = d_start(s), z = d_end(s);
  auto at = [&](std::size_t k) { return forward ? k : n - 1 - k; };
  auto dk = [&](std::size_t k) {
    if (k == 0) return a;
    if (k + 1 == n) return z;
    const double v = e.clearance[at(k)];
    return std::clamp(v, std::min(a, z), std::max(a, z));
  };
  double prev_d = 0;
  for (std::size_t k = 0; k < n; ++k) {
    double dd = dk(k);
    if (k > 0) dd = a <= z ? std::max(dd, prev_d) : std::min(dd, prev_d);
    const Point& p = e.polyline[at(k)];
    if (k > 0 && (prev_d < level) != (dd < level)) {
      m.push_back(crossing(s / 2, e.polyline[at(k - 1)], p, prev_d, dd, level));
      d.push_back(level);
    }
    if (dd >= level) m.push_back(p), d.push_back(dd);
    prev_d = dd;
  }
}

Point BrushfireDecomposition::on_flow_line(std::uint32_t s, const Point& m, double /*dm*/, double lambda) const {
  const auto& site = gvd_.medial_edges()[s / 2].sites[s % 2];
  const Point c = gvd_.nearest_on_site(site, m);
  const double len = span(c, m);
  if (!(len > 0) || lambda >= len) return m;
  const double t = lambda / len;
  return {c.x() + t * (m.x() - c.x()), c.y() + t * (m.y() - c.y())};
}

void BrushfireDecomposition::offset_run(std::uint32_t s, const std::vector<Point>& m, const std::vector<double>& d, double lambda, double sag,
                                        std::vector<Point>& out) const {
  const auto& site = gvd_.medial_edges()[s / 2].sites[s % 2];
  const bool arc = site.kind == geometry::GvdSite::Kind::Vertex;
  const Point c = arc ? gvd_.nearest_on_site(site, m.empty() ? Point(0, 0) : m.front()) : Point(0, 0);
  auto add = [&](const Point& p) {
    if (out.empty() || out.back() != p) out.push_back(p);
  };
  for (std::size_t k = 0; k < m.size(); ++k) {
    const double l = std::min(lambda, d[k]);
    const Point p = on_flow_line(s, m[k], d[k], l);
    if (arc && k > 0 && !out.empty() && l > 0 && std::min(lambda, d[k - 1]) == l) {
      // both ends on the circle of radius l around the site: subdivide the arc
      const Point& q = out.back();
      const double a0 = std::atan2(q.y() - c.y(), q.x() - c.x()), a1 = std::atan2(p.y() - c.y(), p.x() - c.x());
      double da = a1 - a0;
      while (da > std::numbers::pi) da -= 2 * std::numbers::pi;
      while (da < -std::numbers::pi) da += 2 * std::numbers::pi;
      // never coarser than pi/32 (a chord then misses 0.2% of its sector)
      const double step = std::min(std::numbers::pi / 32, 2 * std::acos(std::max(-1.0, 1 - sag / l)));
      const auto pieces = static_cast<std::size_t>(std::min(4096.0, std::ceil(std::fabs(da) / std::max(step, 1e-6))));
      for (std::size_t i = 1; i < pieces; ++i) {
        const double t = a0 + da * static_cast<double>(i) / static_cast<double>(pieces);
        add(Point(c.x() + l * std::cos(t), c.y() + l * std::sin(t)));
      }
    }
    add(p);
  }
}

std::vector<Point> BrushfireDecomposition::band_polygon(std::uint32_t b, double sag) const {
  const std::uint32_t s = band_sheet_[b];
  const double lo = band_lo(b), hi = band_hi(b);
  std::vector<Point> m, lower, upper;
  std::vector<double> d;
  sheet_run(s, lo, m, d);
  if (m.empty()) return {};
  // the crossing of hi, if any, as a sample (D is monotone along the run)
  if (hi < kInf) {
    std::vector<Point> m2;
    std::vector<double> d2;
    for (std::size_t k = 0; k < m.size(); ++k) {
      if (k > 0 && (d[k - 1] < hi) != (d[k] < hi)) {
        m2.push_back(crossing(s / 2, m[k - 1], m[k], d[k - 1], d[k], hi));
        d2.push_back(hi);
      }
      m2.push_back(m[k]), d2.push_back(d[k]);
    }
    m.swap(m2), d.swap(d2);
  }
  offset_run(s, m, d, lo, sag, lower);
  offset_run(s, m, d, hi, sag, upper);
  std::vector<Point> poly = lower;
  for (auto it = upper.rbegin(); it != upper.rend(); ++it)
    if (poly.empty() || poly.back() != *it) poly.push_back(*it);
  return poly;
}

std::vector<BrushfireDecomposition::LevelCurve> BrushfireDecomposition::level_curves(double lambda, double sag) const {
  const auto& E = gvd_.medial_edges();
  const std::size_t ns = 2 * E.size();
  std::vector<char> done(ns, 0);
  std::vector<LevelCurve> out;
  std::vector<Point> m;
  std::vector<double> d;
  for (std::uint32_t s0 = 0; s0 < ns; ++s0) {
    if (done[s0] || !(d_hi(s0 / 2) > lambda)) continue;
    LevelCurve curve;
    curve.cell = band_cell_[band_at(s0, lambda)];
    std::uint32_t s = s0;
    for (std::size_t guard = 0; guard <= ns; ++guard) {
      done[s] = 1;
      sheet_run(s, lambda, m, d);
      offset_run(s, m, d, lambda, sag, curve.points);
      const std::uint32_t n = d_end(s) > lambda ? E[s / 2].next_sheet[s % 2] : s ^ 1u;
      if (n == kNoId) throw std::logic_error("brushfire: a slice runs into a sheet without successor");
      s = n;
      if (s == s0) break;
      if (done[s]) throw std::logic_error("brushfire: a slice does not close");
    }
    if (curve.points.size() > 1 && curve.points.front() == curve.points.back()) curve.points.pop_back();
    out.push_back(std::move(curve));
  }
  return out;
}

std::vector<BrushfireDecomposition::AxisPiece> BrushfireDecomposition::axis_pieces() const {
  const auto& E = gvd_.medial_edges();
  std::vector<AxisPiece> out;
  std::vector<Point> m;
  std::vector<double> d;
  for (std::uint32_t e = 0; e < E.size(); ++e) {
    const std::uint32_t s = 2 * e;
    const double lo = d_lo(e), hi = d_hi(e);
    if (!(hi > 0) || band_start_[s + 1] == band_start_[s]) continue;
    if (hi == lo) {
      // a plateau: with the band just below it
      AxisPiece p;
      p.points = E[e].polyline;
      p.clearance.assign(p.points.size(), hi);
      p.cell = band_cell_[band_at(s, hi)];
      out.push_back(std::move(p));
      continue;
    }
    for (std::uint32_t b = band_start_[s]; b < band_start_[s + 1]; ++b) {
      const double a = std::max(band_lo(b), lo), z = std::min(band_hi(b), hi);
      if (!(a < z)) continue;
      sheet_run(s, a, m, d);
      AxisPiece p;
      p.cell = band_cell_[b];
      // keep the part with D <= z (D is monotone along the run)
      for (std::size_t k = 0; k < m.size(); ++k) {
        if (k > 0 && (d[k - 1] <= z) != (d[k] <= z)) {
          p.points.push_back(crossing(e, m[k - 1], m[k], d[k - 1], d[k], z));
          p.clearance.push_back(z);
        }
        if (d[k] <= z) p.points.push_back(m[k]), p.clearance.push_back(d[k]);
      }
      if (p.points.size() >= 2) out.push_back(std::move(p));
    }
  }
  return out;
}

}  // namespace preimage::decompose
