// SPDX-License-Identifier: Apache-2.0
// The map of a wall-following pursuit plan (section VI): cuts (inflections, whose
// crossings make primitives appear and disappear, drawn stronger than the other cuts),
// bitangent rays (split and merge), and the path the robot executed.
#pragma once
#include <preimage/render/svg.hpp>
#include <preimage/wallfollow/cut_ordering.hpp>
#include <preimage/wallfollow/sensors.hpp>

#include <string>
#include <vector>

namespace preimage::wallfollow {

render::SvgCanvas pursuit_map(const geometry::Environment& env, const TrueCuts& cuts, const std::vector<Bitangent>& bitangents,
                              const std::vector<geometry::ExactPoint>& path, double width_px, const std::string& title);

}  // namespace preimage::wallfollow
