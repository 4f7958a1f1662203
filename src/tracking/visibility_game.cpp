// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/configuration_space.hpp>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/parallel_for.hpp>
#include <preimage/tracking/visibility_game.hpp>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

namespace preimage::tracking {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Grid offsets (di, dj) with di^2 + dj^2 <= r2, (0, 0) first.
std::vector<std::pair<int, int>> disc_offsets(double r2) {
  std::vector<std::pair<int, int>> out{{0, 0}};
  const int r = static_cast<int>(std::floor(std::sqrt(r2)));
  for (int dj = -r; dj <= r; ++dj)
    for (int di = -r; di <= r; ++di)
      if ((di != 0 || dj != 0) && di * di + dj * dj <= r2) out.emplace_back(di, dj);
  return out;
}

}  // namespace

VisibilityGame::VisibilityGame(const geometry::Environment& env, const GameParams& p) : params_(p), vertices_(env.vertices()) {
  const double h = p.resolution;
  if (!(h > 0) || !std::isfinite(h)) throw InputError("game: the resolution must be a positive number of metres");
  if (!(p.observer_speed > 0) || !std::isfinite(p.observer_speed)) throw InputError("game: the observer's speed must be positive");
  if (!(p.speed_ratio > 0) || !std::isfinite(p.speed_ratio)) throw InputError("game: the speed ratio must be positive");
  if (!(p.range > 0)) throw InputError("game: the sensor range must be positive");
  if (!(p.separation >= 0) || !std::isfinite(p.separation)) throw InputError("game: the separation must be >= 0");
  const unsigned threads = p.threads ? p.threads : std::max(1u, std::thread::hardware_concurrency());
  const auto t0 = Clock::now();

  // The target steps at most one diagonal grid step (unless the step is given); the
  // observer proportionally more.
  if (!(p.step_time >= 0) || !std::isfinite(p.step_time)) throw InputError("game: the step time must be >= 0 seconds");
  target_reach_ = p.step_time > 0 ? p.speed_ratio * p.observer_speed * p.step_time : h * std::sqrt(2.0);
  step_ = target_reach_ / (p.speed_ratio * p.observer_speed);
  observer_reach_ = target_reach_ / p.speed_ratio;
  if (target_reach_ < h)  // only with a given step: the usual one reaches a diagonal step
    throw InputError("game: in a step of " + std::to_string(step_) + " s the target moves at most " +
                     std::to_string(target_reach_) + " m, less than one grid step (" + std::to_string(h) +
                     " m): it could not move on the grid; choose a longer step or a finer grid");
  const double target_r2 = p.step_time > 0 ? (target_reach_ / h) * (target_reach_ / h) * (1 + 1e-12) : 2.0;
  const double observer_r2 = (p.step_time > 0 ? (observer_reach_ / h) * (observer_reach_ / h) : 2.0 / (p.speed_ratio * p.speed_ratio)) * (1 + 1e-12);

  // The grid in the environment's own frame: points at x0 + i h, y0 + j h, so that the
  // answers do not depend on where the plan sits in the plane.
  const auto box = env.bbox();
  x0_ = box.xmin();
  y0_ = box.ymin();
  columns_ = static_cast<std::int64_t>(std::floor((box.xmax() - x0_) / h)) + 1;
  rows_ = static_cast<std::int64_t>(std::floor((box.ymax() - y0_) / h)) + 1;
  if (static_cast<double>(columns_) * static_cast<double>(rows_) > 1e8)
    throw InputError("game: the grid at resolution " + std::to_string(h) + " m has more than 10^8 cells; choose a coarser resolution");
  const geometry::VisibilityIndex index(env);
  cell_to_point_.assign(static_cast<std::size_t>(columns_ * rows_), kNoPoint);
  for (std::int64_t j = 0; j < rows_; ++j)
    for (std::int64_t i = 0; i < columns_; ++i) {
      const Point q(x0_ + static_cast<double>(i) * h, y0_ + static_cast<double>(j) * h);
      // Open free space only: a player standing on a wall would see along it.
      if (index.locate(q).kind != geometry::Location::Kind::Interior) continue;
      cell_to_point_[static_cast<std::size_t>(j * columns_ + i)] = static_cast<std::uint32_t>(points_.size());
      points_.push_back(q);
    }
  const std::size_t n = points_.size();
  if (n == 0) throw InputError("game: no grid point at resolution " + std::to_string(h) + " m lies in the open free space");
  const double states = static_cast<double>(n) * static_cast<double>(n);
  // States are indexed by 32-bit numbers in the induction's frontier.
  if (states > static_cast<double>(std::min<std::size_t>(p.max_states, std::numeric_limits<std::uint32_t>::max() - 1)))
    throw InputError("game: " + std::to_string(n) + " grid points make " + std::to_string(static_cast<long long>(states)) +
                     " states, more than the limit " + std::to_string(p.max_states) + "; choose a coarser resolution");
  stats_.points = n;
  stats_.states = n * n;

  // Where the target's disc fits: the configuration space of a disc of the target's
  // radius admits the point (exact, distance >= r from every obstacle edge).
  if (!(p.target_radius >= 0) || !std::isfinite(p.target_radius)) throw InputError("game: the target radius must be >= 0");
  target_ok_.assign(n, 1);
  if (p.target_radius > 0) {
    const geometry::ConfigurationSpace disc(env, p.target_radius);
    for (std::size_t a = 0; a < n; ++a) target_ok_[a] = disc.admits(points_[a]);  // one thread: admits keeps scratch
  }

  // Moves: straight free segments to the grid points within reach.
  auto build_moves = [&](double r2, std::vector<std::uint32_t>& begin, std::vector<std::uint32_t>& list) {
    const auto offsets = disc_offsets(r2);
    std::vector<std::vector<std::uint32_t>> per(n);
    parallel_for(n, threads, [&](std::size_t a) {
      const std::int64_t i = static_cast<std::int64_t>(std::llround((points_[a].x() - x0_) / h));
      const std::int64_t j = static_cast<std::int64_t>(std::llround((points_[a].y() - y0_) / h));
      for (const auto& [di, dj] : offsets) {
        const std::int64_t ii = i + di, jj = j + dj;
        if (ii < 0 || jj < 0 || ii >= columns_ || jj >= rows_) continue;
        const std::uint32_t b = cell_to_point_[static_cast<std::size_t>(jj * columns_ + ii)];
        if (b == kNoPoint) continue;
        if (b == a || index.visible(points_[a], points_[b])) per[a].push_back(b);
      }
    });
    begin.assign(n + 1, 0);
    for (std::size_t a = 0; a < n; ++a) begin[a + 1] = begin[a] + static_cast<std::uint32_t>(per[a].size());
    list.clear();
    list.reserve(begin[n]);
    for (auto& v : per) list.insert(list.end(), v.begin(), v.end());
  };
  build_moves(target_r2, target_begin_, target_moves_);
  {  // the target moves only between points where it may stand
    std::vector<std::uint32_t> begin(n + 1, 0), list;
    for (std::size_t a = 0; a < n; ++a) {
      if (target_ok_[a])
        for (std::uint32_t b : target_moves(static_cast<std::uint32_t>(a)))
          if (target_ok_[b]) list.push_back(b);
      begin[a + 1] = static_cast<std::uint32_t>(list.size());
    }
    target_begin_.swap(begin);
    target_moves_.swap(list);
  }
  build_moves(observer_r2, observer_begin_, observer_moves_);
  for (std::size_t a = 0; a < n; ++a)  // the answer counters below are 16 bits
    if (observer_begin_[a + 1] - observer_begin_[a] > 65535)
      throw InputError("game: the observer reaches more than 65535 grid points in one step; raise the speed ratio or the resolution");

  // Level 0: the states where the observer does not see the target (exact line of sight,
  // then the range and the separation, compared exactly on squared distances).
  const double range2 = std::isfinite(p.range) ? p.range * p.range : 0, sep2 = p.separation * p.separation;
  level_.assign(n * n, kForever);
  parallel_for(n, threads, [&](std::size_t o) {
    if (p.progress && o % threads == 0 && o % 64 == 0) {  // rows below o hold 1 - ((n - o) / n)^2 of the triangle
      const double left = static_cast<double>(n - o) / static_cast<double>(n);
      p.progress(0.4 * (1.0 - left * left));
    }
    for (std::size_t t = o; t < n; ++t) {
      const Point &a = points_[o], &b = points_[t];
      bool seen = CGAL::compare_squared_distance(a, b, sep2) != CGAL::SMALLER;
      if (seen && std::isfinite(p.range)) seen = CGAL::compare_squared_distance(a, b, range2) != CGAL::LARGER;
      if (seen) seen = target_ok_[o] || target_ok_[t];  // the pair is a state with the target at one of them
      if (seen) seen = index.visible(a, b);
      // A line of sight that only touches an obstacle corner is not kept: the least motion
      // of either player breaks it, and on a grid aligned with the obstacles' coordinates
      // such lines are everywhere (they made the game keep targets a continuous observer
      // loses at once). Exact: no environment vertex strictly inside the segment.
      if (seen) {
        const double x0 = std::min(a.x(), b.x()), x1 = std::max(a.x(), b.x()), y0 = std::min(a.y(), b.y()), y1 = std::max(a.y(), b.y());
        for (const Point& v : env.vertices())
          if (v.x() >= x0 && v.x() <= x1 && v.y() >= y0 && v.y() <= y1 &&  // a vertex inside the segment is in its box
              CGAL::collinear(a, v, b) && CGAL::collinear_are_strictly_ordered_along_line(a, v, b)) {
            seen = false;
            break;
          }
      }
      if (!seen) level_[o * n + t] = 0;
    }
  });
  for (std::size_t o = 0; o < n; ++o)  // symmetric: copy the upper triangle down
    for (std::size_t t = 0; t < o; ++t) level_[o * n + t] = level_[t * n + o];
  for (std::size_t o = 0; o < n; ++o)  // no state has the target where its disc does not fit
    for (std::size_t t = 0; t < n; ++t)
      if (!target_ok_[t]) level_[o * n + t] = 0;
  stats_.seconds_visibility = seconds_since(t0);
  const auto t1 = Clock::now();

  // Backward induction (the attractor of the losing states for the target). Y(o, t') is
  // the state after the target moved to t', the observer to answer: lost at step k when
  // every answer o' has X(o', t') lost by step k. X(o, t) is lost at step k + 1 when some
  // target move t' makes Y(o, t') lost at step k. answers[o, t'] counts the answers of
  // Y(o, t') not yet known to be lost; it reaches 0 exactly when Y is lost.
  std::vector<std::uint16_t> answers(n * n);
  std::vector<std::uint32_t> frontier;  // X states lost at the current step
  {
    parallel_for(n, threads, [&](std::size_t o) {
      const auto moves = observer_moves(static_cast<std::uint32_t>(o));
      for (std::size_t t = 0; t < n; ++t) {
        std::uint32_t alive = 0;
        for (std::uint32_t q : moves) alive += level_[q * n + t] != 0;
        answers[o * n + t] = static_cast<std::uint16_t>(std::min<std::uint32_t>(alive, 65535));
      }
    });
    std::vector<std::vector<std::uint32_t>> next(threads);
    parallel_for(threads, threads, [&](std::size_t th) {
      for (std::size_t o = th; o < n; o += threads)
        for (std::size_t tp = 0; tp < n; ++tp) {
          if (answers[o * n + tp] != 0) continue;
          for (std::uint32_t t : target_moves(static_cast<std::uint32_t>(tp))) {  // the moves are symmetric
            std::uint32_t& l = level_[o * n + t];
            if (l == kForever) {
              std::atomic_ref<std::uint32_t> a(l);
              std::uint32_t expect = kForever;
              if (a.compare_exchange_strong(expect, 1)) next[th].push_back(static_cast<std::uint32_t>(o * n + t));
            }
          }
        }
    });
    for (auto& v : next) frontier.insert(frontier.end(), v.begin(), v.end());
  }
  stats_.memory_bytes = n * n * (sizeof(std::uint32_t) + sizeof(std::uint16_t));
  std::uint32_t k = 1;
  std::vector<std::vector<std::uint32_t>> zero(threads), next(threads);
  std::size_t peak_frontier = frontier.size();
  std::size_t seen = 0, decided = 0;
  if (p.progress)
    for (std::uint32_t l : level_) seen += l != 0;
  while (!frontier.empty()) {
    stats_.levels = k;
    decided += frontier.size();
    if (p.progress && seen) p.progress(0.4 + 0.6 * std::min(1.0, static_cast<double>(decided) / static_cast<double>(seen)));
    // X states lost at step k: each takes one live answer from the Y states that could
    // answer into it (o in observer_moves(o'), which is symmetric).
    parallel_for(threads, threads, [&](std::size_t th) {
      zero[th].clear();
      for (std::size_t f = th; f < frontier.size(); f += threads) {
        const std::uint32_t s = frontier[f];
        const std::uint32_t op = static_cast<std::uint32_t>(s / n), tp = static_cast<std::uint32_t>(s % n);
        for (std::uint32_t o : observer_moves(op)) {
          std::atomic_ref<std::uint16_t> c(answers[static_cast<std::size_t>(o) * n + tp]);
          if (c.fetch_sub(1, std::memory_order_relaxed) == 1) zero[th].push_back(static_cast<std::uint32_t>(o * n + tp));
        }
      }
    });
    // Y states lost at step k: the target moves into them from X states, lost at k + 1.
    parallel_for(threads, threads, [&](std::size_t th) {
      next[th].clear();
      for (const auto& zs : zero)
        for (std::size_t z = th; z < zs.size(); z += threads) {
          const std::uint32_t s = zs[z];
          const std::uint32_t o = static_cast<std::uint32_t>(s / n), tp = static_cast<std::uint32_t>(s % n);
          for (std::uint32_t t : target_moves(tp)) {
            std::atomic_ref<std::uint32_t> a(level_[static_cast<std::size_t>(o) * n + t]);
            std::uint32_t expect = kForever;
            if (a.compare_exchange_strong(expect, k + 1)) next[th].push_back(static_cast<std::uint32_t>(o * n + t));
          }
        }
    });
    frontier.clear();
    for (auto& v : next) frontier.insert(frontier.end(), v.begin(), v.end());
    peak_frontier = std::max(peak_frontier, frontier.size());
    ++k;
  }
  stats_.memory_bytes += peak_frontier * 2 * sizeof(std::uint32_t);
  for (std::uint32_t l : level_) {
    stats_.seen += l != 0;
    stats_.winning += l == kForever;
  }
  stats_.seconds_solve = seconds_since(t1);
}

std::array<int, 2> VisibilityGame::offset(std::uint32_t i, std::uint32_t j) const {
  const double h = params_.resolution;
  return {static_cast<int>(std::llround((points_[j].x() - x0_) / h) - std::llround((points_[i].x() - x0_) / h)),
          static_cast<int>(std::llround((points_[j].y() - y0_) / h) - std::llround((points_[i].y() - y0_) / h))};
}

std::span<const std::uint32_t> VisibilityGame::observer_moves(std::uint32_t i) const {
  return {observer_moves_.data() + observer_begin_[i], observer_moves_.data() + observer_begin_[i + 1]};
}
std::span<const std::uint32_t> VisibilityGame::target_moves(std::uint32_t i) const {
  return {target_moves_.data() + target_begin_[i], target_moves_.data() + target_begin_[i + 1]};
}

std::uint32_t VisibilityGame::nearest_where(const Point& p, bool target) const {
  const double h = params_.resolution;
  const double fi = (p.x() - x0_) / h, fj = (p.y() - y0_) / h;
  if (!std::isfinite(fi) || !std::isfinite(fj)) return kNoPoint;
  const std::int64_t ci = static_cast<std::int64_t>(std::llround(std::clamp(fi, -4.0, static_cast<double>(columns_ + 4))));
  const std::int64_t cj = static_cast<std::int64_t>(std::llround(std::clamp(fj, -4.0, static_cast<double>(rows_ + 4))));
  std::uint32_t best = kNoPoint;
  double best_d = 0;
  for (std::int64_t j = cj - 2; j <= cj + 2; ++j)
    for (std::int64_t i = ci - 2; i <= ci + 2; ++i) {
      if (i < 0 || j < 0 || i >= columns_ || j >= rows_) continue;
      const std::uint32_t q = cell_to_point_[static_cast<std::size_t>(j * columns_ + i)];
      if (q == kNoPoint || (target && !target_ok_[q])) continue;
      const double d = std::hypot(points_[q].x() - p.x(), points_[q].y() - p.y());
      if (best == kNoPoint || d < best_d) {
        best = q;
        best_d = d;
      }
    }
  return best;
}

std::uint32_t VisibilityGame::answer_value(std::uint32_t o, std::uint32_t t) const {
  std::uint32_t best = 0;
  for (std::uint32_t q : observer_moves(o)) best = std::max(best, escape_steps(q, t));
  return best;
}

std::uint32_t VisibilityGame::observer_policy(std::uint32_t o, std::uint32_t t) const {
  std::uint32_t best = o, best_value = escape_steps(o, t);
  double best_len = 0;
  for (std::uint32_t q : observer_moves(o)) {
    const std::uint32_t v = escape_steps(q, t);
    const double len = std::hypot(points_[q].x() - points_[o].x(), points_[q].y() - points_[o].y());
    if (v > best_value || (v == best_value && (len < best_len || (len == best_len && q < best)))) {
      best = q;
      best_value = v;
      best_len = len;
    }
  }
  return best;
}

std::uint32_t VisibilityGame::target_policy(std::uint32_t o, std::uint32_t t) const {
  std::uint32_t best = t, best_value = kForever;
  std::size_t best_keeping = SIZE_MAX;
  for (std::uint32_t q : target_moves(t)) {
    const std::uint32_t v = answer_value(o, q);
    std::size_t keeping = 0;
    if (v == kForever)
      for (std::uint32_t a : observer_moves(o)) keeping += keeps(a, q);
    if (v < best_value || (v == best_value && keeping < best_keeping)) {
      best = q;
      best_value = v;
      best_keeping = keeping;
    }
  }
  return best;
}

std::vector<std::uint32_t> VisibilityGame::keeping_observers(std::uint32_t t) const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t o = 0; o < points_.size(); ++o)
    if (keeps(o, t)) out.push_back(o);
  return out;
}

}  // namespace preimage::tracking
