// Loads a scene and prints the area visible from a point.
#include <preimage/geometry/visibility.hpp>
#include <preimage/scene/scene.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: visible_area SCENE.json X Y\n";
    return 2;
  }
  const auto scene = preimage::scene::load_scene(argv[1]);
  const preimage::geometry::VisibilityIndex index(scene.require_environment());
  const auto v = index.compute(preimage::geometry::Point(std::stod(argv[2]), std::stod(argv[3])));
  std::cout << "visible area " << v.area() << " with " << v.vertices.size() << " vertices\n";
}
