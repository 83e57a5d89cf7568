#include "raster/RenderOptions.h"

#include <algorithm>
#include <array>
#include <utility>

namespace termshade {
namespace {

constexpr std::array<std::pair<Method, std::string_view>, 5> kMethodNames{{
    {Method::kZBuffer, "zbuffer"},
    {Method::kPainter, "painter"},
    {Method::kCull, "cull"},
    {Method::kWire, "wire"},
    {Method::kAuto, "auto"},
}};

constexpr std::array<std::pair<ShadeMode, std::string_view>, 2> kShadeNames{{
    {ShadeMode::kContrast, "contrast"},
    {ShadeMode::kLambert, "lambert"},
}};

template <typename Enum, size_t N>
std::string_view NameOf(const std::array<std::pair<Enum, std::string_view>, N>& table, Enum value) {
  for (const auto& [candidate, name] : table) {
    if (candidate == value) return name;
  }
  return "?";
}

template <typename Enum, size_t N>
std::optional<Enum> ValueOf(const std::array<std::pair<Enum, std::string_view>, N>& table,
                            std::string_view name) {
  for (const auto& [candidate, candidateName] : table) {
    if (candidateName == name) return candidate;
  }
  return std::nullopt;
}

}  // namespace

std::string_view MethodName(Method method) {
  return NameOf(kMethodNames, method);
}
std::optional<Method> ParseMethod(std::string_view name) {
  return ValueOf(kMethodNames, name);
}
std::string_view ShadeModeName(ShadeMode mode) {
  return NameOf(kShadeNames, mode);
}
std::optional<ShadeMode> ParseShadeMode(std::string_view name) {
  return ValueOf(kShadeNames, name);
}

SampleGrid PatternSampleGrid(const RenderOptions& options) {
  const SampleGrid forced = options.variant.samples;
  if (forced.Count() <= 0) return ModeSampleGrid(options.glyphs);
  // At most 32 samples: a cell's coverage pattern is 32 bits.
  return {std::clamp(forced.across, 1, 4), std::clamp(forced.down, 1, 8)};
}

SampleGrid FrameSampleGrid(const RenderOptions& options) {
  const SampleGrid pattern = PatternSampleGrid(options);
  if (options.variant.samples.Count() > 0 || !options.twoColour) return pattern;
  const SampleGrid sub = ColourSubsamples(options.glyphs);
  return {pattern.across * sub.across, pattern.down * sub.down};
}

}  // namespace termshade
