#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>

#include "geometry/Rgb.h"
#include "shade/Background.h"
#include "shade/ColourMode.h"

namespace termshade {

/// A colour in the terminal's encoding: 8-bit sRGB components.
struct Srgb8 {
  uint8_t r = 0;
  uint8_t g = 0;
  uint8_t b = 0;
  bool operator==(const Srgb8&) const = default;
};

/// A cell's colour as sent to a terminal: the terminal's default, an entry of
/// the xterm 256-colour palette (cube or grey ramp, never redefined; 0..15:
/// the 16 ANSI colours, sent as SGR 30-37 and 90-97), or 24-bit.
struct TermColour {
  enum class Kind : uint8_t { kDefault, kIndexed, kRgb };
  Kind kind = Kind::kDefault;
  uint8_t index = 0;  ///< for kIndexed
  Srgb8 rgb;          ///< for kRgb
  bool operator==(const TermColour&) const = default;
};

/// An sRGB albedo (a texture's colour at a cell) packed as a cell keeps it:
/// 0x01RRGGBB, never 0 (0 stands for "the face's colour").
inline uint32_t PackAlbedo(Srgb8 colour) {
  return 0x01000000U | (uint32_t{colour.r} << 16) | (uint32_t{colour.g} << 8) | colour.b;
}
/// sRGB steps a channel below which a change of a cell's albedo goes unseen.
inline constexpr int kAlbedoStepSeen = 12;
/// Whether two packed albedos (0 included) look alike: both 0, or both set
/// and no sRGB channel apart by more than `step`.
inline bool AlbedosAlike(uint32_t a, uint32_t b, int step) {
  if (a == 0 || b == 0) return a == b;
  for (const int shift : {16, 8, 0}) {
    const int apart =
        static_cast<int>((a >> shift) & 0xFFU) - static_cast<int>((b >> shift) & 0xFFU);
    if (apart > step || -apart > step) return false;
  }
  return true;
}
/// Linear light to 8-bit sRGB, each component clamped to [0, 1].
Srgb8 EncodeSrgb8(Rgb linear);
/// The linear colour of a packed albedo.
Rgb UnpackAlbedo(uint32_t packed);

/// The colour of faces whose file gives none (SPEC 10): a neutral light grey.
constexpr Rgb kDefaultFaceColour{0.8F, 0.8F, 0.8F};

/// The least WCAG 2 contrast, (L1 + 0.05) / (L2 + 0.05), every shaded cell
/// colour keeps against the terminal's background, so silhouettes stay
/// visible; there is no bound against the other end.
constexpr double kMinBackgroundContrast = 1.5;
/// On a dark (black) background: the darkest shade's least relative luminance.
constexpr double kDarkFloorLuminance = kMinBackgroundContrast * 0.05 - 0.05;  // 0.025
/// On a light (white) background: the brightest shade's most relative luminance.
constexpr double kLightCeilingLuminance = 1.05 / kMinBackgroundContrast - 0.05;  // 0.65
/// Intensity 0 keeps this share of the face's brightness: close to black.
constexpr double kDarkestShare = 0.08;

/// Intensity in [0, 1] of shade level `level` of `levelCount` (dark to bright).
double IntensityForLevel(int level, int levelCount);

/// Face colour x intensity, from kDarkestShare of the face's colour at 0 to
/// all of it at 1, in linear light, encoded as sRGB once: the truecolor
/// cell colour. On a dark background a shade darker than kDarkFloorLuminance
/// is lifted with grey; on a light one a face brighter than
/// kLightCeilingLuminance is scaled down first, keeping its hue.
Srgb8 ShadedFaceColour(Rgb faceLinear, double intensity, Background background = Background::kDark);

/// The nearest entry of the 6x6x6 cube or the grey ramp (16..255) that keeps
/// kMinBackgroundContrast against the background.
int Nearest256Colour(Srgb8 colour, Background background = Background::kDark);
/// The sRGB value of a palette entry 16..255 as xterm defines it.
Srgb8 Palette256Colour(int index);

/// The one mapping from (face colour, intensity) to a terminal colour, used
/// by the viewer and the ansi dump, for a glyph's foreground or a background.
TermColour CellColour(Rgb faceLinear, double intensity, ColourMode mode,
                      Background background = Background::kDark);

/// WCAG 2 relative luminance of an sRGB colour, in [0, 1].
double RelativeLuminance(Srgb8 colour);
/// WCAG 2 contrast ratio of two colours, in [1, 21].
double ContrastRatio(Srgb8 a, Srgb8 b);

/// CellColour for the cells of a frame: the face colour of a 1-based face
/// number (kDefaultFaceColour when the mesh has none) at a shade level.
/// Remembers what it computed, so a frame costs a lookup per cell.
class CellColourMap {
 public:
  CellColourMap(std::span<const Rgb> faceColours, int levelCount, ColourMode mode,
                Background background = Background::kDark)
      : faceColours_(faceColours), levelCount_(levelCount), mode_(mode), background_(background) {}
  /// With a nonzero albedo (PackAlbedo) the cell's texture colour replaces the face's.
  TermColour ForFace(uint32_t faceNumber, int level, uint32_t albedo = 0);

 private:
  // A face colour's exact bits and a level.
  struct Key {
    uint32_t r, g, b;
    int level;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& key) const;
  };
  std::span<const Rgb> faceColours_;
  int levelCount_;
  ColourMode mode_;
  Background background_;
  static constexpr size_t kMaxCachedColours = size_t{1} << 16;
  std::unordered_map<Key, TermColour, KeyHash> cache_;
};

}  // namespace termshade
