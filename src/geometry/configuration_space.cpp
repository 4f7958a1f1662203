// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/configuration_space.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/queries.hpp>

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace preimage::geometry {

// Uniform grid of the workspace's edges, for "which edges may be within r of this segment".
struct ConfigurationSpace::EdgeGrid {
  double x0 = 0, y0 = 0, cell = 1;
  std::uint32_t nx = 1, ny = 1;
  std::vector<std::uint32_t> offset, edges;
  mutable std::vector<std::uint32_t> stamp;
  mutable std::uint32_t now = 0;

  explicit EdgeGrid(const Environment& env) {
    const auto box = env.bbox();
    const std::size_t n = env.num_vertices();
    x0 = box.xmin(), y0 = box.ymin();
    const double w = std::max(box.xmax() - box.xmin(), 1e-300), h = std::max(box.ymax() - box.ymin(), 1e-300);
    cell = std::max(std::sqrt(w * h / static_cast<double>(std::max<std::size_t>(n, 1))), std::max(w, h) / 2048);
    nx = static_cast<std::uint32_t>(std::clamp(std::ceil(w / cell), 1.0, 2048.0));
    ny = static_cast<std::uint32_t>(std::clamp(std::ceil(h / cell), 1.0, 2048.0));
    offset.assign(std::size_t(nx) * ny + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::uint32_t> fill;
      if (pass == 1) {
        for (std::size_t i = 1; i < offset.size(); ++i) offset[i] += offset[i - 1];
        edges.resize(offset.back());
        fill.assign(offset.begin(), offset.end() - 1);
      }
      for (std::uint32_t e = 0; e < n; ++e) {
        const CGAL::Bbox_2 b = env.vertex(e).bbox() + env.vertex(env.next(e)).bbox();
        visit(b.xmin(), b.ymin(), b.xmax(), b.ymax(), [&](std::size_t c) {
          if (pass == 0) ++offset[c + 1];
          else edges[fill[c]++] = e;
        });
      }
    }
    stamp.assign(n, 0);
  }
  // Cells overlapping the box, widened by one so rounding in the index never loses one.
  template <class F>
  void visit(double xa, double ya, double xb, double yb, F&& f) const {
    auto ix = [&](double x) { return static_cast<long>(std::floor((x - x0) / cell)); };
    auto iy = [&](double y) { return static_cast<long>(std::floor((y - y0) / cell)); };
    const long i0 = std::max<long>(0, ix(xa) - 1), i1 = std::min<long>(nx - 1, ix(xb) + 1);
    const long j0 = std::max<long>(0, iy(ya) - 1), j1 = std::min<long>(ny - 1, iy(yb) + 1);
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i) f(std::size_t(j) * nx + std::size_t(i));
  }
  // Calls f(e) once for every edge filed in a cell within `reach` of segment pq's box.
  template <class F>
  void near(const Point& p, const Point& q, double reach, F&& f) const {
    if (++now == 0) std::fill(stamp.begin(), stamp.end(), 0), now = 1;
    visit(std::min(p.x(), q.x()) - reach, std::min(p.y(), q.y()) - reach, std::max(p.x(), q.x()) + reach,
          std::max(p.y(), q.y()) + reach, [&](std::size_t c) {
            for (auto k = offset[c]; k < offset[c + 1]; ++k) {
              const std::uint32_t e = edges[k];
              if (stamp[e] != now) stamp[e] = now, f(e);
            }
          });
  }
};

namespace {

using ExactSegment = ExactKernel::Segment_2;

// Distance from p to segment ab in double (a clamped projection: well-conditioned even for
// a segment of zero length).
double point_segment(const Point& p, const Point& a, const Point& b) {
  const double vx = b.x() - a.x(), vy = b.y() - a.y(), wx = p.x() - a.x(), wy = p.y() - a.y();
  const double l2 = vx * vx + vy * vy;
  const double t = l2 > 0 ? std::clamp((wx * vx + wy * vy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(wx - t * vx, wy - t * vy);
}

// Is segment pq at distance >= r from workspace edge e? Crossing segments are at distance
// 0 (exact orientations); otherwise the distance is the least of the four endpoint-to-
// segment distances, filtered in double, decided in exact (rational) arithmetic when the
// filter cannot tell.
bool clear_of(const Environment& env, std::uint32_t e, const Point& p, const Point& q, double r, double slack) {
  const Point &a = env.vertex(e), &b = env.vertex(env.next(e));
  if (CGAL::do_intersect(Kernel::Segment_2(p, q), Kernel::Segment_2(a, b))) return false;
  const double d = std::min({point_segment(p, a, b), point_segment(q, a, b), point_segment(a, p, q), point_segment(b, p, q)});
  if (d >= r + slack) return true;
  if (d + slack < r) return false;
  const ExactFT exact = CGAL::squared_distance(ExactSegment(to_exact(p), to_exact(q)), ExactSegment(env.exact_vertex(e), env.exact_vertex(env.next(e))));
  return exact >= ExactFT(r) * ExactFT(r);
}

}  // namespace

ConfigurationSpace::~ConfigurationSpace() = default;
ConfigurationSpace::ConfigurationSpace(ConfigurationSpace&&) noexcept = default;
ConfigurationSpace& ConfigurationSpace::operator=(ConfigurationSpace&&) noexcept = default;

ConfigurationSpace::ConfigurationSpace(const Environment& workspace, double radius)
    : workspace_(&workspace), radius_(radius), grid_(std::make_unique<EdgeGrid>(workspace)) {
  if (!(radius >= 0) || !std::isfinite(radius)) throw InputError("robot radius must be a finite number >= 0");
  if (radius == 0) {
    components_.push_back(workspace);
    return;
  }
  // Integer grid for Clipper: a power of two, so scaling and unscaling are exact, with
  // every coordinate below 2^51 in magnitude.
  double M = radius;
  for (const Point& v : workspace.vertices()) M = std::max({M, std::fabs(v.x()), std::fabs(v.y())});
  int exp2 = 0;
  std::frexp(M * 4, &exp2);
  const double scale = std::ldexp(1.0, 51 - exp2), unit = 1 / scale;
  ClipperLib::Paths rings;
  for (std::size_t r = 0; r < workspace.num_rings(); ++r) {
    ClipperLib::Path path;
    for (std::size_t v = workspace.ring_begin(r); v < workspace.ring_end(r); ++v)
      path.emplace_back(std::llround(workspace.vertex(v).x() * scale), std::llround(workspace.vertex(v).y() * scale));
    rings.push_back(std::move(path));
  }
  // Arc chords lie inside the offset circle by at most the arc tolerance; grid rounding
  // moves input and output by at most a unit each way.
  const double arc = std::max(radius * 1e-3, 8 * unit);
  for (double margin = arc + 4 * unit; margin < radius; margin *= 4) {
    const double delta = radius + margin;
    ClipperLib::ClipperOffset offset(2.0, arc * scale);
    offset.AddPaths(rings, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    ClipperLib::Paths eroded;
    offset.Execute(eroded, -delta * scale);
    // A union that splits the result where it touches itself (pinch points stay apart).
    ClipperLib::Clipper clean;
    clean.StrictlySimple(true);
    clean.AddPaths(eroded, ClipperLib::ptSubject, true);
    ClipperLib::PolyTree tree;
    clean.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);

    std::vector<Environment> comps;
    bool ok = true;
    auto to_ring = [&](const ClipperLib::Path& path) {
      Ring ring;
      for (const auto& ip : path) ring.emplace_back(static_cast<double>(ip.X) * unit, static_cast<double>(ip.Y) * unit);
      return ring;
    };
    std::vector<const ClipperLib::PolyNode*> outers;
    for (const ClipperLib::PolyNode* node : tree.Childs) outers.push_back(node);
    for (std::size_t i = 0; i < outers.size() && ok; ++i) {
      const ClipperLib::PolyNode* node = outers[i];
      if (node->Contour.size() < 3) continue;
      std::vector<Ring> holes;
      for (const ClipperLib::PolyNode* h : node->Childs) {
        if (h->Contour.size() >= 3) holes.push_back(to_ring(h->Contour));
        for (const ClipperLib::PolyNode* island : h->Childs) outers.push_back(island);
      }
      try {
        comps.push_back(Environment::make(to_ring(node->Contour), std::move(holes), "configuration space", "configuration space hole"));
      } catch (const InputError&) {
        ok = false;  // touching rings after rounding: erode a little more
      }
    }
    if (!ok) continue;
    // Certify each component inside the exact eroded set: (1) every edge at distance >= r
    // from every obstacle edge, (2) every ring in free space (one vertex each: a ring that
    // keeps r away cannot cross the boundary), (3) no obstacle ring inside a component.
    const double slack = 1e-9 * (M + radius);
    for (const Environment& c : comps) {
      for (std::size_t e = 0; e < c.num_vertices() && ok; ++e) {
        const Point &p = c.vertex(e), &q = c.vertex(c.next(e));
        grid_->near(p, q, radius + slack, [&](std::uint32_t w) { ok = ok && clear_of(workspace, w, p, q, radius, slack); });
      }
      for (std::size_t r = 0; r < c.num_rings() && ok; ++r) ok = locate(workspace, c.vertex(c.ring_begin(r))).in_free_space();
      for (std::size_t r = 0; r < workspace.num_rings() && ok; ++r) ok = !locate(c, workspace.vertex(workspace.ring_begin(r))).in_free_space();
      if (!ok) break;
    }
    if (!ok) continue;
    std::sort(comps.begin(), comps.end(), [](const Environment& a, const Environment& b) { return a.area() > b.area(); });
    components_ = std::move(comps);
    error_ = margin + 2 * unit;
    return;
  }
  throw std::logic_error("configuration space: the eroded polygons could not be certified inside the exact eroded set");
}

std::optional<std::size_t> ConfigurationSpace::component_of(const Point& p) const {
  for (std::size_t i = 0; i < components_.size(); ++i)
    if (locate(components_[i], p).in_free_space()) return i;
  return std::nullopt;
}

std::optional<ConfigurationSpace::Entry> ConfigurationSpace::entry(const Point& p) const {
  if (!admits(p)) return std::nullopt;
  if (auto c = component_of(p)) return Entry{*c, p};
  std::optional<Entry> best;
  double best_d = INFINITY;
  for (std::size_t k = 0; k < components_.size(); ++k) {
    const Environment& C = components_[k];
    for (std::size_t e = 0; e < C.num_vertices(); ++e) {
      const Kernel::Segment_2 s(C.vertex(e), C.vertex(C.next(e)));
      const double d = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, s)));
      if (d >= best_d) continue;
      // The nearest point of the edge, rounded; the ends of the edge as fallbacks.
      const Point foot = s.supporting_line().projection(p);
      for (const Point& q : {foot, s.source(), s.target()})
        if (locate(C, q).in_free_space() && admits(p, q)) {
          best_d = d, best = Entry{k, q};
          break;
        }
    }
  }
  return best;
}

bool ConfigurationSpace::admits(const Point& p) const { return admits(p, p); }

bool ConfigurationSpace::admits(const Point& p, const Point& q) const {
  if (!locate(*workspace_, p).in_free_space()) return false;
  if (radius_ == 0) return visible(*workspace_, p, q);
  const double slack = 1e-9 * (std::max({std::fabs(p.x()), std::fabs(p.y()), std::fabs(q.x()), std::fabs(q.y())}) + radius_);
  bool ok = true;
  grid_->near(p, q, radius_ + slack, [&](std::uint32_t e) { ok = ok && clear_of(*workspace_, e, p, q, radius_, slack); });
  return ok;
}

double ConfigurationSpace::clearance(const Point& p) const {
  double best = INFINITY;
  for (std::size_t e = 0; e < workspace_->num_vertices(); ++e)
    best = std::min(best, std::sqrt(CGAL::to_double(CGAL::squared_distance(
                              p, Kernel::Segment_2(workspace_->vertex(e), workspace_->vertex(workspace_->next(e)))))));
  return best;
}

}  // namespace preimage::geometry
