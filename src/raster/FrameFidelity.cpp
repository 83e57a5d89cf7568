#include "raster/FrameFidelity.h"

#include <algorithm>
#include <cmath>

#include "geometry/RayCast.h"
#include "geometry/ViewingTransform.h"
#include "raster/TextureSample.h"
#include "shade/BlockGlyphs.h"
#include "shade/CellColour.h"

namespace termshade {
namespace {

constexpr int kAcross = kFidelityPxPerCellAcross, kDown = kFidelityPxPerCellDown;

std::vector<float> GaussianKernel(double sigmaPx) {
  const int radius = static_cast<int>(std::ceil(3.0 * sigmaPx));
  std::vector<float> kernel(static_cast<size_t>(2 * radius + 1));
  double sum = 0.0;
  for (int i = -radius; i <= radius; ++i) sum += std::exp(-0.5 * i * i / (sigmaPx * sigmaPx));
  for (int i = -radius; i <= radius; ++i) {
    kernel[static_cast<size_t>(i + radius)] =
        static_cast<float>(std::exp(-0.5 * i * i / (sigmaPx * sigmaPx)) / sum);
  }
  return kernel;
}

// Separable convolution; pixels beyond the border repeat the border.
std::vector<float> Blur(const std::vector<float>& image, int width, int height, double sigmaPx) {
  const std::vector<float> kernel = GaussianKernel(sigmaPx);
  const int radius = static_cast<int>(kernel.size() / 2);
  std::vector<float> across(image.size()), out(image.size());
  for (int y = 0; y < height; ++y) {
    const float* row = &image[static_cast<size_t>(y) * width];
    for (int x = 0; x < width; ++x) {
      float sum = 0.0F;
      for (int i = -radius; i <= radius; ++i) {
        sum += kernel[static_cast<size_t>(i + radius)] * row[std::clamp(x + i, 0, width - 1)];
      }
      across[static_cast<size_t>(y) * width + x] = sum;
    }
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float sum = 0.0F;
      for (int i = -radius; i <= radius; ++i) {
        sum += kernel[static_cast<size_t>(i + radius)] *
               across[static_cast<size_t>(std::clamp(y + i, 0, height - 1)) * width + x];
      }
      out[static_cast<size_t>(y) * width + x] = sum;
    }
  }
  return out;
}

// The luminance of the texel a pixel's ray sees on a textured face (1 on
// other faces): at the pixel's exact coordinates, on the level its footprint
// (one pixel right and down) asks for.
float TextureLuminance(const Scene& scene, const FrameView& view, uint32_t face, int xPx, int yPx) {
  if (scene.textures.FaceTexture(face) == nullptr) return 1.0F;
  int level = -1;
  const FrameStep pixel{1.0 / kAcross, 1.0 / kDown};
  const Rgb albedo =
      TexturedAlbedoAt(scene, view, face, (xPx + 0.5) / kAcross, (yPx + 0.5) / kDown, pixel, level);
  return static_cast<float>(LinearLuminance(albedo));
}

// A side's albedo luminance: 1 where the face's colour serves (albedo 0).
float AlbedoLuminance(uint32_t packed) {
  return packed == 0 ? 1.0F : static_cast<float>(LinearLuminance(UnpackAlbedo(packed)));
}

std::vector<float> Product(const std::vector<float>& a, const std::vector<float>& b) {
  std::vector<float> out(a.size());
  for (size_t i = 0; i < a.size(); ++i) out[i] = a[i] * b[i];
  return out;
}

}  // namespace

InkImage ExactImage(const Scene& scene, const Camera& camera, const RenderOptions& options,
                    int widthCells, int heightCells, double inkRange) {
  ReferenceRayCaster exact(scene, camera, options.cullBackFaces);
  exact.BinFaces(widthCells, heightCells);
  const Mat4 eyeFromWorld = EyeFromWorld(camera.view);
  const Vec3 eyeWorld = EyePositionWorld(camera.view);
  // Lambert intensity per face, once.
  std::vector<float> faceIntensity(scene.FaceCount());
  for (size_t f = 0; f < scene.FaceCount(); ++f) {
    const FacePlane& plane = scene.facePlanesWorld[f];
    const Vec3 nEye =
        TransformDirection(eyeFromWorld, plane.FacesPoint(eyeWorld) ? plane.normal : -plane.normal);
    faceIntensity[f] =
        static_cast<float>(inkRange * LambertIntensity(Dot(nEye, options.sunEye), options.ambient));
  }
  const bool textured = options.textures && scene.textures.Any();
  const FrameView view{camera, eyeFromWorld, eyeWorld, {}};
  InkImage image{widthCells * kAcross, heightCells * kDown, {}};
  image.pixels.assign(static_cast<size_t>(image.widthPx) * image.heightPx, 0.0F);
  for (int y = 0; y < image.heightPx; ++y) {
    for (int x = 0; x < image.widthPx; ++x) {
      const RaySample hit = exact.Cast((x + 0.5) / kAcross, (y + 0.5) / kDown);
      if (hit.faceNumber == 0) continue;
      const uint32_t face = hit.faceNumber - 1;
      image.pixels[static_cast<size_t>(y) * image.widthPx + x] =
          faceIntensity[face] * (textured ? TextureLuminance(scene, view, face, x, y) : 1.0F);
    }
  }
  return image;
}

InkImage GlyphImage(const CellBuffer& cells, const GlyphInkTable& table, bool colour) {
  InkImage image{cells.WidthCells() * kAcross, cells.HeightCells() * kDown, {}};
  image.pixels.assign(static_cast<size_t>(image.widthPx) * image.heightPx, 0.0F);
  for (int row = 0; row < cells.HeightCells(); ++row) {
    for (int col = 0; col < cells.WidthCells(); ++col) {
      const InkMap* ink = table.Find(cells.Glyph(col, row));
      if (ink == nullptr || cells.FaceNumber(col, row) == 0) continue;
      const float fore =
          colour ? cells.Intensity(col, row) / 255.0F * AlbedoLuminance(cells.ForeAlbedo(col, row))
                 : 1.0F;
      const float back = colour ? cells.BackIntensity(col, row) / 255.0F *
                                      AlbedoLuminance(cells.BackAlbedo(col, row))
                                : 0.0F;
      for (int j = 0; j < kDown; ++j) {
        for (int i = 0; i < kAcross; ++i) {
          const float a = (*ink)[static_cast<size_t>(j * kAcross + i)] / 255.0F;
          image.pixels[static_cast<size_t>(row * kDown + j) * image.widthPx + col * kAcross + i] =
              a * fore + (1.0F - a) * back;
        }
      }
    }
  }
  return image;
}

double InkRange(const RenderOptions& options, bool colour, const GlyphInkTable& table) {
  double range = 0.0;
  switch (options.glyphs) {
    case GlyphMode::kRamp:
      for (int level = 0; level < options.ramp.LevelCount(); ++level) {
        range = std::max(range, table.MeanInk(options.ramp.Glyph(level)));
      }
      return range;
    case GlyphMode::kAscii:
      for (char32_t c = U'!'; c <= U'~'; ++c) range = std::max(range, table.MeanInk(c));
      return range;
    case GlyphMode::kBraille:
      return table.MeanInk(PatternGlyph(GlyphMode::kBraille, 255));
    default:
      return colour ? 1.0 : table.MeanInk(U'\u2588');
  }
}

Fidelity CompareImages(const InkImage& exact, const InkImage& frame, double range) {
  const int w = exact.widthPx, h = exact.heightPx;
  const double sigmaPx = 0.5 * kAcross;
  const std::vector<float> a = Blur(exact.pixels, w, h, sigmaPx);
  const std::vector<float> b = Blur(frame.pixels, w, h, sigmaPx);
  // Only where the model is: pixels that either blurred image reaches, so the
  // empty border around a small model does not count as perfectly drawn.
  const float reached = static_cast<float>(1e-3 * range);
  std::vector<char> inside(a.size());
  for (size_t i = 0; i < a.size(); ++i) inside[i] = a[i] > reached || b[i] > reached;
  Fidelity result;
  double squared = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (!inside[i]) continue;
    squared += double(a[i] - b[i]) * (a[i] - b[i]);
    ++count;
  }
  if (count == 0) return {0.0, 1.0};  // nothing drawn, nothing to draw
  result.mse = squared / count;
  // SSIM: local means, variances and covariance under an 11-tap sigma 1.5 window.
  constexpr double kWindowSigma = 1.5;
  const std::vector<float> muA = Blur(a, w, h, kWindowSigma), muB = Blur(b, w, h, kWindowSigma);
  const std::vector<float> aa = Blur(Product(a, a), w, h, kWindowSigma);
  const std::vector<float> bb = Blur(Product(b, b), w, h, kWindowSigma);
  const std::vector<float> ab = Blur(Product(a, b), w, h, kWindowSigma);
  const double c1 = (0.01 * range) * (0.01 * range), c2 = (0.03 * range) * (0.03 * range);
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (!inside[i]) continue;
    const double ma = muA[i], mb = muB[i];
    const double va = aa[i] - ma * ma, vb = bb[i] - mb * mb, cov = ab[i] - ma * mb;
    sum += ((2 * ma * mb + c1) * (2 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
  }
  result.ssim = sum / count;
  return result;
}

double ChangedShare(const CellBuffer& before, const CellBuffer& after, bool colour) {
  const auto albedosDiffer = [&](size_t i) {
    const int col = static_cast<int>(i % before.WidthCells());
    const int row = static_cast<int>(i / before.WidthCells());
    return !AlbedosAlike(before.ForeAlbedo(col, row), after.ForeAlbedo(col, row),
                         kAlbedoStepSeen) ||
           !AlbedosAlike(before.BackAlbedo(col, row), after.BackAlbedo(col, row), kAlbedoStepSeen);
  };
  long shown = 0, changed = 0;
  for (size_t i = 0; i < before.Glyphs().size(); ++i) {
    if (before.FaceNumbers()[i] == 0 && after.FaceNumbers()[i] == 0) continue;
    ++shown;
    bool differs = before.Glyphs()[i] != after.Glyphs()[i];
    if (colour) {
      differs = differs || before.Levels()[i] != after.Levels()[i] ||
                before.BackLevels()[i] != after.BackLevels()[i] || albedosDiffer(i);
    }
    changed += differs ? 1 : 0;
  }
  return shown > 0 ? double(changed) / shown : 0.0;
}

}  // namespace termshade
