#include "raster/TextureDetail.h"

#include <algorithm>
#include <array>

#include "shade/BlockGlyphs.h"
#include "shade/CellColour.h"
#include "shade/ShadeRamp.h"

namespace termshade {
namespace {

constexpr size_t kMostSamples = 32;
// Sides whose mean shaded luminance differs by less than this look alike.
constexpr double kLeastLuminanceStep = 0.02;

// The samples' mean albedo and their most frequent face, over `members`.
struct Side {
  Rgb albedo;
  uint32_t face = 0;
  double luminance = 0.0;
};

// A cell reduced to the glyph's parts.
struct Parts {
  size_t count = 0;
  std::array<uint32_t, kMostSamples> faces{};
  std::array<Rgb, kMostSamples> albedos{};
  std::array<double, kMostSamples> shaded{};
};

// Each part's mean albedo and shaded luminance, and its samples' most frequent
// face; false when a sample shows no face.
bool ReduceToParts(const TexturedCell& cell, SampleGrid pattern,
                   std::span<const uint8_t> faceIntensities, Parts& parts) {
  const int subAcross = cell.grid.across / pattern.across, subDown = cell.grid.down / pattern.down;
  parts.count = static_cast<size_t>(pattern.Count());
  for (int p = 0; p < pattern.Count(); ++p) {
    const int first =
        (p / pattern.across) * subDown * cell.grid.across + (p % pattern.across) * subAcross;
    double sum[3] = {0, 0, 0}, shaded = 0.0;
    int bestVotes = 0;
    for (int k = 0; k < subAcross * subDown; ++k) {
      const size_t n =
          static_cast<size_t>(first + (k / subAcross) * cell.grid.across + k % subAcross);
      const uint32_t face = cell.faces[n];
      if (face == 0 || face > faceIntensities.size()) return false;
      const Rgb a = cell.albedos[n];
      sum[0] += a.r, sum[1] += a.g, sum[2] += a.b;
      shaded += LinearLuminance(a) * faceIntensities[face - 1] / 255.0;
      int votes = 0;
      for (int j = 0; j < subAcross * subDown; ++j) {
        votes += cell.faces[static_cast<size_t>(first + (j / subAcross) * cell.grid.across +
                                                j % subAcross)] == face
                     ? 1
                     : 0;
      }
      if (votes > bestVotes) bestVotes = votes, parts.faces[static_cast<size_t>(p)] = face;
    }
    const double count = subAcross * subDown;
    parts.albedos[static_cast<size_t>(p)] =
        Rgb{static_cast<float>(sum[0] / count), static_cast<float>(sum[1] / count),
            static_cast<float>(sum[2] / count)};
    parts.shaded[static_cast<size_t>(p)] = shaded / count;
  }
  return true;
}

Side SideOf(const Parts& cell, std::span<const double> shaded, uint32_t members) {
  Side side;
  double sum[3] = {0, 0, 0};
  int count = 0, bestVotes = 0;
  for (size_t n = 0; n < cell.count; ++n) {
    if ((members >> n & 1U) == 0) continue;
    sum[0] += cell.albedos[n].r;
    sum[1] += cell.albedos[n].g;
    sum[2] += cell.albedos[n].b;
    side.luminance += shaded[n];
    ++count;
    int votes = 0;
    for (size_t m = 0; m < cell.count; ++m) {
      votes += (members >> m & 1U) != 0 && cell.faces[m] == cell.faces[n] ? 1 : 0;
    }
    if (votes > bestVotes) bestVotes = votes, side.face = cell.faces[n];
  }
  side.albedo = Rgb{static_cast<float>(sum[0] / count), static_cast<float>(sum[1] / count),
                    static_cast<float>(sum[2] / count)};
  side.luminance /= count;
  return side;
}

// The brighter samples of the least squared error cut of their values (0: none).
uint32_t BrighterSamples(std::span<const double> values) {
  std::array<double, kMostSamples> sorted{};
  const size_t count = values.size();
  std::copy(values.begin(), values.end(), sorted.begin());
  std::sort(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(count));
  double total = 0.0;
  for (size_t i = 0; i < count; ++i) total += sorted[i];
  double bestScore = -1.0, lowSum = 0.0;
  size_t bestCut = 0;
  for (size_t cut = 1; cut < count; ++cut) {
    lowSum += sorted[cut - 1];
    const double highSum = total - lowSum;
    const double score = lowSum * lowSum / cut + highSum * highSum / (count - cut);
    if (sorted[cut - 1] != sorted[cut] && score > bestScore) bestScore = score, bestCut = cut;
  }
  if (bestCut == 0) return 0;
  uint32_t ink = 0;
  for (size_t n = 0; n < count; ++n) ink |= (values[n] >= sorted[bestCut] ? 1U : 0U) << n;
  return ink;
}

}  // namespace

bool SplitTexturedCell(const TexturedCell& cell, std::span<const uint8_t> faceIntensities,
                       const GlyphPlan& plan, CellBuffer& cells) {
  // Step 1: the parts; a cell reaching the background is left as it is.
  if (plan.pattern.Count() < 2 || cell.grid.Count() > static_cast<int>(kMostSamples)) return false;
  Parts parts;
  if (!ReduceToParts(cell, plan.pattern, faceIntensities, parts)) return false;
  const std::span<const double> values(parts.shaded.data(), parts.count);
  // Step 2: the cut, and the two sides it makes.
  const uint32_t all = (parts.count == 32 ? 0U : 1U << parts.count) - 1U;
  const uint32_t ink = BrighterSamples(values);
  if (ink == 0 || ink == all) return false;
  const Side fore = SideOf(parts, values, ink), back = SideOf(parts, values, all & ~ink);
  if (fore.luminance - back.luminance < kLeastLuminanceStep) return false;
  // Step 3: the cell as the pattern of the brighter side.
  const size_t at = cells.Index(cell.col, cell.row);
  cells.Glyphs()[at] = PatternGlyph(plan.mode, ink);
  cells.FaceNumbers()[at] = fore.face;
  cells.BackFaceNumbers()[at] = back.face;
  const uint8_t foreIntensity = faceIntensities[fore.face - 1];
  const uint8_t backIntensity = faceIntensities[back.face - 1];
  cells.Intensities()[at] = foreIntensity;
  cells.BackIntensities()[at] = backIntensity;
  cells.Levels()[at] = static_cast<int16_t>(plan.ramp->LevelFor(foreIntensity / 255.0));
  cells.BackLevels()[at] = static_cast<int16_t>(plan.ramp->LevelFor(backIntensity / 255.0));
  cells.ForeAlbedos()[at] = PackAlbedo(EncodeSrgb8(fore.albedo));
  cells.BackAlbedos()[at] = PackAlbedo(EncodeSrgb8(back.albedo));
  return true;
}

}  // namespace termshade
