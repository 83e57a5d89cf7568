#include "shade/ShadeRamp.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shade/Utf8.h"

namespace termshade {

ShadeRamp::ShadeRamp(const std::string& glyphsUtf8) {
  const std::string& usable = Problem(glyphsUtf8) ? std::string(kDefaultGlyphs) : glyphsUtf8;
  for (char32_t glyph : DecodeUtf8(usable).value_or(std::vector<char32_t>{})) {
    glyphs_[static_cast<size_t>(levelCount_++)] = glyph;
  }
}

std::optional<std::string> ShadeRamp::Problem(const std::string& glyphsUtf8) {
  const std::optional<std::vector<char32_t>> glyphs = DecodeUtf8(glyphsUtf8);
  if (!glyphs) return "the ramp is not valid UTF-8";
  if (glyphs->empty()) return "the ramp needs at least one character";
  if (glyphs->size() > kMaxGlyphs) return "the ramp has more than 64 characters";
  for (char32_t c : *glyphs) {
    if (c == U' ') return "the ramp may not contain a blank (the background is blank)";
    if (!IsRampGlyph(c)) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "U+%04X cannot be a ramp character (use printable ASCII, Latin-1, box "
                    "drawing, block elements, geometric shapes or braille: one cell wide)",
                    static_cast<unsigned>(c));
      return text;
    }
  }
  return std::nullopt;
}

int ShadeRamp::LevelFor(double intensity) const {
  const double clamped = std::isnan(intensity) ? 0.0 : std::clamp(intensity, 0.0, 1.0);
  const int level = static_cast<int>(std::floor(clamped * LevelCount()));
  return std::min(level, LevelCount() - 1);
}

bool ShadeRamp::IsAscii() const {
  return std::all_of(glyphs_.begin(), glyphs_.begin() + levelCount_,
                     [](char32_t c) { return c < 0x80; });
}

}  // namespace termshade
