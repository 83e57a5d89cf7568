#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>

#include "geometry/Rgb.h"
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
/// the xterm 256-colour palette (cube or grey ramp, never redefined), or 24-bit.
struct TermColour {
  enum class Kind : uint8_t { kDefault, kIndexed, kRgb };
  Kind kind = Kind::kDefault;
  uint8_t index = 0;  ///< for kIndexed
  Srgb8 rgb;          ///< for kRgb
  bool operator==(const TermColour&) const = default;
};

/// The colour of faces whose file gives none (SPEC 10): a neutral light grey.
constexpr Rgb kDefaultFaceColour{0.8F, 0.8F, 0.8F};

/// Relative luminance bounds of every shaded cell colour: the darkest stays
/// visible on a black background and the brightest on a white one. WCAG
/// contrast (L1 + 0.05) / (L2 + 0.05): 2.6 against black, 2.6 against white
/// (a little less after rounding to 8 bits, never below 2.5).
constexpr double kMinCellLuminance = 0.08;
constexpr double kMaxCellLuminance = 0.36;
/// Intensity 0 keeps this share of the face's (capped) brightness.
constexpr double kDarkestShare = 0.2;

/// Intensity in [0, 1] of shade level `level` of `levelCount` (dark to bright).
double IntensityForLevel(int level, int levelCount);

/// Face colour x intensity, in linear light, kept within the luminance
/// bounds (a too bright colour is scaled down, keeping its hue; a too dark
/// shade is lifted with grey), encoded as sRGB. The truecolor cell colour.
Srgb8 ShadedFaceColour(Rgb faceLinear, double intensity);

/// The nearest entry of the 6x6x6 cube or the grey ramp (16..255) whose
/// luminance lies within the bounds above.
int Nearest256Colour(Srgb8 colour);
/// The sRGB value of a palette entry 16..255 as xterm defines it.
Srgb8 Palette256Colour(int index);

/// The one mapping from (face colour, intensity) to a terminal colour, used
/// by the viewer and the ansi dump, for a glyph's foreground or a background.
TermColour CellColour(Rgb faceLinear, double intensity, ColourMode mode);

/// WCAG 2 relative luminance of an sRGB colour, in [0, 1].
double RelativeLuminance(Srgb8 colour);
/// WCAG 2 contrast ratio of two colours, in [1, 21].
double ContrastRatio(Srgb8 a, Srgb8 b);

/// CellColour for the cells of a frame: the face colour of a 1-based face
/// number (kDefaultFaceColour when the mesh has none) at a shade level.
/// Remembers what it computed, so a frame costs a lookup per cell.
class CellColourMap {
 public:
  CellColourMap(std::span<const Rgb> faceColours, int levelCount, ColourMode mode)
      : faceColours_(faceColours), levelCount_(levelCount), mode_(mode) {}
  TermColour ForFace(uint32_t faceNumber, int level);

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
  std::unordered_map<Key, TermColour, KeyHash> cache_;
};

}  // namespace termshade
