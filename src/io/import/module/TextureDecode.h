#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "geometry/TextureImage.h"

// Inside the Assimp import module only (the helper process decodes images:
// decoders are hostile territory, docs/reliability.md).
namespace termshade {

/// Decodes an image file's bytes (PNG, JPEG, TGA, BMP, GIF, PSD, HDR, PNM
/// through stb_image) to 8-bit sRGB, reduced to at most
/// kMaxTextureSideTexels a side. Its dimensions are read and checked against
/// maxBytes before anything is decoded; a refusal or a decoding failure
/// gives an empty image with the reason.
TextureImage DecodeTexture(std::string_view fileBytes, size_t maxBytes);

/// The same for texels already decoded: rows top to bottom, 4 bytes a texel
/// in the order b, g, r, a (Assimp's aiTexel of an embedded image).
TextureImage TextureFromBgra(const uint8_t* texels, uint32_t widthTexels, uint32_t heightTexels,
                             size_t maxBytes);

/// Reduces an RGB image (3 bytes a texel) by a whole factor so that its
/// longer side is at most maxSideTexels, averaging blocks in linear light.
TextureImage ReduceTexture(const uint8_t* rgb, uint32_t widthTexels, uint32_t heightTexels,
                           uint32_t maxSideTexels);

}  // namespace termshade
