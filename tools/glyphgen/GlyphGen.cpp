// glyphgen: measures glyph ink maps from a font with FreeType and writes the
// C++ header termshade chooses and scores glyphs with (SPEC 11, 12).
//
//   glyphgen OUTPUT.h NAME FONT [FALLBACK_FONT...]
//
// Each glyph is loaded unhinted from the first font that has it, scaled so
// the font's cell (advance width x line height, from hhea) fills 256 x 512
// pixels, rendered anti-aliased by FreeType, and reduced to 8 x 16 mean
// coverage values. Block elements, sextants and braille no font has are drawn
// from their Unicode definitions (exact fractions of the cell), as terminals
// draw them. The output depends only on the font files: run twice, same bytes.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_TABLES_H

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kWidthPx = 256, kHeightPx = 512;  // the cell, rendered
constexpr int kColumns = 8, kRows = 16;         // the ink map

using Bitmap = std::vector<unsigned char>;  // kWidthPx x kHeightPx, row 0 at the top

// The characters measured: printable ASCII, block elements, sextants, braille.
std::vector<char32_t> Repertoire() {
  std::vector<char32_t> codes;
  for (char32_t c = 0x20; c <= 0x7E; ++c) codes.push_back(c);
  for (char32_t c = 0x2580; c <= 0x259F; ++c) codes.push_back(c);
  for (char32_t c = 0x2800; c <= 0x28FF; ++c) codes.push_back(c);
  for (char32_t c = 0x1FB00; c <= 0x1FB3B; ++c) codes.push_back(c);
  return codes;
}

void FillRect(Bitmap& bitmap, double left, double top, double right, double bottom) {
  // Fractions of the cell; pixel centers inside are inked (boundaries fall on pixels).
  for (int y = 0; y < kHeightPx; ++y) {
    const double fy = (y + 0.5) / kHeightPx;
    if (fy < top || fy >= bottom) continue;
    for (int x = 0; x < kWidthPx; ++x) {
      const double fx = (x + 0.5) / kWidthPx;
      if (fx >= left && fx < right) bitmap[static_cast<size_t>(y) * kWidthPx + x] = 255;
    }
  }
}

void FillDot(Bitmap& bitmap, double cx, double cy, double radius) {
  for (int y = 0; y < kHeightPx; ++y) {
    for (int x = 0; x < kWidthPx; ++x) {
      const double dx = (x + 0.5) - cx * kWidthPx, dy = (y + 0.5) - cy * kHeightPx;
      if (dx * dx + dy * dy < radius * radius) bitmap[static_cast<size_t>(y) * kWidthPx + x] = 255;
    }
  }
}

// Unicode's own definitions of the block, sextant and braille characters.
bool DrawDefinition(char32_t c, Bitmap& bitmap) {
  if (c >= 0x1FB00 && c <= 0x1FB3B) {
    unsigned pattern = c - 0x1FB00 + 1;
    if (pattern >= 21) ++pattern;  // the block skips the half-cell columns 21 and 42
    if (pattern >= 42) ++pattern;
    for (int n = 0; n < 6; ++n) {
      if ((pattern >> n) & 1U) {
        FillRect(bitmap, (n % 2) / 2.0, (n / 2) / 3.0, (n % 2 + 1) / 2.0, (n / 2 + 1) / 3.0);
      }
    }
    return true;
  }
  if (c >= 0x2800 && c <= 0x28FF) {
    static constexpr int kDotColumn[8] = {0, 0, 0, 1, 1, 1, 0, 1};
    static constexpr int kDotRow[8] = {0, 1, 2, 0, 1, 2, 3, 3};
    for (int n = 0; n < 8; ++n) {
      if (((c - 0x2800) >> n) & 1U) {
        FillDot(bitmap, (kDotColumn[n] + 0.5) / 2.0, (kDotRow[n] + 0.5) / 4.0, 0.15 * kWidthPx);
      }
    }
    return true;
  }
  const double e = 1.0 / 8.0;
  switch (c) {
    case 0x2580:
      FillRect(bitmap, 0, 0, 1, 0.5);
      return true;
    case 0x2584:
      FillRect(bitmap, 0, 0.5, 1, 1);
      return true;
    case 0x2588:
      FillRect(bitmap, 0, 0, 1, 1);
      return true;
    case 0x258C:
      FillRect(bitmap, 0, 0, 0.5, 1);
      return true;
    case 0x2590:
      FillRect(bitmap, 0.5, 0, 1, 1);
      return true;
    default:
      break;
  }
  if (c >= 0x2581 && c <= 0x2587) {  // lower eighths
    FillRect(bitmap, 0, 1 - (c - 0x2580) * e, 1, 1);
    return true;
  }
  if (c >= 0x2589 && c <= 0x258F) {  // left eighths
    FillRect(bitmap, 0, 0, 1 - (c - 0x2588) * e, 1);
    return true;
  }
  if (c >= 0x2596 && c <= 0x259F) {  // quadrants: TL TR BL BR bits
    static constexpr unsigned kBits[10] = {4, 8, 1, 13, 9, 7, 11, 2, 6, 14};
    const unsigned bits = kBits[c - 0x2596];
    if (bits & 1U) FillRect(bitmap, 0, 0, 0.5, 0.5);
    if (bits & 2U) FillRect(bitmap, 0.5, 0, 1, 0.5);
    if (bits & 4U) FillRect(bitmap, 0, 0.5, 0.5, 1);
    if (bits & 8U) FillRect(bitmap, 0.5, 0.5, 1, 1);
    return true;
  }
  return false;  // shades U+2591..2593, upper and right eighths: from the font only
}

struct Font {
  FT_Face face = nullptr;
  std::string name;
};

// Renders c from the font into the 256 x 512 cell; false when the font lacks it.
bool DrawFromFont(FT_Library library, const Font& font, char32_t c, Bitmap& bitmap) {
  const FT_UInt index = FT_Get_Char_Index(font.face, c);
  if (index == 0 && c != U' ') return false;
  if (FT_Load_Glyph(font.face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
    return false;
  if (font.face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) return false;
  // The cell: advance width of the font's '0' by hhea ascender - descender.
  const TT_HoriHeader* hhea =
      static_cast<const TT_HoriHeader*>(FT_Get_Sfnt_Table(font.face, FT_SFNT_HHEA));
  const double ascender = hhea ? hhea->Ascender : font.face->ascender;
  const double descender = hhea ? hhea->Descender : font.face->descender;
  FT_Load_Glyph(font.face, FT_Get_Char_Index(font.face, U'0'), FT_LOAD_NO_SCALE);
  const double advance = static_cast<double>(font.face->glyph->advance.x);
  FT_Load_Glyph(font.face, index, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP);
  FT_Outline& outline = font.face->glyph->outline;
  // Font units -> 26.6 pixels: x by 256 / advance, y by 512 / line height, baseline lifted.
  FT_Matrix scale{
      static_cast<FT_Fixed>(std::lround(65536.0 * 64.0 * kWidthPx / advance)), 0, 0,
      static_cast<FT_Fixed>(std::lround(65536.0 * 64.0 * kHeightPx / (ascender - descender)))};
  FT_Outline_Transform(&outline, &scale);
  FT_Outline_Translate(
      &outline, 0,
      static_cast<FT_Pos>(std::lround(-descender * 64.0 * kHeightPx / (ascender - descender))));
  FT_Bitmap target{};
  target.rows = kHeightPx;
  target.width = kWidthPx;
  target.pitch = kWidthPx;
  target.pixel_mode = FT_PIXEL_MODE_GRAY;
  target.num_grays = 256;
  target.buffer = bitmap.data();
  return FT_Outline_Get_Bitmap(library, &outline, &target) == 0;
}

std::array<int, kColumns * kRows> Reduce(const Bitmap& bitmap) {
  constexpr int kBinW = kWidthPx / kColumns, kBinH = kHeightPx / kRows;
  std::array<int, kColumns * kRows> ink{};
  for (int row = 0; row < kRows; ++row) {
    for (int col = 0; col < kColumns; ++col) {
      long sum = 0;
      for (int y = row * kBinH; y < (row + 1) * kBinH; ++y) {
        for (int x = col * kBinW; x < (col + 1) * kBinW; ++x) {
          sum += bitmap[static_cast<size_t>(y) * kWidthPx + x];
        }
      }
      ink[static_cast<size_t>(row * kColumns + col)] =
          static_cast<int>((sum + kBinW * kBinH / 2) / (kBinW * kBinH));
    }
  }
  return ink;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: glyphgen OUTPUT.h NAME FONT [FALLBACK_FONT...]\n";
    return 2;
  }
  const std::string outputPath = argv[1], name = argv[2];
  FT_Library library;
  if (FT_Init_FreeType(&library)) return 3;
  std::vector<Font> fonts;
  for (int i = 3; i < argc; ++i) {
    Font font;
    if (FT_New_Face(library, argv[i], 0, &font.face)) {
      std::cerr << "glyphgen: cannot open font " << argv[i] << "\n";
      return 1;
    }
    font.name = std::string(font.face->family_name ? font.face->family_name : "?") + " " +
                (font.face->style_name ? font.face->style_name : "");
    fonts.push_back(font);
  }
  std::ostringstream body;
  int fromFont = 0, fromDefinition = 0;
  for (char32_t c : Repertoire()) {
    Bitmap bitmap(static_cast<size_t>(kWidthPx) * kHeightPx, 0);
    std::string source;
    for (const Font& font : fonts) {
      if (DrawFromFont(library, font, c, bitmap)) {
        source = font.name;
        break;
      }
      std::fill(bitmap.begin(), bitmap.end(), 0);
    }
    if (source.empty()) {
      if (!DrawDefinition(c, bitmap)) continue;  // not in any font, no definition: left out
      source = "Unicode definition";
      ++fromDefinition;
    } else {
      ++fromFont;
    }
    char head[64];
    std::snprintf(head, sizeof head, "    {0x%05X, {", static_cast<unsigned>(c));
    body << head;
    const auto ink = Reduce(bitmap);
    for (size_t i = 0; i < ink.size(); ++i) body << (i ? "," : "") << ink[i];
    body << "}},  // " << source << "\n";
  }
  std::ofstream out(outputPath, std::ios::binary | std::ios::trunc);
  out << "// Generated by tools/glyphgen: do not edit. Regenerate with\n"
         "//   cmake -B build -DTERMSHADE_GLYPHGEN=ON && cmake --build build --target "
         "glyph_tables\n"
      << "// " << fromFont << " glyphs from " << fonts.front().name << " (and fallbacks), "
      << fromDefinition << " drawn from their Unicode definitions.\n"
      << "#pragma once\n\n#include \"shade/GlyphInk.h\"\n\nnamespace termshade {\n\n"
      << "inline constexpr const char* k" << name << "Font = \"" << fonts.front().name << "\";\n"
      << "inline constexpr GlyphInk k" << name << "[] = {\n"
      << body.str() << "};\n\n}  // namespace termshade\n";
  for (Font& font : fonts) FT_Done_Face(font.face);
  FT_Done_FreeType(library);
  return out ? 0 : 1;
}
