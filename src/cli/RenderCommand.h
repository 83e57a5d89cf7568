#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/UpAxis.h"
#include "io/load/ModelLoader.h"
#include "raster/RenderOptions.h"

namespace termshade {

/// `termshade render MODEL... [options]`: headless frames to stdout or a file.
struct RenderCommandOptions {
  std::vector<std::string> modelPaths;  ///< rendered one after another
  int widthCells = 0;                   ///< 0 (with heightCells): see kDefault*Cells
  int heightCells = 0;
  double cellAspect = 2.0;
  double theta = 0.3;
  double phi = 1.3;
  double rho = 0.0;            ///< 0: the model's default distance
  bool fit = false;            ///< --fit: the viewer's framing (Framing::kOrbit)
  double fitRho = 0.0;         ///< --fit-rho: the distance the frame is fitted at; 0: the default
  double budgetSeconds = 0.0;  ///< --budget: the whole command's time (RenderBudget); 0: none
  std::string method = "zbuffer";
  std::string shade = "contrast";
  std::string ramp = ShadeRamp::kDefaultGlyphs;
  std::string glyphs = "ramp";
  std::string format = "text";
  std::string outputPath;  ///< empty: stdout
  int frames = 1;
  double stepRadians = 0.1;
  double framesPerSecond = 25.0;  ///< --fps: asciicast frames a second (the viewer's cap)
  bool noCull = false;
  int threads = 0;              ///< --threads: frame threads, 0 every core
  std::string inputFormat;      ///< --input-format: extension for content that cannot be sniffed
  LoadLimits loadLimits;        ///< --memory-budget, --import-seconds
  std::string reader = "auto";  ///< --reader auto|assimp
  /// --color: none, 16, 256, truecolor or auto; empty: the command's default
  /// (render: 256, so dumps do not depend on the environment; viewer: auto).
  std::string colour;
  bool mono = false;  ///< --mono: --color none
  /// --background dark|light: the terminal the colours are made for; render's
  /// default is dark whatever the terminal, so dumps stay reproducible.
  std::string background;        ///< empty: the command's default
  std::optional<UpAxis> upAxis;  ///< unset: each file's own (SPEC 10)
  /// --light AZIMUTH,ELEVATION: the sun's angles (SunFromAngles); unset: the default sun.
  std::optional<std::pair<double, double>> lightRadians;
  /// --lod auto|off; empty: the command's default (render: off, exact dumps; viewer: auto).
  std::string lod;
  /// --textures on|off: faces take their texture's colours where colours are shown (default on).
  std::string textures;
};

/// Frame size without --size when stdout is not a terminal (or -o is given);
/// on a terminal, its width and its height less one row (the prompt stays visible).
constexpr int kDefaultWidthCells = 80;
constexpr int kDefaultHeightCells = 24;

/// Runs the command; returns the process exit code (0 ok, 1 bad input, 2 bad usage).
int RunRenderCommand(const RenderCommandOptions& options);

}  // namespace termshade
