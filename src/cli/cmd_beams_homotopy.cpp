// SPDX-License-Identifier: Apache-2.0
// preimage beams homotopy | winding (beams paper, sections 5 and 6)
#include "common.hpp"

#include <preimage/beams/export.hpp>
#include <preimage/beams/homotopy.hpp>
#include <preimage/beams/paths.hpp>
#include <preimage/error.hpp>
#include <preimage/filter/trellis.hpp>

#include <iostream>

namespace preimage::cli {
namespace {

using nlohmann::json;
using beams::BeamArrangement;
using beams::LoopBasis;

struct ClassArgs {
  std::string file, word, basis, start, end, svg;
  std::size_t limit = 20, max_states = std::size_t(1) << 22;
  bool open = false, as_json = false;
};

json basis_json(const BeamArrangement& A, const LoopBasis& L) {
  json gens = json::array();
  auto side = [&](std::uint32_t o) { return o == beams::kOuter ? json("outer") : json(o + 1); };
  for (std::uint32_t g = 0; g < L.rank(); ++g) {
    json e = json::array();
    for (auto o : L.encloses(g)) e.push_back(o + 1);
    gens.push_back({{"name", L.names()[g]}, {"from", point_json(L.from(g))}, {"to", point_json(L.to(g))}, {"ray", L.ray(g)},
                    {"child", side(L.child(g))}, {"parent", side(L.parent(g))}, {"sign", L.sign(g)}, {"encloses", e}});
  }
  json obstacles = json::array();
  for (std::uint32_t o = 0; o < A.num_obstacles(); ++o) obstacles.push_back(A.obstacle_name(o));
  const char* kind = L.kind() == LoopBasis::Kind::Tree ? "tree" : L.kind() == LoopBasis::Kind::User ? "user" : "imaginary";
  json j = {{"kind", kind}, {"obstacles", obstacles}, {"generators", gens}};
  if (L.kind() == LoopBasis::Kind::Tree) {
    json dropped = json::array();
    for (auto b : L.dropped()) dropped.push_back(A.alphabet().name(A.beams()[b].label));
    j["perfect"] = L.perfect();
    j["dropped"] = dropped;
  }
  return j;
}

void print_basis(const BeamArrangement& A, const LoopBasis& L) {
  if (L.kind() == LoopBasis::Kind::Tree) {
    std::cout << "basis: " << (L.perfect() ? "perfect beams (5.1)" : "a spanning tree of the scene's beams (5.2)");
    if (!L.dropped().empty()) {
      std::cout << "; letters of dropped beams deleted:";
      for (auto b : L.dropped()) std::cout << " " << A.alphabet().name(A.beams()[b].label);
    }
    std::cout << "\n";
  } else {
    std::cout << "basis: " << (L.kind() == LoopBasis::Kind::User ? "the scene's imaginary beams" : "one vertical imaginary beam per obstacle")
              << " (5.3)\n";
  }
  for (auto& line : L.describe(A)) std::cout << "  " << line << "\n";
}

LoopBasis make_basis(const BeamArrangement& A, const scene::Scene& s, const std::string& basis, bool for_winding) {
  if (basis == "tree") return LoopBasis::tree(A, s, for_winding);
  if (basis == "imaginary") return s.imaginary_beams.empty() ? LoopBasis::imaginary(A, s) : LoopBasis::user(A, s);
  throw InputError("--basis: expected imaginary or tree, got '" + basis + "'");
}

beams::PathEnds make_ends(const ClassArgs& a) {
  beams::PathEnds ends;
  if (!a.start.empty()) {
    if (a.open) throw InputError("--open: not with --start (a fixed start closes the path)");
    ends.mode = beams::PathEnds::Mode::Fixed;
    ends.start = geometry::to_exact(parse_point(a.start, "--start"));
    if (!a.end.empty()) ends.end = geometry::to_exact(parse_point(a.end, "--end"));
  } else if (!a.end.empty()) {
    throw InputError("--end: needs --start");
  } else if (a.open) {
    ends.mode = beams::PathEnds::Mode::Open;
  }
  return ends;
}

const char* ends_text(const beams::PathEnds& e) {
  switch (e.mode) {
    case beams::PathEnds::Mode::Closed: return "closed (a loop, based at the sample point of its start region)";
    case beams::PathEnds::Mode::Open: return "open (closed by a fixed return path from the end region's sample point to the start's)";
    case beams::PathEnds::Mode::Fixed: return "from --start to --end, closed by a fixed return path";
  }
  return "";
}
const char* ends_name(const beams::PathEnds& e) {
  return e.mode == beams::PathEnds::Mode::Closed ? "closed" : e.mode == beams::PathEnds::Mode::Open ? "open" : "fixed";
}

std::string where_text(std::uint32_t s, std::uint32_t r) {
  std::string t;
  if (s != beams::kNone) t.append("r").append(std::to_string(s));
  if (r != beams::kNone) t += " -> r" + std::to_string(r);
  return t.empty() ? t : t + ": ";
}

// Tree basis: the word by renaming (Props. 5.1, 5.3), closed by the return path.
void run_tree(const BeamArrangement& A, const LoopBasis& L, const ClassArgs& a, const beams::PathEnds& ends,
              const std::vector<beams::Symbol>& word, bool winding_only) {
  if (ends.mode == beams::PathEnds::Mode::Open) throw InputError("--open: needs --basis imaginary");
  beams::BasisWordFilter F(L);
  for (auto y : word) F.step(y);
  beams::FreeWord w = F.word();
  if (ends.mode == beams::PathEnds::Mode::Fixed && ends.end && !(*ends.end == *ends.start))
    w *= L.crossing_word(beams::free_path(A, *ends.end, *ends.start));
  // Whether some path explains the word at all: the region filter (section 4).
  std::vector<std::uint32_t> R0;
  if (ends.mode == beams::PathEnds::Mode::Fixed) {
    auto r = A.locate(*ends.start);
    if (!r) throw InputError("--start: not strictly inside a region");
    R0.push_back(*r);
  }
  const filter::Trellis T(A.graph(), R0, word);
  const auto v = L.winding(w);
  if (a.as_json) {
    // The schema of the general case, with its one class.
    json c = {{"winding", v}};
    if (!winding_only) c["word"] = w.format(L.names()), c["length"] = w.length();
    json j = {{"basis", basis_json(A, L)}, {"ends", ends_name(ends)}, {"consistent", T.consistent()}, {"count", 1},
              {"listed", 1}, {"truncated", false}, {winding_only ? "windings" : "classes", json::array({c})}};
    if (!a.svg.empty()) beams::basis_figure(A, L).save(a.svg);
    return print_json(j);
  }
  print_basis(A, L);
  if (!a.svg.empty()) {
    beams::basis_figure(A, L).save(a.svg);
    std::cout << "wrote " << a.svg << "\n";
  }
  if (!T.consistent()) std::cout << "note: no path explains the word (inconsistent at observation " << T.inconsistent_at() << ")\n";
  if (!winding_only) std::cout << "homotopy class: " << w.format(L.names()) << "\n";
  std::cout << "winding numbers: " << tuple_string(v) << "\n";
}

void run_classes(const ClassArgs& a, bool winding_only) {
  const scene::Scene s = scene::load_scene(a.file);
  const BeamArrangement A = BeamArrangement::build(s);
  const std::vector<beams::Symbol> word = A.alphabet().parse_word(a.word);
  const beams::PathEnds ends = make_ends(a);
  std::string basis = a.basis;
  if (basis.empty()) {
    // Winding numbers need only directed, distinguishable beams reaching every obstacle (6.3).
    basis = "imaginary";
    if (winding_only && s.imaginary_beams.empty()) {
      try {
        (void)LoopBasis::tree(A, s, true);
        basis = "tree";
      } catch (const InputError&) {
        // Some obstacle is not reached by such beams: the general method.
      }
    }
  }
  if (basis == "tree") return run_tree(A, make_basis(A, s, basis, winding_only), a, ends, word, winding_only);

  beams::require_sufficient(A);
  const LoopBasis L = make_basis(A, s, basis, winding_only);
  const beams::GraphEmbedding G(A, L);
  json classes = json::array();
  std::vector<std::string> lines;
  std::size_t count = 0;
  std::string sequences;
  bool consistent = true;
  std::size_t inconsistent_at = 0, peak = 0;
  if (winding_only) {
    const beams::WindingSet W(G, ends, word, a.max_states);
    consistent = W.consistent(), inconsistent_at = W.inconsistent_at(), sequences = W.sequences(), peak = W.peak_states();
    count = W.classes().size();
    for (std::size_t i = 0; i < count && i < a.limit; ++i) {
      const auto& c = W.classes()[i];
      const auto ex = W.store().vector(c.element);
      const auto v = L.winding(ex);
      json e = {{"winding", v}};
      if (c.start_region != beams::kNone) e["start_region"] = c.start_region;
      if (c.end_region != beams::kNone) e["end_region"] = c.end_region;
      classes.push_back(e);
      lines.push_back(where_text(c.start_region, c.end_region) + tuple_string(v));
    }
  } else {
    const beams::HomotopySet H(G, ends, word, a.max_states);
    consistent = H.consistent(), inconsistent_at = H.inconsistent_at(), sequences = H.sequences(), peak = H.peak_states();
    count = H.classes().size();
    for (std::size_t i = 0; i < count && i < a.limit; ++i) {
      const auto& c = H.classes()[i];
      const beams::FreeWord w = H.store().word(c.element);
      const auto v = L.winding(w);
      json e = {{"word", w.format(L.names())}, {"length", w.length()}, {"winding", v}};
      if (c.start_region != beams::kNone) e["start_region"] = c.start_region;
      if (c.end_region != beams::kNone) e["end_region"] = c.end_region;
      classes.push_back(e);
      lines.push_back(where_text(c.start_region, c.end_region) + w.format(L.names()) + "   winding " + tuple_string(v));
    }
  }
  const bool truncated = count > a.limit;
  if (a.as_json) {
    json j = {{"basis", basis_json(A, L)}, {"ends", ends_name(ends)}, {"consistent", consistent}, {"sequences", sequences},
              {"count", count}, {"listed", classes.size()}, {"truncated", truncated}, {"peak_states", peak},
              {winding_only ? "windings" : "classes", classes}};
    if (!consistent) j["inconsistent_at"] = inconsistent_at;
    if (!a.svg.empty()) beams::basis_figure(A, L).save(a.svg);
    return print_json(j);
  }
  print_basis(A, L);
  std::cout << "paths: " << ends_text(ends) << "\n";
  if (!consistent) {
    std::cout << "no path explains the word: inconsistent at observation " << inconsistent_at << "\n";
  } else {
    std::cout << "region sequences: " << sequences << "; " << (winding_only ? "winding vectors: " : "homotopy classes: ") << count
              << "\n";
    for (auto& l : lines) std::cout << "  " << l << "\n";
    if (truncated) std::cout << "(listed " << a.limit << " of " << count << "; raise --limit)\n";
    if (count == 0 && ends.mode == beams::PathEnds::Mode::Closed)
      std::cout << "no region sequence returns to its start region: not a loop (try --open, or --start and --end)\n";
  }
  if (!a.svg.empty()) {
    beams::basis_figure(A, L).save(a.svg);
    std::cout << "wrote " << a.svg << "\n";
  }
}

void add_class_options(CLI::App* c, ClassArgs& a) {
  c->add_option("scene", a.file, "scene file (JSON)")->required();
  c->add_option("--word", a.word, "sensor word: \"a b' c\" or the one-character stream \"ab'c\"")->required();
  c->add_option("--start", a.start, "the path starts at X,Y (the basepoint of a loop)");
  c->add_option("--end", a.end, "with --start: the path ends at X,Y (default: back at --start)");
  c->add_flag("--open", a.open, "start and end anywhere: one group per (start, end) region pair");
  c->add_option("--limit", a.limit, "list at most this many (default 20)");
  c->add_option("--max-states", a.max_states, "give up beyond this many (start, region, class) states (default 4194304)");
  c->add_flag("--json", a.as_json, "JSON output");
  c->add_option("--svg", a.svg, "draw the regions, the basis beams and their loops (Fig. 16)");
}

}  // namespace

void add_beams_homotopy_commands(CLI::App* beams_cmd) {
  auto* h = beams_cmd->add_subcommand("homotopy", "the possible paths up to homotopy, as reduced words of F_n (paper section 5)");
  static ClassArgs ha;
  add_class_options(h, ha);
  h->add_option("--basis", ha.basis,
                "imaginary (default: the scene's imaginary_beams, else one vertical beam per obstacle; any sufficient beams) "
                "or tree (the scene's own disjoint, distinguishable, directed beams)");
  h->callback([] { run_classes(ha, false); });

  auto* w = beams_cmd->add_subcommand("winding", "the possible winding numbers about each obstacle (paper section 6)");
  static ClassArgs wa;
  add_class_options(w, wa);
  w->add_option("--basis", wa.basis,
                "tree (counters over directed, distinguishable beams; the default when they reach every obstacle) or imaginary");
  w->callback([] { run_classes(wa, true); });
}

}  // namespace preimage::cli
