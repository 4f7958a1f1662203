// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/wallfollow/environment.hpp>

#include <algorithm>
#include <numeric>

namespace preimage::wallfollow {

void require_general_position(const geometry::Environment& env, const std::string& where) {
  if (env.num_holes() > 0)
    throw InputError("$.environment.obstacles: the wall-following robot needs a simply connected environment (no obstacles)");
  const auto& P = env.vertices();
  const std::size_t n = P.size();
  std::vector<std::size_t> others;
  for (std::size_t i = 0; i < n; ++i) {
    others.clear();
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) others.push_back(j);
    // Directions from P[i] modulo pi: a point below P[i] (or level and left) stands
    // for its opposite direction, which flips the sign of the orientation test.
    auto upper = [&](std::size_t j) { return CGAL::compare_yx(P[j], P[i]) == CGAL::LARGER ? 1 : -1; };
    std::sort(others.begin(), others.end(), [&](std::size_t a, std::size_t b) {
      return upper(a) * upper(b) * geometry::orientation(P[i], P[a], P[b]) > 0;
    });
    for (std::size_t k = 1; k < others.size(); ++k)
      if (geometry::orientation(P[i], P[others[k - 1]], P[others[k]]) == 0) {
        std::size_t t[3] = {env.input_index(i), env.input_index(others[k - 1]), env.input_index(others[k])};
        std::sort(t, t + 3);
        throw InputError(where + ": vertices " + std::to_string(t[0]) + ", " + std::to_string(t[1]) + " and " +
                         std::to_string(t[2]) + " are collinear (the wall-following robot needs general position: "
                         "no three collinear vertices)");
      }
  }
}

}  // namespace preimage::wallfollow
