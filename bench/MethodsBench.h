#pragma once

#include <string>
#include <vector>

namespace termshade {

/// `termshade bench methods`: speed against error for every method on the
/// same frames.
struct MethodsBenchOptions {
  int widthCells = 160;
  int heightCells = 48;
  int frames = 8;               ///< turntable views per scene
  double secondsPerCase = 0.3;  ///< timing budget per method and scene
  std::string csvPath = "docs/bench-methods.csv";
  std::string svgPath = "docs/bench-methods.svg";
  std::string dataDirectory = "data";
};

int RunMethodsBench(const MethodsBenchOptions& options);

/// CPU model, kernel and thread count, for the reports' headers.
std::string MachineDescription();

}  // namespace termshade
