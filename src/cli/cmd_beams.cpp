// SPDX-License-Identifier: Apache-2.0
// preimage beams graph | filter | simulate | landmarks (homotopy and winding: cmd_beams_homotopy.cpp)
#include "common.hpp"
#include "progress.hpp"

#include <preimage/beams/examples.hpp>
#include <preimage/beams/export.hpp>
#include <preimage/beams/paths.hpp>
#include <preimage/beams/region_filter.hpp>
#include <preimage/error.hpp>
#include <preimage/filter/trellis.hpp>


#include <charconv>
#include <chrono>
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
void run_graph(const std::string& file, bool as_json, bool dot, bool merged, const std::string& svg) {
  const scene::Scene s = scene::load_scene(file);
  const BeamArrangement A = BeamArrangement::build(s);
  if (!svg.empty()) beams::arrangement_figure(A).save(svg);
  if (as_json) return print_json(beams::graph_json(A, merged));
  if (dot) {
    std::cout << beams::graph_dot(A, merged);
    return;
  }
  const auto& E = A.edges();
  const std::size_t labels = A.alphabet().num_labels();
  std::cout << "G: " << A.num_regions() << " regions, " << A.beams().size() << " beams (" << labels << (labels == 1 ? " label), " : " labels), ")
            << A.num_crossings() << " beam crossings, " << A.num_pieces() << " beam pieces, " << E.size() << " edges ("
            << A.graph().num_transitions() << " distinct (from, observation, to))\n";
  // Edges are sorted by (from, symbol, to): one line per region.
  auto e = E.begin();
  for (std::uint32_t r = 0; r < A.num_regions(); ++r) {
    std::cout << "  r" << r << " at " << geometry::format_point(geometry::to_double(A.regions()[r].sample)) << ":";
    for (; e != E.end() && e->from == r; ++e) {
      const bool repeat = e != E.begin() && e[-1].from == r && e[-1].symbol == e->symbol && e[-1].to == e->to;
      if (merged && repeat) continue;
      std::cout << " -" << A.alphabet().format(e->symbol) << "-> r" << e->to;
      if (!merged) std::cout << " (" << beams::piece_name(A, e->half_edge) << ")";
    }
    std::cout << "\n";
  }
  if (!svg.empty()) std::cout << "wrote " << svg << "\n";
}

// ---------------------------------------------------------------- filter
struct FilterArgs {
  std::string file, word, stream, svg, from;
  std::vector<std::string> at;
  std::size_t bodies = 1, limit = 10, cache_mb = 64, max_mb = 1024;
  bool has_word = false, several = false;  // --word given (possibly empty); --bodies given
  bool distinguishable = false, together = false, sequences = false, sample = false, cached = false, as_json = false;
};

std::vector<std::uint32_t> parse_ids(const std::string& text) {
  std::vector<std::uint32_t> out;
  std::stringstream ss(text);
  std::string tok;
  while (std::getline(ss, tok, ',')) {
    // Digits only: no sign (stoul would wrap "-1"), nothing past 32 bits.
    std::uint32_t v = 0;
    const auto [ptr, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (tok.empty() || ec != std::errc() || ptr != tok.data() + tok.size())
      throw InputError("--from: expected region ids like 0,3, got '" + text + "'");
    out.push_back(v);
  }
  return out;
}

// Calls `fn` for each observation of --word, or of --stream as it is read. A bad token
// ends the stream with an error after everything before it was delivered. A long --word
// shows progress on a terminal (a stream's lines are their own progress).
template <class Fn>
void for_each_observation(const BeamArrangement& A, const FilterArgs& a, Fn fn) {
  if (a.has_word) {
    const auto word = A.alphabet().parse_word(a.word);
    Progress progress("beams filter", "observations");
    for (std::size_t i = 0; i < word.size(); ++i) {
      fn(word[i]);
      progress(i + 1, word.size());
    }
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

// One JSON Lines record per observation of a stream (--stream --json), flushed.
void print_json_line(const json& j) { std::cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl; }

// "2.1 GiB": a byte count for messages about memory bounds.
std::string bytes_text(double b) {
  const char* unit[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int u = 0;
  while (b >= 1024 && u < 6) b /= 1024, ++u;
  std::ostringstream s;
  s.precision(b < 10 ? 2 : 3);
  s << b << " " << unit[u];
  return s.str();
}

// "{r0: 2, r3: 1}": a multiset of regions (a sorted tuple) as bodies per region (Fig. 12).
std::vector<std::pair<std::uint32_t, std::size_t>> bodies_per_region(const filter::ProductFilter::Assignment& t) {
  std::vector<std::pair<std::uint32_t, std::size_t>> out;
  for (auto r : t)
    if (!out.empty() && out.back().first == r) ++out.back().second;
    else out.push_back({r, 1});
  return out;
}

void run_bodies(const BeamArrangement& A, const FilterArgs& a, const std::vector<std::uint32_t>& R0) {
  const std::size_t n = a.bodies;
  const std::string kind = a.distinguishable ? "tuples" : "multisets";
  // The product filter's I-state is a set of assignments of n region ids (4 bytes each);
  // a step builds the next one beside it. Both are bounded by --max-mb before they are
  // built, so a huge --bodies is refused with the size it implies instead of exhausting
  // memory.
  const double budget = double(a.max_mb) * (1 << 20), per = 4.0 * double(n);
  const std::uint64_t init = beams::count_initial_assignments(R0.size(), n, a.distinguishable, a.together);
  if (double(init) * per > budget) {
    const std::string size = init == UINT64_MAX ? "more than 1.8e19 " + kind
                                                : std::to_string(init) + " " + kind + " (" + bytes_text(double(init) * per) + ")";
    throw InputError("--bodies " + std::to_string(n) + ": the initial I-state holds " + size + " of " + std::to_string(n) +
                     " bodies, more than --max-mb " + std::to_string(a.max_mb) + " allows");
  }
  filter::ProductFilter F(A.graph(), n, a.distinguishable, beams::initial_assignments(R0, n, a.distinguishable, a.together));
  // Largest number of transitions one region has for each symbol: with at most
  // min(n, regions) distinct positions moving per assignment (all n when the bodies are
  // distinguishable), a step makes at most size * positions * fan-out candidates.
  std::vector<std::size_t> fan_out(A.alphabet().num_symbols(), 0);
  for (std::uint32_t r = 0; r < A.num_regions(); ++r)
    for (beams::Symbol y = 0; y < fan_out.size(); ++y) fan_out[y] = std::max(fan_out[y], A.graph().out(r, y).size());
  const double positions = double(a.distinguishable ? n : std::min<std::size_t>(n, A.num_regions()));

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
  const bool live = !a.has_word;
  for_each_observation(A, a, [&](beams::Symbol y) {
    word.push_back(y);
    if (!ok) return;
    const double candidates = double(F.size()) * positions * double(fan_out[y]);
    if ((double(F.size()) + candidates) * per > budget)
      throw InputError("observation " + std::to_string(word.size()) + " (token " + A.alphabet().format(y) + "): the next I-state of " +
                       std::to_string(n) + " bodies may hold up to " + std::to_string(std::uint64_t(candidates)) + " " + kind + " (" +
                       bytes_text((double(F.size()) + candidates) * per) + " with the current one), more than --max-mb " +
                       std::to_string(a.max_mb) + " allows");
    if (fig11) fig11_state = fig11->step(fig11_state, y);
    if (!F.step(y)) {
      ok = false;
      k = word.size() - 1;
    }
    if (live && a.as_json)
      print_json_line({{"observation", word.size()}, {"token", A.alphabet().format(y)}, {"count", F.size()}});
    else if (live)
      std::cout << word.size() << " " << A.alphabet().format(y) << ": " << F.size() << " possible assignments" << std::endl;
  });
  const auto as = F.assignments();
  const std::size_t listed = std::min(as.size(), a.limit);
  if (!a.svg.empty()) {
    // The regions some body may be in.
    beams::FigureOptions o;
    std::vector<char> any(A.num_regions(), 0);
    for (auto& t : as)
      for (auto r : t) any[r] = 1;
    for (std::uint32_t r = 0; r < A.num_regions(); ++r)
      if (any[r]) o.highlight.push_back(r);
    beams::arrangement_figure(A, o).save(a.svg);
  }
  if (a.as_json) {
    json list = json::array();
    for (std::size_t i = 0; i < listed; ++i) {
      if (a.distinguishable) {
        list.push_back(as[i]);
      } else {
        json m = json::array();
        for (auto [r, c] : bodies_per_region(as[i])) m.push_back({r, c});
        list.push_back(m);
      }
    }
    json j = {{"bodies", n},         {"distinguishable", a.distinguishable}, {"observations", word.size()},
              {"consistent", ok},    {"count", as.size()},                   {"listed", listed},
              {"truncated", listed < as.size()}, {a.distinguishable ? "assignments" : "multisets", list}};
    if (!ok) j["inconsistent_at"] = k + 1;
    if (fig11) j["fig11_filter"] = fig11_state == filter::kNoState ? "none" : fig11->names[fig11_state];
    return live ? print_json_line(j) : print_json(j);
  }
  if (!ok) {
    std::cout << "inconsistent at observation " << k + 1 << " (token " << A.alphabet().format(word[k]) << "): no assignment of "
              << n << " bodies explains the word\n";
  } else {
    std::cout << n << (a.distinguishable ? " distinguishable" : " indistinguishable") << " bodies after " << word.size()
              << " observations: " << as.size() << " possible "
              << (a.distinguishable ? "assignments (region of each body)" : "multisets (bodies per region)") << "\n";
    for (std::size_t i = 0; i < listed; ++i) {
      if (a.distinguishable) {
        std::cout << "  (";
        for (std::size_t b = 0; b < n; ++b) std::cout << (b ? ", " : "") << "r" << as[i][b];
        std::cout << ")\n";
      } else {
        std::cout << "  {";
        bool first = true;
        for (auto [r, c] : bodies_per_region(as[i])) std::cout << (first ? "" : ", ") << "r" << r << ": " << c, first = false;
        std::cout << "}\n";
      }
    }
    if (as.size() > listed) std::cout << "  ... " << as.size() - listed << " more (--limit)\n";
    if (fig11) {
      auto reading = beams::together_reading(A, as);
      std::cout << "Fig. 11 filter (" << fig11->size() << " I-states): "
                << (fig11_state == filter::kNoState ? "none" : fig11->names[fig11_state]) << "; the product filter says "
                << (reading ? *reading : "mixed") << "\n";
    }
  }
  if (!a.svg.empty()) std::cout << "wrote " << a.svg << "\n";
}

void run_filter(const FilterArgs& a) {
  const scene::Scene s = scene::load_scene(a.file);
  const BeamArrangement A = BeamArrangement::build(s);
  std::vector<geometry::ExactPoint> pts;
  for (auto& t : a.at) pts.push_back(geometry::to_exact(parse_point(t, "--at")));
  const std::vector<std::uint32_t> R0 = beams::initial_regions(A, a.from.empty() ? std::vector<std::uint32_t>{} : parse_ids(a.from), pts);
  std::vector<std::uint32_t> R0all = R0;
  if (R0all.empty())
    for (std::uint32_t r = 0; r < A.num_regions(); ++r) R0all.push_back(r);

  if (a.several) return run_bodies(A, a, R0all);
  std::vector<beams::Symbol> word;

  beams::RegionFilter F(A, R0, a.cached ? beams::FilterMode::Cached : beams::FilterMode::Plain, a.cache_mb << 20);
  std::size_t bad = 0;  // 1-based observation that emptied the I-state
  // Streaming: one line (or JSON Lines record) per observation, flushed, so the filter
  // runs on a live feed.
  const bool live = !a.has_word;
  for_each_observation(A, a, [&](beams::Symbol y) {
    word.push_back(y);
    if (!bad && !F.step(y)) bad = word.size();
    if (!live) return;
    const auto rs = F.regions();
    if (a.as_json)
      print_json_line({{"observation", word.size()}, {"token", A.alphabet().format(y)}, {"regions", rs}});
    else
      std::cout << word.size() << " " << A.alphabet().format(y) << ": " << rs.size() << " possible: " << region_list(rs) << std::endl;
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
    // Listing holds (k+1) region ids per sequence: bound it like the other I-states.
    const double list_bytes = 4.0 * double(word.size() + 1) * double(a.limit);
    if (list_bytes > double(std::size_t(1) << 30))
      throw InputError("--limit " + std::to_string(a.limit) + ": listing that many sequences of " + std::to_string(word.size() + 1) +
                       " regions needs " + bytes_text(list_bytes) + ", more than 1 GiB");
    bool cut = false;
    const auto seqs = T.enumerate(std::max<std::size_t>(a.limit, a.sample ? 1 : 0), &cut);
    const std::size_t listed = std::min(seqs.size(), a.limit);
    cut = cut || listed < seqs.size();
    const std::string count = T.count().str();
    if (a.sample && !seqs.empty()) path = to_double(beams::sample_path(A, seqs.front(), word));
    if (a.as_json) {
      j["sequences"] = {{"count", count}, {"listed", std::vector<std::vector<std::uint32_t>>(seqs.begin(), seqs.begin() + listed)},
                        {"truncated", cut}};
      json stages = json::array();
      for (std::size_t i = 0; i <= T.length(); ++i) stages.push_back(T.stage(i));
      j["sequences"]["stages"] = stages;
      if (!path.empty()) j["sample_path"] = points_json(path);
    } else {
      std::cout << "possible region sequences: " << count << "\n";
      for (std::size_t i = 0; i < listed; ++i) std::cout << "  " << region_list(seqs[i]) << "\n";
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
  if (a.as_json) live ? print_json_line(j) : print_json(j);
}

// ---------------------------------------------------------------- simulate
void run_simulate(const std::string& file, std::uint64_t seed, std::size_t steps, bool as_json, const std::string& svg) {
  const scene::Scene s = scene::load_scene(file);
  const BeamArrangement A = BeamArrangement::build(s);
  Progress progress("beams simulate", "path segments");
  const beams::Simulation sim = beams::simulate(A, seed, steps, [&](std::size_t k) { progress(k, steps); });
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
  auto* beams_cmd = app.add_subcommand("beams", "Sensor beams: regions, region filter, possible paths (beams paper)");
  beams_cmd->require_subcommand(1);

  auto* g = beams_cmd->add_subcommand("graph", "Regions of free space cut by the beams, and the crossing multigraph G");
  set_examples(g, {"preimage beams graph examples/beams/fig03b_crossing.json --svg beams.svg", "preimage beams graph examples/beams/fig03b_crossing.json --dot"});
  static std::string g_file, g_svg;
  static bool g_json = false, g_dot = false, g_merged = false;
  g->add_option("scene", g_file, "Scene file (JSON)")->required();
  auto* gj = add_json_flag(g, g_json, "G as JSON");
  g->add_flag("--dot", g_dot, "G as Graphviz DOT")->excludes(gj);
  g->add_flag("--merged", g_merged,
              "Merge parallel edges: one per (from, observation, to) listing its beam pieces (text, JSON), "
              "one arrow per region pair with a list of labels (DOT, Fig. 7(b))");
  g->add_option("--svg", g_svg, "Draw regions and beams to this SVG file");
  g->callback([] { run_graph(g_file, g_json, g_dot, g_merged, g_svg); });

  auto* f = beams_cmd->add_subcommand("filter", "Possible regions (and region sequences) after a sensor word");
  set_examples(f, {"preimage beams filter examples/beams/fig03b_crossing.json --word \"a b c\"", "preimage beams filter examples/beams/fig01_six_beams.json --stream examples/beams/fig01_words.txt --json"});
  static FilterArgs fa;
  f->add_option("scene", fa.file, "Scene file (JSON)")->required();
  auto* word = f->add_option("--word", fa.word, "Sensor word: \"c b a' b\" or the one-character stream \"cba'b\" (\"\": no observation)");
  auto* stream = f->add_option("--stream", fa.stream, "Read the word from a file, or - for stdin, observation by observation")
                     ->excludes(word);
  f->add_option("--from", fa.from, "Initial regions R_0 as ids, e.g. 0,3 (default: all)");
  f->add_option("--at", fa.at, "Initial region containing point X,Y (repeatable)");
  auto* bodies = add_count(f, "--bodies", fa.bodies, 1, 1000000000,
                           "number of bodies, observed anonymously: the product filter of 4.2");
  f->add_flag("--distinguishable", fa.distinguishable, "Track tuples (which body is where) instead of bodies per region")->needs(bodies);
  f->add_flag("--together", fa.together, "All bodies start in the same region")->needs(bodies);
  add_count(f, "--max-mb", fa.max_mb, 1, 1048576, "Memory bound of the several-body I-state in MiB")->needs(bodies);
  auto* seqs = f->add_flag("--sequences", fa.sequences, "Count and list the possible region sequences (one body)")->excludes(bodies);
  auto* limit = add_count(f, "--limit", fa.limit, 0, 1000000, "List at most this many sequences or assignments");
  auto* sample = f->add_flag("--sample-path", fa.sample, "A sample path for the first possible sequence (one body)")->excludes(bodies);
  auto* cached = f->add_flag("--cached", fa.cached, "Compile the filter lazily into a subset automaton (one body)")->excludes(bodies);
  add_count(f, "--cache-mb", fa.cache_mb, 1, 1048576, "Memory bound of the cached mode in MiB")->needs(cached);
  add_json_flag(f, fa.as_json, "JSON output (JSON Lines with --stream: one record per observation, then the summary)");
  f->add_option("--svg", fa.svg, "Draw the final possible regions (and the sample path)");
  f->callback([word, stream, bodies, seqs, limit, sample] {
    if (word->count() == 0 && stream->count() == 0) throw CLI::RequiredError("--word or --stream");
    if (limit->count() > 0 && seqs->count() == 0 && sample->count() == 0 && bodies->count() == 0)
      throw CLI::ValidationError("--limit", "needs --sequences, --sample-path or --bodies (it bounds their lists)");
    fa.has_word = word->count() > 0;
    fa.several = bodies->count() > 0;
    run_filter(fa);
  });

  auto* sm = beams_cmd->add_subcommand("simulate", "A random body path: its true word and regions, and the filter's answer");
  set_examples(sm, {"preimage beams simulate examples/beams/fig01_six_beams.json --seed 3 --steps 20"});
  static std::string s_file, s_svg;
  static std::uint64_t s_seed = 1;
  static std::size_t s_steps = 20;
  static bool s_json = false;
  sm->add_option("scene", s_file, "Scene file (JSON)")->required();
  add_count(sm, "--seed", s_seed, 0, INT64_MAX, "Random seed");
  add_count(sm, "--steps", s_steps, 0, 1000000, "Path segments");
  add_json_flag(sm, s_json, "JSON output");
  sm->add_option("--svg", s_svg, "Draw the path and the final possible regions");
  sm->callback([] { run_simulate(s_file, s_seed, s_steps, s_json, s_svg); });

  auto* lm = beams_cmd->add_subcommand("landmarks", "Virtual beams of a landmark scene (paper section 3, Fig. 6)");
  set_examples(lm, {"preimage beams landmarks examples/beams/fig06b_landmarks_north.json --model north -o virtual.json"});
  static std::string l_file, l_out, l_model = "crossing";
  static bool l_undirected = false, l_indist = false;
  lm->add_option("scene", l_file, "Scene with landmarks and no environment")->required();
  lm->add_option("--model", l_model, "crossing (pairs of landmarks aligned, Fig. 6a) or north (landmark due south, Fig. 6b)")
      ->check(CLI::IsMember({"crossing", "north"}));
  lm->add_flag("--undirected", l_undirected, "Beams do not report the crossing direction");
  lm->add_flag("--indistinguishable", l_indist, "Crossing model: both beams of a pair share one label (Fig. 10)");
  lm->add_option("-o,--output", l_out, "Output scene file")->required();
  lm->callback([] {
    if (l_indist && l_model == "north")
      throw CLI::ValidationError("--indistinguishable", "only with --model crossing (north beams are one per landmark)");
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
