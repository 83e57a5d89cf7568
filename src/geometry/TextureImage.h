#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace termshade {

/// Longest side of a texture as loaded: larger images are reduced at load (a
/// terminal view never shows more texels than this across a face).
inline constexpr uint32_t kMaxTextureSideTexels = 1024;

/// A decoded base-colour texture: rows top to bottom, 3 bytes (sRGB) a texel;
/// empty, with the reason in `problem`, when it could not be read or decoded.
struct TextureImage {
  uint32_t widthTexels = 0;
  uint32_t heightTexels = 0;
  std::vector<uint8_t> srgbTexels;
  std::string problem;

  bool Decoded() const { return widthTexels > 0 && heightTexels > 0; }
};

}  // namespace termshade
