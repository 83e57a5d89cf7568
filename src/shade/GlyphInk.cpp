#include "shade/GlyphInk.h"

#include <algorithm>
#include <numeric>

#include "shade/GlyphInkDejaVuSansMono.h"
#include "shade/GlyphInkUnifont.h"

namespace termshade {

const InkMap* GlyphInkTable::Find(char32_t codePoint) const {
  const auto it = std::lower_bound(
      glyphs.begin(), glyphs.end(), codePoint,
      [](const GlyphInk& glyph, char32_t wanted) { return glyph.codePoint < wanted; });
  return it != glyphs.end() && it->codePoint == codePoint ? &it->ink : nullptr;
}

double GlyphInkTable::MeanInk(char32_t codePoint) const {
  const InkMap* ink = Find(codePoint);
  if (ink == nullptr) return 0.0;
  return std::accumulate(ink->begin(), ink->end(), 0.0) / (255.0 * ink->size());
}

const GlyphInkTable& DefaultInkTable() {
  static const GlyphInkTable table{kGlyphInkDejaVuSansMonoFont, kGlyphInkDejaVuSansMono};
  return table;
}

const GlyphInkTable& UnifontInkTable() {
  static const GlyphInkTable table{kGlyphInkUnifontFont, kGlyphInkUnifont};
  return table;
}

}  // namespace termshade
