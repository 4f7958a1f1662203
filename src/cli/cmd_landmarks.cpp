// SPDX-License-Identifier: Apache-2.0
// preimage landmarks order-type | count-order-types (landmark paper, section 3)
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/landmarks/order_type.hpp>

#include <iostream>

namespace preimage::cli {
namespace {

using nlohmann::json;

void run_order_type(const std::string& file, bool as_json) {
  const landmarks::LandmarkSet L = landmarks::landmark_set(scene::load_scene(file));
  const landmarks::OrderType T = landmarks::OrderType::of(L.points);
  const std::size_t n = L.size();
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
  static std::string o_file;
  static bool o_json = false;
  o->add_option("scene", o_file, "scene with landmarks (JSON)")->required();
  o->add_flag("--json", o_json, "JSON output (with every Lambda(i, j))");
  o->callback([] { run_order_type(o_file, o_json); });

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
