#pragma once

#include <optional>
#include <string>

namespace termshade {

/// Characters ordered from dark to bright onto which intensity in [0, 1] maps.
class ShadeRamp {
 public:
  static constexpr const char* kDefaultGlyphs = ".:-=+*#%@";

  ShadeRamp() : glyphs_(kDefaultGlyphs) {}
  /// Call Problem() first: glyphs must be valid.
  explicit ShadeRamp(std::string glyphs) : glyphs_(std::move(glyphs)) {}

  /// Why a ramp cannot be used (empty, blank, not printable ASCII), if it cannot.
  static std::optional<std::string> Problem(const std::string& glyphs);

  int LevelCount() const { return static_cast<int>(glyphs_.size()); }
  /// Level in [0, LevelCount()): never darker for a larger intensity.
  int LevelFor(double intensity) const;
  char Glyph(int level) const { return glyphs_[static_cast<size_t>(level)]; }
  const std::string& Glyphs() const { return glyphs_; }

 private:
  std::string glyphs_;
};

}  // namespace termshade
