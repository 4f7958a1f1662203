// Classes that keep a pointer or reference to an input must not accept a temporary: a
// temporary would be destroyed at the end of the statement and leave them dangling
// (issue 25, defect 6). Their rvalue constructors are deleted; this file fails to compile
// if one comes back. (CellLocator copies what it needs and accepts temporaries.)
#include <gtest/gtest.h>
#include <preimage/beams/alphabet.hpp>
#include <preimage/beams/homotopy.hpp>
#include <preimage/beams/region_filter.hpp>
#include <preimage/decompose/boustrophedon.hpp>
#include <preimage/decompose/cell_locator.hpp>
#include <preimage/decompose/planner.hpp>
#include <preimage/decompose/trapezoidal.hpp>
#include <preimage/error.hpp>
#include <preimage/filter/product_filter.hpp>
#include <preimage/filter/subset_automaton.hpp>
#include <preimage/filter/subset_filter.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/triangulation.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/geometry/visibility_graph.hpp>
#include <preimage/scene/import.hpp>
#include <preimage/tracking/simulation.hpp>
#include <preimage/wallfollow/robot.hpp>

#include <istream>
#include <memory>
#include <optional>
#include <type_traits>

using namespace preimage;
using geometry::Environment;
using filter::TransitionSystem;

namespace {

// Constructible from an lvalue, not from a temporary.
template <class T, class In, class... Rest>
constexpr bool lvalue_only = std::is_constructible_v<T, const In&, Rest...> && !std::is_constructible_v<T, In&&, Rest...> &&
                             !std::is_constructible_v<T, In, Rest...>;

static_assert(lvalue_only<geometry::Triangulation, Environment>);
static_assert(lvalue_only<geometry::VisibilityIndex, Environment>);
static_assert(lvalue_only<geometry::VisibilityGraph, geometry::VisibilityIndex>);
static_assert(lvalue_only<geometry::ConfigurationSpace, Environment, double>);
static_assert(lvalue_only<decompose::TrapezoidalDecomposition, Environment>);
static_assert(lvalue_only<decompose::BoustrophedonDecomposition, Environment>);
static_assert(lvalue_only<decompose::BoustrophedonDecomposition, Environment, double>);
static_assert(lvalue_only<decompose::TrapezoidalPlanner, decompose::TrapezoidalDecomposition>);
static_assert(lvalue_only<filter::SubsetFilter, TransitionSystem>);
static_assert(lvalue_only<filter::SubsetAutomaton, TransitionSystem>);
static_assert(lvalue_only<filter::ProductFilter, TransitionSystem, std::size_t, bool>);
static_assert(lvalue_only<beams::RegionFilter, beams::BeamArrangement>);
static_assert(lvalue_only<beams::BasisWordFilter, beams::LoopBasis>);
static_assert(lvalue_only<beams::WordReader, beams::Alphabet, std::istream&>);
static_assert(lvalue_only<wallfollow::Simulator, Environment, const geometry::Point&, const geometry::Vector&>);
static_assert(std::is_constructible_v<beams::GraphEmbedding, const beams::BeamArrangement&, const beams::LoopBasis&>);
static_assert(!std::is_constructible_v<beams::GraphEmbedding, beams::BeamArrangement&&, const beams::LoopBasis&>);
static_assert(!std::is_constructible_v<beams::GraphEmbedding, const beams::BeamArrangement&, beams::LoopBasis&&>);
static_assert(!std::is_constructible_v<beams::GraphEmbedding, beams::BeamArrangement&&, beams::LoopBasis&&>);

// TrackingScenario::from_scene keeps a pointer to the scene's environment.
template <class S>
concept from_scene_accepts = requires(S&& s) { tracking::TrackingScenario::from_scene(static_cast<S&&>(s)); };
static_assert(from_scene_accepts<const scene::Scene&>);
static_assert(!from_scene_accepts<scene::Scene&&>);

}  // namespace

// The one-argument importers read a file: a path that is not a file is "cannot open", not
// a JSON syntax error at byte 1 (issue 25, defect 6).
TEST(Lifetimes, ImportersTakingAPathSayTheFileCannotBeOpened) {
  const std::string missing = std::string(PREIMAGE_FIXTURES) + "/no_such_plan.json";
  for (auto import : {+[](const std::string& p) { return scene::import_houseexpo(p); },
                      +[](const std::string& p) { return scene::import_visilibity(p); }}) {
    try {
      import(missing);
      ADD_FAILURE() << "imported a missing file";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), missing + ": cannot open file");
    }
  }
  const auto s = scene::import_visilibity(std::string(PREIMAGE_FIXTURES) + "/visilibity/room_with_pillar.txt");
  ASSERT_TRUE(s.environment);
  EXPECT_EQ(s.environment->num_vertices(), 8u);
  EXPECT_EQ(s.environment->num_holes(), 1u);
}

// CellLocator copies the bounds it searches, so it may outlive its decomposition (and be
// built from a temporary): the same answers after the decomposition is destroyed.
TEST(Lifetimes, CellLocatorOutlivesItsDecomposition) {
  const Environment env = Environment::make({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {{{3, 2}, {5, 2}, {5, 4}, {3, 4}}});
  auto d = std::make_unique<decompose::TrapezoidalDecomposition>(env);
  const decompose::CellLocator kept(*d);
  std::vector<std::optional<std::uint32_t>> before;
  const std::vector<geometry::Point> qs = {{1, 1}, {4, 1}, {4, 5}, {8, 3}, {4, 3}, {11, 3}};
  for (const auto& q : qs) before.push_back(kept.locate(q));
  d.reset();
  for (std::size_t i = 0; i < qs.size(); ++i) EXPECT_EQ(kept.locate(qs[i]), before[i]) << i;
  EXPECT_FALSE(before[4]);  // inside the hole
  EXPECT_TRUE(before[0] && before[1] && before[2] && before[3]);
  const decompose::CellLocator from_temporary(decompose::TrapezoidalDecomposition{env});
  EXPECT_EQ(from_temporary.locate(qs[1]), before[1]);
}
