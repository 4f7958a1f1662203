// SPDX-License-Identifier: Apache-2.0
// Demo section for beams paper sections 5-6: homotopy classes and winding vectors of a
// word on the Fig. 1 scene, the paper's winding example (6), and the commutator of Fig. 18.
#include "common.hpp"
#include "demo.hpp"

#include <preimage/beams/examples.hpp>
#include <preimage/beams/export.hpp>
#include <preimage/beams/homotopy.hpp>
#include <preimage/beams/paths.hpp>
#include <preimage/geometry/queries.hpp>

namespace preimage::cli {

void demo_beams_homotopy(DemoContext& ctx) {
  auto& R = ctx.report;
  R.section("Sensor beams: paths up to homotopy and winding numbers (beams paper, 5-6)");

  // Fig. 1: undirected beams, so the general method with imaginary beams (5.3).
  const scene::Scene s1 = beams::fig1_scene();
  const auto A = beams::BeamArrangement::build(s1);
  beams::require_sufficient(A);
  const auto L = beams::LoopBasis::imaginary(A, s1);
  const beams::GraphEmbedding G(A, L);
  const auto w = A.alphabet().parse_word("cbabdeeefed");
  const beams::HomotopySet H(G, {}, w);
  std::string classes;
  for (auto& c : H.classes()) {
    const auto word = H.store().word(c.element);
    classes += (classes.empty() ? "" : "; ") + word.format(L.names()) + " with winding " + tuple_string(L.winding(word));
  }
  R.result("Fig. 1 scene, loop word cbabdeeefed (undirected beams): " + H.sequences() + " region sequence, " +
           std::to_string(H.classes().size()) + " homotopy classes in the basis of one vertical imaginary beam per obstacle: " +
           classes + ". They differ only in the direction the undirected self-loop f was crossed, one turn around o4.");
  ctx.figure("beams-homotopy-fig1.svg", beams::basis_figure(A, L).str(),
             "Fig. 1 scene with the imaginary beams o1..o4 (dashed) and the basis loops they induce (Fig. 16): o1 hangs "
             "below o2, so the loop of o2 winds around both");

  // The paper's example (5): perfect beams, winding by counters (6.1).
  const scene::Scene s13 = beams::fig13_scene();
  const auto A13 = beams::BeamArrangement::build(s13);
  const auto T13 = beams::LoopBasis::tree(A13, s13);
  beams::BasisWordFilter F(T13);
  for (auto y : A13.alphabet().parse_word("b1 b2 b1' b2 b2 b1 b2' b2' b1 b2' b2' b2' b2'")) F.step(y);
  R.result(std::string("Perfect beams (Fig. 13, ") + (T13.perfect() ? "detected as perfect" : "NOT DETECTED") +
           "): the word of (5) is its own reduced word, " + F.word().format(T13.names()) + ", with winding vector " +
           tuple_string(F.winding()) + " as in (6).");

  // Fig. 18: the commutator, drawn as the sample loop of its word.
  const scene::Scene s18 = beams::fig18_scene();
  const auto A18 = beams::BeamArrangement::build(s18);
  const auto T18 = beams::LoopBasis::tree(A18, s18);
  const auto w18 = A18.alphabet().parse_word("a b a' b'");
  beams::BasisWordFilter C(T18);
  for (auto y : w18) C.step(y);
  const auto loop = beams::sample_path(A18, std::vector<std::uint32_t>(w18.size() + 1, 0), w18);
  std::vector<std::int64_t> geo;
  for (std::uint32_t o = 0; o < A18.num_obstacles(); ++o) geo.push_back(geometry::winding_number(loop, A18.obstacle_point(o)));
  R.result("Fig. 18: the word a b a' b' reduces to " + C.word().format(T18.names()) + " (length " +
           std::to_string(C.word().length()) + ", not the identity) yet its winding vector is " + tuple_string(C.winding()) +
           "; the drawn loop's winding numbers, computed geometrically, are " + tuple_string(geo) + ".");
  beams::FigureOptions o;
  for (auto& p : loop) o.path.push_back(geometry::to_double(p));
  o.path_label = "a sample loop for a b a' b' (the commutator)";
  ctx.figure("beams-commutator.svg", beams::arrangement_figure(A18, o).str(),
             "Fig. 18: the commutator loop winds around neither obstacle, but cannot be pulled tight to a point");
}

}  // namespace preimage::cli
