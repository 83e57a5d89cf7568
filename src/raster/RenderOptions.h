#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "geometry/Vec3.h"
#include "raster/TriangleRasterizer.h"
#include "shade/Lighting.h"
#include "shade/ShadeRamp.h"

namespace termshade {

/// Hidden-surface methods (SPEC 5), the textbook's wire frame, and auto: the
/// cheapest exact one for the scene (cull for one convex closed solid, else zbuffer).
enum class Method { kZBuffer, kPainter, kCull, kWire, kAuto };

std::string_view MethodName(Method method);
std::optional<Method> ParseMethod(std::string_view name);
std::string_view ShadeModeName(ShadeMode mode);
std::optional<ShadeMode> ParseShadeMode(std::string_view name);

/// Variants of the pipeline kept to measure the product against
/// (termshade bench); the defaults are the product.
struct RenderVariant {
  DepthFormat depthFormat = DepthFormat::kFloatInverseZ;
  bool scanline = false;       ///< the classic scanline rasterizer instead of edge functions
  bool floatGeometry = false;  ///< transform and project in float instead of double
  int samplesPerAxis = 1;      ///< k: k x k samples per cell, glyph from the mean intensity
};

/// Everything about how a frame is drawn that is not the camera.
struct RenderOptions {
  Method method = Method::kZBuffer;
  ShadeMode shade = ShadeMode::kContrast;
  ShadeRamp ramp;
  bool cullBackFaces = true;
  Vec3 sunEye = DefaultSunEye();
  double ambient = kDefaultAmbient;
  RenderVariant variant;
  /// False: the depth buffer need not hold the frame's depth afterwards (only
  /// the json dump reads it), so methods that need no depth test skip it.
  bool keepDepth = true;
};

}  // namespace termshade
