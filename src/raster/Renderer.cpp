#include "raster/Renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "geometry/ViewingTransform.h"
#include "process/HugePages.h"
#include "raster/ClipToRaster.h"
#include "raster/FixedPoint.h"
#include "raster/LineRasterizer.h"
#include "raster/SampledRasterizer.h"
#include "raster/VertexStage.h"

namespace termshade {
namespace {

// The near plane sits a tiny, scale-relative distance in front of the eye.
double NearDistance(const Scene& scene) {
  return 1e-6 * (scene.diagonalModelUnits > 0.0 ? scene.diagonalModelUnits : 1.0);
}

// Only the Z-buffer's test and a caller reading depth afterwards need it cleared.
bool NeedsDepth(const RenderOptions& options) {
  return options.keepDepth || options.method == Method::kZBuffer;
}

// zbuffer and cull go cluster by cluster, except for the 16-bit depth variant
// (its scale comes from every vertex of the scene).
bool DrawsByCluster(const Scene& scene, const RenderOptions& options) {
  return (options.method == Method::kZBuffer || options.method == Method::kCull) &&
         options.variant.clusters && options.variant.depthFormat != DepthFormat::kFixed16InverseZ &&
         ClusterStage::Usable(scene);
}

RenderOptions ResolvedOptions(const Scene& scene, const RenderOptions& options) {
  RenderOptions resolved = options;
  resolved.method = ResolvedMethod(scene, options.method);
  return resolved;
}

// The sampled rasterizer serves cluster frames on one thread with the product's depth.
bool DrawsSampled(const Scene& scene, const RenderOptions& single, SampleGrid grid) {
  // The triangle count first: counting the usable cores is a system call (1.6 us here).
  const bool oneThread = scene.triangles.size() < single.threadsFromTriangles ||
                         ResolvedThreadCount(single.threads) <= 1;
  return single.variant.sampledRasterizer && DrawsByCluster(scene, single) &&
         !single.variant.scanline && single.variant.depthFormat == DepthFormat::kFloatInverseZ &&
         SampledRasterizer::Supports(grid) && oneThread;
}

class SampleSink final : public TriangleSink {
 public:
  explicit SampleSink(SampledRasterizer& rasterizer) : rasterizer_(rasterizer) {}
  void Draw(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
            uint32_t faceNumber) override {
    rasterizer_.Draw(a, b, c, faceNumber);
  }

 private:
  SampledRasterizer& rasterizer_;
};

DepthRule SurfaceRule(const RenderOptions& options) {
  return options.method == Method::kZBuffer ? DepthRule::kNearestWins
         : options.keepDepth                ? DepthRule::kOverwrite
                                            : DepthRule::kCoverOnly;
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

RenderStats Renderer::Render(const Scene& scene, const Camera& camera, const RenderOptions& options,
                             DepthBuffer& depth, CellBuffer& cells) {
  const SampleGrid grid = FrameSampleGrid(options);
  lastGrid_ = options.method == Method::kWire ? SampleGrid{} : grid;
  if (lastGrid_.Count() > 1) return RenderSampled(scene, camera, options, depth, cells);
  RenderOptions resolved = options;
  resolved.method = ResolvedMethod(scene, options.method);
  cells.Clear();
  if (NeedsDepth(resolved)) depth.Clear();
  framePool_ = nullptr;
  clipPlanes_ = MakeViewClipPlanes(camera.projection, NearDistance(scene));
  eyeWorld_ = EyePositionWorld(camera.view);
  RenderStats stats;
  if (DrawsByCluster(scene, resolved)) {
    stats.trianglesDrawn = DrawClusters(scene, camera, resolved, depth, cells);
    stats.byHierarchy = drewByHierarchy_;
    stats.facesVisible =
        shadeStage_.ShadeCells(scene, {eyeFromWorld_, eyeWorld_}, resolved, framePool_, cells);
    return stats;
  }
  TransformVertices(scene, camera, resolved.variant, resolved.method == Method::kPainter);
  if (resolved.method == Method::kWire) {
    stats.trianglesDrawn = DrawEdges(scene, camera, resolved, depth, cells);
  } else {
    stats.trianglesDrawn = DrawSurfaces(scene, camera, resolved, depth, cells);
  }
  stats.facesVisible =
      shadeStage_.ShadeCells(scene, {eyeFromWorld_, eyeWorld_}, resolved, nullptr, cells);
  return stats;
}

// k x m samples per cell (SPEC 11): the frame drawn at k times the columns
// and m times the rows (the camera scaled to match, so each sample sits at
// the center of its part of the cell), each sample resolved and shaded as a
// one-sample frame's cell is; then the glyph stage turns samples into cells.
RenderStats Renderer::RenderSampled(const Scene& scene, const Camera& camera,
                                    const RenderOptions& options, DepthBuffer& depth,
                                    CellBuffer& cells) {
  const SampleGrid grid = lastGrid_;
  const Camera fine = SampleCamera(camera, grid);
  const int fineWidth = cells.WidthCells() * grid.across;
  const int fineHeight = cells.HeightCells() * grid.down;
  if (!fineCells_.FacesOnly() || fineCells_.WidthCells() != fineWidth ||
      fineCells_.HeightCells() != fineHeight) {
    fineCells_.ResizeFacesOnly(fineWidth, fineHeight);
  }
  if (fineDepth_.WidthCells() != fineWidth || fineDepth_.HeightCells() != fineHeight) {
    fineDepth_.Resize(fineWidth, fineHeight);
  }
  sampleFrame_.Begin(cells.WidthCells(), cells.HeightCells(), grid);
  RenderOptions single = options;
  single.variant.samples = {1, 1};
  single.glyphs = GlyphMode::kRamp;
  RenderStats stats;
  if (DrawsSampled(scene, ResolvedOptions(scene, single), grid)) {
    stats = DrawSampleFrame(scene, fine, ResolvedOptions(scene, single));
    fineCellsCurrent_ = false;
  } else {
    // Render below clears what it reads; only the faces are kept a sample.
    stats = Render(scene, fine, single, fineDepth_, fineCells_);
    lastGrid_ = grid;
    const bool depthKept = NeedsDepth(ResolvedOptions(scene, single));
    sampleFrame_.CopyFrom(fineCells_, depthKept ? &fineDepth_ : nullptr);
    fineCellsCurrent_ = true;
  }
  glyphStage_.Compose(
      {sampleFrame_, shadeStage_.FaceIntensities(), PatternSampleGrid(options), options.keepDepth},
      options, cells, depth);
  return stats;
}

// The cluster frame of Render, drawn by the sampled rasterizer into
// sampleFrame_, then the faces it shows shaded (the glyph stage reads them).
RenderStats Renderer::DrawSampleFrame(const Scene& scene, const Camera& fine,
                                      const RenderOptions& single) {
  clipPlanes_ = MakeViewClipPlanes(fine.projection, NearDistance(scene));
  eyeWorld_ = EyePositionWorld(fine.view);
  SampledRasterizer rasterizer(sampleFrame_, SurfaceRule(single), single.variant.wideLanes);
  SampleSink sink(rasterizer);
  RenderStats stats;
  stats.trianglesDrawn = DrawClusters(scene, fine, single, fineDepth_, fineCells_, &sink);
  stats.facesVisible =
      shadeStage_.ShadeSamples(scene, {eyeFromWorld_, eyeWorld_}, single, sampleFrame_);
  return stats;
}

WorkerPool* Renderer::PoolFor(int threads) {
  if (threads <= 1) return nullptr;
  if (!pool_ || pool_->Workers() != threads) pool_ = std::make_unique<WorkerPool>(threads);
  return pool_.get();
}

const CellBuffer& Renderer::Samples() const {
  if (!fineCellsCurrent_) {
    sampleFrame_.CopyTo(fineCells_);
    fineCellsCurrent_ = true;
  }
  return fineCells_;
}

void Renderer::TransformVertices(const Scene& scene, const Camera& camera,
                                 const RenderVariant& variant, bool needEyeZ) {
  eyeFromWorld_ = EyeFromWorld(camera.view);
  const Projection& proj = camera.projection;
  const size_t count = scene.verticesWorld.size();
  ResizeWithHugePages(zEye_, needEyeZ ? count : 0);
  ResizeWithHugePages(rasterVertices_, count);
  ResizeWithHugePages(outCodes_, count);
  maxW_ = ProjectVertices(
      scene.verticesWorld, eyeFromWorld_, proj, clipPlanes_, variant.floatGeometry,
      {rasterVertices_.data(), outCodes_.data(), needEyeZ ? zEye_.data() : nullptr});
  depthEncoding_ = {variant.depthFormat, maxW_ > 0.0F ? 65535.0F / maxW_ : 1.0F};
  scanline_ = variant.scanline;
}

bool Renderer::FaceIsFront(const Scene& scene, uint32_t face) const {
  // The eye strictly in front of the face's plane (h < 0 in eye space).
  return scene.facePlanesWorld[face].FacesPoint(eyeWorld_);
}

int Renderer::DrawTriangle(const Scene& scene, const Camera& camera, uint32_t triangle,
                           DepthRule rule, DepthBuffer& depth, CellBuffer& cells) {
  const SceneTriangle& t = scene.triangles[triangle];
  const uint32_t faceNumber = scene.TriangleFace(triangle) + 1;
  const unsigned codes[3] = {outCodes_[t.vertices[0]], outCodes_[t.vertices[1]],
                             outCodes_[t.vertices[2]]};
  // Fast path: wholly inside the near plane and the guard band.
  if ((codes[0] | codes[1] | codes[2]) == 0) {
    const RasterVertex& a = rasterVertices_[t.vertices[0]];
    const RasterVertex& b = rasterVertices_[t.vertices[1]];
    const RasterVertex& c = rasterVertices_[t.vertices[2]];
    if (!MayCoverSample(a, b, c, cells.WidthCells(), cells.HeightCells())) return 0;
    Rasterize(a, b, c, faceNumber, rule, depth, cells);
    return 1;
  }
  if ((codes[0] & codes[1] & codes[2]) != 0) return 0;
  std::array<RasterVertex, kClippedCornersMax> projected{};
  const size_t count =
      ClipToRaster(scene, triangle, eyeFromWorld_, clipPlanes_, camera.projection, projected);
  if (count < 3) return 0;
  // The clipped polygon is convex: a fan from its first corner covers it.
  for (size_t i = 1; i + 1 < count; ++i) {
    Rasterize(projected[0], projected[i], projected[i + 1], faceNumber, rule, depth, cells);
  }
  return 1;
}

void Renderer::Rasterize(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c,
                         uint32_t faceNumber, DepthRule rule, DepthBuffer& depth,
                         CellBuffer& cells) const {
  if (scanline_) {
    RasterizeTriangleScanline(a, b, c, faceNumber, rule, depth, cells);
  } else {
    RasterizeTriangle(a, b, c, faceNumber, rule, depth, cells, depthEncoding_);
  }
}

int Renderer::DrawSurfaces(const Scene& scene, const Camera& camera, const RenderOptions& options,
                           DepthBuffer& depth, CellBuffer& cells) {
  int drawn = 0;
  const bool cull = options.cullBackFaces;
  // Face by face: a face behind its plane is skipped whole, its triangles never read.
  if (options.method == Method::kPainter) {
    // Textbook painter: far to near by the sum of the vertices' eye z.
    painterOrder_.clear();
    for (uint32_t f = 0; f < scene.FaceCount(); ++f) {
      if (cull && !FaceIsFront(scene, f)) continue;
      for (uint32_t i = scene.FaceTrianglesBegin(f); i < scene.FaceTrianglesBegin(f + 1); ++i) {
        const SceneTriangle& t = scene.triangles[i];
        painterOrder_.emplace_back(
            zEye_[t.vertices[0]] + zEye_[t.vertices[1]] + zEye_[t.vertices[2]], i);
      }
    }
    std::sort(painterOrder_.begin(), painterOrder_.end());
    const DepthRule rule = options.keepDepth ? DepthRule::kOverwrite : DepthRule::kCoverOnly;
    for (const auto& [zSum, i] : painterOrder_) {
      drawn += DrawTriangle(scene, camera, i, rule, depth, cells);
    }
    return drawn;
  }
  const DepthRule rule = SurfaceRule(options);
  // The hot loop: plain pointers, the in-view case inline, the rest out of line.
  const FacePlane* const planes = scene.facePlanesWorld.data();
  const uint32_t* const starts =
      scene.faceTriangleStarts.empty() ? nullptr : scene.faceTriangleStarts.data();
  const SceneTriangle* const triangles = scene.triangles.data();
  const RasterVertex* const raster = rasterVertices_.data();
  const uint8_t* const codes = outCodes_.data();
  const Vec3 eyeWorld = eyeWorld_;
  const int width = cells.WidthCells(), height = cells.HeightCells();
  const uint32_t faceCount = static_cast<uint32_t>(scene.FaceCount());
  for (uint32_t f = 0; f < faceCount; ++f) {
    if (cull && !planes[f].FacesPoint(eyeWorld)) continue;
    const uint32_t end = starts != nullptr ? starts[f + 1] : f + 1;
    for (uint32_t i = starts != nullptr ? starts[f] : f; i < end; ++i) {
      const auto& v = triangles[i].vertices;
      if ((codes[v[0]] | codes[v[1]] | codes[v[2]]) != 0) {
        drawn += DrawTriangle(scene, camera, i, rule, depth, cells);
        continue;
      }
      const RasterVertex& a = raster[v[0]];
      const RasterVertex& b = raster[v[1]];
      const RasterVertex& c = raster[v[2]];
      if (!MayCoverSample(a, b, c, width, height)) continue;
      Rasterize(a, b, c, f + 1, rule, depth, cells);
      ++drawn;
    }
  }
  return drawn;
}

int Renderer::DrawClusters(const Scene& scene, const Camera& camera, const RenderOptions& options,
                           DepthBuffer& depth, CellBuffer& cells, TriangleSink* sink) {
  eyeFromWorld_ = EyeFromWorld(camera.view);
  ClusterFrame frame;
  frame.projection = camera.projection;
  frame.eyeFromWorld = eyeFromWorld_;
  frame.clipPlanes = clipPlanes_;
  frame.eyeWorld = eyeWorld_;
  frame.depthEncoding = {options.variant.depthFormat, 1.0F};
  frame.rule = SurfaceRule(options);
  frame.cullBackFaces = options.cullBackFaces;
  frame.clusterCulling = options.variant.clusterCulling;
  frame.floatGeometry = options.variant.floatGeometry;
  frame.scanline = options.variant.scanline;
  frame.threadsFromTriangles = options.threadsFromTriangles;
  frame.sink = sink;
  // The scanline variant steps rows in float from its first row: one band only.
  const int threads = options.variant.scanline ? 1 : ResolvedThreadCount(options.threads);
  // The frame's pool: the surface pass's threads, then shading's (big scenes only).
  framePool_ = scene.triangles.size() >= options.threadsFromTriangles ? PoolFor(threads) : nullptr;
  const HierarchyUse use = options.variant.hierarchy;
  const int width = cells.WidthCells(), height = cells.HeightCells();
  const bool wanted =
      use == HierarchyUse::kAlways ||
      (use == HierarchyUse::kWhenFaster && RayCastStage::WorthTrying(scene, width, height));
  const std::shared_ptr<const RayBvh> bvh = wanted ? scene.hierarchy.Get(scene) : nullptr;
  drewByHierarchy_ = bvh != nullptr && RayCastStage::Applies(scene, *bvh, frame);
  if (!drewByHierarchy_) return clusterStage_.Draw(scene, frame, framePool_, depth, cells);
  if (use == HierarchyUse::kAlways) {
    return rayCastStage_.Draw(scene, *bvh, frame, PoolFor(threads), depth, cells);
  }
  return DrawByQuickerPass(scene, bvh, frame, threads, depth, cells);
}

// Both passes draw this frame bit for bit: the one measured quicker here.
int Renderer::DrawByQuickerPass(const Scene& scene, const std::shared_ptr<const RayBvh>& bvh,
                                const ClusterFrame& frame, int threads, DepthBuffer& depth,
                                CellBuffer& cells) {
  // Another hierarchy, even at a freed one's address, is another key.
  const bool sameHierarchy =
      !choiceHierarchy_.owner_before(bvh) && !bvh.owner_before(choiceHierarchy_);
  if (!sameHierarchy) {
    choiceHierarchy_ = bvh;
    ++choiceHierarchySerial_;
  }
  const int width = cells.WidthCells(), height = cells.HeightCells();
  const SurfaceChoiceKey key{choiceHierarchySerial_, width, height, threads};
  const SurfacePass prior =
      RayCastStage::Faster(scene, width, height) ? SurfacePass::kHierarchy : SurfacePass::kClusters;
  drewByHierarchy_ = passChoice_.Pick(key, prior) == SurfacePass::kHierarchy;
  const auto start = std::chrono::steady_clock::now();
  const int drawn = drewByHierarchy_
                        ? rayCastStage_.Draw(scene, *bvh, frame, PoolFor(threads), depth, cells)
                        : clusterStage_.Draw(scene, frame, framePool_, depth, cells);
  passChoice_.Record(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  return drawn;
}

int Renderer::DrawEdges(const Scene& scene, const Camera& camera, const RenderOptions& options,
                        DepthBuffer& depth, CellBuffer& cells) {
  const auto topLevel = static_cast<int16_t>(options.ramp.LevelCount() - 1);
  int drawn = 0;
  for (const SceneEdge& edge : scene.Edges()) {
    Vec3 aEye = TransformPoint(eyeFromWorld_, scene.verticesWorld[edge.vertices[0]]);
    Vec3 bEye = TransformPoint(eyeFromWorld_, scene.verticesWorld[edge.vertices[1]]);
    if (!IsFinite(aEye) || !IsFinite(bEye) || !ClipSegment(aEye, bEye, clipPlanes_)) continue;
    const uint32_t faceNumber = edge.face == UINT32_MAX ? 0 : edge.face + 1;
    DrawLine(ProjectToCell(camera.projection, aEye), ProjectToCell(camera.projection, bEye),
             camera.projection.cellAspect, faceNumber, topLevel, depth, cells);
    ++drawn;
  }
  return drawn;
}

}  // namespace termshade
