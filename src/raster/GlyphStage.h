#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/FramePlan.h"
#include "raster/SampleFrame.h"
#include "shade/AsciiMatcher.h"
#include "shade/BlurredGlyphMatch.h"
#include "shade/OrderedDither.h"

namespace termshade {

/// The stage after shading when a cell has several samples (SPEC 11): reads a
/// frame of samples (grid.across x grid.down per cell, each with its face and
/// intensity) and writes each cell's glyph and its fg/bg (face, intensity) pairs.
/// Keeps the ascii matcher's cache and the ramp's level table between frames.
/// Cells no sample reaches are filled as background at once; a cell whose
/// samples show one face takes its tone without a split or a match. Without
/// colour, braille's glyphs are the ordered dither of the covered samples'
/// shades (plan.ditherOrder); blocks', quadrants' and sextants' a bar of the
/// cell's mean shade where every part is covered (ShadeGlyph), else the glyph
/// nearest the parts after a blur (BlurredGlyphMatch); their tones are those
/// of the covered samples.
class GlyphStage {
 public:
  /// A frame of samples (faces and depth per sample, the grid) and the
  /// intensity (0..255) of each face seen (indexed by face number - 1).
  struct Samples {
    const SampleFrame& frame;
    std::span<const uint8_t> faceIntensities;
  };
  /// Every cell's glyph by the plan (its mode, pattern and ramp); with
  /// plan.writeDepth, the cell's depth is its nearest sample's.
  void Compose(const Samples& samples, const GlyphPlan& plan, CellBuffer& cells,
               DepthBuffer& depth);

 private:
  template <int kAcross, int kDown>  // 0: the grid's size at run time
  void ComposeGrid(const Samples& in, const GlyphPlan& plan, CellBuffer& cells, DepthBuffer& depth);

  AsciiMatcher ascii_;
  OrderedDither dither_{1};  ///< the plan's matrix when it dithers (rebuilt when the order changes)
  /// With plan.shadeGlyphs: the silhouette cells' glyphs (rebuilt when the mode or grid changes).
  std::optional<BlurredGlyphMatch> silhouette_;
  int levelCount_ = 0;                  ///< the ramp's level count levelOf_ is for
  std::array<int16_t, 256> levelOf_{};  ///< ramp level by intensity
  /// This frame's ascii glyph of a one-face cell by intensity; 0 unknown.
  std::array<char32_t, 256> uniformAscii_{};
};

}  // namespace termshade
