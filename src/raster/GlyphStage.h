#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/RenderOptions.h"
#include "raster/SampleFrame.h"
#include "shade/AsciiMatcher.h"

namespace termshade {

/// The stage after shading when a cell has several samples (SPEC 11): reads a
/// frame of samples (grid.across x grid.down per cell, each with its face and
/// intensity) and writes each cell's glyph and its fg/bg (face, intensity) pairs.
/// Keeps the ascii matcher's cache and the ramp's level table between frames.
/// Cells no sample reaches are filled as background at once; a cell whose
/// samples show one face takes its tone without a split or a match.
class GlyphStage {
 public:
  /// A frame of samples (faces and depth per sample, the grid), the
  /// intensity (0..255) of each face seen (indexed by face number - 1), and
  /// whether depth is to be kept (then the cell's depth is its nearest sample's).
  struct Samples {
    const SampleFrame& frame;
    std::span<const uint8_t> faceIntensities;
    SampleGrid pattern;  ///< the glyph's parts; the frame's grid is a multiple of it
    bool writeDepth = true;
  };
  void Compose(const Samples& samples, const RenderOptions& options, CellBuffer& cells,
               DepthBuffer& depth);

 private:
  template <int kAcross, int kDown>  // 0: the grid's size at run time
  void ComposeGrid(const Samples& in, const RenderOptions& options, CellBuffer& cells,
                   DepthBuffer& depth);

  AsciiMatcher ascii_;
  int levelCount_ = 0;                  ///< the ramp's level count levelOf_ is for
  std::array<int16_t, 256> levelOf_{};  ///< ramp level by intensity
  /// This frame's ascii glyph of a one-face cell by intensity; 0 unknown.
  std::array<char32_t, 256> uniformAscii_{};
};

}  // namespace termshade
