#pragma once

#include <optional>
#include <string>

#include "geometry/UpAxis.h"
#include "geometry/ViewParams.h"
#include "raster/RenderOptions.h"
#include "shade/Background.h"
#include "shade/ColourMode.h"

namespace termshade {

/// What the viewer shows, as far as `termshade render` can draw it again.
struct ViewToReproduce {
  std::string modelPath;  ///< as the shell should find it (absolute)
  int widthCells = 0;     ///< the frame's area, the status line left out
  int heightCells = 0;
  ViewParams view;
  double fitRho = 0.0;  ///< the distance the frame was fitted at (f); 0: the default
  double cellAspect = 2.0;
  UpAxis upAxis = UpAxis::kPlusZ;
  RenderOptions render;  ///< method, shade, ramp, glyphs, culling
  ColourMode colour = ColourMode::kNone;
  termshade::Background background = termshade::Background::kDark;
  double sunAzimuthRadians = 0.0;  ///< the light's angles (L mode); 0, 0: the default sun
  double sunElevationRadians = 0.0;
  bool levelOfDetail = false;  ///< the frame drew a simplified level (--lod auto)
};

/// The `termshade render ...` command that writes the same frame, cell for
/// cell, in the viewer's framing (--fit, and --fit-rho after f): the model shell-quoted, every
/// number exact (it reads back as the same double), `--format ansi` when there is colour (else
/// text; and for ascii, whose ansi dump matches glyphs to two colours).
std::string RenderCommandFor(const ViewToReproduce& shown);

/// A double as the shortest text that reads back (by strtod, and by
/// strtold rounded to double, as CLI11 reads it) as the same value.
std::string ExactNumber(double value);

}  // namespace termshade
