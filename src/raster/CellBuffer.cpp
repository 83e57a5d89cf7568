#include "raster/CellBuffer.h"

#include <algorithm>

namespace termshade {

void CellBuffer::Resize(int widthCells, int heightCells) {
  widthCells_ = std::max(0, widthCells);
  heightCells_ = std::max(0, heightCells);
  const size_t count = static_cast<size_t>(widthCells_) * heightCells_;
  glyphs_.resize(count);
  faceNumbers_.resize(count);
  levels_.resize(count);
  Clear();
}

void CellBuffer::Clear() {
  std::fill(glyphs_.begin(), glyphs_.end(), ' ');
  std::fill(faceNumbers_.begin(), faceNumbers_.end(), 0U);
  std::fill(levels_.begin(), levels_.end(), int16_t{-1});
}

std::string CellBuffer::RowText(int row) const {
  const auto begin = glyphs_.begin() + static_cast<std::ptrdiff_t>(Index(0, row));
  return {begin, begin + widthCells_};
}

}  // namespace termshade
