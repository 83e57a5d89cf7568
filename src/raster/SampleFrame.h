#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "raster/CellBuffer.h"
#include "raster/DepthBuffer.h"
#include "shade/GlyphMode.h"

namespace termshade {

/// A frame of k x m samples a cell, stored cell by cell: cell c's samples
/// are [c k m, (c + 1) k m), row-major inside the cell, each with its face
/// number (0 = background) and w = 1/(-z_eye) (0 = nothing). A cell no
/// triangle reached this frame is not touched: its samples are background
/// and are neither cleared nor read (a frame clears only the flags).
class SampleFrame {
 public:
  /// Samples past the last cell that may be read and written back unchanged.
  static constexpr size_t kPaddingSamples = 8;
  /// Sizes the frame (keeping capacity) and marks every cell untouched.
  void Begin(int widthCells, int heightCells, SampleGrid grid);

  int WidthCells() const { return widthCells_; }
  int HeightCells() const { return heightCells_; }
  SampleGrid Grid() const { return grid_; }
  size_t CellCount() const { return touched_.size(); }
  bool Touched(size_t cell) const { return touched_[cell] != 0; }
  /// The first touched cell at or after `cell` (eight flags a load), or CellCount().
  size_t NextTouched(size_t cell) const;

  /// The cell's samples; valid only for a touched cell.
  std::span<const uint32_t> Faces(size_t cell) const {
    return {faces_.data() + cell * perCell_, perCell_};
  }
  std::span<const float> Depths(size_t cell) const {
    return {depth_.data() + cell * perCell_, perCell_};
  }

  /// Marks the cell touched, its samples background, the first time in a frame.
  void Touch(size_t cell) {
    if (touched_[cell] != 0) return;
    touched_[cell] = 1;
    for (size_t n = 0; n < perCell_; ++n) {
      faces_[cell * perCell_ + n] = 0;
      depth_[cell * perCell_ + n] = 0.0F;
    }
  }
  uint32_t* FaceData() { return faces_.data(); }
  /// One flag a cell (1: touched); a writer setting one sets the cell's samples to background.
  uint8_t* TouchedData() { return touched_.data(); }
  float* DepthData() { return depth_.data(); }

  /// Copies a row-major sample frame (a one-sample CellBuffer at k x m times the
  /// cells, with its depth unless null) in, every cell touched.
  void CopyFrom(const CellBuffer& samples, const DepthBuffer* depth);
  /// The samples as a row-major one-sample frame of faces (the json dump's order).
  void CopyTo(CellBuffer& samples) const;

 private:
  int widthCells_ = 0;
  int heightCells_ = 0;
  SampleGrid grid_;
  size_t perCell_ = 1;
  std::vector<uint32_t> faces_;
  std::vector<float> depth_;
  std::vector<uint8_t> touched_;
};

}  // namespace termshade
