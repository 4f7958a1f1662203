// Beam words up to homotopy and winding (beams paper, sections 5-6).
//
// perfect-beams: the constant-time filter of 6.1 (rename, reduce incrementally, count)
// over a 2^22-observation word on 8 landmarks with perfect beams due north (Fig. 6b),
// against the paper's batch method in the same run: store the word, reduce it, and
// abelianise by sorting its symbols and counting, as in (6).
//
// homotopy-set: the classes a word allows in the general case (5.3), as the product of
// the pruned trellis H with the Cayley tree of F_n, against the paper's algorithm that
// enumerates region sequences (and pieces of the multigraph) one by one.
#include <preimage/beams/examples.hpp>
#include <preimage/beams/homotopy.hpp>
#include <preimage/beams/paths.hpp>

#include "ratio_reporter.hpp"

#include <support/beam_scenes.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>

using namespace preimage;

namespace {

struct Perfect {
  scene::Scene scene;
  beams::BeamArrangement A;
  beams::LoopBasis L;
  std::vector<beams::Symbol> word;
};

const Perfect& perfect() {
  static const Perfect P = [] {
    scene::Scene s = beams::with_landmark_beams(beams::landmark_scene(8, 3), beams::LandmarkModel::North, true, true);
    auto A = beams::BeamArrangement::build(s);
    auto L = beams::LoopBasis::tree(A, s);
    if (!L.perfect()) throw std::logic_error("bench: the north beams should be perfect");
    // Uniformly random observations: some cancel, the reduced word still grows.
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<std::uint32_t> sym(0, static_cast<std::uint32_t>(A.alphabet().num_symbols()) - 1);
    std::vector<beams::Symbol> w(std::size_t(1) << 22);
    for (auto& y : w) y = sym(rng);
    return Perfect{std::move(s), std::move(A), std::move(L), std::move(w)};
  }();
  return P;
}

void perfect_filter(benchmark::State& state) {
  const Perfect& P = perfect();
  std::vector<std::int64_t> v;
  std::size_t length = 0;
  for (auto _ : state) {
    beams::BasisWordFilter F(P.L);
    for (auto y : P.word) F.step(y);
    v = F.winding();
    length = F.word().length();
    benchmark::DoNotOptimize(v.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * P.word.size()));
  state.counters["reduced_length"] = static_cast<double>(length);
}

void perfect_reference(benchmark::State& state) {
  const Perfect& P = perfect();
  std::vector<std::int64_t> v;
  std::size_t length = 0;
  for (auto _ : state) {
    // Batch: keep the word, reduce it afterwards, and abelianise by sorting (6).
    std::vector<beams::Letter> stored;
    for (auto y : P.word) stored.push_back(P.L.letter(y));
    const beams::FreeWord w = beams::FreeWord::reduce(stored);
    std::vector<beams::Letter> sorted(stored);
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::int64_t> e(P.L.rank(), 0);
    for (auto x : sorted) e[beams::generator_of(x)] += x > 0 ? 1 : -1;
    v = P.L.winding(e);
    length = w.length();
    benchmark::DoNotOptimize(v.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * P.word.size()));
  state.counters["reduced_length"] = static_cast<double>(length);
}

struct General {
  scene::Scene scene;
  beams::BeamArrangement A;
  beams::LoopBasis L;
  std::vector<beams::Symbol> word;
};

// A random sufficient scene (3 obstacles, 2 chords) whose 5 beams share 2 labels and
// are undirected: many region sequences per word. The word is a simulated body's.
const General& general(std::size_t steps) {
  static std::map<std::size_t, General> cache;
  auto it = cache.find(steps);
  if (it != cache.end()) return it->second;
  scene::Scene s = preimage::testing::random_sufficient_scene(16, 3, 2, 4, false, 2, 1.0);
  auto A = beams::BeamArrangement::build(s);
  beams::require_sufficient(A);
  auto L = beams::LoopBasis::imaginary(A, s);
  auto w = beams::simulate(A, 9, steps).trace.word;
  return cache.emplace(steps, General{std::move(s), std::move(A), std::move(L), std::move(w)}).first->second;
}

void homotopy_product(benchmark::State& state) {
  const General& g = general(static_cast<std::size_t>(state.range(0)));
  const beams::GraphEmbedding G(g.A, g.L);
  std::size_t classes = 0, peak = 0;
  std::string sequences;
  for (auto _ : state) {
    const beams::HomotopySet H(G, {}, g.word);
    classes = H.classes().size();
    peak = H.peak_states();
    sequences = H.sequences();
    benchmark::DoNotOptimize(classes);
  }
  state.counters["observations"] = static_cast<double>(g.word.size());
  state.counters["classes"] = static_cast<double>(classes);
  state.counters["sequences"] = std::stod(sequences);
  state.counters["peak_states"] = static_cast<double>(peak);
}

void homotopy_enumeration(benchmark::State& state) {
  const General& g = general(static_cast<std::size_t>(state.range(0)));
  const beams::GraphEmbedding G(g.A, g.L);
  std::size_t classes = 0;
  for (auto _ : state) {
    const auto ref = beams::homotopy_by_enumeration(G, {}, g.word, std::size_t(1) << 24);
    if (!ref) throw std::logic_error("bench: enumeration limit reached");
    classes = ref->size();
    benchmark::DoNotOptimize(classes);
  }
  state.counters["classes"] = static_cast<double>(classes);
  state.counters["observations"] = static_cast<double>(g.word.size());
}

}  // namespace

BENCHMARK(perfect_filter)->Name("perfect-beams/preimage/obs:4194304")->Unit(benchmark::kMillisecond);
BENCHMARK(perfect_reference)->Name("perfect-beams/reference/obs:4194304")->Unit(benchmark::kMillisecond);
BENCHMARK(homotopy_product)->Name("homotopy-set/preimage")->ArgName("steps")->Arg(20)->Arg(30)->Arg(40)->Unit(benchmark::kMillisecond);
// At 40 steps the word allows 674k region sequences; enumerating them one by one
// exceeds 2^24 sample loops, so the reference stops at 30.
BENCHMARK(homotopy_enumeration)->Name("homotopy-set/reference")->ArgName("steps")->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
