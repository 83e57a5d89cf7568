#pragma once

#include <string>
#include <vector>

namespace termshade {

/// `termshade bench load`: what a big model costs before and after its first
/// frame, per format and size (generated spheres, nothing downloaded).
struct LoadBenchOptions {
  std::vector<size_t> triangleCounts{200000, 2000000};
  std::vector<std::string> formats{"obj", "stl", "ply"};
  std::vector<std::string> readers{"auto", "assimp"};  ///< render --reader values, each a row
  int repeats = 3;  ///< runs of the whole command per file; medians are reported
  int widthCells = 160;
  int heightCells = 48;
  std::string directory;       ///< where the models are written (default: a temporary folder)
  std::string executablePath;  ///< this program, run as `render` in a child process
};

int RunLoadBench(const LoadBenchOptions& options);

}  // namespace termshade
