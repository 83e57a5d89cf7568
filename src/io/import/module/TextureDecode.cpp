#include "io/import/module/TextureDecode.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geometry/SrgbCoding.h"
#include "io/read/RegularFile.h"

namespace termshade {
namespace {

// Decoding keeps the file's texels (up to 8 bytes each for 16-bit images),
// stb's own buffers and our 3-byte copy. (In the import helper the data limit
// also stops stb, which then fails cleanly: "outofmem".)
constexpr double kDecodeBytesPerTexel = 16.0;

// stb's reason for the last failure (it may have none).
std::string StbReason() {
  const char* reason = stbi_failure_reason();
  return reason != nullptr ? reason : "no reason given";
}

TextureImage Refused(std::string reason) {
  TextureImage image;
  image.problem = std::move(reason);
  return image;
}

// The reason to refuse an image of these dimensions, or empty.
std::string SizeProblem(uint64_t widthTexels, uint64_t heightTexels, size_t maxBytes) {
  if (widthTexels == 0 || heightTexels == 0) return "an image without texels";
  const double needed =
      static_cast<double>(widthTexels) * static_cast<double>(heightTexels) * kDecodeBytesPerTexel;
  if (needed > static_cast<double>(maxBytes)) {
    return std::to_string(widthTexels) + "x" + std::to_string(heightTexels) + " texels need " +
           FormatBytes(needed) + " to decode, more than the memory budget leaves for textures";
  }
  return "";
}

}  // namespace

TextureImage ReduceTexture(const uint8_t* rgb, uint32_t widthTexels, uint32_t heightTexels,
                           uint32_t maxSideTexels) {
  const uint32_t longer = std::max(widthTexels, heightTexels);
  const uint32_t factor = std::max<uint32_t>(1, (longer + maxSideTexels - 1) / maxSideTexels);
  TextureImage out;
  out.widthTexels = (widthTexels + factor - 1) / factor;
  out.heightTexels = (heightTexels + factor - 1) / factor;
  if (factor == 1) {
    out.srgbTexels.assign(rgb, rgb + size_t{widthTexels} * heightTexels * 3);
    return out;
  }
  // Step: each block of factor x factor texels (cut at the edges) averaged in linear light.
  out.srgbTexels.resize(size_t{out.widthTexels} * out.heightTexels * 3);
  for (uint32_t y = 0; y < out.heightTexels; ++y) {
    for (uint32_t x = 0; x < out.widthTexels; ++x) {
      double sum[3] = {0, 0, 0};
      int count = 0;
      for (uint32_t sy = y * factor; sy < std::min(heightTexels, (y + 1) * factor); ++sy) {
        for (uint32_t sx = x * factor; sx < std::min(widthTexels, (x + 1) * factor); ++sx) {
          const uint8_t* texel = rgb + (size_t{sy} * widthTexels + sx) * 3;
          for (int k = 0; k < 3; ++k) sum[k] += LinearOfSrgb8(texel[k]);
          ++count;
        }
      }
      uint8_t* to = out.srgbTexels.data() + (size_t{y} * out.widthTexels + x) * 3;
      for (int k = 0; k < 3; ++k) to[k] = Srgb8OfLinear(sum[k] / count);
    }
  }
  return out;
}

TextureImage DecodeTexture(std::string_view fileBytes, size_t maxBytes) {
  if (fileBytes.empty()) return Refused("an empty file");
  if (fileBytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) {
    return Refused("a file too large to decode");
  }
  const auto* bytes = reinterpret_cast<const stbi_uc*>(fileBytes.data());
  const int length = static_cast<int>(fileBytes.size());
  // Step 1: the dimensions, from the header alone.
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_memory(bytes, length, &width, &height, &channels) == 0) {
    return Refused("not an image stb_image decodes (" + StbReason() + ")");
  }
  if (std::string problem = SizeProblem(static_cast<uint64_t>(std::max(width, 0)),
                                        static_cast<uint64_t>(std::max(height, 0)), maxBytes);
      !problem.empty()) {
    return Refused(problem);
  }
  // Step 2: the texels, as RGB.
  const std::unique_ptr<stbi_uc, void (*)(void*)> texels(
      stbi_load_from_memory(bytes, length, &width, &height, &channels, 3), stbi_image_free);
  if (!texels || width <= 0 || height <= 0) {
    return Refused("cannot decode (" + StbReason() + ")");
  }
  return ReduceTexture(texels.get(), static_cast<uint32_t>(width), static_cast<uint32_t>(height),
                       kMaxTextureSideTexels);
}

TextureImage TextureFromBgra(const uint8_t* texels, uint32_t widthTexels, uint32_t heightTexels,
                             size_t maxBytes) {
  if (std::string problem = SizeProblem(widthTexels, heightTexels, maxBytes); !problem.empty()) {
    return Refused(problem);
  }
  std::vector<uint8_t> rgb(size_t{widthTexels} * heightTexels * 3);
  for (size_t i = 0; i < size_t{widthTexels} * heightTexels; ++i) {
    rgb[i * 3 + 0] = texels[i * 4 + 2];
    rgb[i * 3 + 1] = texels[i * 4 + 1];
    rgb[i * 3 + 2] = texels[i * 4 + 0];
  }
  return ReduceTexture(rgb.data(), widthTexels, heightTexels, kMaxTextureSideTexels);
}

}  // namespace termshade
