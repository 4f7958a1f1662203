// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/render/svg.hpp>
#include <preimage/tracking/dynamic_visibility_game.hpp>
#include <preimage/tracking/evaluation.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

namespace preimage::tracking {

namespace {
constexpr double kZ = 1.959963984540054;  // the normal 97.5% quantile: two-sided 95% intervals
}

void set_sensor(SimulationParams& p, double fov) {
  if (fov != 360 && fov != 180) throw InputError("--fov: expected 180 or 360, got " + std::to_string(fov));
  p.laser.fov = fov * M_PI / 180;
  p.laser.beams = fov == 360 ? 360 : 361;
  p.tracker.control.reverse = fov == 360;
  p.tracker.control.centre_target = fov != 360;
}

Interval wilson(std::size_t k, std::size_t n) {
  if (n == 0) return {};
  const double nn = static_cast<double>(n), p = static_cast<double>(k) / nn, z2 = kZ * kZ;
  const double centre = (p + z2 / (2 * nn)) / (1 + z2 / nn);
  const double half = kZ * std::sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn)) / (1 + z2 / nn);
  return {p, std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

void summarise(CellResult& c) {
  const std::size_t n = c.escape_times.size();
  c.escaped = static_cast<std::size_t>(
      std::count_if(c.escape_times.begin(), c.escape_times.end(), [&](double t) { return t < c.horizon; }));
  c.winnable_runs = c.kept_winnable = 0;
  for (std::size_t i = 0; i < c.winnable.size() && i < n; ++i)
    if (c.winnable[i]) {
      ++c.winnable_runs;
      c.kept_winnable += c.escape_times[i] >= c.horizon;
    }
  c.kept_winnable_fraction = wilson(c.kept_winnable, c.winnable_runs);
  if (n == 0) return;
  const double nn = static_cast<double>(n);
  c.escaped_fraction = wilson(c.escaped, n);
  // Mean of the escape times (each at most the horizon).
  double sum = 0;
  for (double t : c.escape_times) sum += t;
  const double mean = sum / nn;
  double ss = 0;
  for (double t : c.escape_times) ss += (t - mean) * (t - mean);
  const double se = n > 1 ? std::sqrt(ss / (nn - 1) / nn) : 0;
  c.mean_escape = {mean, mean - kZ * se, mean + kZ * se};
  // Median, and ranks j, k with P(t_(j) <= median <= t_(k)) ~ 95% (binomial, normal
  // approximation), which holds whatever the distribution.
  std::vector<double> s = c.escape_times;
  std::sort(s.begin(), s.end());
  const double med = n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
  const double j = std::floor(nn / 2 - kZ * std::sqrt(nn) / 2), k = std::ceil(nn / 2 + kZ * std::sqrt(nn) / 2);
  const auto rank = [&](double r) { return s[static_cast<std::size_t>(std::clamp(r, 1.0, nn)) - 1]; };
  c.median_escape = {med, rank(j), rank(k)};
}

Interval paired_difference(const CellResult& a, const CellResult& b) {
  const std::size_t n = std::min(a.escape_times.size(), b.escape_times.size());
  if (n == 0) return {};
  std::vector<double> d(n);
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) sum += d[i] = a.escape_times[i] - b.escape_times[i];
  const double nn = static_cast<double>(n), mean = sum / nn;
  double ss = 0;
  for (double x : d) ss += (x - mean) * (x - mean);
  const double se = n > 1 ? std::sqrt(ss / (nn - 1) / nn) : 0;
  return {mean, mean - kZ * se, mean + kZ * se};
}

std::vector<CellResult> evaluate(const std::vector<TrackingScenario>& scenarios, const EvaluationParams& ep,
                                 const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<CellResult> cells;
  std::vector<std::size_t> scenario_of;
  const double horizon = static_cast<double>(ep.steps) * SimulationParams{}.dt;
  for (std::size_t s = 0; s < scenarios.size(); ++s)
    for (double fov : ep.fovs)
      for (bool dyn : ep.dynamics)
        for (TargetPolicy pol : ep.policies)
          for (Strategy st : ep.strategies) {
            CellResult c;
            c.scene = scenarios[s].name;
            c.fov = fov;
            c.dynamics = dyn;
            c.policy = pol;
            c.strategy = st;
            c.horizon = horizon;
            c.escape_times.assign(ep.seeds, horizon);
            cells.push_back(std::move(c));
            scenario_of.push_back(s);
          }
  for (auto& c : cells) {
    SimulationParams probe;
    set_sensor(probe, c.fov);  // reject a bad sensor before any thread starts
  }
  // One game per scene: it depends on the speeds, the laser's range and the target's
  // radius, the same for every cell of the scene (the sensor's cone is not part of it).
  std::vector<std::shared_ptr<const VisibilityGame>> games(scenarios.size());
  const bool wants_game = std::any_of(ep.strategies.begin(), ep.strategies.end(),
                                      [](Strategy s) { return s == Strategy::Game || s == Strategy::RiskGame; }) ||
                          std::find(ep.policies.begin(), ep.policies.end(), TargetPolicy::Game) != ep.policies.end();
  if (ep.game_resolution > 0) {
    for (std::size_t s = 0; s < scenarios.size(); ++s) {
      SimulationParams probe;
      probe.speed_ratio = ep.speed_ratio;
      GameParams gp = game_params(scenarios[s], probe, ep.game_resolution);
      gp.threads = static_cast<unsigned>(std::max<std::size_t>(ep.jobs, 1));
      if (ep.game_progress) gp.progress = [&, s](double f) { ep.game_progress(scenarios[s].name, f); };
      try {
        games[s] = std::make_shared<const VisibilityGame>(*scenarios[s].environment, gp);
      } catch (const InputError& e) {
        throw InputError(scenarios[s].name + ": " + e.what());
      }
    }
    for (auto& c : cells) {
      c.game_resolution = ep.game_resolution;
      c.winnable.assign(ep.seeds, 0);
    }
  } else if (wants_game) {
    throw InputError("the game strategies and the game target need the game (a game resolution above 0)");
  }
  // With dynamics: the game with the observer's velocity in the state, the robot's own
  // step, the same point target; one per scene.
  std::vector<std::shared_ptr<const DynamicVisibilityGame>> dynamic_games(scenarios.size());
  if (ep.game_resolution > 0 && ep.dynamic_game_resolution > 0 && ep.accel > 0 &&
      std::find(ep.dynamics.begin(), ep.dynamics.end(), true) != ep.dynamics.end()) {
    const double h = std::max(ep.game_resolution, ep.dynamic_game_resolution);
    for (std::size_t s = 0; s < scenarios.size(); ++s) {
      SimulationParams probe;
      probe.speed_ratio = ep.speed_ratio;
      GameParams gp = game_params(scenarios[s], probe, h);
      gp.threads = static_cast<unsigned>(std::max<std::size_t>(ep.jobs, 1));
      DynamicGameParams dp;
      dp.accel = ep.accel;
      dp.step = ObserverStep::ConstantAcceleration;
      dp.threads = gp.threads;
      try {
        dynamic_games[s] = std::make_shared<const DynamicVisibilityGame>(
            DynamicVisibilityGame::base_game(*scenarios[s].environment, gp, dp), dp);
      } catch (const InputError& e) {
        throw InputError(scenarios[s].name + ", the game with dynamics: " + e.what());
      }
    }
    for (auto& c : cells)
      if (c.dynamics) {
        c.game_resolution = h;
        c.observer_dynamics = true;
      }
  }
  std::vector<double> var_v(cells.size() * ep.seeds), var_w(cells.size() * ep.seeds);
  std::vector<char> grid_kept(cells.size() * ep.seeds, 0);
  const std::size_t total = cells.size() * ep.seeds;
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex mutex;
  std::exception_ptr failure;
  auto worker = [&]() {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= total) return;
      const std::size_t ci = i / ep.seeds, seed = i % ep.seeds + 1;
      CellResult& c = cells[ci];
      try {
        SimulationParams p;
        set_sensor(p, c.fov);
        p.policy = c.policy;
        p.strategy = c.strategy;
        p.steps = ep.steps;
        p.seed = seed;
        p.speed_ratio = ep.speed_ratio;
        p.lookahead_headings = ep.lookahead_headings;
        p.lookahead_steps = ep.lookahead_steps;
        p.start_spread = ep.start_spread;
        p.heading_spread = ep.heading_spread;
        if (c.dynamics) {
          p.accel = ep.accel;
          p.alpha = ep.alpha;
        }
        p.stop_at_escape = true;
        p.game = games[scenario_of[ci]];
        const SimulationResult r = simulate(scenarios[scenario_of[ci]], p);
        c.escape_times[seed - 1] = r.escape_time >= 0 ? r.escape_time : horizon;  // distinct slots: no lock
        if (c.observer_dynamics) {
          // The start with the observer at rest; the game's policies against each other.
          const DynamicVisibilityGame& d = *dynamic_games[scenario_of[ci]];
          const VisibilityGame& g = d.game();
          std::uint32_t o = g.nearest(r.observer.front().position), t = g.nearest_target(r.target.front()), v = 0;
          const bool win = o != VisibilityGame::kNoPoint && t != VisibilityGame::kNoPoint && d.keeps(o, v, t);
          c.winnable[seed - 1] = win;
          bool kept = win;
          for (std::size_t k = 0, steps = static_cast<std::size_t>(std::ceil(horizon / g.step_time())); kept && k < steps; ++k) {
            t = d.target_policy(o, v, t);
            const std::uint32_t w = d.observer_policy(o, v, t);
            kept = w != DynamicVisibilityGame::kNone;
            if (kept) o = d.destination(o, v, w), v = w, kept = d.escape_steps(o, v, t) != 0;
          }
          grid_kept[i] = kept;
        } else if (p.game) {
          const VisibilityGame& g = *p.game;
          const std::uint32_t go = g.nearest(r.observer.front().position), gt = g.nearest_target(r.target.front());
          const bool win = go != VisibilityGame::kNoPoint && gt != VisibilityGame::kNoPoint && g.keeps(go, gt);
          c.winnable[seed - 1] = win;
          if (win) {
            const auto steps = static_cast<std::size_t>(std::ceil(horizon / g.step_time()));
            const auto optimal = [&](std::uint32_t a, std::uint32_t b) { return g.target_policy(a, b); };
            if (play(g, go, gt, steps, optimal) == VisibilityGame::kForever) grid_kept[i] = 1;
          }
        }
        var_v[i] = r.variation_v();
        var_w[i] = r.variation_omega();
      } catch (const InputError& e) {  // say which run
        const std::lock_guard<std::mutex> lock(mutex);
        if (!failure)
          failure = std::make_exception_ptr(InputError(c.scene + ", " + std::to_string(static_cast<int>(c.fov)) + " deg" +
                                                       (c.dynamics ? ", dynamics" : "") + ", " + to_string(c.policy) + ", " +
                                                       to_string(c.strategy) + ", seed " + std::to_string(seed) + ": " + e.what()));
        next = total;
        return;
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        next = total;  // stop the other workers
        return;
      }
      const std::lock_guard<std::mutex> lock(mutex);
      ++done;
      if (progress) progress(done, total);
    }
  };
  const std::size_t jobs = std::clamp<std::size_t>(ep.jobs, 1, std::max<std::size_t>(total, 1));
  std::vector<std::thread> threads;
  for (std::size_t j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  for (std::size_t ci = 0; ci < cells.size(); ++ci) {
    double sv = 0, sw = 0;
    for (std::size_t s = 0; s < ep.seeds; ++s) {
      sv += var_v[ci * ep.seeds + s];
      sw += var_w[ci * ep.seeds + s];
    }
    cells[ci].variation_v = ep.seeds ? sv / static_cast<double>(ep.seeds) : 0;
    cells[ci].variation_omega = ep.seeds ? sw / static_cast<double>(ep.seeds) : 0;
    cells[ci].grid_kept = static_cast<std::size_t>(std::count(grid_kept.begin() + static_cast<std::ptrdiff_t>(ci * ep.seeds),
                                                              grid_kept.begin() + static_cast<std::ptrdiff_t>((ci + 1) * ep.seeds), 1));
    summarise(cells[ci]);
  }
  return cells;
}

namespace {

const char* strategy_colour(Strategy s) {
  switch (s) {
    case Strategy::Risk: return "#d62728";
    case Strategy::Sde: return "#1f77b4";
    case Strategy::Naive: return "#7f7f7f";
    case Strategy::Game: return "#2ca02c";
    case Strategy::RiskGame: return "#9467bd";
  }
  return "#000";
}
const char* strategy_dash(Strategy s) {
  switch (s) {
    case Strategy::Risk: case Strategy::Game: return "";
    case Strategy::Sde: case Strategy::RiskGame: return "6 3";
    case Strategy::Naive: return "2 3";
  }
  return "";
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

std::string escape_time_cdf_figure(const std::vector<CellResult>& cells, const std::string& title) {
  // Panels in the order the cells come: a new panel whenever the scene, sensor, dynamics
  // or policy changes; four to a row.
  std::vector<std::vector<const CellResult*>> panels;
  for (const auto& c : cells) {
    const CellResult* last = panels.empty() ? nullptr : panels.back().front();
    if (!last || last->scene != c.scene || last->fov != c.fov || last->dynamics != c.dynamics || last->policy != c.policy)
      panels.emplace_back();
    panels.back().push_back(&c);
  }
  const std::size_t cols = std::min<std::size_t>(4, std::max<std::size_t>(panels.size(), 1));
  const std::size_t rows = (panels.size() + cols - 1) / cols;
  // World units: a panel's plot is 1 x 0.6, in a 1.25 x 0.95 cell; a header band on top.
  const double pw = 1.25, ph = 0.95, top = 0.25;
  const double W = pw * static_cast<double>(cols), H = ph * static_cast<double>(std::max<std::size_t>(rows, 1)) + top;
  render::SvgCanvas svg(CGAL::Bbox_2(0, 0, W, H), 300 * static_cast<double>(cols));
  svg.label(Point(0.05, H - 0.1), title, 14);
  const render::Style frame{"none", "#444", 1, 1.0, ""}, grid{"none", "#ccc", 0.6, 1.0, ""};
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const double x0 = pw * static_cast<double>(i % cols) + 0.15;
    const double y0 = H - top - ph * static_cast<double>(i / cols + 1) + 0.18;
    const CellResult& head = *panels[i].front();
    auto at = [&](double t, double f) { return Point(x0 + t / head.horizon, y0 + 0.6 * f); };
    svg.polygon({at(0, 0), at(head.horizon, 0), at(head.horizon, 1), at(0, 1)}, frame);
    for (double f : {0.25, 0.5, 0.75}) svg.segment(at(0, f), at(head.horizon, f), grid);
    svg.label(at(0, 1.08), head.scene + ", " + fmt("%.0f", head.fov) + "°" + (head.dynamics ? ", dynamics" : "") + ", " +
                               to_string(head.policy), 10);
    svg.label(at(0, -0.14), "0", 9);
    svg.label(at(head.horizon * 0.92, -0.14), fmt("%.0f s", head.horizon), 9);
    svg.label(at(-0.1 * head.horizon, 0.97), "1", 9);
    svg.label(at(-0.13 * head.horizon, 0.47), "0.5", 9);
    for (const CellResult* c : panels[i]) {
      std::vector<double> t = c->escape_times;
      std::sort(t.begin(), t.end());
      const double n = static_cast<double>(t.size());
      std::vector<Point> line{at(0, 0)};
      double f = 0;
      for (double x : t) {
        if (x >= c->horizon) break;
        line.push_back(at(x, f));
        f += 1 / n;
        line.push_back(at(x, f));
      }
      line.push_back(at(c->horizon, f));
      svg.polyline(line, render::Style{"none", strategy_colour(c->strategy), 1.8, 1.0, strategy_dash(c->strategy)},
                   std::string(to_string(c->strategy)) + ": " + std::to_string(c->escaped) + " of " +
                       std::to_string(c->escape_times.size()) + " lost by " + fmt("%.0f s", c->horizon));
    }
  }
  for (Strategy s : {Strategy::Risk, Strategy::Sde, Strategy::Naive, Strategy::Game, Strategy::RiskGame})
    if (std::any_of(cells.begin(), cells.end(), [&](const CellResult& c) { return c.strategy == s; }))
    svg.legend(std::string(to_string(s)) + ": fraction of runs that lost the target by time t",
               render::Style{"none", strategy_colour(s), 1.8, 1.0, strategy_dash(s)});
  return svg.str();
}

}  // namespace preimage::tracking
