// SPDX-License-Identifier: Apache-2.0
#include <preimage/error.hpp>
#include <preimage/geometry/general_position.hpp>
#include <preimage/wallfollow/environment.hpp>

#include <algorithm>
#include <numeric>

namespace preimage::wallfollow {

void require_general_position(const geometry::Environment& env, const std::string& where) {
  if (env.num_holes() > 0)
    throw InputError("$.environment.obstacles: the wall-following robot needs a simply connected environment (no obstacles)");
  if (const auto t = geometry::find_collinear_triple(env.vertices())) {
    std::size_t v[3] = {env.input_index((*t)[0]), env.input_index((*t)[1]), env.input_index((*t)[2])};
    std::sort(v, v + 3);
    throw InputError(where + ": vertices " + std::to_string(v[0]) + ", " + std::to_string(v[1]) + " and " +
                     std::to_string(v[2]) + " are collinear (the wall-following robot needs general position: "
                     "no three collinear vertices)");
  }
}

}  // namespace preimage::wallfollow
