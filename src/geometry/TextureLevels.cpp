#include "geometry/TextureLevels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "geometry/SrgbCoding.h"

namespace termshade {
namespace {

// The next level: 2x2 blocks (1x2 or 2x1 where a side is already 1) averaged in linear light.
TextureImage Halve(const TextureImage& from) {
  TextureImage to;
  to.widthTexels = std::max<uint32_t>(1, from.widthTexels / 2);
  to.heightTexels = std::max<uint32_t>(1, from.heightTexels / 2);
  to.srgbTexels.resize(size_t{to.widthTexels} * to.heightTexels * 3);
  const uint32_t stepX = from.widthTexels > 1 ? 2 : 1, stepY = from.heightTexels > 1 ? 2 : 1;
  for (uint32_t y = 0; y < to.heightTexels; ++y) {
    for (uint32_t x = 0; x < to.widthTexels; ++x) {
      for (int k = 0; k < 3; ++k) {
        double sum = 0.0;
        for (uint32_t dy = 0; dy < stepY; ++dy) {
          for (uint32_t dx = 0; dx < stepX; ++dx) {
            const size_t at = (size_t{y * stepY + dy} * from.widthTexels + x * stepX + dx) * 3;
            sum += LinearOfSrgb8(from.srgbTexels[at + k]);
          }
        }
        to.srgbTexels[(size_t{y} * to.widthTexels + x) * 3 + k] =
            Srgb8OfLinear(sum / (stepX * stepY));
      }
    }
  }
  return to;
}

// The fractional part of a repeating coordinate, in [0, 1).
double Wrap(double t) {
  if (!std::isfinite(t)) return 0.0;
  const double f = t - std::floor(t);
  return f < 1.0 ? f : 0.0;
}

}  // namespace

TextureLevels::TextureLevels(TextureImage image) {
  if (!image.Decoded() ||
      image.srgbTexels.size() != size_t{image.widthTexels} * image.heightTexels * 3) {
    return;
  }
  levels_.push_back(std::move(image));
  levels_.back().problem.clear();
  while (levels_.back().widthTexels > 1 || levels_.back().heightTexels > 1) {
    levels_.push_back(Halve(levels_.back()));
  }
}

int TextureLevels::LevelFor(double footprintTexels) const {
  if (!(footprintTexels > 1.0)) return 0;
  const int level = static_cast<int>(std::floor(std::log2(std::min(footprintTexels, 1e9))));
  return std::clamp(level, 0, LevelCount() - 1);
}

Rgb TextureLevels::Sample(double u, double v, int level) const {
  const TextureImage& image = levels_[static_cast<size_t>(std::clamp(level, 0, LevelCount() - 1))];
  const uint32_t w = image.widthTexels, h = image.heightTexels;
  // Step 1: texel space, rows down from the top, centers at half texels.
  const double x = Wrap(u) * w - 0.5;
  const double y = (1.0 - Wrap(v)) * h - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  // A texel index repeated into [0, size) (the modulo only off the image).
  const auto repeated = [](double at, uint32_t size) {
    const auto i = static_cast<int64_t>(at);
    if (i >= 0 && i < int64_t{size}) return static_cast<uint32_t>(i);
    return static_cast<uint32_t>((i % size + size) % size);
  };
  const uint32_t xs[2] = {repeated(x0, w), repeated(x0 + 1, w)};
  const uint32_t ys[2] = {repeated(y0, h), repeated(y0 + 1, h)};
  // Step 2: the four texels weighted in linear light.
  const std::array<float, 256>& linear = LinearOfSrgb8Table();
  double sum[3] = {0, 0, 0};
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      const double weight = (i == 0 ? 1.0 - fx : fx) * (j == 0 ? 1.0 - fy : fy);
      const uint8_t* texel = image.srgbTexels.data() + (size_t{ys[j]} * w + xs[i]) * 3;
      for (int k = 0; k < 3; ++k) sum[k] += weight * linear[texel[k]];
    }
  }
  return Rgb{static_cast<float>(sum[0]), static_cast<float>(sum[1]), static_cast<float>(sum[2])};
}

}  // namespace termshade
