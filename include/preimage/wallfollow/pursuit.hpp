// SPDX-License-Identifier: Apache-2.0
// Pursuit-evasion by the wall-following robot (section VI of the wall-following paper).
// The robot knows only its cut ordering (learned by Strategy 1) and its sensors; it plans
// in a derived I-space and returns a plan: actions RFOLLOW, LFOLLOW, JUMP from where it
// stands, after which every evader has been seen.
//
// - Strategy 2 (gap sensor): I_gap = (position in the cut ordering, 0/1 label per shadow
//   component); the robot executes every motion once to read its gap events, then
//   searches I_gap breadth-first (complete, Proposition 8).
// - Strategy 3 (bitangent sensor): I_bit = (position, partition pi(A) of the active
//   primitives into compounds, labels); primitives appear and disappear at inflections
//   (known from the cut ordering), compounds split and merge at bitangent rays
//   (Proposition 9); the robot executes every motion once to read the crossings.
// - Strategies 4 + 5 (pebble visibility): learn the bitangents B(i, j) among the candidates
//   C(i, j) (Proposition 11) and where their rays end, with the pebble; then Strategy 3 on
//   what was learned, crossings decided from the cut ordering (Proposition 4).
// - Strategy 6 (no special sensor): every candidate C(i, j) taken as a bitangent, its ray
//   ends approximated conservatively (Propositions 13-15), Strategy 3's update in the
//   order of Lemma 16.
// Labels use filter::ShadowLabels (the shadow-label filter shared with module pursuit).
#pragma once
#include <preimage/filter/shadow_labels.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/learn.hpp>
#include <preimage/wallfollow/robot.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace preimage::wallfollow {

/// Where the robot stands: a point of its cut ordering (index into CutOrdering::points)
/// and how it arrived, which decides the cut a JUMP takes (+1 after RFOLLOW,
/// counter-clockwise; -1 after LFOLLOW; 0 after a JUMP or INIT).
struct Position {
  std::uint32_t at = 0;
  std::int8_t arrived = 0;
  bool operator==(const Position&) const = default;
};

/// A motion: from point `at` by `u`; for JUMP also the arrival that picks the cut.
struct Motion {
  std::uint32_t at = 0;
  Action u = Action::RFollow;
  std::int8_t arrived = 0;  // JUMP only
  auto operator<=>(const Motion&) const = default;
};
Motion motion_of(const Position& p, Action u);

/// What the gap sensor said about every motion (Strategy 2's exploration): the number of
/// shadow components at each point, and each motion's events composed into one
/// correspondence.
struct GapTable {
  std::vector<long> gaps_at;  // per point of the ordering
  std::map<Motion, filter::ShadowTransition> transitions;
};

/// A primitive shadow component (VI.C): R_v or L_v of a reflex vertex v whose neighbour
/// before (R) or after (L) it is convex. Id 2 v + (right ? 1 : 0).
using PrimitiveId = std::uint32_t;

/// The cut ordering as the robot uses it: the moves of III.A, boundary arcs, primitives.
/// Boundary places are integer keys 4 k + s along the cyclic order: s = 0 point k, 1 just
/// after it, 2 strictly between point k and point k + 1 (a bitangent endpoint), 3 just
/// before point k + 1.
class OrderingMap {
 public:
  explicit OrderingMap(CutOrdering o);
  const CutOrdering& ordering() const { return o_; }
  std::size_t size() const { return o_.points.size(); }
  std::size_t n() const { return o_.n; }
  std::uint32_t vertex(std::uint32_t v) const { return vertex_at_[v]; }
  std::uint32_t cut(std::uint32_t v, bool left) const { return cut_at_[2 * v + (left ? 0 : 1)]; }
  /// Start vertex of the edge holding point k (k itself for a vertex).
  std::uint32_t edge_of(std::uint32_t k) const { return edge_of_[k]; }
  bool is_vertex(std::uint32_t k) const { return o_.points[k].kind == CutPoint::Kind::Vertex; }
  std::string name(std::uint32_t k) const;

  /// The position after u (RFOLLOW, LFOLLOW or JUMP) with the pebble held or lying at
  /// point `pebble` (a follow stops there), or nothing when u does not apply.
  std::optional<Position> move(const Position& p, Action u, std::optional<std::uint32_t> pebble = std::nullopt) const;
  /// The observation the touch sensor gives at point k.
  Touch touch_at(std::uint32_t k) const;

  std::uint64_t key(std::uint32_t k, unsigned s = 0) const { return 4ull * k + s; }
  std::uint64_t before_vertex(std::uint32_t v) const { return (key(vertex(v)) + 4 * size() - 1) % (4 * size()); }
  std::uint64_t after_vertex(std::uint32_t v) const { return key(vertex(v), 1); }
  /// Is x strictly inside the counter-clockwise arc from a to b?
  bool in_arc(std::uint64_t x, std::uint64_t a, std::uint64_t b) const;
  /// Counter-clockwise distance from a to b in keys.
  std::uint64_t ccw(std::uint64_t a, std::uint64_t b) const { return (b + 4 * size() - a) % (4 * size()); }

  /// Primitives of the environment, ascending.
  const std::vector<PrimitiveId>& primitives() const { return primitives_; }
  /// The boundary germ inside the primitive (next to its vertex's edge it hides).
  std::uint64_t germ(PrimitiveId p) const { return p % 2 ? before_vertex(p / 2) : after_vertex(p / 2); }
  /// A(x): primitives active at point k (R_v on (v, r_v), L_v on (l_v, v)), ascending.
  const std::vector<PrimitiveId>& active(std::uint32_t k) const { return active_[k]; }
  /// v_j lies on the side of v_i where R_i is active, (v_i, r_i) (else on (l_i, v_i)).
  bool on_right_side(std::uint32_t i, std::uint32_t j) const;

 private:
  CutOrdering o_;
  std::vector<std::uint32_t> vertex_at_, cut_at_, edge_of_;
  std::vector<PrimitiveId> primitives_;
  std::vector<std::vector<PrimitiveId>> active_;
};

/// A bitangent as a strategy knows it: reflex vertices i, j and where its rays end (keys;
/// `b_ij` beyond v_i, `b_ji` beyond v_j). Strategy 3 learns b_ji from the sensor when it
/// crosses the ray at v_i; Strategies 5 and 6 know (or bound) both.
struct KnownBitangent {
  std::uint32_t i = 0, j = 0;
  std::uint64_t b_ij = 0, b_ji = 0;
};

/// Crossing of the ray beyond v_i (the closer vertex) of the bitangent of v_i and v_j,
/// whose other ray ends at b_ji; a merge when the robot enters the side where the two
/// shadows are one.
struct RayCrossing {
  std::uint32_t i = 0, j = 0;
  std::uint64_t b_ji = 0;
  bool merge = false;
};

/// The I-state of Strategy 3 at a known position: for each active primitive (ascending,
/// as OrderingMap::active gives them) its compound, compounds numbered by first member;
/// and one label per compound.
struct CompoundState {
  std::vector<std::uint16_t> compound;
  filter::ShadowLabels labels;
  bool operator==(const CompoundState&) const = default;
};

/// Strategy 3's information transition (VI.C, in the order of Lemma 16): splits on the
/// old active set, then primitives that became active get label 0 and inactive ones
/// leave their compounds, then merges on the new active set. Compounds of a split or
/// merge: the active primitives on the arc between v_j and b_ji without v_i, and on the
/// arc from v_i to the nearer of v_j and b_ji away from b_ij (Proposition 9).
CompoundState compound_transition(const OrderingMap& m, std::uint32_t from, const CompoundState& s, std::uint32_t to,
                                  const std::vector<RayCrossing>& crossings);
/// The two sets of Proposition 9 for a crossing (keys of primitives' germs are tested).
std::pair<std::vector<PrimitiveId>, std::vector<PrimitiveId>> proposition9_sets(const OrderingMap& m, const RayCrossing& c,
                                                                                const std::vector<PrimitiveId>& active);

/// Crossings of a move from point `from` to `to` with the rays of known bitangents: a
/// ray is crossed when the robot changes sides of it (the ray from v_i to b_ij cuts E;
/// the merged side is the arc between its ends without v_j).
std::vector<RayCrossing> crossings_of(const OrderingMap& m, const std::vector<KnownBitangent>& bitangents,
                                      std::uint32_t from, std::uint32_t to);

/// C(i, j) of Proposition 11: v_i not in (r_j, l_j) and v_j not in (r_i, l_i).
bool bitangent_candidate(const OrderingMap& m, std::uint32_t i, std::uint32_t j);
/// Strategy 6's bitangents: every candidate, ends approximated by Propositions 13-15.
std::vector<KnownBitangent> approximate_bitangents(const OrderingMap& m);

/// A time after which a strategy gives up (outcome Budget); none: no time limit.
using Deadline = std::optional<std::chrono::steady_clock::time_point>;

/// Strategy 2's search over I_gap from `start` (every label 1). Fills outcome, plan,
/// states and labels_along; gives up after `max_states` I-states or at `deadline`.
struct PursuitReport;
void search_gap(const Position& start, const OrderingMap& m, const GapTable& table, std::size_t max_states, PursuitReport& rep,
                const Deadline& deadline = std::nullopt);

/// Strategy 3's search over I_bit from `start` (every active primitive its own compound,
/// labelled 1) with crossings decided from `bitangents` (Strategies 5 and 6). Fills
/// outcome, plan, states, bitangents and labels_along; gives up as search_gap does.
struct PursuitReport;
void search_compounds(const Position& start, const OrderingMap& m, const std::vector<KnownBitangent>& bitangents,
                      std::size_t max_states, PursuitReport& rep, const Deadline& deadline = std::nullopt);

enum class PursuitSensor { Gap, Bitangent, Pebble, None };
const char* to_string(PursuitSensor s);
/// The simulator's sensors a strategy needs (none beyond III.A for Strategy 6).
Sensors sensors_of(PursuitSensor s);

struct PursuitOptions {
  PursuitSensor sensor = PursuitSensor::Gap;
  std::size_t max_states = 20'000'000;
  /// Give up (outcome Budget, `out_of_time`) once this time has passed: checked before
  /// every action of the robot (Strategy 1, fetching the pebble, Strategy 2's and 3's
  /// exploration, Strategy 4) and every 256 I-states of a search.
  Deadline deadline;
  /// Called before every action of the robot (e.g. to redraw a progress line).
  std::function<void()> on_action;
  LearnOptions learn;
};

struct PursuitReport {
  LearnReport learned;            // Strategy 1
  std::size_t prepare_actions = 0;  // after learning: fetching the pebble, exploring motions (2, 3), Strategy 4 (5)
  Position start;                 // where the plan starts
  enum class Outcome { Plan, NoPlan, Budget } outcome = Outcome::NoPlan;
  bool out_of_time = false;       // Budget because the deadline passed (else: max_states)
  std::vector<Action> plan;
  std::size_t states = 0;         // I-states explored
  std::size_t bitangents = 0;     // known to the strategy: sensed (3), learned (5), candidates (6)
  std::vector<KnownBitangent> known;  // learned by Strategy 4 (5) or approximated (6), robot's labels
  /// The I-state after each plan action (start first): labels ("v3 0110"), or compounds and
  /// their labels ("v3 {L2 R5}:1 {L7}:0").
  std::vector<std::string> labels_along;
  /// Strategy 2: what the exploration read (for searching again, e.g. in benchmarks).
  std::shared_ptr<const GapTable> gap_table;
};

/// Runs the chosen strategy through the robot interface: Strategy 1, then fetching the
/// pebble, then what the sensor needs (exploring every motion once for the gap and
/// bitangent sensors, Strategy 4 for the pebble), then the search. Does not execute the
/// plan. Throws std::runtime_error when the robot does not behave as the model (a
/// reading contradicts the cut ordering).
PursuitReport pursue(RobotInterface& robot, const PursuitOptions& options);

/// Applies a plan, stopping when the detection sensor fires: the number of actions applied
/// by then (0: the evader is seen where the plan starts), or nothing if it never fires.
std::optional<std::size_t> execute(RobotInterface& robot, const std::vector<Action>& plan);

}  // namespace preimage::wallfollow
