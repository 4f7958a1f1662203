// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/parallel_for.hpp>
#include <preimage/tracking/dynamic_visibility_game.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <sstream>
#include <thread>

namespace preimage::tracking {

namespace {
constexpr std::uint8_t kLost = 0, kKept = 255, kLongest = 253;
}

DynamicVisibilityGame::DynamicVisibilityGame(std::shared_ptr<const VisibilityGame> game, const DynamicGameParams& p)
    : game_(std::move(game)), params_(p) {
  if (!game_) throw InputError("dynamic game: no visibility game");
  const auto t0 = std::chrono::steady_clock::now();
  const VisibilityGame& g = *game_;
  const GameParams& gp = g.params();
  const double h = gp.resolution;
  const bool exact = p.step == ObserverStep::ConstantAcceleration;
  if (!(p.accel > 0) || !std::isfinite(p.accel)) throw InputError("dynamic game: the acceleration must be a positive number of m/s^2");
  // The velocity unit (m/s): one grid step per step, or two with the constant
  // acceleration, whose displacement (v + v') step / 2 must land on the grid.
  const double tau = g.step_time();
  unit_ = (exact ? 2 : 1) * h / tau;
  // The acceleration in velocity units per step.
  const double steps = p.accel * tau / unit_;
  accel_steps_ = static_cast<int>(std::llround(steps));
  if (accel_steps_ < 1 || std::abs(steps - accel_steps_) > 1e-9 * steps) {
    std::ostringstream m;
    if (exact) {
      m << "dynamic game: with a constant acceleration of " << p.accel << " m/s^2 per step, the step (" << tau
        << " s) must make accel * step^2 a whole multiple of twice the resolution " << h << " m: "
        << constant_acceleration_step(h, p.accel) << " s, or that times sqrt(k)";
    } else {
      const double base = gp.speed_ratio * gp.speed_ratio * gp.observer_speed * gp.observer_speed / (2 * p.accel);
      m << "dynamic game: an acceleration of " << p.accel << " m/s^2 is " << steps << " grid steps per step squared at resolution " << h
        << " m; the velocities carry grid points to grid points only at a multiple of " << base << " m";
    }
    throw InputError(m.str());
  }
  const unsigned threads = p.threads ? p.threads : std::max(1u, std::thread::hardware_concurrency());
  const std::size_t n = g.num_points();

  // Velocities: up to the observer's top speed (its reach per step).
  const double reach = g.observer_reach() / (unit_ * tau), r2 = reach * reach * (1 + 1e-12);
  const int r = static_cast<int>(std::floor(std::sqrt(r2)));
  velocities_.push_back({0, 0});
  for (int j = -r; j <= r; ++j)
    for (int i = -r; i <= r; ++i)
      if ((i || j) && i * i + j * j <= r2) velocities_.push_back({i, j});
  const std::size_t V = velocities_.size();
  next_begin_.assign(V + 1, 0);
  edge_of_.assign(V * V, kNone);
  for (std::uint32_t v = 0; v < V; ++v) {
    for (std::uint32_t w = 0; w < V; ++w)
      if (std::abs(velocities_[w][0] - velocities_[v][0]) <= accel_steps_ && std::abs(velocities_[w][1] - velocities_[v][1]) <= accel_steps_) {
        edge_of_[static_cast<std::size_t>(v) * V + w] = static_cast<std::uint32_t>(next_.size());
        next_.push_back(w);
      }
    next_begin_[v + 1] = static_cast<std::uint32_t>(next_.size());
  }
  const std::size_t E = next_.size();

  const double states = static_cast<double>(n) * static_cast<double>(n) * static_cast<double>(V);
  if (states > static_cast<double>(std::min<std::size_t>(p.max_states, std::numeric_limits<std::uint32_t>::max() - 1)))
    throw InputError("dynamic game: " + std::to_string(n) + " grid points and " + std::to_string(V) + " velocities make " +
                     std::to_string(static_cast<long long>(states)) + " states, more than the limit " + std::to_string(p.max_states) +
                     "; choose a coarser resolution");
  stats_.velocities = V;
  stats_.states = n * n * V;

  // The observer's free straight moves, by grid offset: moves[o][offset] (o itself at 0).
  const int R = static_cast<int>(std::floor(g.observer_reach() / h * (1 + 1e-12))), side = 2 * R + 1;
  std::vector<std::uint32_t> moves(n * static_cast<std::size_t>(side * side), kNone);
  const auto at = [&](std::size_t o, int di, int dj) -> std::uint32_t {
    if (std::abs(di) > R || std::abs(dj) > R) return kNone;
    return moves[o * static_cast<std::size_t>(side * side) + static_cast<std::size_t>((dj + R) * side + di + R)];
  };
  for (std::uint32_t o = 0; o < n; ++o)
    for (std::uint32_t q : g.observer_moves(o)) {
      const auto d = g.offset(o, q);
      if (std::abs(d[0]) <= R && std::abs(d[1]) <= R)
        moves[static_cast<std::size_t>(o) * static_cast<std::size_t>(side * side) + static_cast<std::size_t>((d[1] + R) * side + d[0] + R)] = q;
    }
  // Where each edge v -> w carries the observer from o.
  const std::vector<Point>& vertices = g.environment_vertices();
  dest_.assign(n * E, kNone);
  parallel_for(n, threads, [&](std::size_t o) {
    for (std::uint32_t v = 0; v < V; ++v)
      for (std::uint32_t e = next_begin_[v]; e < next_begin_[v + 1]; ++e) {
        const auto& w = velocities_[next_[e]];
        if (!exact) {
          dest_[o * E + e] = at(o, w[0], w[1]);
          continue;
        }
        // The parabola's control polygon o -> o + v -> o + v + w (grid steps), and the chord.
        const auto& u = velocities_[v];
        const std::uint32_t q1 = at(o, u[0], u[1]);
        if (q1 == kNone) continue;
        const std::uint32_t q2 = at(q1, w[0], w[1]);
        if (q2 == kNone || at(o, u[0] + w[0], u[1] + w[1]) != q2) continue;
        const Point &a = g.point(static_cast<std::uint32_t>(o)), &b = g.point(q1), &c = g.point(q2);
        const int turn = geometry::orientation(a, b, c);
        bool clear = true;
        if (turn != 0)  // no vertex in the closed triangle (its corners are in the open free space)
          for (const Point& x : vertices)
            if (geometry::orientation(a, b, x) * turn >= 0 && geometry::orientation(b, c, x) * turn >= 0 &&
                geometry::orientation(c, a, x) * turn >= 0) {
              clear = false;
              break;
            }
        if (clear) dest_[o * E + e] = q2;
      }
  });
  src_.assign(n * E, kNone);
  for (std::size_t o = 0; o < n; ++o)
    for (std::size_t e = 0; e < E; ++e)
      if (const std::uint32_t q = dest_[o * E + e]; q != kNone) src_[static_cast<std::size_t>(q) * E + e] = static_cast<std::uint32_t>(o);

  // Level 0 where the game without dynamics has lost already (not seen, within the
  // separation, or the target where it cannot stand): sight does not depend on velocity.
  level_.assign(n * n * V, kKept);
  parallel_for(n, threads, [&](std::size_t o) {
    for (std::size_t t = 0; t < n; ++t)
      if (g.escape_steps(static_cast<std::uint32_t>(o), static_cast<std::uint32_t>(t)) == 0)
        for (std::size_t v = 0; v < V; ++v) level_[(o * V + v) * n + t] = kLost;
  });

  // Backward induction as in VisibilityGame: Y(o, v, t') (the target moved to t', the
  // observer to choose v') is lost at step k when every choice leads to an X lost by k;
  // X(o, v, t) is lost at k + 1 when some target move t' makes Y(o, v, t') lost at k.
  // answers[Y] counts the choices not yet known to be lost (at most 9 per axis pair).
  std::vector<std::uint8_t> answers(n * n * V);
  std::vector<std::vector<std::uint32_t>> next(threads), zero(threads);
  parallel_for(threads, threads, [&](std::size_t th) {
    for (std::size_t o = th; o < n; o += threads)
      for (std::uint32_t v = 0; v < V; ++v) {
        for (std::size_t tp = 0; tp < n; ++tp) {
          unsigned alive = 0;
          for (std::uint32_t e = next_begin_[v]; e < next_begin_[v + 1]; ++e) {
            const std::uint32_t q = dest_[o * E + e], w = next_[e];
            alive += q != kNone && level_[(static_cast<std::size_t>(q) * V + w) * n + tp] != kLost;
          }
          answers[(o * V + v) * n + tp] = static_cast<std::uint8_t>(alive);
          if (alive == 0) zero[th].push_back(static_cast<std::uint32_t>((o * V + v) * n + tp));  // Y lost at step 0
        }
      }
  });
  // X states lost at step 1: a target move into a Y lost already (levels are written only
  // now, after every count has read them).
  parallel_for(threads, threads, [&](std::size_t th) {
    for (const std::uint32_t s0 : zero[th]) {
      const std::size_t ov = s0 / n, tp = s0 % n;
      for (std::uint32_t t : g.target_moves(static_cast<std::uint32_t>(tp))) {  // the moves are symmetric
        std::atomic_ref<std::uint8_t> a(level_[ov * n + t]);
        std::uint8_t expect = kKept;
        if (a.compare_exchange_strong(expect, 1)) next[th].push_back(static_cast<std::uint32_t>(ov * n + t));
      }
    }
  });
  std::vector<std::uint32_t> frontier;
  for (auto& f : next) frontier.insert(frontier.end(), f.begin(), f.end());
  std::size_t peak = frontier.size(), decided = 0;
  std::uint32_t k = 1;
  while (!frontier.empty()) {
    stats_.levels = k;
    decided += frontier.size();
    if (p.progress) p.progress(std::min(1.0, static_cast<double>(decided) / static_cast<double>(n * n * V)));
    // X(o', v', t') lost at k: one choice fewer for every Y(o, v, t') whose edge v -> v'
    // carries o to o' (v' is next to v exactly when v is next to v').
    parallel_for(threads, threads, [&](std::size_t th) {
      zero[th].clear();
      for (std::size_t f = th; f < frontier.size(); f += threads) {
        const std::size_t s = frontier[f];
        const std::size_t tp = s % n, ov = s / n, vp = ov % V, op = ov / V;
        for (std::uint32_t v : next_velocities(static_cast<std::uint32_t>(vp))) {
          const std::uint32_t o = src_[op * E + edge_of_[static_cast<std::size_t>(v) * V + vp]];
          if (o == kNone) continue;
          std::atomic_ref<std::uint8_t> c(answers[(static_cast<std::size_t>(o) * V + v) * n + tp]);
          if (c.fetch_sub(1, std::memory_order_relaxed) == 1) zero[th].push_back(static_cast<std::uint32_t>((static_cast<std::size_t>(o) * V + v) * n + tp));
        }
      }
    });
    const std::uint8_t lost_at = static_cast<std::uint8_t>(std::min<std::uint32_t>(k + 1, kLongest));
    parallel_for(threads, threads, [&](std::size_t th) {
      next[th].clear();
      for (const auto& zs : zero)
        for (std::size_t z = th; z < zs.size(); z += threads) {
          const std::size_t s = zs[z];
          const std::size_t tp = s % n, ov = s / n;
          for (std::uint32_t t : g.target_moves(static_cast<std::uint32_t>(tp))) {
            std::atomic_ref<std::uint8_t> a(level_[ov * n + t]);
            std::uint8_t expect = kKept;
            if (a.compare_exchange_strong(expect, lost_at)) next[th].push_back(static_cast<std::uint32_t>(ov * n + t));
          }
        }
    });
    frontier.clear();
    for (auto& f : next) frontier.insert(frontier.end(), f.begin(), f.end());
    peak = std::max(peak, frontier.size());
    ++k;
  }
  for (std::size_t s = 0; s < level_.size(); ++s) {
    stats_.seen += level_[s] != kLost;
    stats_.winning += level_[s] == kKept;
    stats_.winning_at_rest += level_[s] == kKept && (s / n) % V == 0;
  }
  stats_.memory_bytes = level_.size() * 2 + peak * 2 * sizeof(std::uint32_t) + (dest_.size() + src_.size()) * sizeof(std::uint32_t);
  stats_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::shared_ptr<const VisibilityGame> DynamicVisibilityGame::base_game(const geometry::Environment& env, GameParams game,
                                                                       const DynamicGameParams& params,
                                                                       std::shared_ptr<const VisibilityGame> solved) {
  if (params.step == ObserverStep::ConstantAcceleration) {
    game.step_time = constant_acceleration_step(game.resolution, params.accel);
    return std::make_shared<const VisibilityGame>(env, game);
  }
  return solved ? solved : std::make_shared<const VisibilityGame>(env, game);
}

std::span<const std::uint32_t> DynamicVisibilityGame::next_velocities(std::uint32_t v) const {
  return {next_.data() + next_begin_[v], next_.data() + next_begin_[v + 1]};
}

std::uint32_t DynamicVisibilityGame::escape_steps(std::uint32_t o, std::uint32_t v, std::uint32_t t) const {
  const std::uint8_t l = level_[index(o, v, t)];
  return l == kKept ? kForever : l;
}

std::uint32_t DynamicVisibilityGame::observer_policy(std::uint32_t o, std::uint32_t v, std::uint32_t t) const {
  std::uint32_t best = kNone, best_value = 0;
  int best_speed = 0;
  for (std::uint32_t w : next_velocities(v)) {
    const std::uint32_t q = destination(o, v, w);
    if (q == kNone) continue;
    const std::uint32_t value = escape_steps(q, w, t);
    const int speed = velocities_[w][0] * velocities_[w][0] + velocities_[w][1] * velocities_[w][1];
    if (best == kNone || value > best_value || (value == best_value && speed < best_speed)) best = w, best_value = value, best_speed = speed;
  }
  return best;
}

std::uint32_t DynamicVisibilityGame::answer_value(std::uint32_t o, std::uint32_t v, std::uint32_t t) const {
  const std::uint32_t w = observer_policy(o, v, t);
  return w == kNone ? 0 : escape_steps(destination(o, v, w), w, t);
}

std::uint32_t DynamicVisibilityGame::target_policy(std::uint32_t o, std::uint32_t v, std::uint32_t t) const {
  std::uint32_t best = t, best_value = kForever;
  bool any = false;
  for (std::uint32_t q : game_->target_moves(t)) {
    const std::uint32_t value = answer_value(o, v, q);
    if (!any || value < best_value) best = q, best_value = value, any = true;
  }
  return best;
}

}  // namespace preimage::tracking
