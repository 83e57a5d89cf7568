#include "raster/GlyphStage.h"

#include <algorithm>
#include <array>
#include <bit>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "shade/BlockGlyphs.h"
#include "shade/BlurredGlyphMatch.h"
#include "shade/ShadeGlyph.h"

namespace termshade {
namespace {

constexpr int kMaxSamples = 32;

// One cell's samples: face (0 = background) and intensity 0..255 (0 for background).
struct CellSamples {
  int count = 0;
  std::array<uint32_t, kMaxSamples> faces{};
  std::array<uint8_t, kMaxSamples> values{};
  SamplePattern covered = 0;
};

// A colour: the face it comes from (the one most of its samples show; lower
// number on a tie) and the mean intensity of its samples, background as 0.
struct Tone {
  uint32_t face = 0;
  uint8_t intensity = 0;
};

SamplePattern LowBits(int count) {
  return count >= 32 ? ~SamplePattern{0} : (SamplePattern{1} << count) - 1;
}

// Set bits of a byte.
constexpr std::array<uint8_t, 256> kByteBits = [] {
  std::array<uint8_t, 256> table{};
  for (int b = 1; b < 256; ++b) table[b] = static_cast<uint8_t>((b & 1) + table[b >> 1]);
  return table;
}();

// Set bits of a pattern, inline (std::popcount calls libgcc on baseline x86-64).
int BitCount(SamplePattern bits) {
  if (bits < 256) return kByteBits[bits];  // up to 8 samples: one load
  bits = bits - ((bits >> 1) & 0x55555555U);
  bits = (bits & 0x33333333U) + ((bits >> 2) & 0x33333333U);
  return static_cast<int>((((bits + (bits >> 4)) & 0x0F0F0F0FU) * 0x01010101U) >> 24);
}

// The samples (of the first `count`) showing `face`, as bits.
template <int N>  // N > 0: the count known to the compiler
SamplePattern SameFace(const CellSamples& s, int count, uint32_t face) {
#if defined(__SSE2__)
  if constexpr (N == 8) {  // two compares of four lanes
    const __m128i wanted = _mm_set1_epi32(static_cast<int>(face));
    const __m128i low = _mm_loadu_si128(reinterpret_cast<const __m128i*>(s.faces.data()));
    const __m128i high = _mm_loadu_si128(reinterpret_cast<const __m128i*>(s.faces.data() + 4));
    const int lowBits = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(low, wanted)));
    const int highBits = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(high, wanted)));
    return static_cast<SamplePattern>(lowBits | highBits << 4);
  }
#endif
  SamplePattern same = 0;
  for (int j = 0; j < (N > 0 ? N : count); ++j) {
    same |= static_cast<SamplePattern>(s.faces[j] == face) << j;
  }
  return same;
}

// The face most members show (lower number on a tie): one pass of
// branch-free comparisons per distinct face; with a small count known, one
// branch-free pass per sample (the largest of count << 32 | ~face).
template <int N>
uint32_t MajorityFace(const CellSamples& s, SamplePattern members) {
  const SamplePattern inked = members & s.covered;
  if constexpr (N > 0 && N <= 8) {
    uint64_t best = 0;
    for (int i = 0; i < N; ++i) {
      const uint32_t face = s.faces[i];
      const auto count = static_cast<uint64_t>(BitCount(SameFace<N>(s, N, face) & members));
      const uint64_t key = (count << 32) | (~face & 0xFFFFFFFFU);
      best = std::max(best, ((inked >> i) & 1U) != 0 ? key : 0);
    }
    return best == 0 ? 0 : ~static_cast<uint32_t>(best);
  }
  uint32_t bestFace = 0;
  int bestCount = 0;
  for (SamplePattern left = inked; left != 0;) {
    const uint32_t face = s.faces[std::countr_zero(left)];
    const SamplePattern same = SameFace<N>(s, s.count, face);
    left &= ~same;
    const int count = BitCount(same & members);
    if (count > bestCount || (count == bestCount && face < bestFace)) {
      bestFace = face;
      bestCount = count;
    }
    if (bestCount > BitCount(left)) break;  // no face left can reach it
  }
  return bestFace;
}

// ceil(2^16 / m): (x * kMeanReciprocal[m]) >> 16 is x / m for x < 2^12, m <= 8.
constexpr std::array<uint32_t, 9> kMeanReciprocal{0,     65536, 32768, 21846, 16384,
                                                  13108, 10923, 9363,  8192};

template <int N>
Tone ToneOf(const CellSamples& s, SamplePattern members) {
  members &= LowBits(N > 0 ? N : s.count);
  if constexpr (N > 0 && N <= 8) {  // branch-free: no members gives {0, 0}
    const int memberCount = BitCount(members);
    int sum = 0;
    for (int i = 0; i < N; ++i) sum += ((members >> i) & 1U) != 0 ? s.values[i] : 0;
    const auto scaled = static_cast<uint32_t>(sum + memberCount / 2);
    const auto mean = static_cast<uint8_t>((scaled * kMeanReciprocal[memberCount]) >> 16);
    return {MajorityFace<N>(s, members), mean};
  }
  if (members == 0) return {};
  const int memberCount = BitCount(members);
  int sum = 0;
  for (int i = 0; i < (N > 0 ? N : s.count); ++i) {
    sum += ((members >> i) & 1U) != 0 ? s.values[i] : 0;
  }
  const auto mean = static_cast<uint8_t>((sum + memberCount / 2) / memberCount);
  // Usually the inked members show one face: no counting.
  const SamplePattern inked = members & s.covered;
  if (inked == 0) return {0, mean};
  const uint32_t first = s.faces[std::countr_zero(inked)];
  if ((inked & ~SameFace<N>(s, s.count, first)) == 0) return {first, mean};
  return {MajorityFace<N>(s, members), mean};
}

// The best two-tone split of grey values (least squared error): a threshold
// on the sorted values; the brighter side is the ink. Ties go to the first
// threshold in sorted order. No threshold falls between equal values, so the
// ink is the samples at or above the threshold's value.
template <int N>
SamplePattern BrighterHalf(const CellSamples& s) {
  const int count = N > 0 ? N : s.count;
  std::array<uint8_t, kMaxSamples> sorted;  // NOLINT(cppcoreguidelines-pro-type-member-init)
  int total = 0;
  if constexpr (N > 0 && N <= 8) {  // odd-even transposition sort: branch-free
    for (int i = 0; i < N; ++i) {
      sorted[i] = s.values[i];
      total += s.values[i];
    }
    for (int pass = 0; pass < N; ++pass) {
      for (int i = pass & 1; i + 1 < N; i += 2) {
        const uint8_t low = std::min(sorted[i], sorted[i + 1]);
        sorted[i + 1] = std::max(sorted[i], sorted[i + 1]);
        sorted[i] = low;
      }
    }
  } else {
    for (int i = 0; i < count; ++i) {  // insertion sort: no allocation, n <= 32
      const uint8_t value = s.values[i];
      total += value;
      int j = i;
      for (; j > 0 && sorted[j - 1] > value; --j) sorted[j] = sorted[j - 1];
      sorted[j] = value;
    }
  }
  // Maximizing sumLow^2/nLow + sumHigh^2/nHigh minimizes the squared error
  // (every cut scored, one between equal values never taken: no branches).
  double bestScore = -1.0;
  int bestCut = 0, lowSum = 0;
  for (int cut = 1; cut < count; ++cut) {
    lowSum += sorted[cut - 1];
    const double highSum = total - lowSum;
    const double score = double(lowSum) * lowSum / cut + highSum * highSum / (count - cut);
    const bool better = sorted[cut - 1] != sorted[cut] && score > bestScore;
    bestScore = better ? score : bestScore;
    bestCut = better ? cut : bestCut;
  }
  if (bestCut == 0) return 0;
  SamplePattern ink = 0;
  for (int i = 0; i < count; ++i) {
    ink |= static_cast<SamplePattern>(s.values[i] >= sorted[bestCut]) << i;
  }
  return ink;
}

// The samples of each part of the pattern grid, one value a part: the
// parts' mean intensity (background 0) and the face most of its samples show.
// kSubAcross x kSubDown samples a part (0: at run time).
template <int N, int kSubAcross, int kSubDown>
void ReduceToParts(const CellSamples& s, SampleGrid grid, SampleGrid pattern, CellSamples& parts) {
  const int subAcross = kSubAcross > 0 ? kSubAcross : grid.across / pattern.across;
  const int subDown = kSubDown > 0 ? kSubDown : grid.down / pattern.down;
  const int subCount = subAcross * subDown;
  parts.count = pattern.Count();
  parts.covered = 0;
  for (int pj = 0; pj < pattern.down; ++pj) {
    for (int pi = 0; pi < pattern.across; ++pi) {
      const int first = (pj * subDown) * grid.across + pi * subAcross;
      SamplePattern members = 0;
      int sum = 0;
      for (int y = 0; y < subDown; ++y) {
        for (int x = 0; x < subAcross; ++x) {
          const int n = first + y * grid.across + x;
          members |= SamplePattern{1} << n;
          sum += s.values[n];
        }
      }
      const uint32_t firstFace = s.faces[first];
      uint32_t face = 0;
      if constexpr (kSubAcross * kSubDown == 2) {
        // Two samples: the one face, the covered one, or the lower on a tie.
        const uint32_t second = s.faces[first + (kSubAcross == 2 ? 1 : grid.across)];
        face = firstFace == 0 ? second : second == 0 ? firstFace : std::min(firstFace, second);
      } else {
        const bool oneFace = (members & ~SameFace<N>(s, s.count, firstFace)) == 0;
        face = oneFace || (s.covered & members) == 0 ? firstFace : MajorityFace<N>(s, members);
      }
      const int p = pj * pattern.across + pi;
      parts.faces[p] = face;
      parts.values[p] = static_cast<uint8_t>((sum + subCount / 2) / subCount);
      if (face != 0) parts.covered |= SamplePattern{1} << p;
    }
  }
}

// Every cell background: what the cells no sample of the frame reaches keep.
void FillBackground(CellBuffer& cells) {
  std::fill(cells.Glyphs().begin(), cells.Glyphs().end(), U' ');
  std::fill(cells.FaceNumbers().begin(), cells.FaceNumbers().end(), 0U);
  std::fill(cells.Levels().begin(), cells.Levels().end(), int16_t{-1});
  std::fill(cells.Intensities().begin(), cells.Intensities().end(), uint8_t{0});
  std::fill(cells.BackFaceNumbers().begin(), cells.BackFaceNumbers().end(), 0U);
  std::fill(cells.BackLevels().begin(), cells.BackLevels().end(), int16_t{-1});
  std::fill(cells.BackIntensities().begin(), cells.BackIntensities().end(), uint8_t{0});
}

// The glyph and tones of a cell whose samples (or parts) show more than one face.
// Where a cell is, for the ordered dither's screen-fixed thresholds, and the
// silhouette cells' matcher (with plan.shadeGlyphs).
struct CellPlace {
  const OrderedDither& dither;
  const BlurredGlyphMatch* silhouette = nullptr;
  int col = 0;
  int row = 0;
};

// The glyph of a pattern mode without colour: the ordered dither of the
// covered samples' (or parts') shades; with plan.shadeGlyphs, a cell every
// part of which is covered shows the shade glyph of its mean shade instead,
// and a cell with background parts the glyph nearest its parts after a blur.
char32_t DitheredGlyph(const CellSamples& s, const GlyphPlan& plan, const CellPlace& place,
                       uint8_t meanShade) {
  if (plan.shadeGlyphs) {
    if (s.covered == LowBits(plan.pattern.Count())) return ShadeGlyph(meanShade);
    return place.silhouette->Nearest(s.values.data());
  }
  return PatternGlyph(plan.mode, place.dither.CellInk(s.values.data(), s.covered, plan.pattern,
                                                      place.col, place.row));
}

template <int N>
char32_t MixedCell(const CellSamples& s, const GlyphPlan& plan, SamplePattern all,
                   const std::array<int16_t, 256>& levelOf, AsciiMatcher& ascii,
                   const CellPlace& place, Tone& fore, Tone& back) {
  const GlyphMode mode = plan.mode;
  switch (mode) {
    case GlyphMode::kRamp:
      fore = ToneOf<N>(s, all);
      return plan.ramp->Glyph(levelOf[fore.intensity]);
    case GlyphMode::kAscii:
      fore = ToneOf<N>(s, s.covered);
      return plan.twoColour ? ascii.MatchShape(s.values.data(), s.covered)
                            : ascii.MatchInk(s.values.data(), s.covered);
    case GlyphMode::kBraille:
      fore = ToneOf<N>(s, s.covered);
      return plan.ditherOrder != 0 ? DitheredGlyph(s, plan, place, fore.intensity)
                                   : PatternGlyph(mode, s.covered);
    default: {  // blocks, quadrants, sextants
      SamplePattern ink = s.covered;
      if (plan.twoColour) ink = BrighterHalf<N>(s);
      if (ink == 0) ink = all;
      fore = ToneOf<N>(s, ink);
      if (plan.twoColour) back = ToneOf<N>(s, all & ~ink);
      return plan.ditherOrder != 0 ? DitheredGlyph(s, plan, place, fore.intensity)
                                   : PatternGlyph(mode, ink);
    }
  }
}

}  // namespace

void GlyphStage::Compose(const Samples& in, const GlyphPlan& plan, CellBuffer& cells,
                         DepthBuffer& depth) {
  if (plan.writeDepth) depth.Clear();
  if (plan.mode == GlyphMode::kAscii) ascii_.Prepare(in.frame.Grid());
  // The ramp level of each intensity: LevelFor depends on the level count alone.
  if (levelCount_ != plan.ramp->LevelCount()) {
    levelCount_ = plan.ramp->LevelCount();
    for (int i = 0; i < 256; ++i) {
      levelOf_[i] = static_cast<int16_t>(plan.ramp->LevelFor(i / 255.0));
    }
  }
  if (plan.ditherOrder != 0 && dither_.Side() != 1 << plan.ditherOrder) {
    dither_ = OrderedDither(plan.ditherOrder);
  }
  if (plan.shadeGlyphs && (!silhouette_ || silhouette_->Mode() != plan.mode ||
                           !(silhouette_->Parts() == plan.pattern))) {
    silhouette_.emplace(plan.mode, plan.pattern);
  }
  uniformAscii_.fill(0);  // ascii glyphs of one-face cells, by intensity, filled as met
  FillBackground(cells);
  // The mode's own grids with their sizes known to the compiler; any other (forced) at run time.
  const SampleGrid g = in.frame.Grid();
  if (g == SampleGrid{1, 2}) return ComposeGrid<1, 2>(in, plan, cells, depth);
  if (g == SampleGrid{2, 2}) return ComposeGrid<2, 2>(in, plan, cells, depth);
  if (g == SampleGrid{2, 3}) return ComposeGrid<2, 3>(in, plan, cells, depth);
  if (g == SampleGrid{2, 4}) return ComposeGrid<2, 4>(in, plan, cells, depth);
  ComposeGrid<0, 0>(in, plan, cells, depth);
}

template <int kAcross, int kDown>
void GlyphStage::ComposeGrid(const Samples& in, const GlyphPlan& plan, CellBuffer& cells,
                             DepthBuffer& depth) {
  constexpr int kCount = kAcross * kDown;  // 0: at run time
  const SampleGrid grid = in.frame.Grid();
  const int count = kCount > 0 ? kCount : grid.Count();
  const GlyphMode mode = plan.mode;
  const ShadeRamp& ramp = *plan.ramp;  // in a register: the byte stores below may alias the plan
  const int partCount = plan.pattern.Count();
  const bool reduce = !(plan.pattern == grid);
  const SamplePattern all = LowBits(partCount);
  const uint8_t* const faceIntensity = in.faceIntensities.data();
  CellSamples fine, parts;
  fine.count = count;
  const size_t cellCount = in.frame.CellCount();
  const auto widthCells = static_cast<size_t>(cells.WidthCells());
  for (size_t index = in.frame.NextTouched(0); index < cellCount;
       index = in.frame.NextTouched(index + 1)) {
    // Step 1: the cell's samples and whether they all show one face.
    const uint32_t* const sampleFaces = in.frame.Faces(index).data();
    const uint32_t firstFace = sampleFaces[0];
    bool oneFace = true;
    SamplePattern covered = 0;
    for (int n = 0; n < count; ++n) {
      const uint32_t face = sampleFaces[n];
      fine.faces[n] = face;
      fine.values[n] = face == 0 ? 0 : faceIntensity[face - 1];
      covered |= static_cast<SamplePattern>(face != 0) << n;
      oneFace = oneFace && face == firstFace;
    }
    if (oneFace && firstFace == 0) continue;  // background, as filled
    fine.covered = covered;
    if (plan.writeDepth) {
      const float* const sampleDepths = in.frame.Depths(index).data();
      float nearest = 0.0F;
      for (int n = 0; n < count; ++n) nearest = std::max(nearest, sampleDepths[n]);
      depth.At(index) = nearest;
    }
    // Step 2: the glyph and its colours; a cell of one face has one tone (a full block).
    Tone fore, back;
    char32_t glyph = U' ';
    const CellPlace place{dither_, plan.shadeGlyphs ? &*silhouette_ : nullptr,
                          static_cast<int>(index % widthCells),
                          static_cast<int>(index / widthCells)};
    if (oneFace) {
      fore = {firstFace, fine.values[0]};
      switch (mode) {
        case GlyphMode::kRamp:
          glyph = ramp.Glyph(levelOf_[fore.intensity]);
          break;
        case GlyphMode::kAscii: {
          char32_t& known = uniformAscii_[fore.intensity];
          if (known == 0) {
            known = plan.twoColour ? ascii_.MatchShape(fine.values.data(), all)
                                   : ascii_.MatchInk(fine.values.data(), all);
          }
          glyph = known;
          break;
        }
        default:
          if (plan.ditherOrder != 0) {
            fine.covered = all;  // one face: every part covered, every shade the same
            glyph = DitheredGlyph(fine, plan, place, fore.intensity);
          } else {
            glyph = PatternGlyph(mode, all);
          }
          break;
      }
    } else if (!reduce) {
      glyph = MixedCell<kCount>(fine, plan, all, levelOf_, ascii_, place, fore, back);
    } else {
      // The colour quadrants' (1x2 samples a part) and blocks' (2x2) parts unrolled.
      if (kCount == 8 && plan.pattern == SampleGrid{2, 2}) {
        ReduceToParts<kCount, 1, 2>(fine, grid, plan.pattern, parts);
      } else if (kCount == 8 && plan.pattern == SampleGrid{1, 2}) {
        ReduceToParts<kCount, 2, 2>(fine, grid, plan.pattern, parts);
      } else {
        ReduceToParts<kCount, 0, 0>(fine, grid, plan.pattern, parts);
      }
      // The colour blocks' and quadrants' parts; other forced grids at run time.
      if (parts.count == 2) {
        glyph = MixedCell<2>(parts, plan, all, levelOf_, ascii_, place, fore, back);
      } else if (parts.count == 4) {
        glyph = MixedCell<4>(parts, plan, all, levelOf_, ascii_, place, fore, back);
      } else {
        glyph = MixedCell<0>(parts, plan, all, levelOf_, ascii_, place, fore, back);
      }
    }
    cells.Glyphs()[index] = glyph;
    cells.FaceNumbers()[index] = fore.face;
    cells.Intensities()[index] = fore.intensity;
    cells.Levels()[index] = fore.face == 0 ? int16_t{-1} : levelOf_[fore.intensity];
    cells.BackFaceNumbers()[index] = back.face;
    cells.BackIntensities()[index] = back.intensity;
    cells.BackLevels()[index] = back.face == 0 ? int16_t{-1} : levelOf_[back.intensity];
  }
}

}  // namespace termshade
