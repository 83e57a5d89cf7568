#pragma once

#include <algorithm>
#include <vector>

namespace termshade {

/// Per-cell w = 1 / (-z_eye) of the nearest surface so far (0 = nothing yet).
/// Larger w is nearer; w is linear in screen space, so it is what gets interpolated.
class DepthBuffer {
 public:
  void Resize(int widthCells, int heightCells) {
    widthCells_ = widthCells;
    heightCells_ = heightCells;
    w_.resize(static_cast<size_t>(widthCells) * heightCells);
    Clear();
  }
  void Clear() { std::fill(w_.begin(), w_.end(), 0.0F); }

  int WidthCells() const { return widthCells_; }
  int HeightCells() const { return heightCells_; }
  float& At(size_t index) { return w_[index]; }
  float At(size_t index) const { return w_[index]; }
  /// -z_eye of the stored surface, 0 for background.
  double DepthAt(size_t index) const { return w_[index] > 0.0F ? 1.0 / w_[index] : 0.0; }

 private:
  int widthCells_ = 0;
  int heightCells_ = 0;
  std::vector<float> w_;
};

}  // namespace termshade
