#include "raster/GlyphStage.h"

#include <algorithm>
#include <array>

#include "shade/BlockGlyphs.h"

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

Tone ToneOf(const CellSamples& s, SamplePattern members) {
  uint32_t bestFace = 0;
  int bestCount = 0, memberCount = 0, sum = 0;
  for (int i = 0; i < s.count; ++i) {
    if (!((members >> i) & 1U)) continue;
    ++memberCount;
    sum += s.values[i];
    const uint32_t face = s.faces[i];
    if (face == 0) continue;
    int count = 0;
    for (int j = 0; j < s.count; ++j) count += ((members >> j) & 1U) && s.faces[j] == face ? 1 : 0;
    if (count > bestCount || (count == bestCount && face < bestFace)) {
      bestFace = face;
      bestCount = count;
    }
  }
  if (memberCount == 0) return {};
  return {bestFace, static_cast<uint8_t>((sum + memberCount / 2) / memberCount)};
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

void SetTone(const Tone& tone, const std::array<int16_t, 256>& levelOf, uint32_t& face,
             int16_t& level, uint8_t& intensity) {
  face = tone.face;
  intensity = tone.intensity;
  level = tone.face == 0 ? int16_t{-1} : levelOf[tone.intensity];
}

}  // namespace

void GlyphStage::Compose(const Samples& in, const RenderOptions& options, CellBuffer& cells,
                         DepthBuffer& depth) {
  cells.Clear();
  depth.Clear();
  const int k = in.grid.across, m = in.grid.down;
  const GlyphMode mode = options.glyphs;
  if (mode == GlyphMode::kAscii) ascii_.Prepare(in.grid);
  const SamplePattern all =
      in.grid.Count() >= 32 ? ~SamplePattern{0} : (SamplePattern{1} << in.grid.Count()) - 1;
  // The ramp level of each intensity, once a frame.
  std::array<int16_t, 256> levelOf{};
  for (int i = 0; i < 256; ++i) levelOf[i] = static_cast<int16_t>(options.ramp.LevelFor(i / 255.0));
  const uint32_t* const sampleFaces = in.faces.FaceNumbers().data();
  const uint8_t* const faceIntensity = in.faceIntensities.data();
  CellSamples s;
  s.count = in.grid.Count();
  for (int row = 0; row < cells.HeightCells(); ++row) {
    for (int col = 0; col < cells.WidthCells(); ++col) {
      // Step 1: the cell's samples, whether they all show one face, and the nearest depth.
      s.covered = 0;
      const uint32_t firstFace = sampleFaces[in.faces.Index(col * k, row * m)];
      bool oneFace = true;
      float nearest = 0.0F;
      for (int j = 0; j < m; ++j) {
        const size_t rowStart = in.faces.Index(col * k, row * m + j);
        for (int i = 0; i < k; ++i) {
          const int n = j * k + i;
          const uint32_t face = sampleFaces[rowStart + i];
          s.faces[n] = face;
          s.values[n] = face == 0 ? 0 : faceIntensity[face - 1];
          s.covered |= face != 0 ? SamplePattern{1} << n : 0;
          oneFace = oneFace && face == firstFace;
          if (in.writeDepth) nearest = std::max(nearest, in.depth.At(rowStart + i));
        }
      }
      if (s.covered == 0) continue;
      // Step 2: the glyph and its colours.
      const size_t index = cells.Index(col, row);
      SamplePattern ink = s.covered;
      Tone fore, back;
      char32_t glyph = U' ';
      switch (mode) {
        case GlyphMode::kRamp: {
          fore = oneFace ? Tone{firstFace, s.values[0]} : ToneOf(s, all);
          glyph = options.ramp.Glyph(options.ramp.LevelFor(fore.intensity / 255.0));
          break;
        }
        case GlyphMode::kAscii: {
          fore = oneFace ? Tone{firstFace, s.values[0]} : ToneOf(s, s.covered);
          glyph = options.twoColour ? ascii_.MatchShape(s.values.data(), s.covered)
                                    : ascii_.MatchInk(s.values.data(), s.covered);
          break;
        }
        case GlyphMode::kBraille:
          fore = oneFace ? Tone{firstFace, s.values[0]} : ToneOf(s, s.covered);
          glyph = PatternGlyph(mode, s.covered);
          break;
        default:  // blocks, quadrants, sextants
          if (oneFace) {  // one tone: a full block
            ink = all;
            fore = {firstFace, s.values[0]};
          } else {
            if (options.twoColour) ink = BrighterHalf(s);
            if (ink == 0) ink = all;
            fore = ToneOf(s, ink);
            if (options.twoColour) back = ToneOf(s, all & ~ink);
          }
          glyph = PatternGlyph(mode, ink);
          break;
      }
      cells.Glyphs()[index] = glyph;
      SetTone(fore, levelOf, cells.FaceNumbers()[index], cells.Levels()[index],
              cells.Intensities()[index]);
      SetTone(back, levelOf, cells.BackFaceNumbers()[index], cells.BackLevels()[index],
              cells.BackIntensities()[index]);
      if (in.writeDepth) depth.At(index) = nearest;
    }
  }
}

}  // namespace termshade
