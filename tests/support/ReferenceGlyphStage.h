#pragma once

#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/FramePlan.h"
#include "raster/GlyphStage.h"
#include "shade/AsciiMatcher.h"

namespace termshade {

/// The glyph stage as first written (plain loops, no short cuts, the ascii
/// glyph searched without the matcher's cache): the reference the fast
/// GlyphStage is compared with, cell by cell.
class ReferenceGlyphStage {
 public:
  void Compose(const GlyphStage::Samples& samples, const GlyphPlan& plan, CellBuffer& cells,
               DepthBuffer& depth);

 private:
  AsciiMatcher ascii_;
};

}  // namespace termshade
