#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "geometry/Vec3.h"
#include "shade/Lighting.h"
#include "shade/ShadeRamp.h"

namespace termshade {

/// Hidden-surface methods (SPEC 5) and the textbook's wire frame.
enum class Method { kZBuffer, kPainter, kCull, kWire };

std::string_view MethodName(Method method);
std::optional<Method> ParseMethod(std::string_view name);
std::string_view ShadeModeName(ShadeMode mode);
std::optional<ShadeMode> ParseShadeMode(std::string_view name);

/// Everything about how a frame is drawn that is not the camera.
struct RenderOptions {
  Method method = Method::kZBuffer;
  ShadeMode shade = ShadeMode::kContrast;
  ShadeRamp ramp;
  bool cullBackFaces = true;
  Vec3 sunEye = DefaultSunEye();
  double ambient = kDefaultAmbient;
};

}  // namespace termshade
