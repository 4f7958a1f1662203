// Every command's library work on the ~10^5-vertex scenes of the scale tests (issue 26:
// circle, star, square with collinear runs, office of 16,640 walls), each against a CGAL
// reference on the same input in the same run:
//   validate      Environment::make + the O(n) and O(n log n) parts of the report, against
//                 CGAL::is_simple_2 on every ring (which checks less: rings against rings
//                 and the nesting of holes are not looked at);
//   visibility    VisibilityIndex (triangulation) + V(start), against CGAL's
//                 Triangular_expansion_visibility_2 (arrangement + its own CDT) + V(start);
//   decompose     trapezoidal and boustrophedon, against CGAL's arrangement + decompose();
//   plan          shortest (visibility graph) and trapezoidal, point robot, start to goal,
//                 against CGAL's constrained Delaunay triangulation of the edges (the
//                 first step of any such planner).
// One iteration each (a run is seconds at most); outputs are checked, not just timed.
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/decompose/planner.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/geometry/visibility.hpp>

#include "ratio_reporter.hpp"
#include "support/cgal_oracle.hpp"
#include "support/large_scenes.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

using namespace preimage;

namespace {

const testing::LargeScene& scene(std::size_t k) {
  static const std::vector<testing::LargeScene> all = testing::large_scenes();
  return all[k];
}
const geometry::Environment& env(std::size_t k) { return *scene(k).scene.environment; }

void validate_preimage(benchmark::State& state) {
  const auto& E = env(static_cast<std::size_t>(state.range(0)));
  std::vector<geometry::Ring> holes;
  for (std::size_t r = 1; r < E.num_rings(); ++r) holes.push_back(E.ring(r));
  for (auto _ : state) {
    auto made = geometry::Environment::make(E.ring(0), holes);
    auto straight = geometry::straight_vertices(made);
    auto equal_x = geometry::find_equal_x(made.vertices());
    benchmark::DoNotOptimize(straight);
    benchmark::DoNotOptimize(equal_x);
  }
}

void validate_reference(benchmark::State& state) {
  const auto& E = env(static_cast<std::size_t>(state.range(0)));
  std::vector<geometry::Ring> rings;
  for (std::size_t r = 0; r < E.num_rings(); ++r) rings.push_back(E.ring(r));
  for (auto _ : state) {
    bool simple = true;
    for (const auto& r : rings) simple &= CGAL::is_simple_2(r.begin(), r.end(), geometry::Kernel());
    if (!simple) state.SkipWithError("CGAL: a ring is not simple");
  }
}

void visibility_preimage(benchmark::State& state) {
  const std::size_t k = static_cast<std::size_t>(state.range(0));
  std::size_t vertices = 0;
  for (auto _ : state) {
    const geometry::VisibilityIndex index(env(k));
    vertices = index.compute(*scene(k).scene.start).vertices.size();
  }
  state.counters["vertices"] = static_cast<double>(vertices);
}

void visibility_reference(benchmark::State& state) {
  const std::size_t k = static_cast<std::size_t>(state.range(0));
  const geometry::Point q = *scene(k).scene.start;
  for (auto _ : state) {
    const testing::CgalVisibility cgal(env(k));
    auto v = cgal.compute(q, geometry::Location{geometry::Location::Kind::Interior, 0});
    benchmark::DoNotOptimize(v);
  }
}

void decompose_preimage(benchmark::State& state) {
  std::size_t cells = 0;
  for (auto _ : state) cells = decompose::TrapezoidalDecomposition(env(static_cast<std::size_t>(state.range(0)))).cells().size();
  state.counters["cells"] = static_cast<double>(cells);
}

void boustrophedon_preimage(benchmark::State& state) {
  std::size_t cells = 0;
  for (auto _ : state) cells = decompose::BoustrophedonDecomposition(env(static_cast<std::size_t>(state.range(0)))).cells().size();
  state.counters["cells"] = static_cast<double>(cells);
}

void decompose_reference(benchmark::State& state) {
  for (auto _ : state) {
    auto vd = testing::vertical_decomposition(testing::make_arrangement(env(static_cast<std::size_t>(state.range(0)))));
    benchmark::DoNotOptimize(vd);
  }
}

template <decompose::PlanMethod Method>
void plan_preimage(benchmark::State& state) {
  const auto& s = scene(static_cast<std::size_t>(state.range(0))).scene;
  std::size_t points = 0;
  for (auto _ : state) {
    const auto p = decompose::plan_path(*s.environment, *s.start, *s.goal, 0, Method);
    if (!p.found) state.SkipWithError("no path");
    points = p.path.size();
  }
  state.counters["points"] = static_cast<double>(points);
}

void plan_reference(benchmark::State& state) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag>;
  const auto& E = env(static_cast<std::size_t>(state.range(0)));
  std::size_t faces = 0;
  for (auto _ : state) {
    CDT cdt;
    for (std::size_t r = 0; r < E.num_rings(); ++r) {
      const auto ring = E.ring(r);
      cdt.insert_constraint(ring.begin(), ring.end(), true);
    }
    faces = cdt.number_of_faces();
  }
  state.counters["faces"] = static_cast<double>(faces);
}

void cases(benchmark::internal::Benchmark* b) {
  b->ArgName("scene")->Unit(benchmark::kMillisecond)->Iterations(1);
  for (int k = 0; k < 4; ++k) b->Arg(k);
}

}  // namespace

// Scene numbers: 0 circle_100k, 1 star_100k, 2 collinear_100k, 3 office_100k.
BENCHMARK(validate_preimage)->Name("validate/preimage")->Apply(cases);
BENCHMARK(validate_reference)->Name("validate/reference")->Apply(cases);
BENCHMARK(visibility_preimage)->Name("visibility/preimage")->Apply(cases);
BENCHMARK(visibility_reference)->Name("visibility/reference")->Apply(cases);
BENCHMARK(decompose_preimage)->Name("decompose/preimage")->Apply(cases);
BENCHMARK(decompose_reference)->Name("decompose/reference")->Apply(cases);
BENCHMARK(boustrophedon_preimage)->Name("boustrophedon/preimage")->Apply(cases);
BENCHMARK(decompose_reference)->Name("boustrophedon/reference")->Apply(cases);
BENCHMARK(plan_preimage<decompose::PlanMethod::Shortest>)->Name("plan-shortest/preimage")->Apply(cases);
BENCHMARK(plan_reference)->Name("plan-shortest/reference")->Apply(cases);
BENCHMARK(plan_preimage<decompose::PlanMethod::Trapezoidal>)->Name("plan-trapezoidal/preimage")->Apply(cases);
BENCHMARK(plan_reference)->Name("plan-trapezoidal/reference")->Apply(cases);

int main(int argc, char** argv) { return preimage::bench::run_with_ratios(argc, argv); }
