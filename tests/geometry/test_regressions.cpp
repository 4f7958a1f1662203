// One test per bug found, each on the input that exposed it (tests/fixtures/).
#include <gtest/gtest.h>
#include <preimage/geometry/queries.hpp>
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/scene.hpp>

using namespace preimage;
using geometry::Location;
using geometry::Point;

// locate() tested "q on the closed edge" before "q is the next vertex", so the apex
// (2, 5), reached as the end of edge 2 (4,3)->(2,5), came back as OnEdge.
TEST(Regression, LocateVertexAtEdgeEndIsAVertex) {
  const auto s = scene::load_scene(std::string(PREIMAGE_FIXTURES) + "/scenes/locate_vertex_at_edge_end.json");
  const auto& env = s.require_environment();
  for (std::size_t v = 0; v < env.num_vertices(); ++v) {
    const Location loc = geometry::locate(env, env.vertex(v));
    EXPECT_EQ(loc.kind, Location::Kind::AtVertex) << "vertex " << v;
    EXPECT_EQ(loc.index, v);
  }
  // And the visibility index agrees, so vertex queries take the fan-expansion path.
  const geometry::VisibilityIndex index(env);
  EXPECT_EQ(index.locate(Point(2, 5)).kind, Location::Kind::AtVertex);
  EXPECT_EQ(index.compute(Point(2, 5)).location.kind, Location::Kind::AtVertex);
}
