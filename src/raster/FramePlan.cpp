#include "raster/FramePlan.h"

#include "geometry/ViewingTransform.h"
#include "raster/RayCastStage.h"
#include "raster/SampledRasterizer.h"
#include "raster/WorkerPool.h"

namespace termshade {
namespace {

// The mono pattern modes' Bayer matrix: 2^1 = 2x2, the finest pattern; 4x4
// and 8x8 scored lower blurred SSIM in every mode (`termshade bench fidelity`,
// docs/glyphs-and-fidelity.md#shade-without-colour-ordered-dither).
constexpr int kMonoDitherOrder = 1;

// The mono modes whose covered cells are bars and silhouette cells matched
// glyphs: not braille, whose dots ink about a quarter of the cell at most (a
// bar would outshine a full braille cell).
bool ShadesWithGlyphs(const RenderOptions& options) {
  const GlyphMode mode = options.glyphs;
  return !options.twoColour && (mode == GlyphMode::kBlocks || mode == GlyphMode::kQuadrants ||
                                mode == GlyphMode::kSextants);
}

// The near plane sits a tiny, scale-relative distance in front of the eye.
double NearDistance(const Scene& scene) {
  return 1e-6 * (scene.diagonalModelUnits > 0.0 ? scene.diagonalModelUnits : 1.0);
}

FrameView MakeView(const Scene& scene, const Camera& camera) {
  return {camera, EyeFromWorld(camera.view), EyePositionWorld(camera.view),
          MakeViewClipPlanes(camera.projection, NearDistance(scene))};
}

DepthRule SurfaceRule(Method method, bool keepDepth) {
  return method == Method::kZBuffer ? DepthRule::kNearestWins
         : keepDepth                ? DepthRule::kOverwrite
                                    : DepthRule::kCoverOnly;
}

// zbuffer and cull go cluster by cluster, except for the 16-bit depth variant
// (its scale comes from every vertex of the scene).
bool DrawsByCluster(const Scene& scene, Method method, const RenderVariant& variant) {
  return (method == Method::kZBuffer || method == Method::kCull) && variant.clusters &&
         variant.depthFormat != DepthFormat::kFixed16InverseZ && ClusterStage::Usable(scene);
}

// The sampled rasterizer serves cluster frames on one thread with the product's depth.
bool DrawsSampled(const Scene& scene, const RenderOptions& options, SampleGrid grid) {
  const RenderVariant& variant = options.variant;
  if (!variant.sampledRasterizer || variant.scanline ||
      variant.depthFormat != DepthFormat::kFloatInverseZ || !SampledRasterizer::Supports(grid)) {
    return false;
  }
  // The triangle count first: counting the usable cores is a system call (1.6 us here).
  return scene.triangles.size() < options.threadsFromTriangles ||
         ResolvedThreadCount(options.threads) <= 1;
}

ClusterFrame MakeClusterFrame(const FramePlan& plan, const RenderOptions& options) {
  ClusterFrame frame;
  frame.projection = plan.view.camera.projection;
  frame.eyeFromWorld = plan.view.eyeFromWorld;
  frame.clipPlanes = plan.view.clipPlanes;
  frame.eyeWorld = plan.view.eyeWorld;
  frame.depthEncoding = {plan.raster.depthFormat, 1.0F};
  frame.rule = plan.raster.rule;
  frame.cullBackFaces = plan.raster.cullBackFaces;
  frame.clusterCulling = options.variant.clusterCulling;
  frame.floatGeometry = plan.raster.floatGeometry;
  frame.scanline = plan.raster.scanline;
  frame.threadsFromTriangles = options.threadsFromTriangles;
  return frame;
}

// Rays through the hierarchy where the variant wants them and they draw this
// view exactly: always, or timed against the clusters; else the clusters.
SurfaceRoute PlanHierarchy(const Scene& scene, HierarchyUse use, FramePlan& plan) {
  const bool wanted = use == HierarchyUse::kAlways ||
                      (use == HierarchyUse::kWhenFaster &&
                       RayCastStage::WorthTrying(scene, plan.widthSamples, plan.heightSamples));
  if (!wanted) return SurfaceRoute::kClusters;
  std::shared_ptr<const RayBvh> bvh = scene.hierarchy.Get(scene);
  if (bvh == nullptr || !RayCastStage::Applies(scene, *bvh, plan.clusters)) {
    return SurfaceRoute::kClusters;
  }
  plan.hierarchy = std::move(bvh);
  return use == HierarchyUse::kAlways ? SurfaceRoute::kRays : SurfaceRoute::kQuicker;
}

}  // namespace

Method ResolvedMethod(const Scene& scene, Method method) {
  if (method != Method::kAuto) return method;
  return scene.convexClosedSolid ? Method::kCull : Method::kZBuffer;
}

Camera SampleCamera(const Camera& camera, SampleGrid grid) {
  Camera fine = camera;
  fine.projection.d *= grid.across;
  fine.projection.cx *= grid.across;
  fine.projection.cy *= grid.down;
  fine.projection.cellAspect *= static_cast<double>(grid.across) / grid.down;
  return fine;
}

GlyphPlan PlanGlyphs(const RenderOptions& options) {
  const bool patterned = options.glyphs != GlyphMode::kRamp && options.glyphs != GlyphMode::kAscii;
  return {.mode = options.glyphs,
          .twoColour = options.twoColour,
          .ramp = &options.ramp,
          .pattern = PatternSampleGrid(options),
          .ditherOrder = patterned && !options.twoColour ? kMonoDitherOrder : 0,
          .shadeGlyphs = ShadesWithGlyphs(options),
          .writeDepth = options.keepDepth};
}

FramePlan PlanFrame(const Scene& scene, const Camera& camera, const RenderOptions& options,
                    int widthCells, int heightCells) {
  const RenderVariant& variant = options.variant;
  FramePlan plan;
  // Step 1: the method, the samples a cell and the view they are seen from.
  plan.method = ResolvedMethod(scene, options.method);
  plan.grid = plan.method == Method::kWire ? SampleGrid{} : FrameSampleGrid(options);
  const bool sampled = plan.grid.Count() > 1;
  plan.widthSamples = widthCells * plan.grid.across;
  plan.heightSamples = heightCells * plan.grid.down;
  plan.view = MakeView(scene, sampled ? SampleCamera(camera, plan.grid) : camera);
  // Step 2: the raster rule; depth is cleared for the Z-buffer's test and for a reader.
  plan.raster = {.rule = SurfaceRule(plan.method, options.keepDepth),
                 .depthFormat = variant.depthFormat,
                 .scanline = variant.scanline,
                 .floatGeometry = variant.floatGeometry,
                 .cullBackFaces = options.cullBackFaces,
                 .wideLanes = variant.wideLanes};
  plan.clearDepth = options.keepDepth || plan.method == Method::kZBuffer;
  // Step 3: the surface pass and where it draws.
  const bool byCluster = DrawsByCluster(scene, plan.method, variant);
  if (sampled) {
    plan.target = byCluster && DrawsSampled(scene, options, plan.grid)
                      ? SurfaceTarget::kSampleFrame
                      : SurfaceTarget::kSampleCells;
  }
  if (byCluster) {
    plan.clusters = MakeClusterFrame(plan, options);
    plan.route = SurfaceRoute::kClusters;
    if (plan.target != SurfaceTarget::kSampleFrame) {
      // The scanline variant steps rows in float from its first row: one band only.
      plan.threads = variant.scanline ? 1 : ResolvedThreadCount(options.threads);
      // Waking threads pays for big scenes only.
      const bool big = scene.triangles.size() >= options.threadsFromTriangles;
      plan.sharedThreads = big ? plan.threads : 1;
      plan.route = PlanHierarchy(scene, variant.hierarchy, plan);
    }
  } else if (plan.method == Method::kWire) {
    plan.route = SurfaceRoute::kEdges;
    plan.lineLevel = static_cast<int16_t>(options.ramp.LevelCount() - 1);
  } else {
    plan.route = plan.method == Method::kPainter ? SurfaceRoute::kPainter : SurfaceRoute::kFaces;
  }
  // Step 4: shading, and the glyphs of several samples a cell.
  plan.shading = {.mode = options.shade,
                  .ramp = &options.ramp,
                  .sunEye = options.sunEye,
                  .ambient = options.ambient,
                  .lines = plan.method == Method::kWire,
                  .darkInk = !options.twoColour && options.background == Background::kLight};
  if (sampled) plan.glyphs = PlanGlyphs(options);
  plan.textures = options.textures && options.twoColour && scene.textures.Colour() &&
                  plan.method != Method::kWire;
  return plan;
}

}  // namespace termshade
