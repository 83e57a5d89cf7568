#pragma once

#include <string>
#include <vector>

#include "geometry/Scene.h"
#include "geometry/SnapshotViews.h"
#include "raster/RenderOptions.h"
#include "raster/SnapshotSamples.h"
#include "shade/ShadeRamp.h"

namespace termshade {

/// Everything that makes a snapshot's frames, as its golden records it.
struct SnapshotSettings {
  int widthCells = 80;
  int heightCells = 24;
  double cellAspect = 2.0;
  double theta = 0.3;  ///< the default view; the others follow from it (SnapshotViewFor)
  double phi = 1.3;
  Method method = Method::kZBuffer;
  ShadeMode shade = ShadeMode::kContrast;
  GlyphMode glyphs = GlyphMode::kRamp;
  std::string ramp = ShadeRamp::kDefaultGlyphs;  ///< UTF-8; checked by ShadeRamp::Problem
  bool cullBackFaces = true;
  SampleGrid samples{8, 16};  ///< compared samples a cell, whatever the glyph mode
  std::vector<std::string> views{"default", "opposite", "top", "bottom"};
  int threads = 0;  ///< not recorded: the frames are the same with any count

  /// The options the text frames are drawn with.
  RenderOptions FrameOptions() const;
};

/// One view of a snapshot: the text frame a reviewer reads and the samples compared.
struct SnapshotFrame {
  SnapshotView view;
  std::vector<std::string> textRows;  ///< UTF-8, widthCells characters each
  SnapshotSamples samples;
  /// Per cell (row-major), the texture's colour at its center as PackAlbedo
  /// keeps it (0: no texture there); empty when the model has no textures.
  std::vector<uint32_t> textureColours;
};

/// The frames of every view in settings.views (names from SnapshotViewNames;
/// others are skipped), each fitted as `render` fits its frames.
std::vector<SnapshotFrame> RenderSnapshot(const Scene& scene, const SnapshotSettings& settings);

}  // namespace termshade
