// The glyph stage as first written: see ReferenceGlyphStage.h.
#include "support/ReferenceGlyphStage.h"

#include <algorithm>
#include <array>
#include <vector>

#include "shade/BlockGlyphs.h"
#include "shade/BlurredGlyphMatch.h"
#include "shade/OrderedDither.h"
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

// The face most members show (lower number on a tie): counts per distinct face.
uint32_t MajorityFace(const CellSamples& s, SamplePattern members) {
  std::array<uint32_t, kMaxSamples> distinct;  // NOLINT(cppcoreguidelines-pro-type-member-init)
  std::array<int, kMaxSamples> counts;         // NOLINT(cppcoreguidelines-pro-type-member-init)
  int distinctCount = 0;
  for (int i = 0; i < s.count; ++i) {
    const uint32_t face = s.faces[i];
    if (!((members >> i) & 1U) || face == 0) continue;
    int d = 0;
    while (d < distinctCount && distinct[d] != face) ++d;
    if (d == distinctCount) {
      distinct[d] = face;
      counts[d] = 0;
      ++distinctCount;
    }
    ++counts[d];
  }
  uint32_t bestFace = 0;
  int bestCount = 0;
  for (int d = 0; d < distinctCount; ++d) {
    if (counts[d] > bestCount || (counts[d] == bestCount && distinct[d] < bestFace)) {
      bestFace = distinct[d];
      bestCount = counts[d];
    }
  }
  return bestFace;
}

Tone ToneOf(const CellSamples& s, SamplePattern members) {
  // Usually the members show one face (and perhaps background): no counting.
  uint32_t onlyFace = 0;
  bool oneFace = true;
  int memberCount = 0, sum = 0;
  for (int i = 0; i < s.count; ++i) {
    if (!((members >> i) & 1U)) continue;
    ++memberCount;
    sum += s.values[i];
    const uint32_t face = s.faces[i];
    if (face == 0) continue;
    oneFace = oneFace && (onlyFace == 0 || face == onlyFace);
    onlyFace = face;
  }
  if (memberCount == 0) return {};
  const auto mean = static_cast<uint8_t>((sum + memberCount / 2) / memberCount);
  if (oneFace) return {onlyFace, mean};
  return {MajorityFace(s, members), mean};
}

// The best two-tone split of grey values (least squared error): a threshold
// on the sorted values; the brighter side is the ink. Ties go to the first
// threshold in sorted order, equal values keep sample order.
SamplePattern BrighterHalf(const CellSamples& s) {
  std::array<int, kMaxSamples> order{};
  for (int i = 0; i < s.count; ++i) {  // insertion sort: stable, no allocation, n <= 32
    int j = i;
    for (; j > 0 && s.values[order[j - 1]] > s.values[i]; --j) order[j] = order[j - 1];
    order[j] = i;
  }
  int total = 0;
  for (int i = 0; i < s.count; ++i) total += s.values[i];
  // Maximizing sumLow^2/nLow + sumHigh^2/nHigh minimizes the squared error.
  double bestScore = -1.0;
  int bestCut = 0, lowSum = 0;
  for (int cut = 1; cut < s.count; ++cut) {
    lowSum += s.values[order[cut - 1]];
    if (s.values[order[cut - 1]] == s.values[order[cut]]) continue;
    const double highSum = total - lowSum;
    const double score = double(lowSum) * lowSum / cut + highSum * highSum / (s.count - cut);
    if (score > bestScore) {
      bestScore = score;
      bestCut = cut;
    }
  }
  SamplePattern ink = 0;
  for (int i = bestCut; i < s.count; ++i) ink |= SamplePattern{1} << order[i];
  return ink;
}

// The samples of each part of the pattern grid, one value a part: the
// parts' mean intensity (background 0) and the face most of its samples show.
void ReduceToParts(const CellSamples& s, SampleGrid grid, SampleGrid pattern, CellSamples& parts) {
  const int subAcross = grid.across / pattern.across, subDown = grid.down / pattern.down;
  const int subCount = subAcross * subDown;
  parts.count = pattern.Count();
  parts.covered = 0;
  for (int pj = 0; pj < pattern.down; ++pj) {
    for (int pi = 0; pi < pattern.across; ++pi) {
      SamplePattern members = 0;
      int sum = 0;
      const uint32_t firstFace = s.faces[(pj * subDown) * grid.across + pi * subAcross];
      bool oneFace = true;
      for (int y = 0; y < subDown; ++y) {
        for (int x = 0; x < subAcross; ++x) {
          const int n = (pj * subDown + y) * grid.across + pi * subAcross + x;
          members |= SamplePattern{1} << n;
          sum += s.values[n];
          oneFace = oneFace && s.faces[n] == firstFace;
        }
      }
      const int p = pj * pattern.across + pi;
      parts.faces[p] = oneFace || (s.covered & members) == 0 ? firstFace : MajorityFace(s, members);
      parts.values[p] = static_cast<uint8_t>((sum + subCount / 2) / subCount);
      if (parts.faces[p] != 0) parts.covered |= SamplePattern{1} << p;
    }
  }
}

void SetTone(const Tone& tone, const std::array<int16_t, 256>& levelOf, uint32_t& face,
             int16_t& level, uint8_t& intensity) {
  face = tone.face;
  intensity = tone.intensity;
  level = tone.face == 0 ? int16_t{-1} : levelOf[tone.intensity];
}

// The ascii matcher's sample levels as first written (AsciiMatcher::MatchInk
// and MatchShape): brightness, or the shape scaled to the brightest sample.
std::array<uint8_t, 32> InkLevels(const CellSamples& s) {
  std::array<uint8_t, 32> levels{};
  for (int n = 0; n < s.count; ++n) {
    if ((s.covered >> n) & 1U) levels[n] = static_cast<uint8_t>((s.values[n] * 15 + 127) / 255);
  }
  return levels;
}

std::array<uint8_t, 32> ShapeLevels(const CellSamples& s) {
  int brightest = 1;
  for (int n = 0; n < s.count; ++n) {
    if ((s.covered >> n) & 1U) brightest = std::max<int>(brightest, s.values[n]);
  }
  std::array<uint8_t, 32> levels{};
  for (int n = 0; n < s.count; ++n) {
    if ((s.covered >> n) & 1U) {
      levels[n] = static_cast<uint8_t>(std::max(1, (s.values[n] * 15 + brightest / 2) / brightest));
    }
  }
  return levels;
}

// Without colour: the covered samples whose shade exceeds the dither's
// threshold at their screen position; if none, the covered one of lowest
// threshold (the first in row-major order on a tie).
SamplePattern DitheredInk(const CellSamples& s, SampleGrid pattern, const OrderedDither& dither,
                          int col, int row) {
  SamplePattern ink = 0, lowest = 0;
  int lowestThreshold = 1000;
  for (int n = 0; n < pattern.Count(); ++n) {
    if (((s.covered >> n) & 1U) == 0) continue;
    const int x = col * pattern.across + n % pattern.across;
    const int y = row * pattern.down + n / pattern.across;
    if (dither.Inks(s.values[n], x, y)) ink |= SamplePattern{1} << n;
    // Of equal lowest thresholds, the first in even columns, the last in odd ones.
    if (dither.Threshold(x, y) < lowestThreshold ||
        (dither.Threshold(x, y) == lowestThreshold && col % 2 == 1)) {
      lowestThreshold = dither.Threshold(x, y);
      lowest = SamplePattern{1} << n;
    }
  }
  return ink != 0 ? ink : lowest;
}

// The rounded mean shade of the covered samples (or parts).
uint8_t MeanOfCovered(const CellSamples& s) {
  int sum = 0, count = 0;
  for (int n = 0; n < s.count; ++n) {
    if (((s.covered >> n) & 1U) == 0) continue;
    sum += s.values[n];
    ++count;
  }
  return static_cast<uint8_t>(count == 0 ? 0 : (sum + count / 2) / count);
}

}  // namespace

const BlurredGlyphMatch& ReferenceGlyphStage::Silhouette(GlyphMode mode, SampleGrid parts) {
  if (!silhouette_ || silhouette_->Mode() != mode || !(silhouette_->Parts() == parts)) {
    silhouette_.emplace(mode, parts);
  }
  return *silhouette_;
}

void ReferenceGlyphStage::Compose(const GlyphStage::Samples& in, const GlyphPlan& plan,
                                  CellBuffer& cells, DepthBuffer& depth) {
  if (plan.writeDepth) depth.Clear();
  if (plan.mode == GlyphMode::kAscii) ascii_.Prepare(in.frame.Grid());
  const SampleGrid grid = in.frame.Grid();
  const int k = grid.across;
  const int m = grid.down;
  const GlyphMode mode = plan.mode;
  const int partCount = plan.pattern.Count();
  const bool reduce = !(plan.pattern == grid);
  const SamplePattern all =
      partCount >= 32 ? ~SamplePattern{0} : (SamplePattern{1} << partCount) - 1;
  // The ramp level of each intensity, once a frame.
  std::array<int16_t, 256> levelOf{};
  for (int i = 0; i < 256; ++i) levelOf[i] = static_cast<int16_t>(plan.ramp->LevelFor(i / 255.0));
  const uint8_t* const faceIntensity = in.faceIntensities.data();
  CellSamples fine, parts;
  fine.count = k * m;
  const size_t cellCount = static_cast<size_t>(cells.WidthCells()) * cells.HeightCells();
  for (size_t index = 0; index < cellCount; ++index) {
    // Step 1: the cell's samples, whether they all show one face, and the nearest depth.
    bool oneFace = true;
    uint32_t firstFace = 0;
    if (in.frame.Touched(index)) {
      const uint32_t* const sampleFaces = in.frame.Faces(index).data();
      firstFace = sampleFaces[0];
      for (int n = 0; n < k * m; ++n) {
        const uint32_t face = sampleFaces[n];
        fine.faces[n] = face;
        oneFace = oneFace && face == firstFace;
      }
    }
    if (oneFace && firstFace == 0) {  // background
      SetTone({}, levelOf, cells.FaceNumbers()[index], cells.Levels()[index],
              cells.Intensities()[index]);
      SetTone({}, levelOf, cells.BackFaceNumbers()[index], cells.BackLevels()[index],
              cells.BackIntensities()[index]);
      cells.Glyphs()[index] = U' ';
      continue;
    }
    fine.covered = 0;
    float nearest = 0.0F;
    for (int n = 0; n < k * m; ++n) {
      const uint32_t face = fine.faces[n];
      fine.values[n] = face == 0 ? 0 : faceIntensity[face - 1];
      fine.covered |= face != 0 ? SamplePattern{1} << n : 0;
      if (plan.writeDepth) nearest = std::max(nearest, in.frame.Depths(index)[n]);
    }
    if (reduce) ReduceToParts(fine, grid, plan.pattern, parts);
    const CellSamples& s = reduce ? parts : fine;
    // Step 2: the glyph and its colours.
    const int col = static_cast<int>(index % static_cast<size_t>(cells.WidthCells()));
    const int row = static_cast<int>(index / static_cast<size_t>(cells.WidthCells()));
    SamplePattern ink = s.covered;
    Tone fore, back;
    char32_t glyph = U' ';
    switch (mode) {
      case GlyphMode::kRamp: {
        fore = oneFace ? Tone{firstFace, s.values[0]} : ToneOf(s, all);
        glyph = plan.ramp->Glyph(levelOf[fore.intensity]);
        break;
      }
      case GlyphMode::kAscii: {
        fore = oneFace ? Tone{firstFace, s.values[0]} : ToneOf(s, s.covered);
        glyph = ascii_.Nearest(plan.twoColour ? ShapeLevels(s) : InkLevels(s));
        break;
      }
      case GlyphMode::kBraille:
        fore = oneFace ? Tone{firstFace, s.values[0]} : ToneOf(s, s.covered);
        glyph = PatternGlyph(mode, s.covered);
        if (plan.ditherOrder != 0) {
          const OrderedDither dither(plan.ditherOrder);
          glyph = PatternGlyph(mode, DitheredInk(s, plan.pattern, dither, col, row));
        }
        break;
      default:          // blocks, quadrants, sextants
        if (oneFace) {  // one tone: a full block
          ink = all;
          fore = {firstFace, s.values[0]};
        } else {
          if (plan.twoColour) ink = BrighterHalf(s);
          if (ink == 0) ink = all;
          fore = ToneOf(s, ink);
          if (plan.twoColour) back = ToneOf(s, all & ~ink);
        }
        glyph = PatternGlyph(mode, ink);
        if (plan.ditherOrder != 0) {
          const OrderedDither dither(plan.ditherOrder);
          glyph = PatternGlyph(mode, DitheredInk(s, plan.pattern, dither, col, row));
        }
        if (plan.shadeGlyphs) {
          glyph = s.covered == all ? ShadeGlyph(MeanOfCovered(s))
                                   : Silhouette(mode, plan.pattern).Nearest(s.values.data());
        }
        break;
    }
    cells.Glyphs()[index] = glyph;
    SetTone(fore, levelOf, cells.FaceNumbers()[index], cells.Levels()[index],
            cells.Intensities()[index]);
    SetTone(back, levelOf, cells.BackFaceNumbers()[index], cells.BackLevels()[index],
            cells.BackIntensities()[index]);
    if (plan.writeDepth) depth.At(index) = nearest;
  }
}

}  // namespace termshade
