#pragma once

#include <cstdint>

#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/RenderOptions.h"
#include "shade/AsciiMatcher.h"

namespace termshade {

/// The stage after shading when a cell has several samples (SPEC 11): reads a
/// frame of samples (grid.across x grid.down per cell, each with its face and
/// intensity) and writes each cell's glyph and its fg/bg (face, intensity) pairs.
/// Keeps the ascii matcher's cache between frames.
class GlyphStage {
 public:
  void Compose(const CellBuffer& samples, const DepthBuffer& sampleDepth, SampleGrid grid,
               const RenderOptions& options, CellBuffer& cells, DepthBuffer& depth);

 private:
  AsciiMatcher ascii_;
};

}  // namespace termshade
