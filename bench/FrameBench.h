#pragma once

#include <string>
#include <vector>

namespace termshade {

/// `termshade bench frame`: frame time by triangles x cells, one thread
/// against every thread, cluster culling on and off, and the face-by-face
/// loop; the configurations take turns frame by frame (one interleaved run).
struct FrameBenchOptions {
  std::vector<std::string> modelPaths;  ///< model files; none: data/sphere_cone.dat
  std::vector<size_t> triangleCounts{200000, 2000000};  ///< generated spheres
  std::vector<std::string> sizes{"80x24", "160x48", "400x120"};
  int threads = 0;  ///< "all threads": 0 every core
  int frames = 15;  ///< turntable frames timed per model and size
};

int RunFrameBench(const FrameBenchOptions& options);

}  // namespace termshade
