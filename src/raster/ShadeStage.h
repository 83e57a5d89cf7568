#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "geometry/Mat4.h"
#include "geometry/Scene.h"
#include "geometry/Vec3.h"
#include "raster/CellBuffer.h"
#include "raster/FramePlan.h"
#include "raster/SampleFrame.h"
#include "raster/WorkerPool.h"

namespace termshade {

/// The view a frame was drawn from, as shading needs it (world space).
struct ShadeView {
  Mat4 eyeFromWorld;
  Vec3 eyeWorld;
};

/// Flat shading of the faces a frame shows (SPEC 4): each face seen is
/// shaded once from n . sun (n turned towards the eye) into an intensity
/// 0..255 and a ramp level, contrast spread over the faces seen. With a pool
/// and many faces, the faces and cells are split between its workers (the
/// same values: every face's shade is its own computation).
class ShadeStage {
 public:
  /// A one-sample frame's cells: levels, intensities and ramp glyphs from
  /// their faces. Returns the number of distinct faces seen.
  int ShadeCells(const Scene& scene, const ShadeView& view, const ShadePlan& plan, WorkerPool* pool,
                 CellBuffer& cells);
  /// The faces a sample frame shows: their intensities (FaceIntensities) for
  /// the glyph stage. Returns the number of distinct faces seen.
  int ShadeSamples(const Scene& scene, const ShadeView& view, const ShadePlan& plan,
                   const SampleFrame& samples);
  /// Per face (face number - 1): the last frame's intensity, for the faces it showed.
  std::span<const uint8_t> FaceIntensities() const { return faceIntensities_; }

 private:
  void BeginSeenFaces(size_t faceCount);
  void MarkSeenFaces(std::span<const uint32_t> faceNumbers);
  void ListSampledFaces(const SampleFrame& samples, size_t faceCount);
  void ShadeSeenFaces(const Scene& scene, const ShadeView& view, const ShadePlan& plan, bool levels,
                      WorkerPool* pool);
  void ShadeCellRange(const ShadePlan& plan, size_t begin, size_t end, CellBuffer& cells);
  int EndSeenFaces();

  std::vector<int16_t> faceLevels_;       ///< per face: ramp level; -1 between frames
  std::vector<uint8_t> faceIntensities_;  ///< per face: intensity 0..255 this frame
  std::vector<uint32_t> seenFaces_;       ///< faces seen in some cell this frame
  std::vector<double> seenSunDots_;       ///< their n.s, n turned towards the eye
  std::vector<std::pair<double, double>> workerDotRanges_;  ///< per worker: min, max n.s
};

}  // namespace termshade
