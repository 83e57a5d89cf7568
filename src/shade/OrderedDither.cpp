#include "shade/OrderedDither.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace termshade {

OrderedDither::OrderedDither(int order) {
  if (order < 1 || (1 << order) > kMaxSide) throw std::invalid_argument("dither order 1 to 4");
  side_ = 1 << order;
  mask_ = side_ - 1;
  // Bayer ranks by doubling: M(2n) = [4M, 4M + 2; 4M + 3, 4M + 1].
  std::array<int, kMaxSide * kMaxSide> rank{};  // row-major, kMaxSide a row; rank[0] = 0
  for (int n = 1; n < side_; n *= 2) {
    for (int y = n - 1; y >= 0; --y) {
      for (int x = n - 1; x >= 0; --x) {
        const int r = 4 * rank[static_cast<size_t>(y * kMaxSide + x)];
        rank[static_cast<size_t>(y * kMaxSide + x)] = r;
        rank[static_cast<size_t>(y * kMaxSide + x + n)] = r + 2;
        rank[static_cast<size_t>((y + n) * kMaxSide + x)] = r + 3;
        rank[static_cast<size_t>((y + n) * kMaxSide + x + n)] = r + 1;
      }
    }
  }
  for (int y = 0; y < side_; ++y) {
    for (int x = 0; x < side_; ++x) {
      thresholds_[static_cast<size_t>(y * kMaxSide + x)] =
          RankThreshold(rank[static_cast<size_t>(y * kMaxSide + x)], side_ * side_);
    }
  }
}

uint8_t OrderedDither::RankThreshold(int rank, int ranks) {
  // Between r and r + 1 inked of `ranks`: their geometric mean, where SSIM's
  // luminance term 2ab / (a^2 + b^2) is equal for both. sqrt is correctly
  // rounded in IEEE arithmetic, so every compiler gets the same integers.
  if (rank == 0) return static_cast<uint8_t>(255 / (2 * ranks));
  const long mean = std::lround(255.0 * std::sqrt(rank * (rank + 1.0)) / ranks);
  return static_cast<uint8_t>(std::min(mean, 254L));  // 255 inks every sample
}

SamplePattern OrderedDither::CellInk(const uint8_t* values, SamplePattern covered, SampleGrid grid,
                                     int col, int row) const {
  SamplePattern ink = 0;
  int lowest = 256;
  int lowestSample = 0;
  const int x0 = col * grid.across;
  const int y0 = row * grid.down;
  for (int j = 0; j < grid.down; ++j) {
    for (int i = 0; i < grid.across; ++i) {
      const int n = j * grid.across + i;
      if (((covered >> n) & 1U) == 0) continue;
      const int threshold = Threshold(x0 + i, y0 + j);
      ink |= static_cast<SamplePattern>(values[n] > threshold) << n;
      // Of equal lowest thresholds (braille's two tiles), the first in even
      // columns and the last in odd ones: a diagonal lattice of dots.
      if (threshold < lowest || (threshold == lowest && (col & 1) != 0)) {
        lowest = threshold;
        lowestSample = n;
      }
    }
  }
  if (ink == 0 && covered != 0) ink = SamplePattern{1} << lowestSample;
  return ink;
}

}  // namespace termshade
