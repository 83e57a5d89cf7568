#pragma once

#include <optional>

#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "raster/FramePlan.h"
#include "raster/GlyphStage.h"
#include "shade/AsciiMatcher.h"
#include "shade/BlurredGlyphMatch.h"

namespace termshade {

/// The glyph stage as first written (plain loops, no short cuts, the ascii
/// glyph searched without the matcher's cache): the reference the fast
/// GlyphStage is compared with, cell by cell.
class ReferenceGlyphStage {
 public:
  void Compose(const GlyphStage::Samples& samples, const GlyphPlan& plan, CellBuffer& cells,
               DepthBuffer& depth);

 private:
  /// The silhouette matcher (blocks, quadrants, sextants without colour) for
  /// a mode and grid, kept until another is asked for.
  const BlurredGlyphMatch& Silhouette(GlyphMode mode, SampleGrid parts);

  AsciiMatcher ascii_;
  std::optional<BlurredGlyphMatch> silhouette_;
};

}  // namespace termshade
