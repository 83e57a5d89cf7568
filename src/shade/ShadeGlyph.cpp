#include "shade/ShadeGlyph.h"

namespace termshade {

char32_t ShadeGlyph(uint8_t intensity) {
  // Halfway between the glyphs' ink (64, 128, 191, 255 of 255): integer bounds.
  if (intensity < 96) return U'\u2591';
  if (intensity < 160) return U'\u2592';
  if (intensity < 224) return U'\u2593';
  return U'\u2588';
}

}  // namespace termshade
