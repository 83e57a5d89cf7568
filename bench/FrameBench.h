#pragma once

#include <string>
#include <vector>

namespace termshade {

/// `termshade bench frame`: frame time by triangles x cells, one thread
/// against every thread, cluster culling on and off, and the face-by-face
/// loop; the configurations take turns frame by frame (one interleaved run).
struct FrameBenchOptions {
  /// Model files and generated spheres (triangles); neither given: the
  /// demo scene and spheres of 0.2 and 2 million triangles.
  std::vector<std::string> modelPaths;
  std::vector<size_t> triangleCounts;
  std::vector<std::string> sizes{"80x24", "160x48", "400x120"};
  int threads = 0;  ///< "all threads": 0 every core
  int frames = 15;  ///< turntable frames timed per model and size
};

int RunFrameBench(const FrameBenchOptions& options);

}  // namespace termshade
