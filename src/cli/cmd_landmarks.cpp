// SPDX-License-Identifier: Apache-2.0
// preimage landmarks order-type | count-order-types (landmark paper, section 3)
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/landmarks/order_type.hpp>
#include <preimage/landmarks/robot.hpp>

#include <algorithm>
#include <iostream>

namespace preimage::cli {
namespace {

using nlohmann::json;

// The robot starts at --start, else at the scene's start, else at the first landmark.
landmarks::Simulator make_robot(const scene::Scene& s, const landmarks::LandmarkSet& L, const std::string& start) {
  if (!start.empty()) return landmarks::Simulator(L.points, parse_point(start, "--start"));
  if (s.start) return landmarks::Simulator(L.points, *s.start);
  return landmarks::Simulator(L.points, std::uint32_t{0});
}

void run_hull(const std::string& file, bool learn, const std::string& start) {
  const scene::Scene s = scene::load_scene(file);
  const landmarks::LandmarkSet L = landmarks::landmark_set(s);
  const auto truth = landmarks::OrderType::of(L.points).hull();
  std::vector<std::uint32_t> hull = truth;
  std::size_t primitives = 0;
  if (learn) {
    landmarks::Simulator robot = make_robot(s, L, start);
    hull = landmarks::learn_hull(robot);  // Strategies 4 and 5: readings and track only
    primitives = robot.primitives();
  }
  std::cout << "convex hull, counter-clockwise:";
  for (auto v : hull) std::cout << " " << L.labels[v];
  std::cout << "\n";
  if (learn) {
    auto t = truth;
    std::rotate(t.begin(), std::find(t.begin(), t.end(), hull.front()), t.end());
    std::cout << "learned by the robot with " << primitives << " track primitives (Strategies 4-5, n = " << L.size()
              << "); agrees with the coordinates: " << (t == hull ? "yes" : "NO") << "\n";
  }
}

void run_order_type(const std::string& file, bool as_json, bool learn, const std::string& start) {
  const scene::Scene sc = scene::load_scene(file);
  const landmarks::LandmarkSet L = landmarks::landmark_set(sc);
  const landmarks::OrderType T = landmarks::OrderType::of(L.points);
  const std::size_t n = L.size();
  if (learn) {
    landmarks::Simulator robot = make_robot(sc, L, start);
    const auto lambda = landmarks::learn_order_type(robot);  // Strategy 1 for every pair
    bool agree = true;
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = 0; j < n; ++j) agree = agree && (i == j || lambda[i * n + j] == T.lambda(i, j));
    std::cout << "order type learned by the robot with " << robot.primitives() << " track primitives (Strategy 1 for all "
              << n * (n - 1) / 2 << " pairs); agrees with the coordinates: " << (agree ? "yes" : "NO") << "\n";
  }
  const auto hull = T.hull();
  const auto C = landmarks::canonical_form(T);
  if (as_json) {
    json lam = json::array(), Lam = json::object(), h = json::array();
    for (std::uint32_t i = 0; i < n; ++i) {
      json row = json::array();
      for (std::uint32_t j = 0; j < n; ++j) row.push_back(i == j ? 0 : T.lambda(i, j));
      lam.push_back(row);
      for (std::uint32_t j = 0; j < n; ++j) {
        if (i == j) continue;
        json s = json::array();
        for (auto k : T.Lambda(i, j)) s.push_back(L.labels[k]);
        Lam[L.labels[i] + "," + L.labels[j]] = s;
      }
    }
    for (auto v : hull) h.push_back(L.labels[v]);
    json canon = json::array();
    for (auto v : C.labelling) canon.push_back(L.labels[v]);
    return print_json({{"n", n}, {"labels", L.labels}, {"hull", h}, {"lambda", lam}, {"Lambda", Lam}, {"canonical_labelling", canon}});
  }
  std::cout << "order type of " << n << " landmarks (lambda(i, j) = landmarks left of p_i -> p_j)\n";
  std::cout << "convex hull, counter-clockwise:";
  for (auto v : hull) std::cout << " " << L.labels[v];
  std::cout << "\ncanonical labelling (hull landmark first, the rest counter-clockwise around it):";
  for (auto v : C.labelling) std::cout << " " << L.labels[v];
  std::cout << "\nlambda:\n";
  for (std::uint32_t i = 0; i < n; ++i) {
    std::cout << "  " << L.labels[i] << ":";
    for (std::uint32_t j = 0; j < n; ++j) std::cout << " " << (i == j ? std::string("-") : std::to_string(T.lambda(i, j)));
    std::cout << "\n";
  }
}

}  // namespace

void add_landmarks_commands(CLI::App& app) {
  auto* cmd = app.add_subcommand("landmarks", "landmark order types from cyclic permutations (landmark paper)");
  cmd->require_subcommand(1);

  auto* o = cmd->add_subcommand("order-type", "the order type of the scene's landmarks: lambda, Lambda, hull, canonical labelling");
  static std::string o_file, o_start;
  static bool o_json = false, o_learn = false;
  o->add_option("scene", o_file, "scene with landmarks (JSON)")->required();
  o->add_flag("--json", o_json, "JSON output (with every Lambda(i, j))");
  o->add_flag("--learn", o_learn, "also learn it with the simulated robot (Strategy 1) and print the primitive count");
  o->add_option("--start", o_start, "the robot's start X,Y (default: the scene's start, else the first landmark)");
  o->callback([] { run_order_type(o_file, o_json, o_learn, o_start); });

  auto* h = cmd->add_subcommand("hull", "the convex hull boundary of the landmarks, counter-clockwise");
  static std::string h_file, h_start;
  static bool h_learn = false;
  h->add_option("scene", h_file, "scene with landmarks (JSON)")->required();
  h->add_flag("--learn", h_learn, "learn it with the simulated robot (Strategies 4-5) and print the primitive count");
  h->add_option("--start", h_start, "the robot's start X,Y (default: the scene's start, else the first landmark)");
  h->callback([] { run_hull(h_file, h_learn, h_start); });

  auto* c = cmd->add_subcommand("count-order-types", "distinct order types among random sets of N landmarks");
  static std::size_t c_n = 0, c_samples = 1000;
  static std::uint64_t c_seed = 1;
  static bool c_mirror = false;
  c->add_option("N", c_n, "landmarks per set")->required();
  c->add_option("--samples", c_samples, "random sets to draw (default 1000)");
  c->add_option("--seed", c_seed, "random seed (default 1)");
  c->add_flag("--mirror", c_mirror, "identify mirror images (count up to reflection too)");
  c->callback([] {
    if (c_n < 3 || c_n > 1000) throw InputError("N: expected 3 to 1000 landmarks, got " + std::to_string(c_n));
    const auto r = landmarks::count_order_types(c_n, c_samples, c_seed, c_mirror);
    std::cout << r.distinct << " distinct order types among " << r.samples << " random sets of " << c_n << " landmarks (up to relabelling"
              << (c_mirror ? " and reflection" : "") << "; " << r.redrawn << " degenerate draws redrawn)\n";
  });
}

}  // namespace preimage::cli
