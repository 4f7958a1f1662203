// SPDX-License-Identifier: Apache-2.0
// WKT out: an environment as one POLYGON, so GIS tools (QGIS, Shapely, PostGIS) read it.
#pragma once
#include <preimage/geometry/environment.hpp>

#include <string>

namespace preimage::scene {

/// `POLYGON ((x y, ...), (x y, ...))`: the boundary, then each hole, every ring closed;
/// coordinates in the shortest form that reads back to the same double, so `import_wkt`
/// of the text gives the same environment.
std::string to_wkt(const geometry::Environment& env);

}  // namespace preimage::scene
