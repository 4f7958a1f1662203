// SPDX-License-Identifier: Apache-2.0
#include <preimage/landmarks/order_type.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/error.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>
#include <unordered_set>

namespace preimage::landmarks {
namespace {

using geometry::Point;

std::string name_of(const std::vector<std::string>& names, std::size_t i) {
  if (i < names.size()) return names[i];
  return std::string("landmark ").append(std::to_string(i));
}

}  // namespace

void require_general_position(std::span<const Point> P, const std::vector<std::string>& names) {
  const std::size_t n = P.size();
  std::vector<std::uint32_t> others;
  for (std::size_t i = 0; i < n; ++i) {
    // Around p_i, directions folded onto a half-turn: equal folded directions are
    // collinear triples (equal points show up as a zero direction).
    others.clear();
    for (std::uint32_t k = 0; k < n; ++k) {
      if (k == i) continue;
      if (P[k] == P[i]) throw InputError(name_of(names, std::min<std::size_t>(i, k)) + " and " + name_of(names, std::max<std::size_t>(i, k)) + " coincide");
      others.push_back(k);
    }
    // Fold each direction p_i -> p_k onto the half-turn [0, pi) (negate it if it points
    // below); the folded order is exact: orient(folded a, folded b) is
    // orient(p_i, p_a, p_b) times the two fold signs.
    auto fold = [&](std::uint32_t k) { return geometry::half_turn(P[i], P[k]) == 0 ? 1 : -1; };
    std::sort(others.begin(), others.end(), [&](std::uint32_t a, std::uint32_t b) {
      return fold(a) * fold(b) * geometry::orientation(P[i], P[a], P[b]) > 0;
    });
    for (std::size_t t = 0; t + 1 < others.size(); ++t)
      if (geometry::orientation(P[i], P[others[t]], P[others[t + 1]]) == 0) {
        std::uint32_t tri[3] = {static_cast<std::uint32_t>(i), others[t], others[t + 1]};
        std::sort(tri, tri + 3);
        throw InputError(name_of(names, tri[0]) + ", " + name_of(names, tri[1]) + " and " + name_of(names, tri[2]) +
                         " are collinear (landmarks must be in general position)");
      }
  }
}

LandmarkSet landmark_set(const scene::Scene& s) {
  LandmarkSet L;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < s.landmarks.size(); ++i) {
    L.labels.push_back(s.landmarks[i].label);
    L.points.push_back(s.landmarks[i].at);
    names.push_back("$.landmarks[" + std::to_string(i) + "] ('" + s.landmarks[i].label + "')");
  }
  if (L.size() < 3) throw InputError("$.landmarks: need at least three landmarks, got " + std::to_string(L.size()));
  for (std::size_t i = 0; i < L.size(); ++i)
    for (std::size_t j = i + 1; j < L.size(); ++j)
      if (L.labels[i] == L.labels[j]) throw InputError(names[j] + ": label '" + L.labels[j] + "' is used by " + names[i] + " too");
  require_general_position(L.points, names);
  return L;
}

// ---------------------------------------------------------------- order types
OrderType OrderType::of(std::span<const Point> P) {
  OrderType T;
  const std::size_t n = T.n_ = P.size();
  if (n < 2) return T;
  const std::size_t m = n - 1;
  T.order_.resize(n * m);
  T.rank_.assign(n * n, 0);
  T.lambda_.assign(n * n, 0);
  // Rows are independent: split them over the cores. Each row is an angular sort (one
  // orientation predicate per comparison, the half-plane of each direction computed
  // once) and a rotating sweep that also meets every collinear triple through p_i.
  auto rows = [&](std::size_t first, std::size_t last, std::string& error) {
    std::vector<char> half(n);
    for (std::size_t i = first; i < last && error.empty(); ++i) {
      std::uint32_t* o = T.order_.data() + i * m;
      std::size_t w = 0;
      for (std::uint32_t k = 0; k < n; ++k) {
        if (k == i) continue;
        if (P[k] == P[i]) {
          error = "landmarks " + std::to_string(std::min<std::size_t>(i, k)) + " and " + std::to_string(std::max<std::size_t>(i, k)) + " coincide";
          return;
        }
        half[k] = static_cast<char>(geometry::half_turn(P[i], P[k]));
        o[w++] = k;
      }
      std::sort(o, o + m, [&](std::uint32_t a, std::uint32_t b) {
        return half[a] != half[b] ? half[a] < half[b] : geometry::orientation(P[i], P[a], P[b]) > 0;
      });
      for (std::size_t t = 0; t < m; ++t) T.rank_[i * n + o[t]] = static_cast<std::uint32_t>(t);
      // The landmarks left of p_i -> p_j are those within the half-turn after j: a
      // window whose end only moves forward. Where it stops, a collinear landmark (the
      // one straight behind, or beside j in the same direction) would show as 0.
      std::size_t b = 1;
      for (std::size_t a = 0; a < m; ++a) {
        b = std::max(b, a + 1);
        int side = 1;
        while (b < a + m && (side = geometry::orientation(P[i], P[o[a]], P[o[b % m]])) > 0) ++b;
        if (b < a + m && side == 0) {
          std::uint32_t tri[3] = {static_cast<std::uint32_t>(i), o[a], o[b % m]};
          std::sort(tri, tri + 3);
          error = "landmarks " + std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + " and " + std::to_string(tri[2]) + " are collinear";
          return;
        }
        T.lambda_[i * n + o[a]] = static_cast<std::uint32_t>(b - a - 1);
      }
    }
  };
  const std::size_t threads = n < 256 ? 1 : std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
  std::vector<std::string> errors(threads);
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(rows, n * t / threads, n * (t + 1) / threads, std::ref(errors[t]));
  rows(0, n / threads, errors[0]);
  for (auto& th : pool) th.join();
  for (auto& e : errors)
    if (!e.empty()) throw InputError(e + " (landmarks must be in general position)");
  return T;
}

int OrderType::chi(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
  if (i == j || j == k || i == k) return 0;
  const std::size_t m = n_ - 1;
  const std::size_t r = (rank_[std::size_t(i) * n_ + k] + m - rank_[std::size_t(i) * n_ + j]) % m;
  return r >= 1 && r <= lambda(i, j) ? +1 : -1;
}

std::vector<std::uint32_t> OrderType::Lambda(std::uint32_t i, std::uint32_t j) const {
  std::vector<std::uint32_t> out;
  const std::size_t m = n_ - 1, r = rank_[std::size_t(i) * n_ + j];
  for (std::size_t t = 1; t <= lambda(i, j); ++t) out.push_back(around(i)[(r + t) % m]);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::uint32_t> OrderType::hull() const {
  if (n_ < 3) {
    std::vector<std::uint32_t> all(n_);
    std::iota(all.begin(), all.end(), 0u);
    return all;
  }
  // p_i -> p_j is a counter-clockwise hull edge iff every other landmark is on its left.
  std::vector<std::uint32_t> next(n_, UINT32_MAX);
  for (std::uint32_t i = 0; i < n_; ++i)
    for (std::uint32_t j = 0; j < n_; ++j)
      if (i != j && lambda(i, j) == n_ - 2) next[i] = j;
  std::uint32_t start = 0;
  while (next[start] == UINT32_MAX) ++start;
  std::vector<std::uint32_t> h{start};
  for (std::uint32_t v = next[start]; v != start; v = next[v]) h.push_back(v);
  return h;
}

Chirotope chirotope_of(std::size_t n, const std::function<std::vector<std::uint32_t>(std::uint32_t, std::uint32_t)>& Lambda) {
  // Tabulate once: the checks query every triple many times.
  auto table = std::make_shared<std::vector<signed char>>(n * n * n, 0);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j) {
      if (i == j) continue;
      for (std::uint32_t k = 0; k < n; ++k)
        if (k != i && k != j) (*table)[(i * n + j) * n + k] = -1;
      for (std::uint32_t k : Lambda(i, j))
        if (k < n && k != i && k != j) (*table)[(i * n + j) * n + k] = +1;
    }
  return [table, n](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return int((*table)[(i * n + j) * n + k]); };
}

namespace {
std::string triple(std::initializer_list<std::uint32_t> v) {
  std::string s;
  for (auto x : v) s.append(s.empty() ? "" : " ").append(std::to_string(x + 1));
  return s;
}
}  // namespace

std::optional<std::string> knuth_violation(std::size_t n, const Chirotope& chi) {
  auto pos = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { return chi(a, b, c) > 0; };
  const auto N = static_cast<std::uint32_t>(n);
  for (std::uint32_t p = 0; p < N; ++p)
    for (std::uint32_t q = 0; q < N; ++q)
      for (std::uint32_t r = 0; r < N; ++r) {
        if (p == q || q == r || p == r) continue;
        if (pos(p, q, r) && !pos(r, p, q)) return "axiom 1 (cyclic symmetry) fails for " + triple({p, q, r});
        if (pos(p, q, r) && pos(p, r, q)) return "axiom 2 (antisymmetry) fails for " + triple({p, q, r});
        if (!pos(p, q, r) && !pos(p, r, q)) return "axiom 3 (nondegeneracy) fails for " + triple({p, q, r});
        for (std::uint32_t t = 0; t < N; ++t) {
          if (t == p || t == q || t == r) continue;
          if (pos(p, q, t) && pos(q, r, t) && pos(r, p, t) && !pos(p, q, r))
            return "axiom 4 (interiority) fails for " + triple({p, q, r, t});
          for (std::uint32_t u = 0; u < N; ++u) {
            if (u == p || u == q || u == r || u == t) continue;
            // Axiom 5 with p4 = t, p5 = u, p1..p3 = p, q, r.
            if (pos(t, u, p) && pos(t, u, q) && pos(t, u, r) && pos(t, p, q) && pos(t, q, r) && !pos(t, p, r))
              return "axiom 5 (transitivity) fails for " + triple({p, q, r, t, u});
          }
        }
      }
  return std::nullopt;
}

std::optional<std::string> chirotope_violation(std::size_t n, const Chirotope& chi) {
  const auto N = static_cast<std::uint32_t>(n);
  bool nonzero = false;
  for (std::uint32_t a = 0; a < N; ++a)
    for (std::uint32_t b = 0; b < N; ++b)
      for (std::uint32_t c = 0; c < N; ++c) {
        const int x = chi(a, b, c);
        nonzero = nonzero || x != 0;
        if ((a == b || b == c || a == c) && x != 0) return "chi is not zero on the repeated triple " + triple({a, b, c});
        if (x != chi(c, a, b) || x != -chi(a, c, b)) return "chi is not alternating at " + triple({a, b, c});
      }
  if (!nonzero && n >= 3) return std::string("chi is identically zero");
  // Exchange conditions (3a-c) of section 3.1 over all p1..p3, p1'..p3'.
  for (std::uint32_t p1 = 0; p1 < N; ++p1)
    for (std::uint32_t p2 = 0; p2 < N; ++p2)
      for (std::uint32_t p3 = 0; p3 < N; ++p3) {
        const int base = chi(p1, p2, p3);
        if (base == 0) continue;
        for (std::uint32_t q1 = 0; q1 < N; ++q1)
          for (std::uint32_t q2 = 0; q2 < N; ++q2)
            for (std::uint32_t q3 = 0; q3 < N; ++q3) {
              const int prod = base * chi(q1, q2, q3);
              if (prod >= 0) continue;
              // The conclusion fails: then every premise must fail too.
              if (chi(q1, p2, p3) * chi(p1, q2, q3) >= 0 && chi(q2, p2, p3) * chi(q1, p1, q3) >= 0 &&
                  chi(q3, p2, p3) * chi(q1, q2, p1) >= 0)
                return "the exchange condition fails for " + triple({p1, p2, p3}) + " / " + triple({q1, q2, q3});
            }
      }
  return std::nullopt;
}

// ---------------------------------------------------------------- canonical forms
namespace {

// Candidate labellings: a hull landmark first, the others counter-clockwise around it
// from its counter-clockwise hull neighbour. `mirror` reads the order type reflected
// (lambda(i, j) becomes lambda(j, i), counter-clockwise becomes clockwise).
void best_labelling(const OrderType& T, bool mirror, CanonicalForm& best, bool& have) {
  const std::uint32_t n = static_cast<std::uint32_t>(T.size());
  auto lam = [&](std::uint32_t i, std::uint32_t j) { return mirror ? T.lambda(j, i) : T.lambda(i, j); };
  std::vector<std::uint32_t> inv(n);
  std::vector<std::uint16_t> M(std::size_t(n) * n);
  for (std::uint32_t p = 0; p < n; ++p) {
    // p is on the hull iff some q has every other landmark on the left of p -> q.
    std::uint32_t first = UINT32_MAX;
    for (std::uint32_t q = 0; q < n && first == UINT32_MAX; ++q)
      if (q != p && lam(p, q) == n - 2) first = q;
    if (first == UINT32_MAX) continue;
    // Counter-clockwise around p from `first`: sorted by how many lie left of p -> q
    // (all others lie in a half-plane), i.e. by decreasing lambda.
    inv[0] = p;
    std::uint32_t w = 1;
    for (std::uint32_t q = 0; q < n; ++q)
      if (q != p) inv[w++] = q;
    std::sort(inv.begin() + 1, inv.end(), [&](std::uint32_t a, std::uint32_t b) { return lam(p, a) > lam(p, b); });
    for (std::uint32_t a = 0; a < n; ++a)
      for (std::uint32_t b = 0; b < n; ++b) M[std::size_t(a) * n + b] = a == b ? 0 : static_cast<std::uint16_t>(lam(inv[a], inv[b]));
    if (!have || M < best.lambda) {
      best.lambda = M;
      best.labelling = inv;
      best.mirrored = mirror;
      have = true;
    }
  }
}

}  // namespace

CanonicalForm canonical_form(const OrderType& T, bool mirror) {
  CanonicalForm best;
  best.n = static_cast<std::uint32_t>(T.size());
  if (T.size() < 3) {
    best.labelling.resize(T.size());
    std::iota(best.labelling.begin(), best.labelling.end(), 0u);
    best.lambda.assign(T.size() * T.size(), 0);
    return best;
  }
  bool have = false;
  best_labelling(T, false, best, have);
  if (mirror) best_labelling(T, true, best, have);
  return best;
}

std::vector<Point> random_landmarks(std::size_t n, std::uint64_t seed, int range, std::size_t* redrawn) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> u(-range, range);
  std::vector<Point> P(n);
  for (;;) {
    for (auto& p : P) p = geometry::random_point(rng, u);
    try {
      require_general_position(P);
      return P;
    } catch (const InputError&) {
      if (redrawn) ++*redrawn;  // collinear or coincident draw
    }
  }
}

OrderTypeCount count_order_types(std::size_t n, std::size_t samples, std::uint64_t seed, bool mirror,
                                 const std::function<void(double)>& progress) {
  if (n < 3) throw InputError("count-order-types: need N >= 3");
  std::set<std::vector<std::uint16_t>> seen;
  OrderTypeCount c;
  std::mt19937_64 seeds(seed);
  for (; c.samples < samples; ++c.samples) {
    if (progress && c.samples % 64 == 0) progress(double(c.samples) / double(samples));
    seen.insert(canonical_form(OrderType::of(random_landmarks(n, seeds(), 1 << 20, &c.redrawn)), mirror).lambda);
  }
  c.distinct = seen.size();
  return c;
}

}  // namespace preimage::landmarks
