// SPDX-License-Identifier: Apache-2.0
// Demo section of the wallfollow module: the Fig. 3 environment, its cut ordering
// learned by the robot through actions and sensors alone, the cut diagram, and the
// vertex count and winding number from the I-maps.
#include "demo.hpp"

#include <preimage/scene/scene.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/imaps.hpp>
#include <preimage/wallfollow/learn.hpp>

namespace preimage::cli {

namespace {
// Fig. 3 of the wall-following paper (examples/wallfollow/fig03_two_reflex.json).
geometry::Environment fig3() {
  return geometry::Environment::make({{0, 0}, {2, 1}, {4, 0}, {4, 4}, {2, 2.5}, {0, 4}}, {});
}
}  // namespace

void demo_wallfollow(DemoContext& ctx) {
  using namespace wallfollow;
  auto& R = ctx.report;
  R.section("Wall-following robot: counting, and the cut ordering (wall-following paper, IV-V)");
  const auto env = fig3();
  const auto T = true_cut_ordering(env);
  ctx.figure("wallfollow-fig3.svg", cuts_figure(env, T).str(),
             "Fig. 3: two reflex vertices and their four cuts, computed by exact ray shooting");
  Simulator count_sim(env, geometry::Point(3, 2), geometry::Vector(1, 0));
  const CountingIMaps k = count_by_following(count_sim, false, 100);
  R.result("Counting with a pebble (IV): INIT, DROP, then RFOLLOW until Prop. 2 answers: " + std::to_string(k.k8) +
           " vertices after " + std::to_string(count_sim.actions()) + " actions, winding number " + std::to_string(k.k5) +
           " about the pebble.");
  Simulator sim(env, geometry::Point(1, 3), geometry::Vector(1, 0));
  const auto L = learn_cut_ordering(sim);
  const bool same = L.ordering.canonical() == T.ordering.canonical();
  R.result("True cut ordering " + T.ordering.str() + " (eq. 12). Strategy 1, through the robot's actions and sensors only, "
           "learned " + L.ordering.str() + " (v1 = where it dropped the pebble; eq. 13 is this relabelling) with " +
           std::to_string(L.actions) + " primitives and " + std::to_string(L.comparisons) +
           " pebble comparisons; equal up to relabelling: " + (same ? "yes" : "NO") + ".");
  // The robot names the pebble's vertex v1; draw what it learned with the figure's names
  // (the relabelling that makes the two equal), so both figures say v2 and v5.
  std::size_t shift = 0;
  while (shift < L.ordering.n && L.ordering.relabelled(shift) != T.ordering) ++shift;
  const bool named = shift < L.ordering.n;
  ctx.figure("wallfollow-cut-diagram.svg",
             cut_diagram(named ? L.ordering.relabelled(shift) : L.ordering,
                         named ? "learned cut ordering, in the names of Fig. 3" : "learned cut ordering (robot's names)")
                 .str(),
             "Cut diagram (Fig. 4a) of the learned ordering: chords cross exactly where cuts cross (Prop. 4)" +
                 std::string(named ? "; the robot's v1 is v" + std::to_string((L.ordering.n - shift) % L.ordering.n + 1) +
                                         " of Fig. 3, relabelled here"
                                   : ""));
}

}  // namespace preimage::cli
