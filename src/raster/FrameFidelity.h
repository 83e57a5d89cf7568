#pragma once

#include <vector>

#include "geometry/Camera.h"
#include "geometry/Scene.h"
#include "raster/CellBuffer.h"
#include "raster/RenderOptions.h"
#include "shade/GlyphInk.h"

namespace termshade {

/// A grey image of a frame, 8 x 16 pixels a cell, row-major, values 0..1.
struct InkImage {
  int widthPx = 0;
  int heightPx = 0;
  std::vector<float> pixels;
};

constexpr int kFidelityPxPerCellAcross = kInkColumns;
constexpr int kFidelityPxPerCellDown = kInkRows;

/// The exact image of SPEC 12: a double-precision ray cast (SPEC 8) at the
/// center of each of 8 x 16 pixels a cell, Lambert intensity of the face hit
/// (its normal turned towards the eye; background 0), times inkRange. With
/// options.textures, a textured face's intensity is also times the relative
/// luminance of its texel at the pixel (exact coordinates, bilinear on the
/// level of the pixel's footprint, linear light).
InkImage ExactImage(const Scene& scene, const Camera& camera, const RenderOptions& options,
                    int widthCells, int heightCells, double inkRange);

/// The frame drawn back into pixels: each cell's glyph ink map (from `table`;
/// a glyph it lacks counts as blank) blends fg and bg intensity, each times
/// the relative luminance of the side's texture albedo where it has one.
/// Without colour the ink is the terminal's full-intensity fg on a black bg.
InkImage GlyphImage(const CellBuffer& cells, const GlyphInkTable& table, bool colour);

/// The brightest mean ink a mode's glyphs reach: what the exact image is scaled
/// to (1 for the two-colour block modes with colour, '@' for ASCII, ...).
double InkRange(const RenderOptions& options, bool colour, const GlyphInkTable& table);

struct Fidelity {
  double mse = 0.0;   ///< mean squared difference after the blur, in intensity^2
  double ssim = 0.0;  ///< mean SSIM after the blur (Wang et al. 2004; 11-tap window, sigma 1.5 px)
};

/// Blurs both images by a Gaussian of sigma = half a cell width (4 px) and
/// compares them over the pixels either blurred image reaches (above 1/1000 of
/// the range: the model's footprint, not the empty border); `range` is the
/// images' dynamic range (SSIM's L).
Fidelity CompareImages(const InkImage& exact, const InkImage& frame, double range);

/// Share of cells, among those showing a face in either frame, whose glyph or
/// colours (shade levels; texture colours by more than kAlbedoStepSeen)
/// differ between two frames of the same size.
double ChangedShare(const CellBuffer& before, const CellBuffer& after, bool colour);

}  // namespace termshade
