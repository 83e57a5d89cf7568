#pragma once

#include <array>
#include <optional>
#include <string>

namespace termshade {

/// Characters ordered from dark to bright onto which intensity in [0, 1] maps.
/// Given as UTF-8; see IsRampGlyph for the characters allowed.
class ShadeRamp {
 public:
  static constexpr const char* kDefaultGlyphs = ".:-=+*#%@";
  static constexpr int kMaxGlyphs = 64;

  ShadeRamp() : ShadeRamp(kDefaultGlyphs) {}
  /// Call Problem() first: a ramp with a problem falls back to the default.
  explicit ShadeRamp(const std::string& glyphsUtf8);

  /// Why a ramp cannot be used (empty, a blank, not UTF-8, a character
  /// outside IsRampGlyph), if it cannot.
  static std::optional<std::string> Problem(const std::string& glyphsUtf8);

  int LevelCount() const { return levelCount_; }
  /// Level in [0, LevelCount()): never darker for a larger intensity.
  int LevelFor(double intensity) const;
  char32_t Glyph(int level) const { return glyphs_[static_cast<size_t>(level)]; }
  /// True when every glyph is ASCII (shown the same in any locale).
  bool IsAscii() const;

 private:
  // In place, not on the heap: options holding a ramp copy without allocating.
  std::array<char32_t, kMaxGlyphs> glyphs_{};
  int levelCount_ = 0;
};

}  // namespace termshade
