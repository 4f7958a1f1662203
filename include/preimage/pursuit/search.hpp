// SPDX-License-Identifier: Apache-2.0
// The information graph and its search (6.3, Figs. 6.37-6.39).
//
// One pursuer: an information state is (cell, 0/1 label per shadow component); crossing a
// boundary applies its exact transition (filter::ShadowTransition). From the start (all
// labels 1) a Dijkstra search by the Euclidean length of the walk explores every
// reachable information state until one has all labels 0: the plan is the walk, or, when
// the search runs dry, no plan with one pursuer exists (the search is complete). The
// transitions are monotone (fewer contaminated components in, fewer out), so a state
// whose contaminated set contains that of a state already settled in the same cell is
// skipped: it cannot lead anywhere the other cannot, sooner.
//
// k pursuers: one moves at a time between adjacent cells while the others wait at their
// cells' sample points; labels belong to the joint units of joint.hpp (sound; see there).
// Pursuers are interchangeable: states are kept with the cells sorted.
#pragma once
#include <preimage/pursuit/cells.hpp>

#include <optional>
#include <string>
#include <vector>

namespace preimage::pursuit {

/// A plan for k pursuers: one polyline each, all with the same number of points; every
/// pursuer reaches its waypoint i at time i (a pursuer that waits repeats its point). Each
/// segment was certified in free space with geometry::visible before it was returned.
struct Plan {
  struct Move {
    std::uint32_t pursuer;
    std::uint32_t boundary;  // crossed
    std::uint32_t from, to;  // cells
  };
  std::vector<std::vector<Point>> paths;
  std::vector<Move> moves;
  double length = 0;  // total distance walked
  std::uint32_t start_cell = 0;
};

struct SearchOptions {
  std::optional<Point> start;          // every pursuer starts here; unset: anywhere (the best cell)
  std::size_t max_states = 4'000'000;  // information states stored before giving up (memory bound)
  /// false: any plan, states with fewer contaminated components first (usually far fewer
  /// states; still complete, so "no plan" stays a proof; the plan is not the shortest).
  bool shortest = true;
  /// Further budgets (0: none): wall-clock seconds, and megabytes of search state (the
  /// stored states with their labels, the hash table and the queue, estimated).
  double time_limit = 0;
  std::size_t max_mb = 0;
};

struct SearchResult {
  enum class Outcome { Plan, NoPlan, Budget };
  Outcome outcome = Outcome::NoPlan;
  /// Which budget stopped the search (Outcome::Budget): "states", "time" or "memory".
  std::string budget;
  double seconds = 0;      // wall-clock time of the search
  std::size_t bytes = 0;   // estimated memory of the search state at its end
  std::size_t pursuers = 1;
  std::size_t states = 0;       // information states explored (settled, none dominated by another)
  std::size_t stored = 0;       // information states generated and kept (the budget counts these)
  std::size_t transitions = 0;  // boundary crossings evaluated
  std::optional<Plan> plan;
};
const char* to_string(SearchResult::Outcome o);

/// Exhaustive search with `pursuers` pursuers (1: the exact information graph of 6.3).
/// Throws InputError if the start is not in free space.
SearchResult search(const ConservativeCells& cells, std::size_t pursuers, const SearchOptions& options = {});

/// Searches with 1, 2, ..., max_pursuers pursuers and returns the first result with a plan
/// (or the last one). `results` receives every attempt.
SearchResult least_pursuers(const ConservativeCells& cells, std::size_t max_pursuers, const SearchOptions& options,
                            std::vector<SearchResult>* results = nullptr);

/// The one-pursuer search without merging equal information states: depth-first over
/// cell walks, pruning a walk only when it returns to an information state already on
/// itself (a shortest plan never does), up to `max_depth` crossings and `max_nodes`
/// expanded walks. Returns the fewest crossings of a plan, or nullopt; `nodes` receives
/// the walks expanded and `complete` whether the search finished within its budget.
std::optional<std::size_t> search_without_merging(const ConservativeCells& cells, std::uint32_t start_cell,
                                                  std::size_t max_depth, std::size_t max_nodes, std::size_t& nodes,
                                                  bool& complete);

/// The fewest crossings of a one-pursuer plan from `start_cell` (breadth-first over the
/// information graph, equal states merged), or nullopt if none exists; `reached` receives
/// the number of information states reached.
std::optional<std::size_t> fewest_crossings(const ConservativeCells& cells, std::uint32_t start_cell,
                                            std::size_t* reached = nullptr);

}  // namespace preimage::pursuit
