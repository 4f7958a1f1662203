// SPDX-License-Identifier: Apache-2.0
#include <preimage/beams/region_filter.hpp>
#include <preimage/error.hpp>
#include <preimage/filter/trellis.hpp>

#include <algorithm>
#include <map>
#include <set>

namespace preimage::beams {

std::vector<std::uint32_t> initial_regions(const BeamArrangement& A, const std::vector<std::uint32_t>& ids,
                                           const std::vector<ExactPoint>& points) {
  std::vector<std::uint32_t> out;
  for (auto r : ids) {
    if (r >= A.num_regions())
      throw InputError("initial region " + std::to_string(r) + " does not exist (regions are 0.." +
                       std::to_string(A.num_regions() - 1) + ")");
    out.push_back(r);
  }
  for (auto& p : points) {
    auto r = A.locate(p);
    if (!r) throw InputError("initial point " + geometry::format_point(geometry::to_double(p)) + " is not strictly inside a region");
    out.push_back(*r);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<filter::ProductFilter::Assignment> initial_assignments(const std::vector<std::uint32_t>& R0, std::size_t n,
                                                                   bool distinguishable, bool together) {
  using Assignment = filter::ProductFilter::Assignment;
  std::vector<Assignment> out;
  if (R0.empty() || n == 0) return out;
  if (together) {
    for (auto r : R0) out.push_back(Assignment(n, r));
    return out;
  }
  if (distinguishable) return filter::ProductFilter::all_assignments(R0, n);
  // Non-decreasing index tuples: the next one raises the last index that can rise and
  // levels everything after it (balls and urns, Fig. 12).
  const std::size_t m = R0.size();
  std::vector<std::size_t> idx(n, 0);
  for (;;) {
    Assignment a(n);
    for (std::size_t b = 0; b < n; ++b) a[b] = R0[idx[b]];
    out.push_back(std::move(a));
    std::size_t i = n;
    while (i > 0 && idx[i - 1] == m - 1) --i;
    if (i == 0) return out;
    const std::size_t v = idx[i - 1] + 1;
    std::fill(idx.begin() + static_cast<std::ptrdiff_t>(i - 1), idx.end(), v);
  }
}

std::uint64_t count_initial_assignments(std::size_t m, std::size_t n, bool distinguishable, bool together) {
  constexpr std::uint64_t kMax = UINT64_MAX;
  if (m == 0 || n == 0) return 0;
  if (together) return m;
  if (m == 1) return 1;
  std::uint64_t c = 1;
  if (distinguishable) {
    for (std::size_t b = 0; b < n && c != kMax; ++b) c = c > kMax / m ? kMax : c * m;  // m >= 2: at most 64 rounds
    return c;
  }
  // C(m + n - 1, m - 1) = C(n + m - 1, n) as C(n + i, i) for i = 1..m-1 (each exact, and
  // increasing, so the first one past 2^64 ends the count); the smaller of the two
  // binomial parameters sets the number of rounds.
  const std::size_t k = std::min(m - 1, n), top = n + m - 1 - k;
  for (std::size_t i = 1; i <= k; ++i) {
    const filter::BigCount next = filter::BigCount(c) * (top + i) / i;
    if (next > kMax) return kMax;
    c = static_cast<std::uint64_t>(next);
  }
  return c;
}

RegionFilter::RegionFilter(const BeamArrangement& A, const std::vector<std::uint32_t>& initial, FilterMode mode,
                           std::size_t cache_bytes)
    : mode_(mode), plain_(A.graph(), initial) {
  if (mode == FilterMode::Cached) {
    dfa_.emplace(A.graph(), cache_bytes);
    id_ = dfa_->intern(plain_.sorted());
  }
}

bool RegionFilter::step(Symbol y) {
  if (dfa_) {
    id_ = dfa_->step(id_, y);
    return !dfa_->empty(id_);
  }
  return plain_.step(y);
}

std::vector<std::uint32_t> RegionFilter::regions() const {
  if (dfa_) {
    auto s = dfa_->states(id_);
    return {s.begin(), s.end()};
  }
  return plain_.sorted();
}

bool RegionFilter::empty() const { return dfa_ ? dfa_->empty(id_) : plain_.empty(); }

// ---------------------------------------------------------------- Fig. 11(b)
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

// The unordered region pair each label separates; InputError unless unique.
std::vector<Pair> label_pairs(const BeamArrangement& A, const char* what) {
  std::vector<std::set<Pair>> pairs(A.alphabet().num_labels());
  for (auto& e : A.edges()) pairs[Alphabet::label_of(e.symbol)].insert({std::min(e.from, e.to), std::max(e.from, e.to)});
  std::vector<Pair> out;
  for (std::uint32_t l = 0; l < pairs.size(); ++l) {
    if (pairs[l].size() != 1 || pairs[l].begin()->first == pairs[l].begin()->second)
      throw InputError(std::string(what) + ": beam label '" + A.alphabet().name(l) +
                       "' must separate exactly one pair of distinct regions");
    out.push_back(*pairs[l].begin());
  }
  return out;
}

}  // namespace

filter::Dfa together_filter(const BeamArrangement& A) {
  const char* what = "the together/separated filter (Fig. 11)";
  if (A.num_regions() != 3)
    throw InputError(std::string(what) + " needs three regions, the scene has " + std::to_string(A.num_regions()));
  const std::vector<Pair> lp = label_pairs(A, what);
  // I-states: 0 = T, then one D per separated pair, named after the labels crossing it.
  std::map<Pair, filter::State> pid;
  filter::Dfa d;
  d.names.push_back("T");
  for (std::uint32_t l = 0; l < lp.size(); ++l) {
    auto [it, fresh] = pid.try_emplace(lp[l], static_cast<filter::State>(d.names.size()));
    if (fresh) d.names.push_back("D_" + A.alphabet().name(l));
    else d.names[it->second] += "," + A.alphabet().name(l);
  }
  const std::size_t ns = A.alphabet().num_symbols();
  d.num_symbols = ns;
  d.table.assign(d.names.size() * ns, filter::kNoState);
  for (Symbol y = 0; y < ns; ++y) {
    const std::uint32_t l = Alphabet::label_of(y);
    if ((y & 1) && !A.alphabet().directed(l)) continue;
    const Pair x = lp[l];
    d.table[0 * ns + y] = pid[x];  // together, one crosses x: separated by x
    for (auto& [p, s] : pid) {
      if (p == x) { d.table[s * ns + y] = 0; continue; }  // the separated one comes back
      // Two distinct pairs of three regions share one region; the body there crosses
      // x, so the bodies now sit in the two regions other than the shared one.
      const std::uint32_t shared = (p.first == x.first || p.first == x.second) ? p.first : p.second;
      const std::uint32_t a = p.first == shared ? p.second : p.first, b = x.first == shared ? x.second : x.first;
      auto it = pid.find({std::min(a, b), std::max(a, b)});
      d.table[s * ns + y] = it == pid.end() ? filter::kNoState : it->second;
    }
  }
  return d;
}

std::optional<std::string> together_reading(const BeamArrangement& A, const std::vector<filter::ProductFilter::Assignment>& pairs) {
  const filter::Dfa d = together_filter(A);
  const std::vector<Pair> lp = label_pairs(A, "together filter");
  std::optional<std::string> out;
  for (auto& a : pairs) {
    std::string s;
    if (a[0] == a[1]) {
      s = "T";
    } else {
      const Pair p{std::min(a[0], a[1]), std::max(a[0], a[1])};
      for (std::uint32_t l = 0; l < lp.size() && s.empty(); ++l)
        if (lp[l] == p)
          for (filter::State st = 1; st < d.size(); ++st)
            if (d.table[st * d.num_symbols + Alphabet::positive(l)] == 0) s = d.names[st];
    }
    if (out && *out != s) return std::nullopt;
    out = s;
  }
  return out;
}

// ---------------------------------------------------------------- parity
ParityFilter::ParityFilter(const BeamArrangement& A, const std::vector<std::uint32_t>& bodies_in)
    : toggles_(A.alphabet().num_symbols(), {kNone, kNone}), bits_(A.num_regions(), false) {
  std::vector<std::set<Pair>> seen(A.alphabet().num_symbols());
  for (auto& e : A.edges()) seen[e.symbol].insert({std::min(e.from, e.to), std::max(e.from, e.to)});
  for (Symbol y = 0; y < seen.size(); ++y) {
    std::set<Pair> moves;
    bool loops = false;
    for (auto& p : seen[y]) {
      if (p.first == p.second) loops = true;
      else moves.insert(p);
    }
    if (moves.size() > 1 || (moves.size() == 1 && loops))
      throw InputError("the parity filter needs observation " + A.alphabet().format(y) +
                       " to join one pair of regions (it joins " + std::to_string(seen[y].size()) + ")");
    if (moves.size() == 1) toggles_[y] = *moves.begin();
  }
  for (auto r : bodies_in) {
    if (r >= bits_.size()) throw InputError("parity filter: region " + std::to_string(r) + " does not exist");
    bits_[r] = !bits_[r];
  }
}

std::vector<bool> ParityFilter::next(const std::vector<bool>& bits, Symbol y) const {
  std::vector<bool> out = bits;
  if (toggles_[y].first != kNone) out[toggles_[y].first] = !out[toggles_[y].first], out[toggles_[y].second] = !out[toggles_[y].second];
  return out;
}

void ParityFilter::step(Symbol y) { bits_ = next(bits_, y); }

}  // namespace preimage::beams
