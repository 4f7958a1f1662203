// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/configuration_space.hpp>

#include <preimage/error.hpp>
#include <preimage/geometry/local_frame.hpp>
#include <preimage/geometry/queries.hpp>

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace preimage::geometry {

ConfigurationSpace::~ConfigurationSpace() = default;
ConfigurationSpace::ConfigurationSpace(ConfigurationSpace&&) noexcept = default;
ConfigurationSpace& ConfigurationSpace::operator=(ConfigurationSpace&&) noexcept = default;

ConfigurationSpace::ConfigurationSpace(const Environment& workspace, double radius)
    : workspace_(&workspace), radius_(radius), clearance_(workspace, radius) {
  if (radius == 0) {
    components_.push_back(workspace);
    return;
  }
  // Clipper works in the local frame (a plan far from the origin keeps its digits); its
  // rings come back rounded by at most frame.margin(), which a second try adds to the
  // erosion when the rounded rings fail their certificate.
  const LocalFrame frame = LocalFrame::of(workspace);
  // Integer grid for Clipper: a power of two, so scaling and unscaling are exact, with
  // every coordinate below 2^51 in magnitude.
  double M = radius;
  for (const Point& v : workspace.vertices()) M = std::max({M, std::fabs(v.x() - frame.dx()), std::fabs(v.y() - frame.dy())});
  int exp2 = 0;
  std::frexp(M * 4, &exp2);
  const double scale = std::ldexp(1.0, 51 - exp2), unit = 1 / scale;
  ClipperLib::Paths rings;
  for (std::size_t r = 0; r < workspace.num_rings(); ++r) {
    ClipperLib::Path path;
    for (std::size_t v = workspace.ring_begin(r); v < workspace.ring_end(r); ++v)
      path.emplace_back(std::llround((workspace.vertex(v).x() - frame.dx()) * scale), std::llround((workspace.vertex(v).y() - frame.dy()) * scale));
    rings.push_back(std::move(path));
  }
  // Arc chords lie inside the offset circle by at most the arc tolerance; grid rounding
  // moves input and output by at most a unit each way.
  const double arc = std::max(radius * 1e-3, 8 * unit);
  const double first = arc + 4 * unit;
  if (first + frame.margin() >= radius)
    throw InputError("robot radius " + format_number(radius) + " is below what coordinates of this size resolve: at least " +
                     format_number(4 * (first + frame.margin())) + " here");
  // The first try leaves frame.margin() out (the rings rounded back are certified all the
  // same), so a plan far from the origin gets the polygons it gets at the origin, moved.
  for (double margin = first; margin < radius; margin = !frame.identity() && margin == first ? first + frame.margin() : margin * 4) {
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
      for (const auto& ip : path) ring.push_back(frame.to_input(Point(static_cast<double>(ip.X) * unit, static_cast<double>(ip.Y) * unit)));
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
    for (const Environment& c : comps) {
      for (std::size_t e = 0; e < c.num_vertices() && ok; ++e) {
        const Point &p = c.vertex(e), &q = c.vertex(c.next(e));
        ok = clearance_.clear(p, q, radius);
      }
      for (std::size_t r = 0; r < c.num_rings() && ok; ++r) ok = locate(workspace, c.vertex(c.ring_begin(r))).in_free_space();
      for (std::size_t r = 0; r < workspace.num_rings() && ok; ++r) ok = !locate(c, workspace.vertex(workspace.ring_begin(r))).in_free_space();
      if (!ok) break;
    }
    if (!ok) continue;
    std::sort(comps.begin(), comps.end(), [](const Environment& a, const Environment& b) { return a.area() > b.area(); });
    components_ = std::move(comps);
    error_ = margin + 2 * unit + (frame.identity() ? 0 : frame.margin());
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

}  // namespace preimage::geometry
