#pragma once

#include <cstdint>

#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/FramePlan.h"

namespace termshade {

/// The textbook's wire frame: every edge of the scene taken to eye space,
/// clipped by the view's planes and drawn as a line of glyphs at `level`
/// (LineRasterizer), marked with its face (0 for an edge of none). Returns
/// the edges drawn.
int DrawWireFrame(const Scene& scene, const FrameView& view, int16_t level, DepthBuffer& depth,
                  CellBuffer& cells);

}  // namespace termshade
