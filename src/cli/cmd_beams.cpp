// SPDX-License-Identifier: Apache-2.0
// preimage beams graph | filter | simulate | landmarks (homotopy and winding: cmd_beams_homotopy.cpp)
#include "common.hpp"

#include <preimage/beams/examples.hpp>
#include <preimage/beams/export.hpp>
#include <preimage/beams/paths.hpp>
#include <preimage/beams/region_filter.hpp>
#include <preimage/error.hpp>
#include <preimage/filter/trellis.hpp>

#include <fstream>
#include <iostream>
#include <sstream>

namespace preimage::cli {

namespace {

using nlohmann::json;
using beams::BeamArrangement;

std::string region_list(const std::vector<std::uint32_t>& rs) {
  std::string s;
  for (auto r : rs) s += (s.empty() ? "r" : " r") + std::to_string(r);
  return s.empty() ? "(none)" : s;
}

std::vector<geometry::Point> to_double(const std::vector<geometry::ExactPoint>& path) {
  std::vector<geometry::Point> out;
  for (auto& p : path) out.push_back(geometry::to_double(p));
  return out;
}

// ---------------------------------------------------------------- graph
void run_graph(const std::string& file, bool as_json, bool dot, const std::string& svg) {
  const scene::Scene s = scene::load_scene(file);
  const BeamArrangement A = BeamArrangement::build(s);
  if (!svg.empty()) beams::arrangement_figure(A).save(svg);
  if (as_json) return print_json(beams::graph_json(A));
  if (dot) {
    std::cout << beams::graph_dot(A);
    return;
  }
  std::cout << "G: " << A.num_regions() << " regions, " << A.beams().size() << " beams (" << A.alphabet().num_labels()
            << " labels), " << A.num_crossings() << " beam crossings, " << A.edges().size() << " edges\n";
  for (std::uint32_t r = 0; r < A.num_regions(); ++r) {
    std::cout << "  r" << r << " at " << geometry::format_point(geometry::to_double(A.regions()[r].sample)) << ":";
    for (auto& t : A.graph().out(r)) std::cout << " -" << A.alphabet().format(t.symbol) << "-> r" << t.to;
    std::cout << "\n";
  }
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

// ---------------------------------------------------------------- filter
struct FilterArgs {
  std::string file, word, stream, svg, from;
  std::vector<std::string> at;
  std::size_t bodies = 1, limit = 10, cache_mb = 64;
  bool distinguishable = false, together = false, sequences = false, sample = false, cached = false, as_json = false;
};

std::vector<std::uint32_t> parse_ids(const std::string& text) {
  std::vector<std::uint32_t> out;
  std::stringstream ss(text);
  std::string tok;
  while (std::getline(ss, tok, ',')) {
    std::size_t used = 0;
    unsigned long v = 0;
    try {
      v = std::stoul(tok, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != tok.size()) throw InputError("--from: expected region ids like 0,3, got '" + text + "'");
    out.push_back(static_cast<std::uint32_t>(v));
  }
  return out;
}

// Calls `fn` for each observation of --word, or of --stream as it is read. A bad token
// ends the stream with an error after everything before it was delivered.
template <class Fn>
void for_each_observation(const BeamArrangement& A, const FilterArgs& a, Fn fn) {
  if (!a.word.empty()) {
    for (auto y : A.alphabet().parse_word(a.word)) fn(y);
    return;
  }
  std::ifstream f;
  std::istream* in = &std::cin;
  if (a.stream != "-") {
    f.open(a.stream);
    if (!f) throw InputError(a.stream + ": cannot open file");
    in = &f;
  }
  beams::WordReader r(A.alphabet(), *in);
  beams::Symbol y;
  while (r.next(y)) fn(y);
}

void run_bodies(const BeamArrangement& A, const FilterArgs& a, const std::vector<std::uint32_t>& R0) {
  std::vector<filter::ProductFilter::Assignment> init;
  // Every body in one of R_0 (all of them in the same region with --together).
  const std::size_t n = a.bodies;
  if (a.together) {
    for (auto r : R0) init.push_back(filter::ProductFilter::Assignment(n, r));
  } else {
    init = filter::ProductFilter::all_assignments(R0, n);
  }
  filter::ProductFilter F(A.graph(), n, a.distinguishable, init);
  std::optional<filter::Dfa> fig11;
  filter::State fig11_state = 0;
  if (n == 2 && a.together) try {
      fig11 = beams::together_filter(A);
    } catch (const InputError&) {
    }
  // Observation by observation, as for one body; after an inconsistency the rest of a
  // valid stream is still read (and counted) but no longer filtered.
  std::vector<beams::Symbol> word;
  std::size_t k = 0;
  bool ok = true;
  const bool live = !a.stream.empty() && !a.as_json;
  for_each_observation(A, a, [&](beams::Symbol y) {
    word.push_back(y);
    if (!ok) return;
    if (fig11) fig11_state = fig11->step(fig11_state, y);
    if (!F.step(y)) {
      ok = false;
      k = word.size() - 1;
    }
    if (live) std::cout << word.size() << " " << A.alphabet().format(y) << ": " << F.size() << " possible assignments" << std::endl;
  });
  const auto as = F.assignments();
  if (a.as_json) {
    json j = {{"bodies", n}, {"distinguishable", a.distinguishable}, {"observations", word.size()}, {"consistent", ok},
              {"assignments", as}};
    if (!ok) j["inconsistent_at"] = k + 1;
    if (fig11) j["fig11_filter"] = fig11_state == filter::kNoState ? "none" : fig11->names[fig11_state];
    return print_json(j);
  }
  if (!ok) {
    std::cout << "inconsistent at observation " << k + 1 << " (token " << A.alphabet().format(word[k]) << "): no assignment of "
              << n << " bodies explains the word\n";
    return;
  }
  std::cout << n << (a.distinguishable ? " distinguishable" : " indistinguishable") << " bodies after " << word.size()
            << " observations: " << as.size() << " possible " << (a.distinguishable ? "assignments" : "multisets (bodies per region)")
            << "\n";
  for (std::size_t i = 0; i < std::min<std::size_t>(as.size(), a.limit); ++i) {
    std::cout << "  (";
    for (std::size_t b = 0; b < n; ++b) std::cout << (b ? ", " : "") << "r" << as[i][b];
    std::cout << ")\n";
  }
  if (as.size() > a.limit) std::cout << "  ... " << as.size() - a.limit << " more (--limit)\n";
  if (fig11) {
    auto reading = beams::together_reading(A, as);
    std::cout << "Fig. 11 filter (" << fig11->size() << " I-states): "
              << (fig11_state == filter::kNoState ? "none" : fig11->names[fig11_state])
              << "; the product filter says " << (reading ? *reading : "mixed") << "\n";
  }
}

void run_filter(const FilterArgs& a) {
  if (a.word.empty() == a.stream.empty()) throw InputError("give exactly one of --word and --stream");
  if (a.bodies == 0) throw InputError("--bodies: at least 1");
  const scene::Scene s = scene::load_scene(a.file);
  const BeamArrangement A = BeamArrangement::build(s);
  std::vector<geometry::ExactPoint> pts;
  for (auto& t : a.at) pts.push_back(geometry::to_exact(parse_point(t, "--at")));
  const std::vector<std::uint32_t> R0 = beams::initial_regions(A, a.from.empty() ? std::vector<std::uint32_t>{} : parse_ids(a.from), pts);
  std::vector<std::uint32_t> R0all = R0;
  if (R0all.empty())
    for (std::uint32_t r = 0; r < A.num_regions(); ++r) R0all.push_back(r);

  if (a.bodies > 1) return run_bodies(A, a, R0all);
  std::vector<beams::Symbol> word;

  beams::RegionFilter F(A, R0, a.cached ? beams::FilterMode::Cached : beams::FilterMode::Plain, a.cache_mb << 20);
  std::size_t bad = 0;  // 1-based observation that emptied the I-state
  auto feed = [&](beams::Symbol y) {
    word.push_back(y);
    if (!bad && !F.step(y)) bad = word.size();
  };
  // Streaming: one line per observation, flushed, so the filter runs on a live feed.
  const bool live = !a.stream.empty() && !a.as_json;
  for_each_observation(A, a, [&](beams::Symbol y) {
    feed(y);
    if (live) {
      const auto rs = F.regions();
      std::cout << word.size() << " " << A.alphabet().format(y) << ": " << rs.size() << " possible: " << region_list(rs)
                << std::endl;
    }
  });
  const auto R = F.regions();
  json j;
  if (a.as_json) {
    j = {{"observations", word.size()}, {"word", A.alphabet().format(word)}, {"consistent", !bad}, {"regions", R},
         {"mode", a.cached ? "cached" : "plain"}};
    if (bad) j["inconsistent_at"] = {{"observation", bad}, {"token", A.alphabet().format(word[bad - 1])}};
  } else if (bad) {
    std::cout << "inconsistent at observation " << bad << " (token " << A.alphabet().format(word[bad - 1])
              << "): no region sequence explains the word\n";
  } else {
    std::cout << "possible regions after " << word.size() << " observations: " << region_list(R) << " (" << R.size() << " of "
              << A.num_regions() << ")\n";
  }
  std::vector<geometry::Point> path;
  if (!bad && (a.sequences || a.sample)) {
    const filter::Trellis T(A.graph(), R0, word);
    bool cut = false;
    const auto seqs = T.enumerate(a.limit, &cut);
    const std::string count = T.count().str();
    if (a.sample && !seqs.empty()) path = to_double(beams::sample_path(A, seqs.front(), word));
    if (a.as_json) {
      j["sequences"] = {{"count", count}, {"listed", seqs}, {"truncated", cut}};
      json stages = json::array();
      for (std::size_t i = 0; i <= T.length(); ++i) stages.push_back(T.stage(i));
      j["sequences"]["stages"] = stages;
      if (!path.empty()) j["sample_path"] = points_json(path);
    } else {
      std::cout << "possible region sequences: " << count << "\n";
      for (auto& sq : seqs) std::cout << "  " << region_list(sq) << "\n";
      if (cut) std::cout << "  ... more (--limit " << a.limit << ")\n";
      std::cout << "possible start regions: " << region_list(T.stage(0)) << "\n";
      if (!path.empty()) std::cout << "sample path for the first sequence: " << path.size() << " points\n";
    }
  }
  if (!a.svg.empty()) {
    beams::FigureOptions o;
    o.highlight = R;
    o.path = path;
    o.path_label = "sample path of the first sequence";
    beams::arrangement_figure(A, o).save(a.svg);
    if (!a.as_json) std::cout << "wrote " << a.svg << "\n";
  }
  if (a.as_json) print_json(j);
}

// ---------------------------------------------------------------- simulate
void run_simulate(const std::string& file, std::uint64_t seed, std::size_t steps, bool as_json, const std::string& svg) {
  const scene::Scene s = scene::load_scene(file);
  const BeamArrangement A = BeamArrangement::build(s);
  const beams::Simulation sim = beams::simulate(A, seed, steps);
  const auto& w = sim.trace.word;
  beams::RegionFilter F(A);
  for (auto y : w) F.step(y);
  const auto R = F.regions();
  const std::uint32_t truth = sim.trace.regions.back();
  const bool in = std::binary_search(R.begin(), R.end(), truth);
  const filter::Trellis T(A.graph(), {}, w);
  const bool seq_in = T.contains(sim.trace.regions);
  if (!svg.empty()) {
    beams::FigureOptions o;
    o.highlight = R;
    o.path = to_double(sim.path);
    o.path_label = "simulated body path";
    beams::arrangement_figure(A, o).save(svg);
  }
  if (as_json) {
    json p = json::array();
    for (auto& q : sim.path) p.push_back(point_json(q));
    return print_json({{"seed", seed}, {"path", p}, {"word", A.alphabet().format(w)}, {"regions", sim.trace.regions},
                       {"filter", {{"regions", R}, {"contains_true_region", in}, {"sequences", T.count().str()},
                                   {"contains_true_sequence", seq_in}}}});
  }
  std::cout << "simulated " << sim.path.size() - 1 << " path segments (seed " << seed << "): " << w.size() << " observations\n"
            << "word: " << A.alphabet().format(w) << "\n"
            << "true regions: " << region_list(sim.trace.regions) << "\n"
            << "filter: " << region_list(R) << " possible at the end (true region r" << truth
            << (in ? " included" : " MISSING") << "); " << T.count().str() << " possible sequences (true one "
            << (seq_in ? "included" : "MISSING") << ")\n";
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

}  // namespace

void add_beams_commands(CLI::App& app) {
  auto* beams_cmd = app.add_subcommand("beams", "sensor beams: regions, region filter, possible paths (beams paper)");
  beams_cmd->require_subcommand(1);

  auto* g = beams_cmd->add_subcommand("graph", "regions of free space cut by the beams, and the crossing graph G");
  static std::string g_file, g_svg;
  static bool g_json = false, g_dot = false;
  g->add_option("scene", g_file, "scene file (JSON)")->required();
  auto* gj = g->add_flag("--json", g_json, "G as JSON");
  g->add_flag("--dot", g_dot, "G as Graphviz DOT")->excludes(gj);
  g->add_option("--svg", g_svg, "draw regions and beams to this SVG file");
  g->callback([] { run_graph(g_file, g_json, g_dot, g_svg); });

  auto* f = beams_cmd->add_subcommand("filter", "possible regions (and region sequences) after a sensor word");
  static FilterArgs fa;
  f->add_option("scene", fa.file, "scene file (JSON)")->required();
  f->add_option("--word", fa.word, "sensor word: \"c b a' b\" or the one-character stream \"cba'b\"");
  f->add_option("--stream", fa.stream, "read the word from a file, or - for stdin, observation by observation");
  f->add_option("--from", fa.from, "initial regions R_0 as ids, e.g. 0,3 (default: all)");
  f->add_option("--at", fa.at, "initial region containing point X,Y (repeatable)");
  f->add_option("--bodies", fa.bodies, "number of bodies (observations are anonymous)");
  f->add_flag("--distinguishable", fa.distinguishable, "with --bodies: track tuples (product filter) instead of counts");
  f->add_flag("--together", fa.together, "with --bodies: all bodies start in the same region");
  f->add_flag("--sequences", fa.sequences, "count and list the possible region sequences");
  f->add_option("--limit", fa.limit, "list at most this many sequences or assignments (default 10)");
  f->add_flag("--sample-path", fa.sample, "a sample path for the first possible sequence");
  f->add_flag("--cached", fa.cached, "compile the filter lazily into a subset automaton");
  f->add_option("--cache-mb", fa.cache_mb, "memory bound of the cached mode in MiB (default 64)");
  f->add_flag("--json", fa.as_json, "JSON output");
  f->add_option("--svg", fa.svg, "draw the final possible regions (and the sample path)");
  f->callback([] { run_filter(fa); });

  auto* sm = beams_cmd->add_subcommand("simulate", "a random body path: its true word and regions, and the filter's answer");
  static std::string s_file, s_svg;
  static std::uint64_t s_seed = 1;
  static std::size_t s_steps = 20;
  static bool s_json = false;
  sm->add_option("scene", s_file, "scene file (JSON)")->required();
  sm->add_option("--seed", s_seed, "random seed (default 1)");
  sm->add_option("--steps", s_steps, "path segments (default 20)");
  sm->add_flag("--json", s_json, "JSON output");
  sm->add_option("--svg", s_svg, "draw the path and the final possible regions");
  sm->callback([] { run_simulate(s_file, s_seed, s_steps, s_json, s_svg); });

  auto* lm = beams_cmd->add_subcommand("landmarks", "virtual beams of a landmark scene (paper section 3, Fig. 6)");
  static std::string l_file, l_out, l_model = "crossing";
  static bool l_undirected = false, l_indist = false;
  lm->add_option("scene", l_file, "scene with landmarks and no environment")->required();
  lm->add_option("--model", l_model, "crossing (pairs of landmarks aligned, Fig. 6a) or north (landmark due south, Fig. 6b)");
  lm->add_flag("--undirected", l_undirected, "beams do not report the crossing direction");
  lm->add_flag("--indistinguishable", l_indist, "crossing model: both beams of a pair share one label (Fig. 10)");
  lm->add_option("-o,--output", l_out, "output scene file")->required();
  lm->callback([] {
    if (l_model != "crossing" && l_model != "north") throw InputError("--model: expected crossing or north, got '" + l_model + "'");
    scene::Scene s = beams::with_landmark_beams(scene::load_scene(l_file),
                                                l_model == "north" ? beams::LandmarkModel::North : beams::LandmarkModel::Crossing,
                                                !l_undirected, !l_indist);
    const BeamArrangement A = BeamArrangement::build(s);  // validates general position
    scene::save_scene(s, l_out);
    std::cout << "wrote " << l_out << ": " << s.beams.size() << " beams, " << A.num_regions() << " regions\n";
  });

  add_beams_homotopy_commands(beams_cmd);
}

}  // namespace preimage::cli
