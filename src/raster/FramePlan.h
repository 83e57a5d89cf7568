#pragma once

#include <cstdint>
#include <memory>

#include "geometry/Camera.h"
#include "geometry/ClipPolygon.h"
#include "geometry/Mat4.h"
#include "geometry/RayBvh.h"
#include "geometry/Scene.h"
#include "geometry/Vec3.h"
#include "raster/ClusterStage.h"
#include "raster/RenderOptions.h"
#include "raster/TriangleRasterizer.h"
#include "shade/GlyphMode.h"
#include "shade/Lighting.h"
#include "shade/ShadeRamp.h"

namespace termshade {

/// The method actually drawn: auto becomes cull or zbuffer for the scene.
Method ResolvedMethod(const Scene& scene, Method method);

/// The camera whose one-sample cells are the samples of `camera`'s cells on a
/// k x m grid: u' = k u, v' = m v (d and cx scale by k, cy by m, the aspect by k / m).
Camera SampleCamera(const Camera& camera, SampleGrid grid);

/// Where a frame's surfaces are drawn.
enum class SurfaceTarget {
  kCells,        ///< one sample a cell: the frame's own cells and depth
  kSampleCells,  ///< several: a one-sample frame k x m times the cells, then reordered
  kSampleFrame,  ///< several, on one thread: cell by cell into the samples (SampledRasterizer)
};

/// The pass that draws a frame's surfaces (or, wire, its edges).
enum class SurfaceRoute {
  kFaces,     ///< face by face in scene order, one thread (FaceStage)
  kPainter,   ///< far to near by eye z (FaceStage)
  kClusters,  ///< cluster by cluster (ClusterStage)
  kRays,      ///< a ray a sample through the hierarchy (RayCastStage)
  kQuicker,   ///< rays or clusters, whichever SurfacePassChoice measures quicker
  kEdges,     ///< wire: the edges as lines (WireStage)
};

/// Where the surfaces are seen from: the frame's camera, or its sample camera
/// when a cell has several samples; the eye transform and clip planes from it.
struct FrameView {
  Camera camera;
  Mat4 eyeFromWorld;
  Vec3 eyeWorld;
  ViewClipPlanes clipPlanes{};
};

/// How triangles become samples.
struct RasterPlan {
  DepthRule rule = DepthRule::kNearestWins;
  DepthFormat depthFormat = DepthFormat::kFloatInverseZ;
  bool scanline = false;       ///< the classic scanline rasterizer instead of edge functions
  bool floatGeometry = false;  ///< transform and project in float
  bool cullBackFaces = true;
  bool wideLanes = true;  ///< the sampled rasterizer's eight-lane 2x4 cells
};

/// How the faces a frame shows are shaded (SPEC 4).
struct ShadePlan {
  ShadeMode mode = ShadeMode::kContrast;
  const ShadeRamp* ramp = nullptr;  ///< the options' (a plan lives for one frame)
  Vec3 sunEye = DefaultSunEye();
  double ambient = kDefaultAmbient;
  bool lines = false;  ///< wire: the cells hold lines, drawn at full intensity
  /// Ink darker than the background (no colours on a light one): each face's
  /// intensity and level are its darkness, 1 - its shade (lines stay full).
  bool darkInk = false;
};

/// How a frame of several samples a cell becomes glyphs (SPEC 11).
struct GlyphPlan {
  GlyphMode mode = GlyphMode::kRamp;
  bool twoColour = false;           ///< see RenderOptions::twoColour
  const ShadeRamp* ramp = nullptr;  ///< the options'
  SampleGrid pattern;               ///< the glyph's parts; the frame's grid is a multiple of it
  /// Without colour, the pattern modes ink a part when its shade exceeds the
  /// threshold of a Bayer matrix of side 2^ditherOrder at its screen position
  /// (OrderedDither), unless shadeGlyphs; 0: every covered part is inked.
  int ditherOrder = 0;
  /// Without colour (blocks, quadrants, sextants), a cell whose parts are all
  /// covered is the bar of its covered parts' mean shade (ShadeGlyph) and a
  /// cell on the silhouette the glyph nearest its parts after a blur
  /// (BlurredGlyphMatch), instead of a dithered pattern.
  bool shadeGlyphs = false;
  bool writeDepth = true;  ///< a cell's depth is its nearest sample's
};

/// Everything about a frame resolved once from (scene, camera, options):
/// the renderer runs its stages by it and reads the options no more.
struct FramePlan {
  Method method = Method::kZBuffer;  ///< auto resolved
  SampleGrid grid;                   ///< samples a cell drawn (wire: one)
  int widthSamples = 0;
  int heightSamples = 0;
  SurfaceTarget target = SurfaceTarget::kCells;
  SurfaceRoute route = SurfaceRoute::kFaces;
  bool clearDepth = true;  ///< the surfaces' depth cleared first (a test or a reader needs it)
  FrameView view;
  RasterPlan raster;
  /// kClusters, kRays and kQuicker: the cluster frame (its sink set by the renderer).
  ClusterFrame clusters;
  std::shared_ptr<const RayBvh> hierarchy;  ///< kRays and kQuicker
  int threads = 1;                          ///< the rays' threads, and the timed choice's key
  int sharedThreads = 1;                    ///< the cluster pass's and shading's: big scenes only
  int16_t lineLevel = 0;                    ///< kEdges: the ramp level lines are drawn at
  ShadePlan shading;
  GlyphPlan glyphs;  ///< several samples a cell
  /// The cells' colours from the faces' textures (TextureStage): colours are
  /// shown, textures asked for, the scene has some, and faces are drawn.
  bool textures = false;
};

/// The glyph stage's settings from the options (PlanFrame's; tests build them so too).
GlyphPlan PlanGlyphs(const RenderOptions& options);

/// Resolves the options for one frame of widthCells x heightCells.
FramePlan PlanFrame(const Scene& scene, const Camera& camera, const RenderOptions& options,
                    int widthCells, int heightCells);

}  // namespace termshade
