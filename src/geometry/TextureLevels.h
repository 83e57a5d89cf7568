#pragma once

#include <cstdint>
#include <vector>

#include "geometry/Rgb.h"
#include "geometry/TextureImage.h"

namespace termshade {

/// A texture as frames sample it: the image and its halvings down to one
/// texel (each texel the mean of four in linear light), kept as sRGB bytes.
/// Lookups repeat the image in both directions (glTF's default wrap).
class TextureLevels {
 public:
  TextureLevels() = default;
  explicit TextureLevels(TextureImage image);

  bool Empty() const { return levels_.empty(); }
  int LevelCount() const { return static_cast<int>(levels_.size()); }
  uint32_t WidthTexels() const { return Empty() ? 0 : levels_[0].widthTexels; }
  uint32_t HeightTexels() const { return Empty() ? 0 : levels_[0].heightTexels; }
  /// Bytes of a level's texels.
  size_t LevelBytes(int level) const {
    return levels_[static_cast<size_t>(level)].srgbTexels.size();
  }
  /// The full-size image, as loaded.
  const TextureImage& Image() const { return levels_[0]; }

  /// The level whose texels are about `footprintTexels` full-size texels wide (0: full size).
  int LevelFor(double footprintTexels) const;
  /// The linear-light colour at texture coordinates (u right, v up, 0..1 over
  /// the image, repeating) on a level, bilinear between its four nearest
  /// texels; non-finite coordinates read the origin.
  Rgb Sample(double u, double v, int level) const;

 private:
  std::vector<TextureImage> levels_;
};

}  // namespace termshade
