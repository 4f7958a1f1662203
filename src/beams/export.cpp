// SPDX-License-Identifier: Apache-2.0
#include <preimage/beams/export.hpp>

#include <cmath>
#include <map>
#include <set>

namespace preimage::beams {

using nlohmann::json;
using geometry::to_double;

namespace {
json pt(const ExactPoint& p) {
  const auto q = to_double(p);
  return json::array({q.x(), q.y()});
}
}  // namespace

json graph_json(const BeamArrangement& A) {
  json j;
  j["regions"] = json::array();
  for (std::uint32_t r = 0; r < A.num_regions(); ++r)
    j["regions"].push_back({{"id", r}, {"sample", pt(A.regions()[r].sample)}, {"holes", A.regions()[r].cycles.size() - 1}});
  j["beams"] = json::array();
  for (std::size_t i = 0; i < A.beams().size(); ++i) {
    const auto& b = A.beams()[i];
    j["beams"].push_back({{"index", i}, {"label", A.alphabet().name(b.label)}, {"directed", b.directed},
                          {"from", pt(b.from)}, {"to", pt(b.to)}});
  }
  j["edges"] = json::array();
  for (const auto& e : A.edges())
    j["edges"].push_back({{"from", e.from}, {"to", e.to}, {"observation", A.alphabet().format(e.symbol)},
                          {"beam", A.half_edges()[e.half_edge].beam}});
  j["counts"] = {{"regions", A.num_regions()}, {"beams", A.beams().size()}, {"labels", A.alphabet().num_labels()},
                 {"beam_crossings", A.num_crossings()}, {"edges", A.edges().size()}};
  return j;
}

std::string graph_dot(const BeamArrangement& A) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::string>> merged;
  for (const auto& e : A.edges()) merged[{e.from, e.to}].push_back(A.alphabet().format(e.symbol));
  std::string out = "digraph G {\n  rankdir=LR;\n  node [shape=circle];\n";
  for (std::uint32_t r = 0; r < A.num_regions(); ++r) out += "  r" + std::to_string(r) + ";\n";
  for (auto& [k, labels] : merged) {
    std::string l;
    for (auto& s : labels) l += (l.empty() ? "" : ", ") + s;
    std::string esc;
    for (char c : l) esc += c == '"' ? std::string("\\\"") : std::string(1, c);
    out += "  r" + std::to_string(k.first) + " -> r" + std::to_string(k.second) + " [label=\"" + esc + "\"];\n";
  }
  return out + "}\n";
}

std::vector<std::vector<geometry::Point>> region_rings(const BeamArrangement& A, std::uint32_t r) {
  std::vector<std::vector<geometry::Point>> out;
  const auto& H = A.half_edges();
  for (std::uint32_t h0 : A.regions()[r].cycles) {
    std::vector<geometry::Point> ring;
    std::uint32_t h = h0;
    do {
      ring.push_back(to_double(A.vertices()[H[h].origin]));
      h = H[h].next;
    } while (h != h0);
    out.push_back(std::move(ring));
  }
  return out;
}

render::SvgCanvas arrangement_figure(const BeamArrangement& A, const FigureOptions& o) {
  CGAL::Bbox_2 box = A.environment().bbox();
  render::SvgCanvas c(box);
  c.environment(A.environment());
  static const char* palette[] = {"#8dd3c7", "#ffffb3", "#bebada", "#fb8072", "#80b1d3", "#fdb462", "#b3de69", "#fccde5"};
  std::set<std::uint32_t> hl(o.highlight.begin(), o.highlight.end());
  for (std::uint32_t r = 0; r < A.num_regions(); ++r) {
    const bool strong = hl.count(r) > 0;
    render::Style s{strong ? "#f4b400" : palette[r % 8], "none", 0, strong ? 0.75 : 0.35, ""};
    c.rings(region_rings(A, r), s, "region " + std::to_string(r));
  }
  if (!hl.empty()) c.legend("possible regions", render::Style{"#f4b400", "none", 0, 0.75, ""});
  const render::Style beam{"none", "#c0392b", 2.0, 1.0, ""}, undirected{"none", "#c0392b", 2.0, 1.0, "6 3"};
  bool any_dir = false, any_undir = false;
  for (const auto& b : A.beams()) {
    const auto p = to_double(b.from), q = to_double(b.to);
    c.segment(p, q, b.directed ? beam : undirected, "beam " + A.alphabet().name(b.label));
    (b.directed ? any_dir : any_undir) = true;
    const double dx = q.x() - p.x(), dy = q.y() - p.y(), len = std::hypot(dx, dy);
    const geometry::Point m((p.x() + q.x()) / 2, (p.y() + q.y()) / 2);
    const double px = 12 / c.scale();  // label offset, pixels to world
    if (b.directed) {
      // A tick pointing to the positive side (the left of from->to).
      const geometry::Point tip(m.x() - dy / len * px, m.y() + dx / len * px);
      c.segment(m, tip, beam);
    }
    c.label(geometry::Point(m.x() + dy / len * px, m.y() - dx / len * px), A.alphabet().name(b.label), 13, "#c0392b");
  }
  if (any_dir) c.legend("directed beam (tick: positive side)", beam);
  if (any_undir) c.legend("undirected beam", undirected);
  for (const auto& l : A.landmarks()) c.point(l, 4, render::Style{"#222", "none", 0, 1, ""});
  if (o.region_ids)
    for (std::uint32_t r = 0; r < A.num_regions(); ++r) c.label(to_double(A.regions()[r].sample), std::string("r").append(std::to_string(r)), 11, "#555");
  if (!o.path.empty()) {
    const render::Style ps{"none", "#1a5fb4", 2.0, 0.9, ""};
    c.polyline(o.path, ps);
    c.point(o.path.front(), 4, render::Style{"#1a5fb4", "none", 0, 1, ""});
    c.legend(o.path_label, ps);
  }
  return c;
}

render::SvgCanvas basis_figure(const BeamArrangement& A, const LoopBasis& L, const FigureOptions& o, bool loops) {
  render::SvgCanvas c = arrangement_figure(A, o);
  const CGAL::Bbox_2 box = A.environment().bbox();
  const render::Style beam{"none", "#2e7d32", 2.0, 0.9, "4 3"}, loop{"none", "#2e7d32", 1.2, 0.6, ""};
  if (loops && L.kind() != LoopBasis::Kind::Tree)
    for (auto& l : L.loops()) {
      std::vector<geometry::Point> pts;
      for (auto& p : l) pts.push_back(to_double(p));
      c.polyline(pts, loop);
    }
  for (std::uint32_t g = 0; g < L.rank(); ++g) {
    const geometry::Point p = to_double(L.from(g));
    geometry::Point q = to_double(L.to(g));
    if (L.ray(g)) {
      // An unbounded ray: to the edge of the drawing.
      const double dx = q.x() - p.x(), dy = q.y() - p.y();
      double t = 1e300;
      if (dx > 0) t = std::min(t, (box.xmax() - p.x()) / dx);
      if (dx < 0) t = std::min(t, (box.xmin() - p.x()) / dx);
      if (dy > 0) t = std::min(t, (box.ymax() - p.y()) / dy);
      if (dy < 0) t = std::min(t, (box.ymin() - p.y()) / dy);
      q = geometry::Point(p.x() + t * dx, p.y() + t * dy);
    }
    c.segment(p, q, beam, "basis beam " + L.names()[g]);
    const double px = 10 / c.scale();
    c.label(geometry::Point((p.x() + q.x()) / 2 + px, (p.y() + q.y()) / 2), L.names()[g], 12, "#2e7d32");
  }
  c.legend(L.kind() == LoopBasis::Kind::Tree ? "basis: tree beams" : "basis: imaginary beams", beam);
  if (loops && L.kind() != LoopBasis::Kind::Tree) c.legend("basis loops (Fig. 16)", loop);
  return c;
}

}  // namespace preimage::beams
