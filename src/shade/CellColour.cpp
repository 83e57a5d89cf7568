#include "shade/CellColour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "geometry/SrgbCoding.h"
#include "shade/Palette16.h"

namespace termshade {
namespace {

struct Linear {
  double r, g, b;
};

double LuminanceOf(const Linear& c) {
  return LinearLuminance(c.r, c.g, c.b);
}

// Squared distance of two sRGB colours, weighted by how the eye tells them
// apart ("redmean", Riemersma's low-cost approximation).
double Distance(Srgb8 a, Srgb8 b) {
  const double meanRed = (a.r + b.r) / 2.0;
  const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return (2.0 + meanRed / 256.0) * dr * dr + 4.0 * dg * dg +
         (2.0 + (255.0 - meanRed) / 256.0) * db * db;
}

// Palette entries 16..255 that keep the least contrast against a background.
struct PaletteEntry {
  int index;
  Srgb8 colour;
};
std::vector<PaletteEntry> PaletteAgainst(Background background) {
  std::vector<PaletteEntry> out;
  for (int index = 16; index < 256; ++index) {
    const Srgb8 colour = Palette256Colour(index);
    const double luminance = RelativeLuminance(colour);
    if (background == Background::kDark ? luminance >= kDarkFloorLuminance
                                        : luminance <= kLightCeilingLuminance) {
      out.push_back({index, colour});
    }
  }
  return out;
}
const std::vector<PaletteEntry>& VisiblePalette(Background background) {
  static const std::vector<PaletteEntry> dark = PaletteAgainst(Background::kDark);
  static const std::vector<PaletteEntry> light = PaletteAgainst(Background::kLight);
  return background == Background::kDark ? dark : light;
}

}  // namespace

double IntensityForLevel(int level, int levelCount) {
  if (levelCount <= 1) return 1.0;
  return std::clamp(static_cast<double>(level) / (levelCount - 1), 0.0, 1.0);
}

Srgb8 ShadedFaceColour(Rgb faceLinear, double intensity, Background background) {
  // Step 1: the face colour; on a light background no brighter than its ceiling.
  Linear c{std::clamp<double>(faceLinear.r, 0.0, 1.0), std::clamp<double>(faceLinear.g, 0.0, 1.0),
           std::clamp<double>(faceLinear.b, 0.0, 1.0)};
  const double faceLuminance = LuminanceOf(c);
  if (background == Background::kLight && faceLuminance > kLightCeilingLuminance) {
    const double scale = kLightCeilingLuminance / faceLuminance;
    c = {c.r * scale, c.g * scale, c.b * scale};
  }
  // Step 2: x intensity, from kDarkestShare at 0 to the whole colour at 1.
  const double share = kDarkestShare + (1.0 - kDarkestShare) * std::clamp(intensity, 0.0, 1.0);
  c = {c.r * share, c.g * share, c.b * share};
  // Step 3: on a dark background, a shade below the floor is lifted with grey
  // (the luminance weights sum to 1, so adding g to each component adds g).
  const double luminance = LuminanceOf(c);
  if (background == Background::kDark && luminance < kDarkFloorLuminance) {
    const double lift = kDarkFloorLuminance - luminance;
    c = {c.r + lift, c.g + lift, c.b + lift};
  }
  return {Srgb8OfLinear(c.r), Srgb8OfLinear(c.g), Srgb8OfLinear(c.b)};
}

Srgb8 EncodeSrgb8(Rgb linear) {
  return {Srgb8OfLinear(linear.r), Srgb8OfLinear(linear.g), Srgb8OfLinear(linear.b)};
}

Rgb UnpackAlbedo(uint32_t packed) {
  return Rgb{LinearOfSrgb8(static_cast<uint8_t>(packed >> 16)),
             LinearOfSrgb8(static_cast<uint8_t>(packed >> 8)),
             LinearOfSrgb8(static_cast<uint8_t>(packed))};
}

Srgb8 Palette256Colour(int index) {
  if (index >= 232) {
    const auto grey = static_cast<uint8_t>(8 + 10 * (std::clamp(index, 232, 255) - 232));
    return {grey, grey, grey};
  }
  static constexpr std::array<uint8_t, 6> kLevels{0, 95, 135, 175, 215, 255};
  const int cube = std::clamp(index, 16, 231) - 16;
  return {kLevels[static_cast<size_t>(cube / 36)], kLevels[static_cast<size_t>(cube / 6 % 6)],
          kLevels[static_cast<size_t>(cube % 6)]};
}

int Nearest256Colour(Srgb8 colour, Background background) {
  const std::vector<PaletteEntry>& palette = VisiblePalette(background);
  int best = palette.front().index;
  double bestDistance = Distance(colour, palette.front().colour);
  for (const PaletteEntry& entry : palette) {
    const double distance = Distance(colour, entry.colour);
    if (distance < bestDistance) {  // ties keep the lower index
      best = entry.index;
      bestDistance = distance;
    }
  }
  return best;
}

TermColour CellColour(Rgb faceLinear, double intensity, ColourMode mode, Background background) {
  TermColour out;
  if (mode == ColourMode::kNone || mode == ColourMode::kAuto) return out;
  const Srgb8 shaded = ShadedFaceColour(faceLinear, intensity, background);
  if (mode == ColourMode::kTrueColour) {
    out.kind = TermColour::Kind::kRgb;
    out.rgb = shaded;
  } else if (mode == ColourMode::k16) {
    out.kind = TermColour::Kind::kIndexed;
    const Srgb8 face = ShadedFaceColour(faceLinear, 1.0, background);
    out.index = static_cast<uint8_t>(Nearest16Colour(shaded, face, background));
  } else {
    out.kind = TermColour::Kind::kIndexed;
    out.index = static_cast<uint8_t>(Nearest256Colour(shaded, background));
  }
  return out;
}

double RelativeLuminance(Srgb8 colour) {
  return LuminanceOf(
      {LinearOfSrgb8Exact(colour.r), LinearOfSrgb8Exact(colour.g), LinearOfSrgb8Exact(colour.b)});
}

double ContrastRatio(Srgb8 a, Srgb8 b) {
  const double la = RelativeLuminance(a), lb = RelativeLuminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

TermColour CellColourMap::ForFace(uint32_t faceNumber, int level, uint32_t albedo) {
  const bool known = faceNumber >= 1 && faceNumber <= faceColours_.size();
  const Rgb face = albedo != 0 ? UnpackAlbedo(albedo)
                               : (known ? faceColours_[faceNumber - 1] : kDefaultFaceColour);
  Key key{};
  std::memcpy(&key.r, &face.r, sizeof(float));
  std::memcpy(&key.g, &face.g, sizeof(float));
  std::memcpy(&key.b, &face.b, sizeof(float));
  key.level = level;
  if (cache_.size() >= kMaxCachedColours) cache_.clear();  // textures: many colours a frame
  const auto [at, inserted] = cache_.try_emplace(key);
  if (inserted)
    at->second = CellColour(face, IntensityForLevel(level, levelCount_), mode_, background_);
  return at->second;
}

size_t CellColourMap::KeyHash::operator()(const Key& key) const {
  uint64_t h = static_cast<uint32_t>(key.level);
  for (uint32_t part : {key.r, key.g, key.b}) h = (h ^ part) * 0x100000001B3ULL;
  return static_cast<size_t>(h);
}

}  // namespace termshade
