// SPDX-License-Identifier: Apache-2.0
// Demo section of the beams module: the Fig. 1 word, its possible regions and sequences,
// a reconstructed sample path, and the two-body filter of Fig. 11.
#include "demo.hpp"

#include <preimage/beams/examples.hpp>
#include <preimage/beams/export.hpp>
#include <preimage/beams/paths.hpp>
#include <preimage/beams/region_filter.hpp>
#include <preimage/filter/trellis.hpp>

namespace preimage::cli {

void demo_beams(DemoContext& ctx) {
  auto& R = ctx.report;
  R.section("Sensor beams: regions, the region filter and possible paths (beams paper, 2-4)");
  const auto A = beams::BeamArrangement::build(beams::fig1_scene());
  const auto w = A.alphabet().parse_word("cbabdeeefe");
  beams::RegionFilter F(A);
  for (auto y : w) F.step(y);
  const filter::Trellis T(A.graph(), {}, w);
  std::string regions;
  for (auto r : F.regions()) regions += " r" + std::to_string(r);
  R.result("Fig. 1 scene: " + std::to_string(A.num_regions()) + " regions, " + std::to_string(A.edges().size()) +
           " edges of G (f is a self-loop). Word cbabdeeefe: possible final regions" + regions + "; " + T.count().str() +
           " possible region sequence; the filter started from all 3 regions, and the later observation d narrowed the "
           "start to r" + std::to_string(T.stage(0)[0]) + ".");
  const auto seq = T.enumerate(1).front();
  const auto path = beams::sample_path(A, seq, w);
  const auto back = beams::trace_path(A, path);
  beams::FigureOptions o;
  o.highlight = F.regions();
  for (auto& p : path) o.path.push_back(geometry::to_double(p));
  o.path_label = "sample path reconstructed from the region sequence";
  R.result("Sample path: " + std::to_string(path.size()) + " exact points; traced back it reads \"" +
           A.alphabet().format(back.word, "") + "\" (" + (back.word == w ? "the same word" : "A DIFFERENT WORD") + ").");
  ctx.figure("beams-fig1.svg", beams::arrangement_figure(A, o).str(),
             "Fig. 1 scene: regions, undirected beams, the final possible region and a sample path");

  const auto B = beams::BeamArrangement::build(beams::fig3b_scene());
  ctx.figure("beams-fig3b.svg", beams::arrangement_figure(B).str(),
             "Fig. 3(b): directed beam a crosses undirected b, two indistinguishable beams c, directed d: " +
                 std::to_string(B.num_regions()) + " regions");

  const auto C = beams::BeamArrangement::build(beams::fig11_scene());
  const auto d = beams::together_filter(C);
  const auto w2 = C.alphabet().parse_word("a b c a c");
  filter::ProductFilter P(C.graph(), 2, true, {{0, 0}, {1, 1}, {2, 2}});
  filter::State s = d.initial;
  std::string trail = d.names[s];
  bool agree = true;
  for (auto y : w2) {
    P.step(y);
    s = d.step(s, y);
    trail += " -" + C.alphabet().format(y) + "-> " + d.names[s];
    agree = agree && beams::together_reading(C, P.assignments()) == d.names[s];
  }
  R.result("Two bodies in the ring of Fig. 11, starting together: the " + std::to_string(d.size()) +
           "-state filter runs " + trail + "; the product filter over region pairs (" + std::to_string(P.size()) +
           " possible pairs at the end) gives the same answer at every step: " + (agree ? "yes" : "NO") + ".");
}

}  // namespace preimage::cli
