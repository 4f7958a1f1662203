// SPDX-License-Identifier: Apache-2.0
// Paths up to homotopy and winding numbers from a sensor word (beams paper, sections 5
// and 6, Appendix A).
//
//  - LoopBasis: a minimally sufficient collection of disjoint directed beams forming a
//    spanning tree with the outer boundary and the obstacles as vertices (5.2, Fig. 15b).
//    Generator g is the loop crossing basis beam g once, positively, and no other basis
//    beam; it winds once around every obstacle of the subtree below g (Fig. 16), which is
//    the correction from letter counts to winding numbers of 6.2. Built from the scene's
//    own DDD beams (tree basis, 5.1/5.2), from one vertical imaginary beam per obstacle,
//    or from imaginary beams the user gives (5.3, step 4).
//  - BasisWordFilter: for a tree basis, the sensor word is the F_n element by renaming
//    (Props. 5.1, 5.3) after deleting dropped beams' letters; reduction and winding
//    counters make it a constant-time filter (6.1).
//  - GraphEmbedding: G embedded in free space by sample points and one sample path per
//    beam piece and direction (5.3 phase 1, steps 2-5), each with its word in the basis.
//  - HomotopySet / WindingSet: for any sufficient collection, the set of classes a word
//    allows (5.3 phase 2, 6.3), computed as the product of the pruned trellis H with a
//    group: states (start region, region, element), elements reduced incrementally in the
//    Cayley tree of F_n (homotopy) or in Z^n (winding), duplicates merged at every step
//    rather than after enumerating region sequences one by one.
#pragma once
#include <preimage/beams/arrangement.hpp>
#include <preimage/beams/free_group.hpp>
#include <preimage/scene/scene.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace preimage::beams {

/// Throws InputError unless every region is simply connected (the collection is
/// sufficient, 5.2): names the region and an obstacle it surrounds.
void require_sufficient(const BeamArrangement& arrangement);

class LoopBasis {
 public:
  enum class Kind { Tree, Imaginary, User };

  /// The scene's own beams (5.2): a spanning tree over directed beams whose label no
  /// other beam shares, and that cross no other beam unless `allow_crossings` (enough
  /// for winding numbers, 6.3). InputError names an obstacle the tree cannot reach.
  static LoopBasis tree(const BeamArrangement& arrangement, const scene::Scene& scene, bool allow_crossings = false);
  /// One vertical imaginary beam per obstacle, up from its highest vertex (rightmost
  /// among equals) to the first boundary met, directed so the positive crossing is
  /// counter-clockwise about the obstacle below (5.3, step 4). Generators are named o1..on.
  static LoopBasis imaginary(const BeamArrangement& arrangement, const scene::Scene& scene);
  /// Imaginary beams given by the user (scene key "imaginary_beams"): validated like
  /// beams, pairwise disjoint, with a spanning tree among them; the others are unused.
  static LoopBasis user(const BeamArrangement& arrangement, const scene::Scene& scene);

  Kind kind() const { return kind_; }
  std::size_t rank() const { return child_.size(); }  // = number of obstacles
  const std::vector<std::string>& names() const { return names_; }
  /// Basis beam g as a directed segment (from -> to) or, for an unbounded one, a ray.
  const ExactPoint& from(std::uint32_t g) const { return from_[g]; }
  const ExactPoint& to(std::uint32_t g) const { return to_[g]; }
  bool ray(std::uint32_t g) const { return ray_[g]; }
  /// The tree: the obstacle below beam g, and above it (an obstacle or kOuter).
  std::uint32_t child(std::uint32_t g) const { return child_[g]; }
  std::uint32_t parent(std::uint32_t g) const { return parent_[g]; }
  /// +1 if a positive crossing of beam g runs counter-clockwise about its child.
  int sign(std::uint32_t g) const { return sign_[g]; }
  /// Obstacles generator g winds around (the subtree below beam g), sorted.
  const std::vector<std::uint32_t>& encloses(std::uint32_t g) const { return encloses_[g]; }
  /// Tree basis: the scene beam behind generator g. Imaginary/user: kNone.
  std::uint32_t scene_beam(std::uint32_t g) const { return scene_beam_[g]; }
  /// A perfect collection (5.1): the scene's beams are exactly one outer beam per obstacle.
  bool perfect() const { return perfect_; }
  /// Scene beams (indices) a tree basis dropped.
  const std::vector<std::uint32_t>& dropped() const { return dropped_; }

  /// Tree basis: the letter a sensor symbol maps to (Prop. 5.3), 0 for a dropped beam.
  Letter letter(Symbol y) const { return y < letter_of_symbol_.size() ? letter_of_symbol_[y] : 0; }

  /// Winding numbers about each obstacle from generator exponent sums (6.2).
  std::vector<std::int64_t> winding(std::span<const std::int64_t> exponents) const;
  std::vector<std::int64_t> winding(const FreeWord& w) const { return winding(w.abelianised(rank())); }
  /// The word of a path read off its crossings with the basis beams (positive crossing
  /// of beam g: generator g), reduced.
  FreeWord crossing_word(std::span<const ExactPoint> path) const;
  /// The basis loops of Fig. 16: for each generator, a closed path crossing its beam
  /// once and no other basis beam (drawn in the arrangement of the basis beams alone).
  std::vector<std::vector<ExactPoint>> loops() const;
  /// One line per generator: "o2: (4, 3) -> (4, 5), below o2, above o1, encloses o1 o2".
  std::vector<std::string> describe(const BeamArrangement& arrangement) const;

 private:
  static LoopBasis from_beams(const BeamArrangement& arrangement, const scene::Scene& scene, Kind kind,
                              std::vector<scene::Beam> beams, const std::vector<std::uint32_t>& scene_index,
                              const std::string& where);
  Kind kind_ = Kind::Imaginary;
  std::vector<std::string> names_;
  std::vector<ExactPoint> from_, to_;
  std::vector<char> ray_;
  std::vector<std::uint32_t> child_, parent_, scene_beam_, dropped_;
  std::vector<int> sign_;
  std::vector<std::vector<std::uint32_t>> encloses_;
  std::vector<std::vector<std::uint32_t>> path_to_root_;  // per obstacle: generators above it
  std::vector<Letter> letter_of_symbol_;
  bool perfect_ = false;
  scene::Scene basis_scene_;  // the environment with only the basis beams (for loops())
};

/// Sections 5.1/5.2/6.1/6.2 as a filter: each observation is renamed to its basis letter
/// (dropped beams' letters deleted), appended with free reduction, and counted; O(1)
/// amortised per observation.
class BasisWordFilter {
 public:
  explicit BasisWordFilter(const LoopBasis& basis);
  BasisWordFilter(LoopBasis&&) = delete;  // keeps a pointer to the basis
  void step(Symbol y) {
    const Letter x = basis_->letter(y);
    if (x == 0) return;
    word_.push(x);
    exponents_[generator_of(x)] += x > 0 ? 1 : -1;
  }
  const FreeWord& word() const { return word_; }
  const std::vector<std::int64_t>& exponents() const { return exponents_; }
  std::vector<std::int64_t> winding() const { return basis_->winding(exponents_); }

 private:
  const LoopBasis* basis_;
  FreeWord word_;
  std::vector<std::int64_t> exponents_;
};

/// One crossing of the multigraph G (a beam piece in one direction) embedded in free
/// space: its sample path's word in the basis.
struct EmbeddedCrossing {
  std::uint32_t from, to;
  Symbol symbol;
  std::uint32_t half_edge;  // the piece, entering its face
  FreeWord word;
};

class GraphEmbedding {
 public:
  /// Needs a sufficient collection (require_sufficient) for the classes to be right.
  GraphEmbedding(const BeamArrangement& arrangement, const LoopBasis& basis);
  // Keeps pointers to both.
  GraphEmbedding(BeamArrangement&&, const LoopBasis&) = delete;
  GraphEmbedding(const BeamArrangement&, LoopBasis&&) = delete;
  GraphEmbedding(BeamArrangement&&, LoopBasis&&) = delete;
  const BeamArrangement& arrangement() const { return *A_; }
  const LoopBasis& basis() const { return *basis_; }
  /// Crossings from `region` observing y, one per distinct (to, word).
  std::span<const EmbeddedCrossing> out(std::uint32_t region, Symbol y) const {
    const std::size_t k = std::size_t(region) * A_->alphabet().num_symbols() + y;
    return {crossings_.data() + begin_[k], crossings_.data() + begin_[k + 1]};
  }
  const std::vector<EmbeddedCrossing>& crossings() const { return crossings_; }
  /// The word of a path inside free space (a route or return path).
  FreeWord word_of(std::span<const ExactPoint> path) const { return basis_->crossing_word(path); }

 private:
  const BeamArrangement* A_;
  const LoopBasis* basis_;
  std::vector<EmbeddedCrossing> crossings_;
  std::vector<std::uint32_t> begin_;
};

/// Where paths start and end (paper, end of 5.3).
struct PathEnds {
  enum class Mode {
    Closed,  // loops: the body ends in the region it started in; based at that region's sample point
    Open,    // any start and end region; each pair closed by a fixed return path between sample points
    Fixed    // from `start` to `end` (= start for loops), closed by a fixed return path
  } mode = Mode::Closed;
  std::optional<ExactPoint> start, end;
};

/// Z^n as a store of interned vectors with the CayleyTree interface.
class AbelianStore {
 public:
  using Node = std::uint32_t;
  explicit AbelianStore(std::size_t rank = 0);
  Node identity() const { return 0; }
  Node times(Node v, const FreeWord& u);
  std::span<const std::int64_t> vector(Node v) const { return {data_.data() + v * rank_, rank_}; }
  std::size_t num_nodes() const { return count_; }

 private:
  Node intern(const std::vector<std::int64_t>& v);
  std::size_t rank_, count_ = 0;
  std::vector<std::int64_t> data_;
  std::unordered_map<std::uint64_t, std::vector<Node>> by_hash_;
};

/// The classes a sensor word allows, in one group: Store = CayleyTree (homotopy, 5.3)
/// or AbelianStore (winding vectors before the 6.2 correction, 6.3).
template <class Store>
class PathClassSet {
 public:
  using Node = typename Store::Node;
  struct Class {
    Node element;
    std::uint32_t start_region, end_region;  // kNone where the mode merges them
  };
  /// Runs the word. Throws InputError if the state set exceeds max_states.
  PathClassSet(const GraphEmbedding& embedding, const PathEnds& ends, std::span<const Symbol> word,
               std::size_t max_states = std::size_t(1) << 22);

  bool consistent() const { return consistent_; }
  std::size_t inconsistent_at() const { return inconsistent_at_; }
  /// Distinct classes, sorted by (start, end, element order).
  const std::vector<Class>& classes() const { return classes_; }
  const Store& store() const { return store_; }
  Store& store() { return store_; }
  std::size_t peak_states() const { return peak_; }
  /// Possible region sequences (the region filter's answer), as a decimal string.
  const std::string& sequences() const { return sequences_; }

 private:
  Store store_;
  std::vector<Class> classes_;
  bool consistent_ = true;
  std::size_t inconsistent_at_ = 0, peak_ = 0;
  std::string sequences_;
};

using HomotopySet = PathClassSet<CayleyTree>;
using WindingSet = PathClassSet<AbelianStore>;

/// The paper's literal algorithm (5.3 phase 2) as a reference: enumerate region
/// sequences (and, in a multigraph, the piece crossed at each step) one by one, build
/// each sample loop's word, reduce, and remove duplicates. Exponential; for tests and
/// benchmarks. Returns nullopt if more than `limit` sequences exist.
std::optional<std::vector<std::pair<FreeWord, std::pair<std::uint32_t, std::uint32_t>>>> homotopy_by_enumeration(
    const GraphEmbedding& embedding, const PathEnds& ends, std::span<const Symbol> word, std::size_t limit);

}  // namespace preimage::beams
