#pragma once

#include <cstdint>
#include <span>

#include "geometry/Rgb.h"
#include "raster/CellBuffer.h"
#include "raster/FramePlan.h"

namespace termshade {

/// One cell's samples as the texture stage sees them: the face (1-based) and
/// the albedo (linear light) each sample shows, row-major in `grid`.
struct TexturedCell {
  int col = 0;
  int row = 0;
  SampleGrid grid;
  std::span<const uint32_t> faces;
  std::span<const Rgb> albedos;
};

/// Texture detail inside a cell of the block modes (blocks, quadrants,
/// sextants) with colours shown: when every sample shows a face, the glyph's
/// parts (each the mean of its samples: albedo and shaded luminance, albedo x
/// face intensity; the face most of them show) are split in two by
/// luminance (the least squared error cut, as the glyph stage splits shades)
/// and the cell becomes the pattern of the brighter parts, each side taking
/// its parts' mean albedo and its face's shade. A cell whose samples are
/// all alike keeps what the glyph stage gave it. Returns whether it split.
bool SplitTexturedCell(const TexturedCell& cell, std::span<const uint8_t> faceIntensities,
                       const GlyphPlan& plan, CellBuffer& cells);

}  // namespace termshade
