#include "raster/TextureStage.h"

#include <algorithm>

#include "raster/TextureDetail.h"
#include "raster/TextureSample.h"
#include "shade/CellColour.h"

namespace termshade {
namespace {

uint32_t PackLinear(Rgb linear) {
  const Srgb8 c = EncodeSrgb8(linear);
  return PackAlbedo(c);
}

// Running sums of a cell's foreground and background albedos.
struct AlbedoSums {
  double fore[3] = {0, 0, 0};
  double back[3] = {0, 0, 0};
  int foreCount = 0;
  int backCount = 0;
  void Add(double* sum, int& count, Rgb albedo) {
    sum[0] += albedo.r;
    sum[1] += albedo.g;
    sum[2] += albedo.b;
    ++count;
  }
  static uint32_t Mean(const double* sum, int count) {
    if (count == 0) return 0;
    return PackLinear(Rgb{static_cast<float>(sum[0] / count), static_cast<float>(sum[1] / count),
                          static_cast<float>(sum[2] / count)});
  }
};

// A simplified level: each cell's sides in their faces' flat texture colours.
void ApplyFlatColours(const Scene& scene, CellBuffer& cells) {
  const auto& flat = scene.textures.flatColours;
  const auto colourOf = [&flat](uint32_t face) {
    return face == 0 || face > flat.size() ? 0U : PackLinear(flat[face - 1]);
  };
  for (int row = 0; row < cells.HeightCells(); ++row) {
    for (int col = 0; col < cells.WidthCells(); ++col) {
      const size_t cell = cells.Index(col, row);
      cells.ForeAlbedos()[cell] = colourOf(cells.FaceNumber(col, row));
      cells.BackAlbedos()[cell] = colourOf(cells.BackFaceNumber(col, row));
    }
  }
}

}  // namespace

void TextureStage::Apply(const Scene& scene, const FrameView& view, CellBuffer& cells) const {
  cells.UseAlbedos();
  if (!scene.textures.Any()) return ApplyFlatColours(scene, cells);
  for (int row = 0; row < cells.HeightCells(); ++row) {
    for (int col = 0; col < cells.WidthCells(); ++col) {
      const uint32_t face = cells.FaceNumber(col, row);
      if (face == 0 || scene.textures.FaceTexture(face - 1) == nullptr) continue;
      int level = -1;
      cells.ForeAlbedos()[cells.Index(col, row)] =
          PackLinear(TexturedAlbedoAt(scene, view, face - 1, col + 0.5, row + 0.5, {}, level));
    }
  }
}

void TextureStage::Apply(const Scene& scene, const FrameView& view, const Samples& samples,
                         CellBuffer& cells) {
  cells.UseAlbedos();
  if (!scene.textures.Any()) return ApplyFlatColours(scene, cells);
  const auto textured = [&scene](uint32_t faceNumber) {
    return faceNumber != 0 && faceNumber <= scene.FaceCount() &&
           scene.textures.FaceTexture(faceNumber - 1) != nullptr;
  };
  const auto& faceColours = scene.source.faceColors;
  const SampleGrid grid = samples.frame.Grid();
  const GlyphPlan& glyphs = samples.glyphs;
  const bool detail = glyphs.twoColour &&
                      (glyphs.mode == GlyphMode::kBlocks || glyphs.mode == GlyphMode::kQuadrants ||
                       glyphs.mode == GlyphMode::kSextants);
  for (int row = 0; row < cells.HeightCells(); ++row) {
    for (int col = 0; col < cells.WidthCells(); ++col) {
      const size_t cell = cells.Index(col, row);
      if (!samples.frame.Touched(cell)) continue;
      // Step 1: each sample's albedo: its texel, its face's colour, or none.
      const auto faces = samples.frame.Faces(cell);
      if (std::none_of(faces.begin(), faces.end(), textured)) continue;
      albedos_.assign(faces.size(), Rgb{});
      uint32_t levelFace = 0;
      int level = -1;
      for (size_t n = 0; n < faces.size(); ++n) {
        const uint32_t face = faces[n];
        if (textured(face)) {
          if (face != levelFace) levelFace = face, level = -1;
          const double x = col * grid.across + static_cast<double>(n % grid.across) + 0.5;
          const double y = row * grid.down + static_cast<double>(n / grid.across) + 0.5;
          albedos_[n] = TexturedAlbedoAt(scene, view, face - 1, x, y, {}, level);
        } else if (face != 0) {
          albedos_[n] = face <= faceColours.size() ? faceColours[face - 1] : kDefaultFaceColour;
        }
      }
      // Step 2: the texture's detail inside the cell, where the glyphs can show it.
      if (detail && SplitTexturedCell({col, row, grid, faces, albedos_}, samples.faceIntensities,
                                      glyphs, cells)) {
        continue;
      }
      // Step 3: else each side's albedo: the mean over the samples of its face.
      const uint32_t fore = cells.FaceNumber(col, row), back = cells.BackFaceNumber(col, row);
      AlbedoSums sums;
      for (size_t n = 0; n < faces.size(); ++n) {
        if (!textured(faces[n])) continue;
        if (faces[n] == fore) sums.Add(sums.fore, sums.foreCount, albedos_[n]);
        if (faces[n] == back) sums.Add(sums.back, sums.backCount, albedos_[n]);
      }
      cells.ForeAlbedos()[cell] = AlbedoSums::Mean(sums.fore, sums.foreCount);
      cells.BackAlbedos()[cell] = AlbedoSums::Mean(sums.back, sums.backCount);
    }
  }
}

}  // namespace termshade
