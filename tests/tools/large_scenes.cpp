// Writes the ~10^5-vertex scenes of tests/support/large_scenes.hpp as scene files into a
// directory, for the command-line scale tests (tests/cli/large.cmake).
#include "support/large_scenes.hpp"

#include <preimage/error.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: preimage_large_scenes DIR\n";
    return 2;
  }
  try {
    for (const auto& s : preimage::testing::large_scenes()) {
      const std::string path = std::string(argv[1]) + "/" + s.name + ".json";
      preimage::scene::save_scene(s.scene, path);
      std::cout << "wrote " << path << ": " << s.scene.environment->num_vertices() << " vertices, "
                << s.scene.environment->num_holes() << " obstacles\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "preimage_large_scenes: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
