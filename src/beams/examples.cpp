// SPDX-License-Identifier: Apache-2.0
#include <preimage/beams/examples.hpp>
#include <preimage/geometry/random_point.hpp>
#include <preimage/error.hpp>

#include <random>

namespace preimage::beams {

using geometry::Point;
using scene::Beam;

scene::Scene with_landmark_beams(scene::Scene s, LandmarkModel model, bool directed, bool distinguishable) {
  if (s.environment) throw InputError("landmark beams live in the unbounded plane: the scene must have no environment");
  if (s.landmarks.empty()) throw InputError("the scene has no landmarks");
  s.beams.clear();
  const auto& L = s.landmarks;
  if (model == LandmarkModel::North) {
    for (auto& l : L) s.beams.push_back({l.label, l.at, Point(l.at.x(), l.at.y() + 1), directed, Beam::Shape::Ray});
    return s;
  }
  for (std::size_t i = 0; i < L.size(); ++i)
    for (std::size_t j = i + 1; j < L.size(); ++j) {
      const Point &a = L[i].at, &b = L[j].at;
      const std::string shared = L[i].label + "~" + L[j].label;
      // Beyond b, away from a: the robot sees b in front of a.
      s.beams.push_back({distinguishable ? L[j].label + "/" + L[i].label : shared, b,
                         Point(2 * b.x() - a.x(), 2 * b.y() - a.y()), directed, Beam::Shape::Ray});
      s.beams.push_back({distinguishable ? L[i].label + "/" + L[j].label : shared, a,
                         Point(2 * a.x() - b.x(), 2 * a.y() - b.y()), directed, Beam::Shape::Ray});
    }
  return s;
}

namespace {
scene::Scene box_scene(const std::string& name, const std::string& desc, geometry::Ring outer, std::vector<geometry::Ring> holes) {
  scene::Scene s;
  s.name = name;
  s.description = desc;
  s.environment = geometry::Environment::make(std::move(outer), std::move(holes), "$.environment.boundary", "$.environment.obstacles");
  return s;
}
geometry::Ring rect(double x0, double y0, double x1, double y1) { return {Point(x0, y0), Point(x1, y0), Point(x1, y1), Point(x0, y1)}; }
}  // namespace

scene::Scene fig1_scene() {
  scene::Scene s = box_scene(
      "Fig. 1: six beams, four obstacles, three regions",
      "Beams paper, Fig. 1 and Fig. 3(a): undirected beams a, b, c close the line x = 4 between obstacles, d and e close "
      "x = 8, and f leads from an obstacle to the wall inside the middle region (a self-loop of G). The word cbabdeeefe "
      "is consistent.",
      rect(0, 0, 12, 8), {rect(3.5, 1.5, 4.5, 3), rect(3.5, 5, 4.5, 6.5), rect(7.5, 3.5, 8.5, 4.5), rect(5.5, 1.5, 6.5, 2.5)});
  s.beams = {{"a", Point(4, 0), Point(4, 1.5), false}, {"b", Point(4, 3), Point(4, 5), false},
             {"c", Point(4, 6.5), Point(4, 8), false}, {"d", Point(8, 0), Point(8, 3.5), false},
             {"e", Point(8, 4.5), Point(8, 8), false}, {"f", Point(6, 1.5), Point(6, 0), false}};
  return s;
}

scene::Scene fig3b_scene() {
  scene::Scene s = box_scene(
      "Fig. 3(b): crossing, directed and indistinguishable beams",
      "Beams paper, Fig. 3(b) and Fig. 8: directed beam a crosses undirected beam b; the two beams labelled c cannot be "
      "told apart; d is directed and crosses a. Positive crossings go from the right of from->to to its left.",
      rect(0, 0, 12, 8), {rect(5, 3, 7, 5)});
  s.beams = {{"a", Point(0, 1), Point(12, 2.5), true}, {"b", Point(3, 0), Point(3, 8), false},
             {"c", Point(6, 5), Point(6, 8), false},   {"c", Point(6, 3), Point(6, 0), false},
             {"d", Point(9, 0), Point(10, 8), true}};
  return s;
}

scene::Scene fig11_scene() {
  scene::Scene s = box_scene("Fig. 11: two bodies in a ring of three regions",
                             "Beams paper, Fig. 11(a) and 7.3: one obstacle, three undirected beams a, b, c from it to the "
                             "outer wall cut the ring into three regions.",
                             rect(0, 0, 10, 10), {rect(4, 4, 6, 6)});
  s.beams = {{"a", Point(5, 6), Point(5, 10), false}, {"b", Point(4, 5), Point(0, 5), false}, {"c", Point(6, 5), Point(10, 5), false}};
  return s;
}

scene::Scene fig13_scene() {
  scene::Scene s = box_scene("Fig. 13-14: a perfect collection of beams",
                             "Beams paper 5.1 and 6.1: two obstacles, one directed outer beam each, pointing away from its "
                             "obstacle so that the positive crossing is counter-clockwise about it. The word (5) gives "
                             "winding vector (2, -3).",
                             rect(0, 0, 12, 8), {rect(2, 3, 4, 5), rect(8, 3, 10, 5)});
  s.beams = {{"b1", Point(3, 5), Point(3, 8), true}, {"b2", Point(9, 5), Point(9, 8), true}};
  return s;
}

scene::Scene fig18_scene() {
  scene::Scene s = box_scene("Fig. 18: the commutator path",
                             "Beams paper 6.1, Fig. 18: two obstacles with perfect beams a and b. The word a b a' b' is the "
                             "commutator, a non-trivial homotopy class whose winding numbers are (0, 0).",
                             rect(0, 0, 12, 8), {rect(2, 3, 4, 5), rect(8, 3, 10, 5)});
  s.beams = {{"a", Point(3, 3), Point(3, 0), true}, {"b", Point(9, 3), Point(9, 0), true}};
  return s;
}

scene::Scene landmark_scene(std::size_t n, std::uint64_t seed) {
  // Integer coordinates on a grid, redrawn until no three are collinear and no two
  // share an abscissa (so rays due north meet no other landmark).
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> u(0, 40);
  scene::Scene s;
  s.name = std::to_string(n) + " landmarks";
  while (s.landmarks.size() < n) {
    const Point p = geometry::random_point(rng, u);
    bool ok = true;
    for (std::size_t i = 0; i < s.landmarks.size() && ok; ++i) {
      ok = s.landmarks[i].at.x() != p.x();
      for (std::size_t j = i + 1; j < s.landmarks.size() && ok; ++j)
        ok = geometry::orientation(s.landmarks[i].at, s.landmarks[j].at, p) != 0;
    }
    if (ok) s.landmarks.push_back({std::to_string(s.landmarks.size() + 1), p});
  }
  return s;
}

}  // namespace preimage::beams
