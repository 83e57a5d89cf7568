#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/LevelOfDetail.h"
#include "geometry/UpAxis.h"
#include "io/load/ModelLoader.h"
#include "raster/RenderOptions.h"
#include "shade/Background.h"
#include "shade/ColourMode.h"

namespace termshade {

/// Options of the interactive viewer (`termshade [MODEL...]`).
struct ViewerOptions {
  std::vector<std::string> modelPaths;  ///< empty: the embedded demo scene
  std::optional<double> cellAspect;     ///< unset: from the terminal, else 2.0
  /// kAuto is resolved from the terminal before the viewer starts.
  ColourMode colour = ColourMode::kAuto;
  /// The terminal's background; unset: what COLORFGBG says, else dark.
  std::optional<Background> background;
  RenderOptions render;
  std::optional<GlyphMode> glyphs;  ///< unset: PickGlyphMode for the terminal
  std::optional<UpAxis> upAxis;     ///< unset: each file's own (SPEC 10)
  /// auto: levels of detail built on a worker after a big model's first frame.
  DetailMode detail = DetailMode::kAuto;
  LoadLimits loadLimits;  ///< --memory-budget, --import-seconds
  double theta = 0.3;     ///< the view `r` returns to, radians (SPEC 2)
  double phi = 1.3;
  /// --record FILE.cast: what the viewer shows, as an asciinema v2 recording; empty: none.
  std::string recordPath;
};

/// Runs the full-screen viewer until the user quits; returns the exit code.
/// Restores the terminal on every path, signals included.
int RunViewer(const ViewerOptions& options);

}  // namespace termshade
