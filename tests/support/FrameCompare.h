#pragma once

#include <string>

#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/Renderer.h"

namespace termshade::test {

/// A view about the default one: theta and phi in radians, rho scaled
/// (below 1: the eye close to or inside the model).
struct OrbitView {
  double theta, phi, rhoScale;
};

/// A frame with its depth buffer and counts.
struct DrawnFrame {
  CellBuffer cells;
  DepthBuffer depth;
  RenderStats stats;
};

/// The frame of `scene` from `view` at width x height cells (cell aspect 2), fitted.
DrawnFrame DrawOrbit(Renderer& renderer, const Scene& scene, const OrbitView& view, int width,
                     int height, const RenderOptions& options);

/// Bit for bit: face numbers, glyphs and the depth buffer's floats, and the
/// counts (the triangle count only where neither frame was drawn by rays).
void ExpectSameFrame(const DrawnFrame& expected, const DrawnFrame& actual, const std::string& what);

}  // namespace termshade::test
