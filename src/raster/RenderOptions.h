#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "geometry/Vec3.h"
#include "raster/TriangleRasterizer.h"
#include "shade/Background.h"
#include "shade/GlyphMode.h"
#include "shade/Lighting.h"
#include "shade/ShadeRamp.h"

namespace termshade {

/// Hidden-surface methods (SPEC 5), the textbook's wire frame, and auto: the
/// cheapest exact one for the scene (cull for one convex closed solid, else zbuffer).
enum class Method { kZBuffer, kPainter, kCull, kWire, kAuto };

std::string_view MethodName(Method method);
std::optional<Method> ParseMethod(std::string_view name);
std::string_view ShadeModeName(ShadeMode mode);
std::optional<ShadeMode> ParseShadeMode(std::string_view name);

struct RenderOptions;
/// The sample grid a cell's glyph pattern is chosen on: the variant's, else the glyph mode's.
SampleGrid PatternSampleGrid(const RenderOptions& options);
/// The sample grid a frame is drawn with: the pattern grid, each part of it
/// sampled sub.across x sub.down times where the colours are an average
/// (the block modes with two colours; see GlyphStage).
SampleGrid FrameSampleGrid(const RenderOptions& options);

enum class HierarchyUse { kWhenFaster, kAlways, kNever };

/// Variants of the pipeline kept to measure the product against
/// (termshade bench); the defaults are the product.
struct RenderVariant {
  DepthFormat depthFormat = DepthFormat::kFloatInverseZ;
  bool scanline = false;       ///< the classic scanline rasterizer instead of edge functions
  bool floatGeometry = false;  ///< transform and project in float instead of double
  /// Samples per cell, k across by m down; 0 x 0: the glyph mode's own grid.
  /// More samples than the mode's grid suit ramp only (glyph from the mean intensity).
  SampleGrid samples{0, 0};
  /// zbuffer and cull draw cluster by cluster (src/raster/ClusterStage); false:
  /// the plain face-by-face loop, one thread, the reference the tests compare with.
  bool clusters = true;
  /// Whole clusters that face away or cover no sample are skipped (exact).
  bool clusterCulling = true;
  /// One-sample zbuffer and cull frames of a scene with a hierarchy
  /// (Scene::hierarchy) cast a ray a sample through it (src/raster/RayCastStage)
  /// where that is exact for the view: kWhenFaster when the scene has many
  /// triangles a sample and the rays are measured quicker (SurfacePassChoice), kAlways
  /// whatever the count (tests, bench); else cluster by cluster. The same
  /// frame either way.
  HierarchyUse hierarchy = HierarchyUse::kWhenFaster;
  /// Several samples a cell on one thread: drawn cell by cell into the glyph
  /// stage's layout (src/raster/SampledRasterizer); false: drawn as a one-sample
  /// frame k x m times the size, then reordered. The same samples either way.
  bool sampledRasterizer = true;
  /// The sampled rasterizer's 2x4 cells eight lanes at a time (AVX2) where the
  /// CPU has them; false: four at a time (SSE2). The same samples either way.
  bool wideLanes = true;
};

/// Everything about how a frame is drawn that is not the camera.
struct RenderOptions {
  Method method = Method::kZBuffer;
  ShadeMode shade = ShadeMode::kContrast;
  ShadeRamp ramp;
  bool cullBackFaces = true;
  Vec3 sunEye = DefaultSunEye();
  double ambient = kDefaultAmbient;
  RenderVariant variant;
  GlyphMode glyphs = GlyphMode::kRamp;  ///< SPEC 11
  /// The cells' fg and bg colours are shown (ansi dump, colour terminal): the
  /// two-colour modes split each cell's samples by shade; otherwise their glyph
  /// is the coverage pattern and the fg the covered samples' mean shade.
  bool twoColour = false;
  /// Faces with a decoded base-colour texture take their colours from it,
  /// sample by sample (TextureStage), where colours are shown (twoColour);
  /// false: their face colour.
  bool textures = true;
  /// The terminal's background. Without colours (twoColour false) ink is the
  /// terminal's foreground: on a light background it is dark, so a face's
  /// ink follows its darkness instead of its brightness (no negative image).
  Background background = Background::kDark;
  /// False: the depth buffer need not hold the frame's depth afterwards (only
  /// the json dump reads it), so methods that need no depth test skip it.
  bool keepDepth = true;
  /// Threads drawing the frame: 0 every core; big scenes only (ClusterStage).
  /// The frame is the same whatever the count.
  int threads = 0;
  /// Scenes with fewer triangles draw on one thread: waking threads costs more.
  size_t threadsFromTriangles = 20000;
};

}  // namespace termshade
