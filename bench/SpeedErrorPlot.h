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

}  // namespace termshade
