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

std::string piece_name(const BeamArrangement& A, std::uint32_t h) {
  const auto p = A.piece(h);
  // Even half-edges run from -> to with the region entered on their left: the positive
  // crossing (right to left), which tells the two crossings of an undirected piece apart.
  return "beam " + std::to_string(p.beam) + " piece " + std::to_string(p.index) + (h % 2 == 0 ? ", right to left" : ", left to right");
}

namespace {
// Runs of edges with the same (from, symbol, to): [begin, end) index pairs.
std::vector<std::pair<std::size_t, std::size_t>> parallel_runs(const std::vector<Crossing>& E) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t i = 0; i < E.size(); ++i)
    if (i == 0 || E[i].from != E[i - 1].from || E[i].symbol != E[i - 1].symbol || E[i].to != E[i - 1].to)
      runs.push_back({i, i + 1});
    else
      runs.back().second = i + 1;
  return runs;
}

json piece_json(const BeamArrangement& A, std::uint32_t h) {
  const auto p = A.piece(h);
  return {{"beam", p.beam}, {"piece", p.index}, {"positive", h % 2 == 0}};
}
}  // namespace

json graph_json(const BeamArrangement& A, bool merged) {
  json j;
  j["regions"] = json::array();
  for (std::uint32_t r = 0; r < A.num_regions(); ++r)
    j["regions"].push_back({{"id", r}, {"sample", pt(A.regions()[r].sample)}, {"holes", A.regions()[r].cycles.size() - 1}});
  j["beams"] = json::array();
  for (std::uint32_t i = 0; i < A.beams().size(); ++i) {
    const auto& b = A.beams()[i];
    const auto [first, last] = A.beam_pieces(i);
    j["beams"].push_back({{"index", i}, {"label", A.alphabet().name(b.label)}, {"directed", b.directed},
                          {"from", pt(b.from)}, {"to", pt(b.to)}, {"pieces", (last - first) / 2}});
  }
  const auto& E = A.edges();
  const auto runs = parallel_runs(E);
  j["merged"] = merged;
  j["edges"] = json::array();
  if (merged) {
    for (auto [b, e] : runs) {
      json pieces = json::array();
      for (std::size_t i = b; i < e; ++i) pieces.push_back(piece_json(A, E[i].half_edge));
      j["edges"].push_back({{"from", E[b].from}, {"to", E[b].to}, {"observation", A.alphabet().format(E[b].symbol)},
                            {"pieces", pieces}});
    }
  } else {
    for (const auto& e : E) {
      json x = {{"from", e.from}, {"to", e.to}, {"observation", A.alphabet().format(e.symbol)}};
      x.update(piece_json(A, e.half_edge));
      j["edges"].push_back(x);
    }
  }
  j["counts"] = {{"regions", A.num_regions()}, {"beams", A.beams().size()}, {"labels", A.alphabet().num_labels()},
                 {"beam_crossings", A.num_crossings()}, {"beam_pieces", A.num_pieces()}, {"edges", E.size()},
                 {"merged_edges", runs.size()}};
  return j;
}

std::string graph_dot(const BeamArrangement& A, bool merged) {
  auto quote = [](const std::string& l) {
    std::string esc;
    for (char c : l) esc += c == '"' ? std::string("\\\"") : std::string(1, c);
    return "\"" + esc + "\"";
  };
  std::string out = "digraph G {\n  rankdir=LR;\n  node [shape=circle];\n";
  for (std::uint32_t r = 0; r < A.num_regions(); ++r) out += "  r" + std::to_string(r) + ";\n";
  auto arrow = [&](std::uint32_t from, std::uint32_t to, const std::string& label) {
    out += "  r" + std::to_string(from) + " -> r" + std::to_string(to) + " [label=" + quote(label) + "];\n";
  };
  if (merged) {
    // Fig. 7(b): one arrow per region pair, labelled with the observations it carries.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::string>> pairs;
    for (auto [b, e] : parallel_runs(A.edges())) {
      const Crossing& c = A.edges()[b];
      pairs[{c.from, c.to}].push_back(A.alphabet().format(c.symbol));
    }
    for (auto& [k, labels] : pairs) {
      std::string l;
      for (auto& s : labels) l += (l.empty() ? "" : ", ") + s;
      arrow(k.first, k.second, l);
    }
  } else {
    for (const auto& e : A.edges()) arrow(e.from, e.to, A.alphabet().format(e.symbol) + " (" + piece_name(A, e.half_edge) + ")");
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
    c.path(o.path, ps, o.path_label, 60, 4);
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
