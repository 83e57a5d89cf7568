#include "raster/SampleFrame.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace termshade {

void SampleFrame::Begin(int widthCells, int heightCells, SampleGrid grid) {
  widthCells_ = std::max(0, widthCells);
  heightCells_ = std::max(0, heightCells);
  grid_ = grid;
  perCell_ = static_cast<size_t>(grid.Count());
  const size_t cells = static_cast<size_t>(widthCells_) * heightCells_;
  // Padding: the sampled rasterizer reads and writes back whole vectors of lanes.
  faces_.resize(cells * perCell_ + kPaddingSamples);
  depth_.resize(cells * perCell_ + kPaddingSamples);
  touched_.assign(cells, 0);
}

size_t SampleFrame::NextTouched(size_t cell) const {
  const size_t count = touched_.size();
  while (cell + 8 <= count) {
    uint64_t flags = 0;
    std::memcpy(&flags, touched_.data() + cell, sizeof flags);
    if (flags != 0) return cell + static_cast<size_t>(std::countr_zero(flags) / 8);
    cell += 8;
  }
  while (cell < count && touched_[cell] == 0) ++cell;
  return cell;
}

void SampleFrame::CopyFrom(const CellBuffer& samples, const DepthBuffer* depth) {
  const int k = grid_.across, m = grid_.down;
  std::fill(touched_.begin(), touched_.end(), uint8_t{1});
  size_t n = 0;
  for (int row = 0; row < heightCells_; ++row) {
    for (int col = 0; col < widthCells_; ++col) {
      for (int j = 0; j < m; ++j) {
        for (int i = 0; i < k; ++i, ++n) {
          const size_t index = samples.Index(col * k + i, row * m + j);
          faces_[n] = samples.FaceNumbers()[index];
          depth_[n] = depth == nullptr ? 0.0F : depth->At(index);
        }
      }
    }
  }
}

void SampleFrame::CopyTo(CellBuffer& samples) const {
  const int k = grid_.across, m = grid_.down;
  if (!samples.FacesOnly() || samples.WidthCells() != widthCells_ * k ||
      samples.HeightCells() != heightCells_ * m) {
    samples.ResizeFacesOnly(widthCells_ * k, heightCells_ * m);
  }
  size_t cell = 0;
  for (int row = 0; row < heightCells_; ++row) {
    for (int col = 0; col < widthCells_; ++col, ++cell) {
      for (int j = 0; j < m; ++j) {
        for (int i = 0; i < k; ++i) {
          samples.FaceNumbers()[samples.Index(col * k + i, row * m + j)] =
              Touched(cell) ? faces_[cell * perCell_ + j * k + i] : 0U;
        }
      }
    }
  }
}

}  // namespace termshade
