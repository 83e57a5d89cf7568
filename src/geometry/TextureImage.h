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
  /// Where it was read when not where its name says: the file's name in the
  /// model's folder ("test.png" for "TEST.PNG", "wood.jpg" for "D:\art\wood.jpg").
  std::string readAs;

  bool Decoded() const { return widthTexels > 0 && heightTexels > 0; }
};

}  // namespace termshade
