#pragma once

#include <array>
#include <cstdint>

#include "shade/BlockGlyphs.h"
#include "shade/GlyphMode.h"

namespace termshade {

/// A fixed screen-space threshold pattern (ordered dither, a Bayer matrix):
/// the sample at (x, y) of the frame's sample grid is inked when its shade
/// exceeds the threshold there. A threshold depends on the position alone, so
/// a point of the screen keeps it while the model turns, and a flat shade v
/// inks round(v side^2 / 255) samples of every side x side tile.
class OrderedDither {
 public:
  static constexpr int kMaxSide = 16;

  /// The Bayer matrix of side 2^order, order 1 to 4 (2x2 to 16x16).
  explicit OrderedDither(int order);

  int Side() const { return side_; }
  /// The threshold 0..254 at sample (x, y), x and y >= 0 (the pattern repeats).
  uint8_t Threshold(int x, int y) const {
    return thresholds_[static_cast<size_t>((y & mask_) * kMaxSide + (x & mask_))];
  }
  /// Whether a shade of `intensity` (0..255) is inked at sample (x, y).
  bool Inks(uint8_t intensity, int x, int y) const { return intensity > Threshold(x, y); }

  /// The inked samples of a cell at (col, row) of grid.across x grid.down
  /// samples, whose intensities are `values` (row-major) and whose covered
  /// samples are `covered`: those whose shade exceeds their threshold. A cell
  /// with a covered sample is never blank (SPEC 4: the darkest face keeps its
  /// silhouette): if no shade exceeds its threshold, the covered sample with
  /// the lowest threshold is inked alone.
  SamplePattern CellInk(const uint8_t* values, SamplePattern covered, SampleGrid grid, int col,
                        int row) const;

 private:
  int side_ = 0;
  int mask_ = 0;
  std::array<uint8_t, kMaxSide * kMaxSide> thresholds_{};  ///< row-major, kMaxSide a row
};

}  // namespace termshade
