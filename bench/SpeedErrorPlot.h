#pragma once

#include <string>
#include <vector>

namespace termshade {

/// One method on one scene.
struct PlotPoint {
  std::string scene;
  std::string method;
  double medianMs = 0.0;
  double faceError = -1.0;  ///< share; < 0 when not measured
  double shadeErrorLevels = 0.0;
};

/// Writes an SVG with two panels, time per frame (log scale) against face
/// error and against shade error, one colour per method.
void WriteSpeedErrorPlot(const std::vector<PlotPoint>& points, const std::string& machine,
                         const std::string& path);

/// One glyph mode on one scene.
struct FidelityPoint {
  std::string scene;
  std::string mode;
  double medianMs = 0.0;
  double ssim = 0.0;  ///< blurred SSIM against the exact image (SPEC 12)
};

/// Writes an SVG of time per frame (log scale) against blurred SSIM, one colour per mode.
void WriteSpeedFidelityPlot(const std::vector<FidelityPoint>& points, const std::string& machine,
                            const std::string& path);

}  // namespace termshade
