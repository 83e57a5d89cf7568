#include "raster/CellBuffer.h"

#include <algorithm>

#include "shade/Utf8.h"

namespace termshade {

void CellBuffer::Resize(int widthCells, int heightCells) {
  widthCells_ = std::max(0, widthCells);
  heightCells_ = std::max(0, heightCells);
  facesOnly_ = false;
  const size_t count = static_cast<size_t>(widthCells_) * heightCells_;
  glyphs_.resize(count);
  faceNumbers_.resize(count);
  levels_.resize(count);
  intensities_.resize(count);
  backFaceNumbers_.resize(count);
  backLevels_.resize(count);
  backIntensities_.resize(count);
  foreAlbedos_.clear();
  backAlbedos_.clear();
  Clear();
}

void CellBuffer::UseAlbedos() {
  const size_t count = static_cast<size_t>(widthCells_) * heightCells_;
  foreAlbedos_.assign(count, 0U);
  backAlbedos_.assign(count, 0U);
}

void CellBuffer::ResizeFacesOnly(int widthCells, int heightCells) {
  widthCells_ = std::max(0, widthCells);
  heightCells_ = std::max(0, heightCells);
  facesOnly_ = true;
  faceNumbers_.resize(static_cast<size_t>(widthCells_) * heightCells_);
  glyphs_.clear();
  levels_.clear();
  intensities_.clear();
  backFaceNumbers_.clear();
  backLevels_.clear();
  backIntensities_.clear();
  foreAlbedos_.clear();
  backAlbedos_.clear();
  Clear();
}

void CellBuffer::Clear() {
  std::fill(faceNumbers_.begin(), faceNumbers_.end(), 0U);
  if (facesOnly_) return;
  std::fill(glyphs_.begin(), glyphs_.end(), U' ');
  std::fill(levels_.begin(), levels_.end(), int16_t{-1});
  std::fill(intensities_.begin(), intensities_.end(), uint8_t{0});
  std::fill(backFaceNumbers_.begin(), backFaceNumbers_.end(), 0U);
  std::fill(backLevels_.begin(), backLevels_.end(), int16_t{-1});
  std::fill(backIntensities_.begin(), backIntensities_.end(), uint8_t{0});
  DropAlbedos();
}

std::string CellBuffer::RowText(int row) const {
  std::string text;
  text.reserve(static_cast<size_t>(widthCells_));
  for (int col = 0; col < widthCells_; ++col) AppendUtf8(text, Glyph(col, row));
  return text;
}

}  // namespace termshade
