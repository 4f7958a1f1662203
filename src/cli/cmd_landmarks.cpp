// SPDX-License-Identifier: Apache-2.0
// preimage landmarks order-type | hull | patrol | navigate | swap-graph | count-order-types
// (landmark paper). Every --learn run is checked against the coordinates; a difference is
// a bug in the library and ends the command as an internal error (exit 3).
#include "common.hpp"
#include "progress.hpp"

#include <preimage/error.hpp>
#include <preimage/geometry/coordinates.hpp>
#include <preimage/landmarks/order_type.hpp>
#include <preimage/landmarks/figures.hpp>
#include <preimage/landmarks/robot.hpp>
#include <preimage/landmarks/strategies.hpp>
#include <preimage/landmarks/swap_cells.hpp>


#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <stdexcept>

namespace preimage::cli {
namespace {

using nlohmann::json;

// The swap cell decomposition has Theta(n^4) cells (about 0.05 n^4 for random sets) and
// takes about 2.4 kB per cell: beyond this many landmarks it would not fit in memory or
// minutes (docs/landmarks.md, "Performance").
constexpr std::size_t kMaxSwapCellLandmarks = 60;
// Strategy 9 repels along all n(n - 1) swap lines and records both sides of every piece:
// Theta(n^4) again, about 12 s and 0.7 GB at n = 40.
constexpr std::size_t kMaxLearnedSwapGraphLandmarks = 40;


// A --learn result that differs from the coordinates is a bug: one line, exit 3.
void self_check(bool ok, const std::string& what) {
  if (!ok) throw std::logic_error("self-check failed: " + what);
}

std::string label_list(const landmarks::LandmarkSet& L, const std::vector<std::uint32_t>& v) {
  return landmarks::format_reading(v, L.labels);
}

json label_array(const landmarks::LandmarkSet& L, const std::vector<std::uint32_t>& v) {
  json a = json::array();
  for (auto k : v) a.push_back(L.labels[k]);
  return a;
}

// The robot starts at --start, else at the scene's start, else at the first landmark.
landmarks::Simulator make_robot(const scene::Scene& s, const landmarks::LandmarkSet& L, const std::string& start) {
  if (!start.empty()) {
    const geometry::Point p = parse_point(start, "--start");
    for (double v : {p.x(), p.y()})
      if (const auto why = geometry::coordinate_problem(v); !why.empty()) throw InputError("--start: " + why);
    return landmarks::Simulator(L.points, p, L.labels);
  }
  if (s.start) return landmarks::Simulator(L.points, *s.start, L.labels);
  return landmarks::Simulator(L.points, std::uint32_t{0});
}

// Commands that need the decomposition from coordinates refuse beyond kMaxSwapCellLandmarks.
void require_decomposable(const landmarks::LandmarkSet& L, const std::string& command) {
  const std::size_t n = L.size();
  if (n > kMaxSwapCellLandmarks) {
    const double cells = 0.05 * double(n) * double(n) * double(n) * double(n);
    char buf[160];
    std::snprintf(buf, sizeof buf, "%zu landmarks give about %.1g swap cells (Theta(n^4)); at most %zu landmarks are supported", n,
                  cells, kMaxSwapCellLandmarks);
    throw InputError(command + ": needs the swap cell decomposition from coordinates: " + buf);
  }
}

landmarks::SwapCellDecomposition decomposition(const landmarks::LandmarkSet& L) {
  const std::size_t n = L.size();
  Progress progress("swap cell decomposition of " + std::to_string(n) + " landmarks");
  return landmarks::SwapCellDecomposition::of(L.points, [&](double f) { progress(f); });
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
    auto t = truth;
    std::rotate(t.begin(), std::find(t.begin(), t.end(), hull.front()), t.end());
    self_check(t == hull, "the hull learned by the robot (" + label_list(L, hull) + ") differs from the hull from coordinates (" +
                              label_list(L, truth) + ")");
  }
  std::cout << "convex hull, counter-clockwise: " << label_list(L, hull) << "\n";
  if (learn)
    std::cout << "learned by the robot with " << primitives << " track primitives (Strategies 4-5, n = " << L.size()
              << "); agrees with the coordinates: yes\n";
}

void run_order_type(const std::string& file, bool as_json, bool learn, const std::string& start) {
  const scene::Scene sc = scene::load_scene(file);
  const landmarks::LandmarkSet L = landmarks::landmark_set(sc);
  const landmarks::OrderType T = landmarks::OrderType::of(L.points);
  const std::size_t n = L.size();
  std::vector<std::uint32_t> learned;
  std::size_t primitives = 0;
  if (learn) {
    landmarks::Simulator robot = make_robot(sc, L, start);
    learned = landmarks::learn_order_type(robot);  // Strategy 1 for every pair
    primitives = robot.primitives();
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = 0; j < n; ++j)
        self_check(i == j || learned[i * n + j] == T.lambda(i, j),
                   "the robot learned lambda(" + L.labels[i] + ", " + L.labels[j] + ") = " + std::to_string(learned[i * n + j]) +
                       ", the coordinates give " + std::to_string(T.lambda(i, j)));
  }
  const std::string learn_note = "learned by the robot with " + std::to_string(primitives) +
                                 " track primitives (Strategy 1 for all " + std::to_string(n * (n - 1) / 2) + " pairs)";
  const auto hull = T.hull();
  const auto C = landmarks::canonical_form(T);
  if (as_json) {
    json lam = json::array(), Lam = json::object();
    for (std::uint32_t i = 0; i < n; ++i) {
      json row = json::array();
      for (std::uint32_t j = 0; j < n; ++j) row.push_back(i == j ? 0 : T.lambda(i, j));
      lam.push_back(row);
      for (std::uint32_t j = 0; j < n; ++j)
        if (i != j) Lam[L.labels[i] + "," + L.labels[j]] = label_array(L, T.Lambda(i, j));
    }
    json out{{"n", n}, {"labels", L.labels}, {"hull", label_array(L, hull)}, {"lambda", lam}, {"Lambda", Lam},
             {"canonical_labelling", label_array(L, C.labelling)}};
    if (learn) {
      json rows = json::array();
      for (std::uint32_t i = 0; i < n; ++i) {
        json row = json::array();
        for (std::uint32_t j = 0; j < n; ++j) row.push_back(i == j ? 0 : learned[i * n + j]);
        rows.push_back(row);
      }
      out["learned"] = {{"strategy", "Strategy 1 for every pair"}, {"primitives", primitives}, {"lambda", rows},
                        {"agrees_with_coordinates", true}};
    }
    return print_json(out);
  }
  if (learn) std::cout << "order type " << learn_note << "; agrees with the coordinates: yes\n";
  std::cout << "order type of " << n << " landmarks (lambda(i, j) = landmarks left of p_i -> p_j)\n";
  std::cout << "convex hull, counter-clockwise: " << label_list(L, hull) << "\n";
  std::cout << "canonical labelling (hull landmark first, the rest counter-clockwise around it): " << label_list(L, C.labelling) << "\n";
  std::cout << "lambda:\n";
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
    self_check(learned->route == plan.route, "the robot's patrol route (" + label_list(L, learned->route) +
                                                 ") differs from the route from coordinates (" + label_list(L, plan.route) + ")");
  }
  const auto& p = learned ? *learned : plan;
  if (as_json) {
    json j{{"watch", label_array(L, W)}, {"route", label_array(L, p.route)}, {"M", label_array(L, p.M)}};
    if (learn) j["primitives"] = primitives, j["agrees_with_coordinates"] = true;
    return print_json(j);
  }
  std::cout << "patrol route around " << label_list(L, W) << ", counter-clockwise: " << label_list(L, p.route) << "\n";
  std::cout << "M = {" << label_list(L, p.M) << "} (" << p.M.size() << " landmarks, the fewest with the watched ones strictly inside hull(M))\n";
  if (learn)
    std::cout << "learned by the robot with " << primitives << " track primitives (Strategies 4-5 and one hull tour for the order type; "
              << "Strategy 6); agrees with the coordinates: yes\n";
}

void run_navigate(const std::string& file, const std::string& goal_text, bool learn, const std::string& start, const std::string& svg_file,
                  bool as_json) {
  const scene::Scene s = scene::load_scene(file);
  const landmarks::LandmarkSet L = landmarks::landmark_set(s);
  require_decomposable(L, "navigate");
  const auto goal = parse_labels(L, goal_text, "--goal");
  if (goal.size() != L.size())
    throw InputError("--goal: a cyclic permutation of all " + std::to_string(L.size()) + " landmarks is needed, got " +
                     std::to_string(goal.size()));
  const landmarks::Reading g = landmarks::normalized(goal);
  const auto D = decomposition(L);
  const landmarks::OrderType T = landmarks::OrderType::of(L.points);
  std::vector<std::uint32_t> inside, outside;
  for (std::uint32_t c = 0; c < D.cells().size(); ++c)
    if (D.cells()[c].permutation == g) (D.cells()[c].meets_hull ? inside : outside).push_back(c);
  const auto chi = [&T](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return T.chi(i, j, k); };
  const auto polar = landmarks::polar_pairs(L.size(), chi, g);
  const std::string truth = !inside.empty()  ? "realizable in a cell meeting the hull (Theorem 14: the only cell reading it)"
                            : outside.empty() ? "not realizable anywhere"
                                              : "read only in " + std::to_string(outside.size()) +
                                                    " cell(s) outside the hull, which track cannot reach";
  landmarks::LandmarkFigureOptions fo;
  fo.highlight_cells = inside.empty() ? outside : inside;
  json out{{"goal", label_array(L, g)},
           {"polar_pairs", json::array()},
           {"coordinates", {{"realizable_meeting_hull", !inside.empty()}, {"cells_outside_hull", outside.size()}, {"summary", truth}}}};
  for (auto [i, j] : polar) out["polar_pairs"].push_back({L.labels[i], L.labels[j]});
  std::string robot_line;
  if (learn) {
    landmarks::Simulator robot = make_robot(s, L, start);
    const auto tour = landmarks::learn_by_hull_tour(robot);
    const std::size_t learn_prims = robot.primitives();
    const auto r = landmarks::navigate(robot, tour.order_type.chirotope(), tour.hull, g, L.labels);
    if (r.reached) {
      // The simulator tracks the reading event by event; an exact angular sort at the
      // robot's position must agree, and be the goal cell's.
      std::vector<geometry::ExactPoint> E;
      for (const auto& p : L.points) E.push_back(geometry::to_exact(p));
      const auto sorted = landmarks::normalized(landmarks::angular_reading(E, robot.position(), robot.at(), nullptr, {}));
      self_check(!inside.empty(), "the robot reached a cell reading " + label_list(L, g) +
                                      ", but the coordinates read it in no cell meeting the hull");
      self_check(sorted == g, "the robot believes it reads the goal, but an angular sort at its position reads " + label_list(L, sorted));
      robot_line = "robot: reached a cell reading the goal with " + std::to_string(robot.primitives()) + " primitives (" +
                   std::to_string(learn_prims) + " to learn the hull and order type, " + std::to_string(robot.primitives() - learn_prims) +
                   " to navigate; Strategy 7); reads " + label_list(L, sorted);
    } else {
      self_check(inside.empty(), "the robot reports " + label_list(L, g) + " unrealizable (" + r.reason +
                                     "), but the coordinates read it in a cell meeting the hull");
      robot_line = "robot: not realizable in a cell meeting the hull: " + r.reason + " (" + std::to_string(robot.primitives()) +
                   " primitives)";
    }
    out["robot"] = {{"reached", r.reached},
                    {"reason", r.reason},
                    {"primitives", robot.primitives()},
                    {"primitives_to_learn", learn_prims},
                    {"swap_lines_searched", r.swap_lines_searched},
                    {"agrees_with_coordinates", true}};
    for (const auto& p : robot.waypoints()) fo.path.push_back(geometry::to_double(p));
  }
  if (!svg_file.empty()) {
    landmarks::swap_cell_figure(L, D, fo).save(svg_file);
    out["figure"] = svg_file;
  }
  if (as_json) return print_json(out);
  std::string polar_text;
  for (auto [i, j] : polar) polar_text += (polar_text.empty() ? "" : ", ") + L.labels[i] + "-" + L.labels[j];
  std::cout << "goal " << label_list(L, g) << "; polar pairs: " << (polar_text.empty() ? "none" : polar_text) << "\n";
  std::cout << "from coordinates: " << truth << "\n";
  if (learn) std::cout << robot_line << "\nagrees with the coordinates: yes\n";
  if (!svg_file.empty()) std::cout << "figure: " << svg_file << "\n";
}

void run_swap_graph(const std::string& file, bool learn, const std::string& start, bool as_json, const std::string& svg_file) {
  const scene::Scene s = scene::load_scene(file);
  const landmarks::LandmarkSet L = landmarks::landmark_set(s);
  if (learn && L.size() > kMaxLearnedSwapGraphLandmarks)
    throw InputError("swap-graph --learn: Strategy 9 takes Theta(n^4) time and memory; at most " +
                     std::to_string(kMaxLearnedSwapGraphLandmarks) + " landmarks are supported with --learn, got " + std::to_string(L.size()));
  require_decomposable(L, "swap-graph");
  const auto D = decomposition(L);
  std::size_t inside = 0, inside_edges = 0;
  std::map<landmarks::Reading, std::size_t> readings;
  for (const auto& c : D.cells()) inside += c.meets_hull, ++readings[c.permutation];
  for (const auto& e : D.swap_graph()) inside_edges += e.meets_hull;
  std::size_t shared = 0;
  for (const auto& [p, k] : readings) shared += k > 1 ? k : 0;
  json out{{"landmarks", L.size()},
           {"swap_rays", D.rays().size()},
           {"summary",
            {{"cells", D.cells().size()},
             {"cells_meeting_hull", inside},
             {"edges", D.swap_graph().size()},
             {"edges_meeting_hull", inside_edges},
             {"outside_cells_sharing_permutation", shared}}}};
  std::string learned_text;
  if (learn) {
    landmarks::Simulator robot = make_robot(s, L, start);
    const auto tour = landmarks::learn_by_hull_tour(robot);
    const std::size_t p0 = robot.primitives();
    const auto in = landmarks::learn_inside_swap_graph(robot, tour.order_type.chirotope(), tour.hull);
    const std::size_t p1 = robot.primitives();
    Progress progress("Strategy 9 on " + std::to_string(L.size()) + " landmarks");
    const auto all = landmarks::learn_swap_graph(robot, in, [&](double f) { progress(f); });
    // Strategy 8 against the cells meeting the hull and the edges across pieces inside it.
    std::set<landmarks::Reading> a, b;
    std::set<std::pair<landmarks::Reading, landmarks::Reading>> ea, eb;
    for (const auto& c : in.cells) a.insert(c.permutation);
    for (const auto& e : in.edges) ea.insert(std::minmax(in.cells[e.a].permutation, in.cells[e.b].permutation));
    for (const auto& c : D.cells())
      if (c.meets_hull) b.insert(c.permutation);
    for (const auto& e : D.swap_graph())
      if (e.meets_hull) eb.insert(std::minmax(D.cells()[e.a].permutation, D.cells()[e.b].permutation));
    self_check(a == b, "Strategy 8 learned " + std::to_string(a.size()) + " cells meeting the hull, the coordinates have " +
                           std::to_string(b.size()));
    self_check(ea == eb, "Strategy 8 learned " + std::to_string(ea.size()) + " edges inside the hull, the coordinates have " +
                             std::to_string(eb.size()));
    // Strategy 9: the same multiset of permutations and, by permutation pairs with
    // multiplicity, the same edges (the tests match cells one to one).
    std::multiset<landmarks::Reading> x, y;
    std::multiset<std::pair<landmarks::Reading, landmarks::Reading>> ex, ey;
    for (const auto& c : all.cells) x.insert(c.permutation);
    for (const auto& c : D.cells()) y.insert(c.permutation);
    for (const auto& e : all.edges) ex.insert(std::minmax(all.cells[e.a].permutation, all.cells[e.b].permutation));
    for (const auto& e : D.swap_graph()) ey.insert(std::minmax(D.cells()[e.a].permutation, D.cells()[e.b].permutation));
    self_check(x == y, "Strategy 9 learned " + std::to_string(all.cells.size()) + " cells, the coordinates have " +
                           std::to_string(D.cells().size()) + (all.cells.size() == D.cells().size() ? " with other permutations" : ""));
    self_check(ex == ey, "Strategy 9 learned " + std::to_string(all.edges.size()) + " edges, the coordinates have " +
                             std::to_string(D.swap_graph().size()) +
                             (all.edges.size() == D.swap_graph().size() ? " between other cells" : ""));
    out["learned"] = {{"hull_tour_primitives", p0},
                      {"inside", {{"strategy", "Strategy 8 (track only)"}, {"cells", in.cells.size()}, {"edges", in.edges.size()}, {"primitives", p1 - p0}}},
                      {"everywhere",
                       {{"strategy", "Strategy 9 (with repel)"}, {"cells", all.cells.size()}, {"edges", all.edges.size()}, {"primitives", robot.primitives() - p1}}},
                      {"agrees_with_coordinates", true}};
    learned_text = "learned inside the hull (Strategy 8, track only): " + std::to_string(in.cells.size()) + " cells, " +
                   std::to_string(in.edges.size()) + " edges, " + std::to_string(p1 - p0) + " primitives\n" +
                   "learned everywhere (Strategy 9, with repel): " + std::to_string(all.cells.size()) + " cells, " +
                   std::to_string(all.edges.size()) + " edges, " + std::to_string(robot.primitives() - p1) + " primitives (" +
                   std::to_string(p0) + " more to learn the hull and order type)\nagrees with the coordinates: yes\n";
  }
  if (!svg_file.empty()) {
    landmarks::LandmarkFigureOptions fo;
    fo.route = D.hull();
    landmarks::swap_cell_figure(L, D, fo).save(svg_file);
    out["figure"] = svg_file;
  }
  if (as_json) {
    json cells = json::array(), edges = json::array();
    for (std::uint32_t c = 0; c < D.cells().size(); ++c) {
      const auto& C = D.cells()[c];
      cells.push_back({{"id", c}, {"permutation", label_array(L, C.permutation)}, {"meets_hull", C.meets_hull}, {"unbounded", C.unbounded}});
    }
    for (const auto& e : D.swap_graph())
      edges.push_back({{"cells", {e.a, e.b}}, {"swap", {L.labels[e.i], L.labels[e.j]}}, {"meets_hull", e.meets_hull}});
    out["cells"] = std::move(cells);
    out["edges"] = std::move(edges);
    return print_json(out);
  }
  std::cout << "swap cell decomposition of " << L.size() << " landmarks (" << D.rays().size() << " swap rays): " << D.cells().size()
            << " cells, " << inside << " meeting the hull; swap graph: " << D.swap_graph().size() << " edges (" << inside_edges
            << " across pieces inside the hull)\n";
  std::cout << "cells outside the hull sharing their permutation with another cell (Theorem 13): " << shared << "\n";
  std::cout << learned_text;
  if (!svg_file.empty()) std::cout << "figure: " << svg_file << "\n";
}

// count-order-types draws `samples` sets and keeps one canonical form (N^2 numbers) per
// distinct order type: time (about 1 microsecond per sample and N^2) and memory grow as
// samples * N^2. The bound keeps a run within about a minute.
constexpr std::int64_t kMaxOrderTypeWork = 50'000'000;

}  // namespace

void add_landmarks_commands(CLI::App& app) {
  auto* cmd = app.add_subcommand("landmarks", "Landmark order types from cyclic permutations (landmark paper)");
  cmd->require_subcommand(1);

  auto* o = cmd->add_subcommand("order-type", "The order type of the scene's landmarks: lambda, Lambda, hull, canonical labelling");
  set_examples(o, {"preimage landmarks order-type examples/landmarks/eight.json"});
  static std::string o_file, o_start;
  static bool o_json = false, o_learn = false;
  o->add_option("scene", o_file, "Scene with landmarks (JSON)")->required();
  add_json_flag(o, o_json, "JSON output (with every Lambda(i, j), and the learned lambda with --learn)");
  o->add_flag("--learn", o_learn, "Also learn it with the simulated robot (Strategy 1) and print the primitive count");
  o->add_option("--start", o_start, "The robot's start X,Y (default: the scene's start, else the first landmark)");
  o->callback([] { run_order_type(o_file, o_json, o_learn, o_start); });

  auto* h = cmd->add_subcommand("hull", "The convex hull boundary of the landmarks, counter-clockwise");
  set_examples(h, {"preimage landmarks hull examples/landmarks/eight.json --learn"});
  static std::string h_file, h_start;
  static bool h_learn = false;
  h->add_option("scene", h_file, "Scene with landmarks (JSON)")->required();
  h->add_flag("--learn", h_learn, "Learn it with the simulated robot (Strategies 4-5) and print the primitive count");
  h->add_option("--start", h_start, "The robot's start X,Y (default: the scene's start, else the first landmark)");
  h->callback([] { run_hull(h_file, h_learn, h_start); });

  auto* p = cmd->add_subcommand("patrol", "The smallest patrol route keeping the watched landmarks inside (Strategy 6)");
  set_examples(p, {"preimage landmarks patrol examples/landmarks/eight.json --watch 3,7"});
  static std::string p_file, p_watch, p_start;
  static bool p_learn = false, p_json = false;
  p->add_option("scene", p_file, "Scene with landmarks (JSON)")->required();
  p->add_option("--watch", p_watch, "Labels of the landmarks to keep inside, e.g. 3,5,9")->required();
  p->add_flag("--learn", p_learn, "Plan from what the simulated robot learns on a hull tour; print the primitive count");
  p->add_option("--start", p_start, "The robot's start X,Y (default: the scene's start, else the first landmark)");
  add_json_flag(p, p_json, "JSON output");
  p->callback([] { run_patrol(p_file, p_watch, p_learn, p_start, p_json); });

  auto* nv = cmd->add_subcommand("navigate", "Reach a cell reading a goal cyclic permutation, or report it unrealizable (Strategy 7)");
  set_examples(nv, {"preimage landmarks navigate examples/landmarks/six.json --goal 1,3,2,5,6,4 --svg navigate.svg"});
  static std::string n_file, n_goal, n_start, n_svg;
  static bool n_learn = false, n_json = false;
  nv->add_option("scene", n_file, "Scene with landmarks (JSON)")->required();
  nv->add_option("--goal", n_goal, "The goal reading, counter-clockwise, e.g. \"1,3,2,5,8,6,7,4\"")->required();
  nv->add_flag("--learn", n_learn, "Run the simulated robot (hull tour, then Strategy 7) and print the primitive count");
  nv->add_option("--start", n_start, "The robot's start X,Y (default: the scene's start, else the first landmark)");
  nv->add_option("--svg", n_svg, "Draw the swap cells, the goal cell and the robot's path");
  add_json_flag(nv, n_json, "JSON output");
  nv->callback([] { run_navigate(n_file, n_goal, n_learn, n_start, n_svg, n_json); });

  auto* sg = cmd->add_subcommand("swap-graph", "The swap cell decomposition and its dual, the swap graph (6.1, 7)");
  set_examples(sg, {"preimage landmarks swap-graph examples/landmarks/six.json --svg swap.svg"});
  static std::string g_file, g_start, g_svg;
  static bool g_learn = false, g_json = false;
  sg->add_option("scene", g_file, "Scene with landmarks (JSON)")->required();
  sg->add_flag("--learn", g_learn, "Also learn it with the simulated robot (Strategies 8 and 9) and print the primitive counts");
  sg->add_option("--start", g_start, "The robot's start X,Y (default: the scene's start, else the first landmark)");
  add_json_flag(sg, g_json, "JSON output: every cell with its permutation, every edge with its swap");
  sg->add_option("--svg", g_svg, "Draw the decomposition");
  sg->callback([] { run_swap_graph(g_file, g_learn, g_start, g_json, g_svg); });

  auto* c = cmd->add_subcommand("count-order-types", "Distinct order types among random sets of N landmarks");
  set_examples(c, {"preimage landmarks count-order-types 5 --samples 2000"});
  static std::int64_t c_n = 0, c_samples = 1000, c_seed = 1;
  c->add_option("N", c_n, "Landmarks per set, 3 to 1000")->required()->check(integer_in(3, 1000));
  auto* samples = add_count(c, "--samples", c_samples, 1, kMaxOrderTypeWork / 9,
                            "random sets to draw (default 1000, fewer for large N; samples * N^2 at most 5e7)");
  add_count(c, "--seed", c_seed, 0, INT64_MAX, "Random seed");
  static bool c_mirror = false;
  c->add_flag("--mirror", c_mirror, "Identify mirror images (count up to reflection too)");
  c->callback([samples] {
    const std::int64_t most = kMaxOrderTypeWork / (c_n * c_n);
    if (samples->count() == 0) c_samples = std::min(c_samples, most);
    if (c_samples > most)
      throw CLI::ValidationError("--samples", "at most " + std::to_string(most) + " sets of " + std::to_string(c_n) +
                                                  " landmarks (samples * N^2 <= 5e7, about a minute), got " + std::to_string(c_samples));
    Progress progress("drawing " + std::to_string(c_samples) + " sets of " + std::to_string(c_n) + " landmarks");
    const auto r = landmarks::count_order_types(static_cast<std::size_t>(c_n), static_cast<std::size_t>(c_samples),
                                                static_cast<std::uint64_t>(c_seed), c_mirror, [&](double f) { progress(f); });
    std::cout << r.distinct << " distinct order types among " << r.samples << " random sets of " << c_n << " landmarks (up to relabelling"
              << (c_mirror ? " and reflection" : "") << "; " << r.redrawn << " degenerate draws redrawn)\n";
  });
}

}  // namespace preimage::cli
