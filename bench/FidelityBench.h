#pragma once

#include <string>

namespace termshade {

/// `termshade bench fidelity`: how close each glyph mode's frames look to the
/// exact image (SPEC 12), beside its frame time and flicker.
struct FidelityBenchOptions {
  int widthCells = 160;
  int heightCells = 48;
  int frames = 2;               ///< turntable views per scene
  double secondsPerCase = 0.2;  ///< timing budget per mode and scene
  std::string csvPath = "docs/bench-fidelity.csv";
  std::string svgPath = "docs/bench-fidelity.svg";
  std::string dataDirectory = "data";
  std::string sceneName;    ///< only this scene (empty: every scene)
  bool timingOnly = false;  ///< frame times alone: no fidelity, flicker, CSV or SVG
};

int RunFidelityBench(const FidelityBenchOptions& options);

}  // namespace termshade
