#pragma once

#include <cstdint>

#include "geometry/Rgb.h"
#include "geometry/Scene.h"
#include "raster/FramePlan.h"

namespace termshade {

/// A step across the view's frame, in its own units (cells or samples).
struct FrameStep {
  double across = 1.0;
  double down = 1.0;
};

/// The albedo (linear light) a textured face (0-based) shows at point (x, y)
/// of the view's frame: the ray from the eye through it meets the face's
/// plane, the point's texture coordinates come from FaceUvAt (perspective-
/// correct by construction), the texel is looked up bilinearly on texture
/// level `level` and times the face's colour (glTF's base colour factor).
/// A negative `level` is first found from the footprint, in full-size texels,
/// of one `step` right and down, and set (so the caller may keep it).
Rgb TexturedAlbedoAt(const Scene& scene, const FrameView& view, uint32_t face, double x, double y,
                     FrameStep step, int& level);

}  // namespace termshade
