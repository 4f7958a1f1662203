// SPDX-License-Identifier: Apache-2.0
// preimage beams homotopy | winding (beams paper, sections 5 and 6)
#include "common.hpp"

#include <preimage/beams/export.hpp>
#include <preimage/beams/homotopy.hpp>
#include <preimage/beams/paths.hpp>
#include <preimage/error.hpp>
#include <preimage/filter/trellis.hpp>

#include <iostream>
#include <string_view>
#include <vector>

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
  throw std::logic_error("make_basis: unknown basis '" + basis + "'");  // --basis is checked at parse time
}

// --open, --start and --end exclude and need each other at parse time (usage errors).
beams::PathEnds make_ends(const ClassArgs& a) {
  beams::PathEnds ends;
  if (!a.start.empty()) {
    ends.mode = beams::PathEnds::Mode::Fixed;
    ends.start = geometry::to_exact(parse_point(a.start, "--start"));
    if (!a.end.empty()) ends.end = geometry::to_exact(parse_point(a.end, "--end"));
  } else if (a.open) {
    ends.mode = beams::PathEnds::Mode::Open;
  }
  return ends;
}

// No class at all is not an answer but an impossible input: say why, exit 1 (the same
// for text and JSON, and nothing on stdout).
[[noreturn]] void no_class(const BeamArrangement& A, const std::vector<beams::Symbol>& word, std::size_t inconsistent_at,
                           const beams::PathEnds& ends) {
  if (inconsistent_at > 0)
    throw InputError("--word: no path explains the word (inconsistent at observation " + std::to_string(inconsistent_at) +
                     ", token " + A.alphabet().format(word[inconsistent_at - 1]) + ")");
  if (ends.mode == beams::PathEnds::Mode::Fixed)
    throw InputError("--word: no region sequence from the region of --start ends in the region of " +
                     std::string(ends.end ? "--end" : "--start (a loop)"));
  throw InputError(
      "--word: no region sequence returns to its start region, so no loop explains the word (try --open, or --start and --end)");
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
  if (!T.consistent()) no_class(A, word, T.inconsistent_at(), ends);
  const auto v = L.winding(w);
  if (a.as_json) {
    // The schema of the general case, with its one class.
    json c = {{"winding", v}};
    if (!winding_only) c["word"] = w.format(L.names()), c["length"] = w.length();
    const bool listed = a.limit > 0;
    json j = {{"basis", basis_json(A, L)}, {"ends", ends_name(ends)}, {"sequences", T.count().str()},
              {"count", 1}, {"listed", listed ? 1 : 0}, {"truncated", !listed},
              {winding_only ? "windings" : "classes", listed ? json::array({c}) : json::array()}};
    if (!a.svg.empty()) beams::basis_figure(A, L).save(a.svg);
    return print_json(j);
  }
  print_basis(A, L);
  if (!a.svg.empty()) {
    beams::basis_figure(A, L).save(a.svg);
    std::cout << "wrote " << a.svg << "\n";
  }
  if (a.limit == 0) {
    std::cout << "(listed 0 of 1; raise --limit)\n";
    return;
  }
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
    if (winding_only && s.imaginary_beams.empty() && ends.mode != beams::PathEnds::Mode::Open) {
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
  std::size_t inconsistent_at = 0, peak = 0;
  if (winding_only) {
    const beams::WindingSet W(G, ends, word, a.max_states);
    inconsistent_at = W.inconsistent_at(), sequences = W.sequences(), peak = W.peak_states();
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
    inconsistent_at = H.inconsistent_at(), sequences = H.sequences(), peak = H.peak_states();
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
  if (count == 0) no_class(A, word, inconsistent_at, ends);
  const bool truncated = count > a.limit;
  if (a.as_json) {
    json j = {{"basis", basis_json(A, L)}, {"ends", ends_name(ends)}, {"sequences", sequences}, {"count", count},
              {"listed", classes.size()}, {"truncated", truncated}, {"peak_states", peak},
              {winding_only ? "windings" : "classes", classes}};
    if (!a.svg.empty()) beams::basis_figure(A, L).save(a.svg);
    return print_json(j);
  }
  print_basis(A, L);
  std::cout << "paths: " << ends_text(ends) << "\n";
  std::cout << "region sequences: " << sequences << "; " << (winding_only ? "winding vectors: " : "homotopy classes: ") << count
            << "\n";
  for (auto& l : lines) std::cout << "  " << l << "\n";
  if (truncated) std::cout << "(listed " << a.limit << " of " << count << "; raise --limit)\n";
  if (!a.svg.empty()) {
    beams::basis_figure(A, L).save(a.svg);
    std::cout << "wrote " << a.svg << "\n";
  }
}

void add_class_options(CLI::App* c, ClassArgs& a) {
  c->add_option("scene", a.file, "Scene file (JSON)")->required();
  c->add_option("--word", a.word, "Sensor word: \"a b' c\" or the one-character stream \"ab'c\" (\"\": no observation)")->required();
  auto* start = c->add_option("--start", a.start, "The path starts at X,Y (the basepoint of a loop)");
  c->add_option("--end", a.end, "The path ends at X,Y (default: back at --start)")->needs(start);
  c->add_flag("--open", a.open, "Start and end anywhere: one group per (start, end) region pair")->excludes(start);
  add_count(c, "--limit", a.limit, 0, 1000000, "List at most this many");
  // A state takes at least 48 bytes (two state vectors and a hash-set node): 2^27 of them need over 6 GiB.
  add_count(c, "--max-states", a.max_states, 1, std::int64_t(1) << 27, "Give up beyond this many (start, region, class) states");
  add_json_flag(c, a.as_json, "JSON output");
  c->add_option("--svg", a.svg, "Draw the regions, the basis beams and their loops (Fig. 16)");
}

// --basis tree renames the word along the scene's own beams, which gives one class per
// word whatever the ends: --open's grouping by region pair needs the general method.
// --max-states bounds the general method; the tree's renaming keeps no states.
void check_basis(const ClassArgs& a, const CLI::Option* max_states) {
  if (a.basis == "tree" && a.open) throw CLI::ValidationError("--open", "needs --basis imaginary (--basis tree gives one class per word)");
  if (a.basis == "tree" && max_states->count() > 0)
    throw CLI::ValidationError("--max-states", "only with --basis imaginary (--basis tree keeps no states)");
}

}  // namespace

void add_beams_homotopy_commands(CLI::App* beams_cmd) {
  // homotopy and winding share their options and differ in the group the classes live in.
  auto add = [beams_cmd](const char* name, const char* help, ClassArgs& a, const char* basis_help, bool winding_only) {
    auto* c = beams_cmd->add_subcommand(name, help);
    set_examples(c, std::string_view(name) == "winding" ? std::vector<std::string>{"preimage beams winding examples/beams/fig01_six_beams.json --word cbabdeeefe --open"}
                                                        : std::vector<std::string>{"preimage beams homotopy examples/beams/fig18_commutator.json --word \"a b a' b'\" --basis tree", "preimage beams homotopy examples/beams/fig01_six_beams.json --word cbabdeeefe --open"});
    add_class_options(c, a);
    c->add_option("--basis", a.basis, basis_help)->check(CLI::IsMember({"imaginary", "tree"}));
    c->callback([c, &a, winding_only] {
      check_basis(a, c->get_option("--max-states"));
      run_classes(a, winding_only);
    });
  };
  static ClassArgs ha, wa;
  add("homotopy", "the possible paths up to homotopy, as reduced words of F_n (paper section 5)", ha,
      "imaginary (default: the scene's imaginary_beams, else one vertical beam per obstacle; any sufficient beams) "
      "or tree (the scene's own disjoint, distinguishable, directed beams)",
      false);
  add("winding", "the possible winding numbers about each obstacle (paper section 6)", wa,
      "tree (counters over directed, distinguishable beams; the default when they reach every obstacle and "
      "without --open) or imaginary",
      true);
}

}  // namespace preimage::cli
