#include "raster/Renderer.h"

#include <chrono>

#include "raster/SampledRasterizer.h"
#include "raster/WireStage.h"

namespace termshade {
namespace {

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

}  // namespace

RenderStats Renderer::Render(const Scene& scene, const Camera& camera, const RenderOptions& options,
                             DepthBuffer& depth, CellBuffer& cells) {
  const FramePlan plan = PlanFrame(scene, camera, options, cells.WidthCells(), cells.HeightCells());
  lastGrid_ = plan.grid;
  // Step 1: the buffers the surfaces go to (the cells, or the samples), cleared.
  const SurfaceBuffers surfaces = BeginSurfaces(plan, depth, cells);
  framePool_ = PoolFor(plan.sharedThreads);
  // Step 2: the surface pass.
  RenderStats stats = DrawSurfaces(scene, plan, surfaces);
  // Step 3: the faces seen, shaded.
  stats.facesVisible = ShadeFaces(scene, plan, surfaces.cells);
  // Step 4: several samples a cell: the glyph of each cell from its samples.
  if (plan.target != SurfaceTarget::kCells) ComposeGlyphs(plan, depth, cells);
  // Step 5: textured faces: each cell's colours from the texels its samples see.
  if (plan.textures) {
    if (plan.target == SurfaceTarget::kCells) {
      textureStage_.Apply(scene, plan.view, cells);
    } else {
      textureStage_.Apply(scene, plan.view,
                          {sampleFrame_, shadeStage_.FaceIntensities(), plan.glyphs}, cells);
    }
  } else {
    cells.DropAlbedos();
  }
  return stats;
}

// k x m samples per cell (SPEC 11): the frame drawn at k times the columns
// and m times the rows (the sample camera: each sample at the center of its
// part of the cell), each sample resolved and shaded as a one-sample frame's
// cell is; then the glyph stage turns samples into cells.
Renderer::SurfaceBuffers Renderer::BeginSurfaces(const FramePlan& plan, DepthBuffer& depth,
                                                 CellBuffer& cells) {
  if (plan.target == SurfaceTarget::kCells) {
    cells.Clear();
    if (plan.clearDepth) depth.Clear();
    return {cells, depth};
  }
  const int width = plan.widthSamples, height = plan.heightSamples;
  if (!fineCells_.FacesOnly() || fineCells_.WidthCells() != width ||
      fineCells_.HeightCells() != height) {
    fineCells_.ResizeFacesOnly(width, height);
  }
  if (fineDepth_.WidthCells() != width || fineDepth_.HeightCells() != height) {
    fineDepth_.Resize(width, height);
  }
  sampleFrame_.Begin(cells.WidthCells(), cells.HeightCells(), plan.grid);
  // Only the faces are kept a sample; the sampled rasterizer clears what it writes.
  if (plan.target == SurfaceTarget::kSampleCells) {
    fineCells_.Clear();
    if (plan.clearDepth) fineDepth_.Clear();
  }
  return {fineCells_, fineDepth_};
}

RenderStats Renderer::DrawSurfaces(const Scene& scene, const FramePlan& plan, SurfaceBuffers to) {
  RenderStats stats;
  switch (plan.route) {
    case SurfaceRoute::kFaces:
    case SurfaceRoute::kPainter:
      stats.trianglesDrawn = faceStage_.Draw(
          scene, plan.view, plan.raster, plan.route == SurfaceRoute::kPainter, to.depth, to.cells);
      break;
    case SurfaceRoute::kEdges:
      stats.trianglesDrawn = DrawWireFrame(scene, plan.view, plan.lineLevel, to.depth, to.cells);
      break;
    case SurfaceRoute::kClusters:
      stats.trianglesDrawn = DrawClusters(scene, plan, to);
      break;
    case SurfaceRoute::kRays:
      stats.trianglesDrawn = rayCastStage_.Draw(scene, *plan.hierarchy, plan.clusters,
                                                PoolFor(plan.threads), to.depth, to.cells);
      stats.byHierarchy = true;
      break;
    case SurfaceRoute::kQuicker:
      stats.trianglesDrawn = DrawByQuickerPass(scene, plan, to, stats.byHierarchy);
      break;
  }
  return stats;
}

// Cluster by cluster into the buffers, or (the sampled rasterizer) into the samples.
int Renderer::DrawClusters(const Scene& scene, const FramePlan& plan, SurfaceBuffers to) {
  if (plan.target != SurfaceTarget::kSampleFrame) {
    return clusterStage_.Draw(scene, plan.clusters, framePool_, to.depth, to.cells);
  }
  SampledRasterizer rasterizer(sampleFrame_, plan.raster.rule, plan.raster.wideLanes);
  SampleSink sink(rasterizer);
  ClusterFrame frame = plan.clusters;
  frame.sink = &sink;
  return clusterStage_.Draw(scene, frame, framePool_, to.depth, to.cells);
}

// Both passes draw this frame bit for bit: the one measured quicker here.
int Renderer::DrawByQuickerPass(const Scene& scene, const FramePlan& plan, SurfaceBuffers to,
                                bool& byHierarchy) {
  // Another hierarchy, even at a freed one's address, is another key.
  const std::shared_ptr<const RayBvh>& bvh = plan.hierarchy;
  const bool sameHierarchy =
      !choiceHierarchy_.owner_before(bvh) && !bvh.owner_before(choiceHierarchy_);
  if (!sameHierarchy) {
    choiceHierarchy_ = bvh;
    ++choiceHierarchySerial_;
  }
  const int width = plan.widthSamples, height = plan.heightSamples;
  const SurfaceChoiceKey key{choiceHierarchySerial_, width, height, plan.threads};
  const SurfacePass prior =
      RayCastStage::Faster(scene, width, height) ? SurfacePass::kHierarchy : SurfacePass::kClusters;
  byHierarchy = passChoice_.Pick(key, prior) == SurfacePass::kHierarchy;
  const auto start = std::chrono::steady_clock::now();
  const int drawn = byHierarchy
                        ? rayCastStage_.Draw(scene, *bvh, plan.clusters, PoolFor(plan.threads),
                                             to.depth, to.cells)
                        : clusterStage_.Draw(scene, plan.clusters, framePool_, to.depth, to.cells);
  passChoice_.Record(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  return drawn;
}

// A one-sample frame's cells get their levels and glyphs; samples only their faces' intensities.
int Renderer::ShadeFaces(const Scene& scene, const FramePlan& plan, CellBuffer& surfaceCells) {
  const ShadeView view{plan.view.eyeFromWorld, plan.view.eyeWorld};
  if (plan.target == SurfaceTarget::kSampleFrame) {
    return shadeStage_.ShadeSamples(scene, view, plan.shading, sampleFrame_);
  }
  return shadeStage_.ShadeCells(scene, view, plan.shading, framePool_, surfaceCells);
}

void Renderer::ComposeGlyphs(const FramePlan& plan, DepthBuffer& depth, CellBuffer& cells) {
  // Drawn as a one-sample frame: reordered into the samples (depth where it was kept).
  fineCellsCurrent_ = plan.target == SurfaceTarget::kSampleCells;
  if (fineCellsCurrent_) sampleFrame_.CopyFrom(fineCells_, plan.clearDepth ? &fineDepth_ : nullptr);
  glyphStage_.Compose({sampleFrame_, shadeStage_.FaceIntensities()}, plan.glyphs, cells, depth);
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

}  // namespace termshade
