#pragma once

#include <array>
#include <cstdint>

#include "shade/BlockGlyphs.h"
#include "shade/GlyphMode.h"

namespace termshade {

/// A fixed screen-space threshold pattern (ordered dither, a Bayer matrix):
/// the sample at (x, y) of the frame's sample grid is inked when its shade
/// exceeds the threshold there. A threshold depends on the position alone, so
/// a point of the screen keeps it while the model turns. Rank r of side^2
/// inks above 255 sqrt(r (r + 1)) / side^2 (the geometric mean of r and r + 1
/// inked; rank 0 above half the first level), so a flat shade inks the level
/// nearest it by SSIM's luminance term in every side x side tile.
class OrderedDither {
 public:
  static constexpr int kMaxSide = 16;

  /// The Bayer matrix of side 2^order, order 1 to 4 (2x2 to 16x16).
  explicit OrderedDither(int order);

  int Side() const { return side_; }
  /// The threshold of rank `rank` of `ranks` (ranks >= 1, 0 <= rank < ranks).
  static uint8_t RankThreshold(int rank, int ranks);
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
  /// the lowest threshold is inked alone; of several, the first in even
  /// columns and the last in odd ones (braille's one dot a cell then falls
  /// in the top and bottom tile by turns: a lattice repeating every 11 px
  /// on the diagonal, not 16 px down).
  SamplePattern CellInk(const uint8_t* values, SamplePattern covered, SampleGrid grid, int col,
                        int row) const;

 private:
  int side_ = 0;
  int mask_ = 0;
  std::array<uint8_t, kMaxSide * kMaxSide> thresholds_{};  ///< row-major, kMaxSide a row
};

}  // namespace termshade
