#include "shade/OrderedDither.h"

#include <algorithm>
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
  // Rank r's threshold: floor((r + 1/2) 255 / side^2), so 0 inks nothing and
  // 255 everything, and a shade v exceeds round(v side^2 / 255) of them (ties down).
  const int cells = side_ * side_;
  for (int y = 0; y < side_; ++y) {
    for (int x = 0; x < side_; ++x) {
      const int r = rank[static_cast<size_t>(y * kMaxSide + x)];
      thresholds_[static_cast<size_t>(y * kMaxSide + x)] =
          static_cast<uint8_t>(((2 * r + 1) * 255) / (2 * cells));
    }
  }
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
      if (threshold < lowest) {
        lowest = threshold;
        lowestSample = n;
      }
    }
  }
  if (ink == 0 && covered != 0) ink = SamplePattern{1} << lowestSample;
  return ink;
}

}  // namespace termshade
