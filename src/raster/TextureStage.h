#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/Rgb.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/FramePlan.h"
#include "raster/SampleFrame.h"

namespace termshade {

/// The stage after the glyphs when the frame's faces have textures: each
/// cell's foreground and background albedo (CellBuffer::ForeAlbedo) is the
/// mean, in linear light, of the texels its samples of that face see, times
/// the face's colour. A sample's texture coordinates are exact: its ray from
/// the eye meets its face's plane, and the point's barycentric coordinates in
/// the face's triangle that holds it weigh the corners' coordinates
/// (perspective-correct by construction). The texture level follows the
/// sample's footprint (the coordinates of its right and lower neighbours).
/// In the block modes a cell of textured samples may then show the texture's
/// detail inside it (SplitTexturedCell).
class TextureStage {
 public:
  /// A frame of several samples a cell (seen from the sample camera), the
  /// intensity of each face seen, and how its glyphs were made.
  struct Samples {
    const SampleFrame& frame;
    std::span<const uint8_t> faceIntensities;
    const GlyphPlan& glyphs;
  };
  /// One sample a cell: the cells are the samples.
  void Apply(const Scene& scene, const FrameView& view, CellBuffer& cells) const;
  void Apply(const Scene& scene, const FrameView& view, const Samples& samples, CellBuffer& cells);

 private:
  std::vector<Rgb> albedos_;  ///< one cell's samples' albedos (kept between cells)
};

}  // namespace termshade
