// SPDX-License-Identifier: Apache-2.0
#include <preimage/geometry/hole_union.hpp>

#include <preimage/error.hpp>

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>

namespace preimage::geometry {

MergedHoles merge_overlapping_holes(const std::vector<Ring>& holes) {
  MergedHoles out;
  out.input = holes.size();
  if (holes.empty()) return out;
  double M = 1;
  for (const Ring& r : holes)
    for (const Point& p : r) M = std::max({M, std::fabs(p.x()), std::fabs(p.y())});
  int exp2 = 0;
  std::frexp(M * 4, &exp2);
  const double scale = std::ldexp(1.0, 51 - exp2);
  out.grid = 1 / scale;
  ClipperLib::Paths paths;
  for (const Ring& r : holes) {
    ClipperLib::Path path;
    for (const Point& p : r) path.emplace_back(std::llround(p.x() * scale), std::llround(p.y() * scale));
    paths.push_back(std::move(path));
  }
  ClipperLib::Clipper clipper;
  clipper.StrictlySimple(true);
  clipper.AddPaths(paths, ClipperLib::ptSubject, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  for (const ClipperLib::PolyNode* node : tree.Childs) {
    if (!node->Childs.empty()) {
      const auto& ip = node->Childs[0]->Contour[0];
      throw InputError("the merged obstacles enclose free space (a hole inside an obstacle) at " +
                       format_point(static_cast<double>(ip.X) * out.grid, static_cast<double>(ip.Y) * out.grid) +
                       ": open the enclosure or remove it");
    }
    if (node->Contour.size() < 3) continue;
    Ring ring;
    for (const auto& ip : node->Contour) ring.emplace_back(static_cast<double>(ip.X) * out.grid, static_cast<double>(ip.Y) * out.grid);
    out.holes.push_back(std::move(ring));
  }
  return out;
}

}  // namespace preimage::geometry
