#pragma once

#include <cstddef>
#include <string>

#include "raster/RenderOptions.h"

namespace termshade {

/// `termshade render MODEL [options]`: headless frames to stdout or a file.
struct RenderCommandOptions {
  std::string modelPath;
  int widthCells = 80;
  int heightCells = 24;
  double cellAspect = 2.0;
  double theta = 0.3;
  double phi = 1.3;
  double rho = 0.0;  ///< 0: the model's default distance
  std::string method = "zbuffer";
  std::string shade = "contrast";
  std::string ramp = ShadeRamp::kDefaultGlyphs;
  std::string glyphs = "ramp";
  std::string format = "text";
  std::string outputPath;  ///< empty: stdout
  int frames = 1;
  double stepRadians = 0.1;
  bool noCull = false;
  std::string inputFormat;       ///< --input-format: extension for content that cannot be sniffed
  size_t memoryBudgetBytes = 0;  ///< --memory-budget; 0: DefaultMemoryBudgetBytes()
  std::string reader = "auto";   ///< --reader auto|assimp
  /// --color: none, 256, truecolor or auto; empty: the command's default
  /// (render: 256, so dumps do not depend on the environment; viewer: auto).
  std::string colour;
  bool mono = false;  ///< --mono: --color none
};

/// Runs the command; returns the process exit code (0 ok, 1 bad input, 2 bad usage).
int RunRenderCommand(const RenderCommandOptions& options);

}  // namespace termshade
