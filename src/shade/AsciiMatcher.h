#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "shade/GlyphMode.h"

namespace termshade {

/// Shape-matched ASCII (SPEC 11; Harri's "shape vectors"): each printable
/// ASCII glyph becomes a vector of its measured ink (DefaultInkTable) over
/// the regions a cell's samples sit in; a cell takes the glyph nearest its
/// samples (brightness scaled to the most mean ink any glyph has). Integer
/// arithmetic; ties go to the lower code point. Results are
/// memoized per quantized sample vector (a level 0..15 a sample), so a frame costs
/// one table probe per cell for the values seen before; the cache does not
/// change any result.
class AsciiMatcher {
 public:
  /// Builds the glyph vectors for a sample grid (no work if it is the current one).
  void Prepare(SampleGrid grid);

  /// For a screen without colour: the glyph whose ink best shows the samples'
  /// brightness (values 0..255, background 0; sample n is bit n of `covered`).
  char32_t MatchInk(const uint8_t* values, uint32_t covered);
  /// With colour: the glyph whose shape matches the samples scaled to their
  /// brightest one (the fg colour carries the brightness).
  char32_t MatchShape(const uint8_t* values, uint32_t covered);

  /// MatchShape's sample levels: round(15 value / brightest) (at least 1) for
  /// covered samples, 0 for the others, the brightest covered value at least 1.
  static std::array<uint8_t, 32> ShapeLevels(const uint8_t* values, uint32_t covered, int count);
  /// The glyph nearest these sample levels (0..15 each), searched without
  /// the cache: what MatchInk and MatchShape return for the levels they make.
  char32_t Nearest(const std::array<uint8_t, 32>& levels) const;

 private:
  static constexpr int kLevels = 16;  // quantization of a sample for the cache key
  struct Entry {
    uint64_t key = 0;
    char32_t glyph = 0;  // 0: empty
  };
  char32_t Match(const std::array<uint8_t, 32>& levels);
  /// Nearest for 8 samples, four glyphs at a time (SSE2 where built for it): the same glyph.
  char32_t Nearest8(const std::array<uint8_t, 32>& levels) const;
  /// The target ink per region of Nearest's search.
  std::array<int, 32> TargetInk(const std::array<uint8_t, 32>& levels) const;
  /// Match for a cache key (the levels as bytes, the second eight in the high nibbles).
  char32_t MatchKey(uint64_t key, const std::array<uint8_t, 32>* levels);
  /// Up to 8 samples: the levels as bytes of a key, level = row[value], 0 where not covered.
  uint64_t ByteKey(const uint8_t* row, const uint8_t* values, uint32_t covered) const;

  SampleGrid grid_{0, 0};
  int count_ = 0;
  std::vector<char32_t> glyphs_;
  std::vector<int> vectors_;  ///< glyph-major: count_ region inks, 0..255
  /// 8 samples: the inks in blocks of four glyphs, per pair of regions k the
  /// 16-bit lanes (glyph 0 region 2k, glyph 0 region 2k + 1, glyph 1 ...);
  /// missing glyphs of the last block far from any target.
  std::vector<int16_t> pairedInks_;
  int inkScale_ = 0;  ///< the most mean ink a glyph has, 0..255
  std::array<std::array<int, kLevels>, kLevels> enhanced_{};  ///< [level][cell's max level]
  std::vector<Entry> cache_;
  std::array<uint8_t, 256> inkLevels_{};  ///< MatchInk's level by value
  std::vector<uint8_t> shapeLevels_;      ///< ShapeLevels' level by [brightest][value]
};

}  // namespace termshade
