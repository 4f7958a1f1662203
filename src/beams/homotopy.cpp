// SPDX-License-Identifier: Apache-2.0
#include <preimage/beams/homotopy.hpp>
#include <preimage/beams/paths.hpp>
#include <preimage/error.hpp>
#include <preimage/filter/trellis.hpp>
#include <preimage/geometry/queries.hpp>

#include <algorithm>
#include <deque>
#include <functional>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <unordered_set>

namespace preimage::beams {
namespace {

std::string region_name(const BeamArrangement& A, std::uint32_t r) {
  return std::string("region r").append(std::to_string(r)).append(" around ").append(geometry::format_point(A.regions()[r].sample));
}

}  // namespace

// ---------------------------------------------------------------- sufficiency (5.2)
void require_sufficient(const BeamArrangement& A) {
  const auto& H = A.half_edges();
  auto fail = [&](std::uint32_t r, std::uint32_t o) {
    throw InputError("the beams are not sufficient (beams paper 5.2): " + region_name(A, r) +
                     " is not simply connected, it surrounds " + A.obstacle_name(o) +
                     "; join that obstacle to the others or to the outer boundary by a beam");
  };
  for (std::uint32_t r = 0; r < A.num_regions(); ++r) {
    const auto& cycles = A.regions()[r].cycles;
    for (std::size_t c = 1; c < cycles.size(); ++c) {
      // An inner boundary cycle holds an obstacle (beams end on obstacles or the outer boundary).
      std::uint32_t h = cycles[c];
      do {
        const std::uint32_t o = A.vertex_obstacle(H[h].origin);
        if (o != kNone && o != kOuter) fail(r, o);
        h = H[h].next;
      } while (h != cycles[c]);
      throw std::logic_error("require_sufficient: an inner cycle without an obstacle");
    }
  }
  if (A.unbounded()) {
    // A landmark no beam touches is a puncture inside its region.
    std::vector<char> touched(A.num_obstacles(), 0);
    for (std::uint32_t v = 0; v < A.vertices().size(); ++v)
      if (const std::uint32_t o = A.vertex_obstacle(v); o < A.num_obstacles()) touched[o] = 1;
    for (std::uint32_t o = 0; o < A.num_obstacles(); ++o)
      if (!touched[o]) {
        // Not a vertex, so locate() finds the region around it.
        const auto r = A.locate(A.obstacle_point(o));
        if (!r) throw std::logic_error("require_sufficient: a free landmark outside every region");
        fail(*r, o);
      }
  }
}

// ---------------------------------------------------------------- loop bases (5.2, 5.3 step 4)
namespace {

// Breadth-first spanning tree from the outer boundary over beams joining obstacles.
// Returns, per obstacle, the index (into ends) of the beam above it, kNone if unreached.
std::vector<std::uint32_t> spanning_tree(std::size_t n, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& ends) {
  auto id = [&](std::uint32_t o) { return o == kOuter ? static_cast<std::uint32_t>(n) : o; };
  std::vector<std::vector<std::uint32_t>> incident(n + 1);
  for (std::uint32_t i = 0; i < ends.size(); ++i) {
    if (id(ends[i].first) == id(ends[i].second)) continue;  // a beam from an obstacle to itself closes no tree edge
    incident[id(ends[i].first)].push_back(i);
    incident[id(ends[i].second)].push_back(i);
  }
  std::vector<std::uint32_t> above(n, kNone);
  std::vector<char> seen(n + 1, 0);
  std::deque<std::uint32_t> queue{static_cast<std::uint32_t>(n)};
  seen[n] = 1;
  while (!queue.empty()) {
    const std::uint32_t v = queue.front();
    queue.pop_front();
    for (std::uint32_t i : incident[v]) {
      const std::uint32_t w = id(ends[i].first) == v ? id(ends[i].second) : id(ends[i].first);
      if (seen[w]) continue;
      seen[w] = 1;
      above[w] = i;
      queue.push_back(w);
    }
  }
  return above;
}

}  // namespace

LoopBasis LoopBasis::from_beams(const BeamArrangement& A, const scene::Scene& scene, Kind kind, std::vector<scene::Beam> beams,
                                const std::vector<std::uint32_t>& scene_index, const std::string& path) {
  const std::size_t n = A.num_obstacles();
  // The beams' geometry: the scene's own arrangement for a tree basis, otherwise an
  // arrangement of the environment with the given beams alone (which validates them).
  std::vector<BeamGeometry> geo;
  if (kind == Kind::Tree) {
    for (std::uint32_t s : scene_index) geo.push_back(A.beams()[s]);
  } else {
    scene::Scene alone = scene;
    alone.beams = beams;
    alone.imaginary_beams.clear();
    try {
      const BeamArrangement B = BeamArrangement::build(alone);
      geo = B.beams();
      for (std::uint32_t i = 0; i < B.beams().size(); ++i) {
        const auto [first, last] = B.beam_pieces(i);
        if (last - first > 2) throw InputError(path + "[" + std::to_string(i) + "] ('" + beams[i].label + "'): imaginary beams must be disjoint, and this one crosses another");
      }
    } catch (const InputError& e) {
      std::string msg = e.what();
      if (msg.rfind("$.beams[", 0) == 0) msg = path + msg.substr(7);
      throw InputError(msg);
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  for (auto& g : geo) ends.push_back({g.from_obstacle, g.to_obstacle});
  const std::vector<std::uint32_t> above = spanning_tree(n, ends);
  for (std::uint32_t o = 0; o < n; ++o)
    if (above[o] == kNone) {
      if (kind == Kind::Tree)
        throw InputError("basis tree: " + A.obstacle_name(o) +
                         " is not joined to the outer boundary by a tree of directed beams, each with a label of its own"
                         " (and, for homotopy, crossing no other beam; beams paper 5.2); use the imaginary basis");
      throw InputError(path + ": no tree of these beams joins " + A.obstacle_name(o) + " to the outer boundary");
    }

  LoopBasis L;
  L.kind_ = kind;
  // Generators: the tree beams in input order.
  std::vector<std::uint32_t> tree(above.begin(), above.end());
  std::sort(tree.begin(), tree.end());
  std::vector<std::uint32_t> gen_of_beam(geo.size(), kNone);
  for (std::uint32_t g = 0; g < tree.size(); ++g) gen_of_beam[tree[g]] = g;
  for (std::uint32_t g = 0; g < tree.size(); ++g) {
    const std::uint32_t i = tree[g];
    const BeamGeometry& b = geo[i];
    L.names_.push_back(beams[i].label);
    L.from_.push_back(b.from);
    L.to_.push_back(b.to);
    L.ray_.push_back(b.unbounded_to);
    const std::uint32_t child = b.from_obstacle != kOuter && above[b.from_obstacle] == i ? b.from_obstacle : b.to_obstacle;
    const std::uint32_t parent = child == b.from_obstacle ? b.to_obstacle : b.from_obstacle;
    L.child_.push_back(child);
    L.parent_.push_back(parent);
    // Positive = from the right of from->to to its left: counter-clockwise about `from`'s side.
    L.sign_.push_back(child == b.from_obstacle ? +1 : -1);
    L.scene_beam_.push_back(kind == Kind::Tree ? scene_index[i] : kNone);
    L.basis_scene_.beams.push_back(beams[i]);
  }
  L.basis_scene_.environment = scene.environment;
  L.basis_scene_.landmarks = scene.landmarks;
  L.encloses_.assign(tree.size(), {});
  L.path_to_root_.assign(n, {});
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::uint32_t v = o; v != kOuter;) {
      const std::uint32_t g = gen_of_beam[above[v]];
      L.path_to_root_[o].push_back(g);
      L.encloses_[g].push_back(o);
      v = L.parent_[g];
    }
  if (kind == Kind::Tree) {
    L.letter_of_symbol_.assign(A.alphabet().num_symbols(), 0);
    for (std::uint32_t g = 0; g < tree.size(); ++g) {
      const std::uint32_t label = A.beams()[L.scene_beam_[g]].label;
      L.letter_of_symbol_[Alphabet::positive(label)] = generator(g);
      L.letter_of_symbol_[Alphabet::negative(label)] = -generator(g);
    }
    std::vector<char> used(A.beams().size(), 0);
    for (std::uint32_t s : L.scene_beam_) used[s] = 1;
    for (std::uint32_t s = 0; s < A.beams().size(); ++s)
      if (!used[s]) L.dropped_.push_back(s);
    L.perfect_ = A.beams().size() == n && std::all_of(L.parent_.begin(), L.parent_.end(), [](auto p) { return p == kOuter; });
  }
  return L;
}

LoopBasis LoopBasis::tree(const BeamArrangement& A, const scene::Scene& scene, bool allow_crossings) {
  std::vector<std::uint32_t> uses(A.alphabet().num_labels(), 0);
  for (auto& b : A.beams()) ++uses[b.label];
  std::vector<scene::Beam> beams;
  std::vector<std::uint32_t> index;
  for (std::uint32_t i = 0; i < A.beams().size(); ++i) {
    const BeamGeometry& b = A.beams()[i];
    const auto [first, last] = A.beam_pieces(i);
    if (!b.directed || uses[b.label] != 1 || (!allow_crossings && last - first > 2)) continue;
    beams.push_back(scene.beams[i]);
    index.push_back(i);
  }
  return from_beams(A, scene, Kind::Tree, std::move(beams), index, "$.beams");
}

LoopBasis LoopBasis::imaginary(const BeamArrangement& A, const scene::Scene& scene) {
  std::vector<scene::Beam> beams;
  const std::size_t n = A.num_obstacles();
  for (std::uint32_t o = 0; o < n; ++o) {
    scene::Beam b;
    b.label = std::string("o").append(std::to_string(o + 1));
    b.directed = true;
    if (A.unbounded()) {
      // North to the nearest landmark straight above, or to infinity.
      const geometry::Point p = A.landmarks()[o];
      std::optional<geometry::Point> stop;
      for (auto& q : A.landmarks())
        if (q.x() == p.x() && q.y() > p.y() && (!stop || q.y() < stop->y())) stop = q;
      b.from = p;
      b.to = stop ? *stop : geometry::Point(p.x(), p.y() + std::max(1.0, std::abs(p.y())));
      b.shape = stop ? scene::Beam::Shape::Segment : scene::Beam::Shape::Ray;
    } else {
      // Up from the highest vertex (rightmost among equals): locally free above it.
      const auto& env = A.environment();
      std::size_t top = env.ring_begin(o + 1);
      for (std::size_t v = top; v < env.ring_end(o + 1); ++v) {
        const auto c = CGAL::compare_yx(env.vertex(v), env.vertex(top));
        if (c == CGAL::LARGER) top = v;
      }
      const geometry::Point p = env.vertex(top);
      b.from = p;
      b.to = geometry::Point(p.x(), p.y() + std::max(1.0, std::abs(p.y())));
      b.shape = scene::Beam::Shape::Ray;
    }
    beams.push_back(b);
  }
  return from_beams(A, scene, Kind::Imaginary, std::move(beams), {}, "imaginary beams");
}

LoopBasis LoopBasis::user(const BeamArrangement& A, const scene::Scene& scene) {
  if (scene.imaginary_beams.empty()) throw InputError("$.imaginary_beams: the scene gives no imaginary beams");
  for (std::size_t i = 0; i < scene.imaginary_beams.size(); ++i)
    if (!scene.imaginary_beams[i].directed)
      throw InputError("$.imaginary_beams[" + std::to_string(i) + "] ('" + scene.imaginary_beams[i].label +
                       "'): imaginary beams are directed");
  return from_beams(A, scene, Kind::User, scene.imaginary_beams, {}, "$.imaginary_beams");
}

std::vector<std::int64_t> LoopBasis::winding(std::span<const std::int64_t> exponents) const {
  // A loop crosses a curve from obstacle j out to the boundary as often (signed) as it
  // winds around j; the tree path above j is such a curve (6.2).
  std::vector<std::int64_t> v(path_to_root_.size(), 0);
  for (std::size_t j = 0; j < v.size(); ++j)
    for (std::uint32_t g : path_to_root_[j]) v[j] += sign_[g] * exponents[g];
  return v;
}

FreeWord LoopBasis::crossing_word(std::span<const ExactPoint> path) const {
  struct Hit { std::size_t segment; ExactPoint at; Letter x; };
  std::vector<Hit> hits;
  for (std::uint32_t g = 0; g < rank(); ++g)
    for (auto& c : geometry::polyline_crossings(path, from_[g], to_[g], ray_[g]))
      hits.push_back({c.segment, c.at, c.sign > 0 ? generator(g) : -generator(g)});
  std::sort(hits.begin(), hits.end(), [&](const Hit& u, const Hit& v) {
    if (u.segment != v.segment) return u.segment < v.segment;
    return CGAL::compare_distance_to_point(path[u.segment], u.at, v.at) == CGAL::SMALLER;
  });
  FreeWord w;
  for (auto& h : hits) w.push(h.x);
  return w;
}

std::vector<std::vector<ExactPoint>> LoopBasis::loops() const {
  const BeamArrangement B = BeamArrangement::build(basis_scene_);
  if (B.num_regions() != 1) throw std::logic_error("LoopBasis::loops: the basis beams cross");
  std::vector<std::vector<ExactPoint>> out;
  for (std::uint32_t g = 0; g < rank(); ++g) out.push_back(crossing_path(B, B.beam_pieces(g).first));
  return out;
}

std::vector<std::string> LoopBasis::describe(const BeamArrangement& A) const {
  auto side = [&](std::uint32_t o) { return o == kOuter ? std::string("the outer boundary") : A.obstacle_name(o); };
  std::vector<std::string> lines;
  for (std::uint32_t g = 0; g < rank(); ++g) {
    std::string s = names_[g] + ": " + geometry::format_point(from_[g]) + (ray_[g] ? " towards " : " -> ") + geometry::format_point(to_[g]);
    s += ray_[g] ? " (ray)" : "";
    s += ", joins " + side(child_[g]) + " to " + side(parent_[g]) + "; winds " + (sign_[g] > 0 ? "+1" : "-1") + " around";
    for (std::uint32_t o : encloses_[g]) s += " o" + std::to_string(o + 1);
    lines.push_back(std::move(s));
  }
  return lines;
}

BasisWordFilter::BasisWordFilter(const LoopBasis& basis) : basis_(&basis), exponents_(basis.rank(), 0) {
  if (basis.kind() != LoopBasis::Kind::Tree) throw std::invalid_argument("BasisWordFilter: needs a tree basis of the scene's beams");
}

// ---------------------------------------------------------------- embedding of G (5.3 phase 1)
GraphEmbedding::GraphEmbedding(const BeamArrangement& A, const LoopBasis& basis) : A_(&A), basis_(&basis) {
  const auto& H = A.half_edges();
  for (std::uint32_t h = 0; h < H.size(); ++h) {
    if (H[h].beam == kNone) continue;
    const BeamGeometry& b = A.beams()[H[h].beam];
    // Even half-edges run from -> to with the region entered on their left: positive.
    const Symbol y = h % 2 == 0 || !b.directed ? Alphabet::positive(b.label) : Alphabet::negative(b.label);
    const std::vector<ExactPoint> path = crossing_path(A, h);
    crossings_.push_back({A.region_of(BeamArrangement::twin(h)), A.region_of(h), y, h, basis.crossing_word(path)});
  }
  auto key = [](const EmbeddedCrossing& c) { return std::tie(c.from, c.symbol, c.to); };
  std::sort(crossings_.begin(), crossings_.end(), [&](const auto& a, const auto& b) {
    return key(a) != key(b) ? key(a) < key(b) : a.word < b.word;
  });
  crossings_.erase(std::unique(crossings_.begin(), crossings_.end(),
                               [&](const auto& a, const auto& b) { return key(a) == key(b) && a.word == b.word; }),
                   crossings_.end());
  const std::size_t k = A.alphabet().num_symbols();
  begin_.assign(A.num_regions() * k + 1, 0);
  for (auto& c : crossings_) ++begin_[c.from * k + c.symbol + 1];
  for (std::size_t i = 1; i < begin_.size(); ++i) begin_[i] += begin_[i - 1];
}

// ---------------------------------------------------------------- Z^n
AbelianStore::AbelianStore(std::size_t rank) : rank_(rank) { intern(std::vector<std::int64_t>(rank, 0)); }

AbelianStore::Node AbelianStore::intern(const std::vector<std::int64_t>& v) {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the entries
  for (auto x : v) h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ull;
  auto& bucket = by_hash_[h];
  for (Node n : bucket)
    if (std::equal(v.begin(), v.end(), data_.begin() + static_cast<std::ptrdiff_t>(n * rank_))) return n;
  const Node n = static_cast<Node>(count_++);
  data_.insert(data_.end(), v.begin(), v.end());
  bucket.push_back(n);
  return n;
}

AbelianStore::Node AbelianStore::times(Node v, const FreeWord& u) {
  if (u.identity()) return v;
  std::vector<std::int64_t> w(vector(v).begin(), vector(v).end());
  for (Letter x : u.letters()) w[generator_of(x)] += x > 0 ? 1 : -1;
  return intern(w);
}

// ---------------------------------------------------------------- class sets (5.3 phase 2, 6.3)
namespace {

// How a region sequence's sample path is closed into a loop, per PathEnds mode.
class Closure {
 public:
  Closure(const GraphEmbedding& G, const PathEnds& ends) : G_(G), A_(G.arrangement()), ends_(ends) {
    if (ends.mode == PathEnds::Mode::Fixed) {
      if (!ends.start) throw std::invalid_argument("PathEnds::Fixed needs a start point");
      start_ = *ends.start;
      end_ = ends.end ? *ends.end : start_;
      r_start_ = locate(start_, "start");
      r_end_ = locate(end_, "end");
      if (!(end_ == start_)) return_word_ = G.word_of(free_path(A_, end_, start_));
    }
  }
  std::vector<std::uint32_t> initial() const {
    return ends_.mode == PathEnds::Mode::Fixed ? std::vector<std::uint32_t>{r_start_} : std::vector<std::uint32_t>{};
  }
  // Word from the basepoint to the sample point of the first region.
  FreeWord head(std::uint32_t r0) const {
    if (ends_.mode != PathEnds::Mode::Fixed) return {};
    return G_.word_of(route_in_region(A_, r0, start_, A_.regions()[r0].sample));
  }
  bool accepts(std::uint32_t s, std::uint32_t r) const {
    switch (ends_.mode) {
      case PathEnds::Mode::Closed: return r == s;
      case PathEnds::Mode::Open: return true;
      case PathEnds::Mode::Fixed: return r == r_end_;
    }
    return false;
  }
  // Word from the last region's sample point back to the basepoint.
  const FreeWord& tail(std::uint32_t s, std::uint32_t r) {
    const std::uint64_t k = (std::uint64_t(s) << 32) | r;
    auto it = tails_.find(k);
    if (it != tails_.end()) return it->second;
    FreeWord w;
    if (ends_.mode == PathEnds::Mode::Fixed)
      w = G_.word_of(route_in_region(A_, r, A_.regions()[r].sample, end_)) * return_word_;
    else if (ends_.mode == PathEnds::Mode::Open && r != s)
      w = G_.word_of(free_path(A_, A_.regions()[r].sample, A_.regions()[s].sample));
    return tails_.emplace(k, std::move(w)).first->second;
  }

 private:
  std::uint32_t locate(const ExactPoint& p, const char* what) const {
    auto r = A_.locate(p);
    if (!r) throw InputError(std::string(what) + " point " + geometry::format_point(p) + " is not strictly inside a region (it is on a beam, on the boundary or outside free space)");
    return *r;
  }
  const GraphEmbedding& G_;
  const BeamArrangement& A_;
  PathEnds ends_;
  ExactPoint start_, end_;
  std::uint32_t r_start_ = kNone, r_end_ = kNone;
  FreeWord return_word_;
  std::unordered_map<std::uint64_t, FreeWord> tails_;
};

bool element_less(const CayleyTree& T, CayleyTree::Node a, CayleyTree::Node b) { return T.word(a) < T.word(b); }
bool element_less(const AbelianStore& S, AbelianStore::Node a, AbelianStore::Node b) {
  const auto u = S.vector(a), v = S.vector(b);
  return std::lexicographical_compare(u.begin(), u.end(), v.begin(), v.end());
}

}  // namespace

template <class Store>
PathClassSet<Store>::PathClassSet(const GraphEmbedding& G, const PathEnds& ends, std::span<const Symbol> word,
                                  std::size_t max_states) {
  if constexpr (std::is_same_v<Store, AbelianStore>) store_ = AbelianStore(G.basis().rank());
  const BeamArrangement& A = G.arrangement();
  Closure close(G, ends);
  const filter::Trellis T(A.graph(), close.initial(), word);
  sequences_ = T.count().str();
  if (!T.consistent()) {
    consistent_ = false;
    inconsistent_at_ = T.inconsistent_at();
    return;
  }
  // The product of the pruned trellis H with the group: (start, region, element).
  struct State { std::uint32_t s, r; Node e; };
  struct Hash {
    std::size_t operator()(const State& x) const {
      return std::hash<std::uint64_t>()((std::uint64_t(x.s) * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(x.r) << 32) ^ x.e);
    }
  };
  struct Eq {
    bool operator()(const State& a, const State& b) const { return a.s == b.s && a.r == b.r && a.e == b.e; }
  };
  std::vector<State> cur, next;
  std::unordered_set<State, Hash, Eq> seen;
  auto bound = [&](const std::vector<State>& states, std::size_t at) {
    peak_ = std::max(peak_, states.size());
    if (states.size() > max_states)
      throw InputError("more than " + std::to_string(max_states) + " (start region, region, class) states after observation " +
                       std::to_string(at) + ": the word is too ambiguous to list its classes exactly");
  };
  for (std::uint32_t r : T.stage(0)) cur.push_back({r, r, store_.times(Node(0), close.head(r))});
  bound(cur, 0);
  std::vector<char> allowed(A.num_regions(), 0);
  for (std::size_t i = 0; i < word.size(); ++i) {
    for (std::uint32_t r : T.stage(i + 1)) allowed[r] = 1;
    next.clear();
    seen.clear();
    for (const State& st : cur)
      for (const EmbeddedCrossing& c : G.out(st.r, word[i])) {
        if (!allowed[c.to]) continue;
        const State n{st.s, c.to, store_.times(st.e, c.word)};
        if (seen.insert(n).second) next.push_back(n);
      }
    for (std::uint32_t r : T.stage(i + 1)) allowed[r] = 0;
    bound(next, i + 1);
    cur.swap(next);
  }
  // Close each path; merge what the mode does not tell apart. Winding vectors of loops
  // do not depend on the basepoint, homotopy classes do (they are conjugated).
  const bool merge_starts = ends.mode == PathEnds::Mode::Fixed ||
                            (ends.mode == PathEnds::Mode::Closed && std::is_same_v<Store, AbelianStore>);
  const bool keep_end = ends.mode == PathEnds::Mode::Open;
  for (const State& st : cur) {
    if (!close.accepts(st.s, st.r)) continue;
    const Node e = store_.times(st.e, close.tail(st.s, st.r));
    classes_.push_back({e, merge_starts ? kNone : st.s, keep_end ? st.r : kNone});
  }
  std::sort(classes_.begin(), classes_.end(), [&](const Class& a, const Class& b) {
    if (a.start_region != b.start_region) return a.start_region < b.start_region;
    if (a.end_region != b.end_region) return a.end_region < b.end_region;
    return a.element != b.element && element_less(store_, a.element, b.element);
  });
  classes_.erase(std::unique(classes_.begin(), classes_.end(),
                             [](const Class& a, const Class& b) {
                               return a.element == b.element && a.start_region == b.start_region && a.end_region == b.end_region;
                             }),
                 classes_.end());
}

template class PathClassSet<CayleyTree>;
template class PathClassSet<AbelianStore>;

std::optional<std::vector<std::pair<FreeWord, std::pair<std::uint32_t, std::uint32_t>>>> homotopy_by_enumeration(
    const GraphEmbedding& G, const PathEnds& ends, std::span<const Symbol> word, std::size_t limit) {
  const BeamArrangement& A = G.arrangement();
  Closure close(G, ends);
  const filter::Trellis T(A.graph(), close.initial(), word);
  std::vector<std::pair<FreeWord, std::pair<std::uint32_t, std::uint32_t>>> out;
  if (!T.consistent()) return out;
  bool truncated = false;
  const auto seqs = T.enumerate(limit, &truncated);
  if (truncated) return std::nullopt;
  std::size_t expanded = 0;
  for (const auto& seq : seqs) {
    const std::uint32_t s = seq.front(), r = seq.back();
    if (!close.accepts(s, r)) continue;
    // Every choice of piece at every step (G is a multigraph), depth first.
    std::function<void(std::size_t, const FreeWord&)> walk = [&](std::size_t i, const FreeWord& w) {
      if (i == word.size()) {
        if (++expanded > limit) throw std::length_error("limit");
        const bool merge = ends.mode == PathEnds::Mode::Fixed;
        out.push_back({w * close.tail(s, r), {merge ? kNone : s, ends.mode == PathEnds::Mode::Open ? r : kNone}});
        return;
      }
      for (const EmbeddedCrossing& c : G.out(seq[i], word[i]))
        if (c.to == seq[i + 1]) walk(i + 1, w * c.word);
    };
    try {
      walk(0, close.head(s));
    } catch (const std::length_error&) {
      return std::nullopt;
    }
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return a.second != b.second ? a.second < b.second : a.first < b.first;
  });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace preimage::beams
