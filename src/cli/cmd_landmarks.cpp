// SPDX-License-Identifier: Apache-2.0
// preimage landmarks order-type | count-order-types (landmark paper, section 3)
#include "common.hpp"

#include <preimage/error.hpp>
#include <preimage/landmarks/order_type.hpp>
#include <preimage/landmarks/figures.hpp>
#include <preimage/landmarks/robot.hpp>
#include <preimage/landmarks/strategies.hpp>
#include <preimage/landmarks/swap_cells.hpp>

#include <algorithm>
#include <iostream>
#include <map>
#include <set>

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

// "3,5,9" -> indices of those labels; errors name the token and its position.
std::vector<std::uint32_t> parse_labels(const landmarks::LandmarkSet& L, const std::string& text, const std::string& what) {
  std::vector<std::uint32_t> out;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t end = text.find(',', at);
    if (end == std::string::npos) end = text.size();
    std::string token = text.substr(at, end - at);
    token.erase(0, token.find_first_not_of(' '));
    token.erase(token.find_last_not_of(' ') + 1);
    const auto it = std::find(L.labels.begin(), L.labels.end(), token);
    if (it == L.labels.end())
      throw InputError(what + ": no landmark labelled '" + token + "' (token " + std::to_string(out.size() + 1) + ", at character " +
                       std::to_string(at + 1) + ")");
    if (std::find(out.begin(), out.end(), static_cast<std::uint32_t>(it - L.labels.begin())) != out.end())
      throw InputError(what + ": landmark '" + token + "' is listed twice (token " + std::to_string(out.size() + 1) + ")");
    out.push_back(static_cast<std::uint32_t>(it - L.labels.begin()));
    at = end + 1;
  }
  return out;
}

std::string label_list(const landmarks::LandmarkSet& L, const std::vector<std::uint32_t>& v) {
  return landmarks::format_reading(v, L.labels);
}

void save_svg(const render::SvgCanvas& svg, const std::string& file) {
  svg.save(file);
  std::cout << "figure: " << file << "\n";
}

void run_patrol(const std::string& file, const std::string& watch, bool learn, const std::string& start, bool as_json) {
  const scene::Scene s = scene::load_scene(file);
  const landmarks::LandmarkSet L = landmarks::landmark_set(s);
  const auto W = parse_labels(L, watch, "--watch");
  const landmarks::OrderType T = landmarks::OrderType::of(L.points);
  const auto chi = [&T](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return T.chi(i, j, k); };
  const auto plan = landmarks::patrol_route(L.size(), chi, T.hull(), W, L.labels);
  std::optional<landmarks::PatrolPlan> learned;
  std::size_t primitives = 0;
  if (learn) {
    landmarks::Simulator robot = make_robot(s, L, start);
    const auto tour = landmarks::learn_by_hull_tour(robot);  // sees readings only
    learned = landmarks::patrol_route(L.size(), tour.order_type.chirotope(), tour.hull, W, L.labels);
    primitives = robot.primitives();
  }
  const auto& p = learned ? *learned : plan;
  if (as_json) {
    json j{{"watch", landmarks::format_reading(W, L.labels)}, {"route", json::array()}, {"M", json::array()}};
    for (auto k : p.route) j["route"].push_back(L.labels[k]);
    for (auto k : p.M) j["M"].push_back(L.labels[k]);
    if (learn) j["primitives"] = primitives, j["agrees_with_coordinates"] = p.route == plan.route;
    return print_json(j);
  }
  std::cout << "patrol route around " << label_list(L, W) << ", counter-clockwise: " << label_list(L, p.route) << "\n";
  std::cout << "M = {" << label_list(L, p.M) << "} (" << p.M.size() << " landmarks, the fewest with the watched ones strictly inside hull(M))\n";
  if (learn)
    std::cout << "learned by the robot with " << primitives << " track primitives (Strategies 4-5 and one hull tour for the order type; "
              << "Strategy 6); agrees with the coordinates: " << (p.route == plan.route ? "yes" : "NO") << "\n";
}

void run_navigate(const std::string& file, const std::string& goal_text, bool learn, const std::string& start, const std::string& svg_file) {
  const scene::Scene s = scene::load_scene(file);
  const landmarks::LandmarkSet L = landmarks::landmark_set(s);
  const auto goal = parse_labels(L, goal_text, "--goal");
  if (goal.size() != L.size())
    throw InputError("--goal: a cyclic permutation of all " + std::to_string(L.size()) + " landmarks is needed, got " +
                     std::to_string(goal.size()));
  const landmarks::Reading g = landmarks::normalized(goal);
  const auto D = landmarks::SwapCellDecomposition::of(L.points);
  const landmarks::OrderType T = landmarks::OrderType::of(L.points);
  std::vector<std::uint32_t> inside, outside;
  for (std::uint32_t c = 0; c < D.cells().size(); ++c)
    if (D.cells()[c].permutation == g) (D.cells()[c].meets_hull ? inside : outside).push_back(c);
  const auto chi = [&T](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return T.chi(i, j, k); };
  std::string polar;
  for (auto [i, j] : landmarks::polar_pairs(L.size(), chi, g)) polar += (polar.empty() ? "" : ", ") + L.labels[i] + "-" + L.labels[j];
  std::cout << "goal " << landmarks::format_reading(g, L.labels) << "; polar pairs: " << (polar.empty() ? "none" : polar) << "\n";
  std::cout << "from coordinates: "
            << (!inside.empty() ? "realizable in a cell meeting the hull (Theorem 14: the only cell reading it)"
                                : outside.empty() ? "not realizable anywhere"
                                                  : "read only in " + std::to_string(outside.size()) + " cell(s) outside the hull, which track cannot reach")
            << "\n";
  landmarks::LandmarkFigureOptions fo;
  fo.highlight_cells = inside.empty() ? outside : inside;
  if (learn) {
    landmarks::Simulator robot = make_robot(s, L, start);
    const auto tour = landmarks::learn_by_hull_tour(robot);
    const std::size_t learn_prims = robot.primitives();
    const auto r = landmarks::navigate(robot, tour.order_type.chirotope(), tour.hull, g);
    if (r.reached)
      std::cout << "robot: reached a cell reading the goal with " << robot.primitives() << " primitives (" << learn_prims
                << " to learn the hull and order type, " << robot.primitives() - learn_prims << " to navigate; Strategy 7); reads "
                << landmarks::format_reading(landmarks::normalized(robot.lcd()), L.labels) << "\n";
    else
      std::cout << "robot: not realizable in a cell meeting the hull: " << r.reason << " (" << robot.primitives() << " primitives)\n";
    std::cout << "agrees with the coordinates: " << (r.reached == !inside.empty() ? "yes" : "NO") << "\n";
    for (const auto& p : robot.waypoints()) fo.path.push_back(geometry::to_double(p));
  }
  if (!svg_file.empty()) save_svg(landmarks::swap_cell_figure(L, D, fo), svg_file);
}

void run_swap_graph(const std::string& file, bool learn, const std::string& start, bool as_json, const std::string& svg_file) {
  const scene::Scene s = scene::load_scene(file);
  const landmarks::LandmarkSet L = landmarks::landmark_set(s);
  const auto D = landmarks::SwapCellDecomposition::of(L.points);
  std::size_t inside = 0, inside_edges = 0;
  std::map<landmarks::Reading, std::size_t> readings;
  for (const auto& c : D.cells()) inside += c.meets_hull, ++readings[c.permutation];
  for (const auto& e : D.swap_graph()) inside_edges += e.meets_hull;
  std::size_t shared = 0;
  for (const auto& [p, k] : readings) shared += k > 1 ? k : 0;
  if (as_json && !learn) {
    json cells = json::array(), edges = json::array();
    for (std::uint32_t c = 0; c < D.cells().size(); ++c) {
      const auto& C = D.cells()[c];
      json perm = json::array();
      for (auto k : C.permutation) perm.push_back(L.labels[k]);
      cells.push_back({{"id", c}, {"permutation", perm}, {"meets_hull", C.meets_hull}, {"unbounded", C.unbounded}});
    }
    for (const auto& e : D.swap_graph())
      edges.push_back({{"cells", {e.a, e.b}}, {"swap", {L.labels[e.i], L.labels[e.j]}}, {"meets_hull", e.meets_hull}});
    return print_json({{"landmarks", L.size()}, {"swap_rays", D.rays().size()}, {"cells", cells}, {"edges", edges}});
  }
  std::cout << "swap cell decomposition of " << L.size() << " landmarks (" << D.rays().size() << " swap rays): " << D.cells().size()
            << " cells, " << inside << " meeting the hull; swap graph: " << D.swap_graph().size() << " edges (" << inside_edges
            << " across pieces inside the hull)\n";
  std::cout << "cells outside the hull sharing their permutation with another cell (Theorem 13): " << shared << "\n";
  if (learn) {
    landmarks::Simulator robot = make_robot(s, L, start);
    const auto tour = landmarks::learn_by_hull_tour(robot);
    const std::size_t p0 = robot.primitives();
    const auto in = landmarks::learn_inside_swap_graph(robot, tour.order_type.chirotope(), tour.hull);
    const std::size_t p1 = robot.primitives();
    const auto all = landmarks::learn_swap_graph(robot, in);
    std::set<landmarks::Reading> a, b;
    for (const auto& c : in.cells) a.insert(c.permutation);
    for (const auto& c : D.cells())
      if (c.meets_hull) b.insert(c.permutation);
    std::multiset<landmarks::Reading> x, y;
    for (const auto& c : all.cells) x.insert(c.permutation);
    for (const auto& c : D.cells()) y.insert(c.permutation);
    std::cout << "learned inside the hull (Strategy 8, track only): " << in.cells.size() << " cells, " << in.edges.size() << " edges, "
              << p1 - p0 << " primitives\n";
    std::cout << "learned everywhere (Strategy 9, with repel): " << all.cells.size() << " cells, " << all.edges.size() << " edges, "
              << robot.primitives() - p1 << " primitives (" << p0 << " more to learn the hull and order type)\n";
    std::cout << "agrees with the coordinates: "
              << (a == b && in.edges.size() == inside_edges && x == y && all.edges.size() == D.swap_graph().size() ? "yes" : "NO") << "\n";
  }
  if (!svg_file.empty()) {
    landmarks::LandmarkFigureOptions fo;
    fo.route = D.hull();
    save_svg(landmarks::swap_cell_figure(L, D, fo), svg_file);
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

  auto* p = cmd->add_subcommand("patrol", "the smallest patrol route keeping the watched landmarks inside (Strategy 6)");
  static std::string p_file, p_watch, p_start;
  static bool p_learn = false, p_json = false;
  p->add_option("scene", p_file, "scene with landmarks (JSON)")->required();
  p->add_option("--watch", p_watch, "labels of the landmarks to keep inside, e.g. 3,5,9")->required();
  p->add_flag("--learn", p_learn, "plan from what the simulated robot learns on a hull tour; print the primitive count");
  p->add_option("--start", p_start, "the robot's start X,Y (default: the scene's start, else the first landmark)");
  p->add_flag("--json", p_json, "JSON output");
  p->callback([] { run_patrol(p_file, p_watch, p_learn, p_start, p_json); });

  auto* nv = cmd->add_subcommand("navigate", "reach a cell reading a goal cyclic permutation, or report it unrealizable (Strategy 7)");
  static std::string n_file, n_goal, n_start, n_svg;
  static bool n_learn = false;
  nv->add_option("scene", n_file, "scene with landmarks (JSON)")->required();
  nv->add_option("--goal", n_goal, "the goal reading, counter-clockwise, e.g. \"7,2,8,5,3,6,1,4\"")->required();
  nv->add_flag("--learn", n_learn, "run the simulated robot (hull tour, then Strategy 7) and print the primitive count");
  nv->add_option("--start", n_start, "the robot's start X,Y (default: the scene's start, else the first landmark)");
  nv->add_option("--svg", n_svg, "draw the swap cells, the goal cell and the robot's path");
  nv->callback([] { run_navigate(n_file, n_goal, n_learn, n_start, n_svg); });

  auto* sg = cmd->add_subcommand("swap-graph", "the swap cell decomposition and its dual, the swap graph (6.1, 7)");
  static std::string g_file, g_start, g_svg;
  static bool g_learn = false, g_json = false;
  sg->add_option("scene", g_file, "scene with landmarks (JSON)")->required();
  sg->add_flag("--learn", g_learn, "also learn it with the simulated robot (Strategies 8 and 9) and print the primitive counts");
  sg->add_option("--start", g_start, "the robot's start X,Y (default: the scene's start, else the first landmark)");
  sg->add_flag("--json", g_json, "JSON output: every cell with its permutation, every edge with its swap");
  sg->add_option("--svg", g_svg, "draw the decomposition");
  sg->callback([] { run_swap_graph(g_file, g_learn, g_start, g_json, g_svg); });

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
