#include "raster/ShadeStage.h"

#include <algorithm>
#include <cmath>

#include "shade/Lighting.h"

namespace termshade {
namespace {

// How far ahead per-face reads are requested, from how many faces (smaller
// scenes' per-face arrays stay in the caches, and the requests cost time).
constexpr size_t kAhead = 16;
constexpr size_t kPrefetchFromFaces = size_t{1} << 17;

// From this many faces seen, a pool's workers share the shading (fewer: a
// pool's hand-over, about a microsecond while its workers spin, would cost more
// than it saves).
constexpr size_t kSplitFrom = 1024;

// Adds a face not seen before to `seen`, marking its level 0 (EndSeenFaces
// restores -1); runs of one face look it up once.
inline void MarkSeen(uint32_t faceNumber, uint32_t& previous, std::vector<int16_t>& levels,
                     std::vector<uint32_t>& seen) {
  if (faceNumber == previous) return;
  previous = faceNumber;
  if (faceNumber != 0 && levels[faceNumber - 1] == -1) {
    levels[faceNumber - 1] = 0;
    seen.push_back(faceNumber - 1);
  }
}

// job(worker, begin, end) over `count` items in equal ranges, on the pool's
// workers or (no pool) on this thread alone.
template <typename Job>
void ForRanges(WorkerPool* pool, size_t count, const Job& job) {
  if (pool == nullptr) {
    job(0, size_t{0}, count);
    return;
  }
  const auto workers = static_cast<size_t>(pool->Workers());
  auto range = [&](int worker) {
    const auto w = static_cast<size_t>(worker);
    job(worker, count * w / workers, count * (w + 1) / workers);
  };
  pool->Run(range);
}

}  // namespace

int ShadeStage::ShadeCells(const Scene& scene, const ShadeView& view, const ShadePlan& plan,
                           WorkerPool* pool, CellBuffer& cells) {
  const auto& faces = cells.FaceNumbers();
  BeginSeenFaces(scene.FaceCount());
  MarkSeenFaces(faces);
  WorkerPool* const split = seenFaces_.size() >= kSplitFrom ? pool : nullptr;
  ShadeSeenFaces(scene, view, plan, true, split);
  if (cells.FacesOnly()) {
    // Samples: the glyph stage reads FaceIntensities of the faces seen.
  } else if (!plan.lines) {
    ForRanges(split, faces.size(),
              [&](int, size_t begin, size_t end) { ShadeCellRange(plan, begin, end, cells); });
  } else {
    auto& intensities = cells.Intensities();  // lines are drawn at full intensity
    for (size_t i = 0; i < intensities.size(); ++i) {
      if (cells.Levels()[i] >= 0) intensities[i] = 255;
    }
  }
  return EndSeenFaces();
}

int ShadeStage::ShadeSamples(const Scene& scene, const ShadeView& view, const ShadePlan& plan,
                             const SampleFrame& samples) {
  BeginSeenFaces(scene.FaceCount());
  ListSampledFaces(samples, scene.FaceCount());
  ShadeSeenFaces(scene, view, plan, false, nullptr);  // the glyph stage maps intensities
  return EndSeenFaces();
}

void ShadeStage::BeginSeenFaces(size_t faceCount) {
  faceLevels_.resize(faceCount, -1);
  faceIntensities_.resize(faceCount, 0);
  seenFaces_.clear();
}

// Adds the faces of these cells not seen before to seenFaces_ (big scenes'
// faces are cache misses at random: requested kAhead cells early).
void ShadeStage::MarkSeenFaces(std::span<const uint32_t> faceNumbers) {
  uint32_t previous = 0;
  if (faceLevels_.size() < kPrefetchFromFaces) {
    for (const uint32_t faceNumber : faceNumbers) {
      MarkSeen(faceNumber, previous, faceLevels_, seenFaces_);
    }
    return;
  }
  const size_t count = faceNumbers.size();
  for (size_t i = 0; i < count; ++i) {
    if (i + kAhead < count) {
      __builtin_prefetch(faceLevels_.data() + std::max(faceNumbers[i + kAhead], 1U) - 1);
    }
    MarkSeen(faceNumbers[i], previous, faceLevels_, seenFaces_);
  }
}

// The faces the samples show, without a branch a sample (where faces are
// first seen is unpredictable): background looks up a slot past the faces
// that reads as seen; every sample's face is written to the list, which
// grows only by the new ones.
void ShadeStage::ListSampledFaces(const SampleFrame& samples, size_t faceCount) {
  faceLevels_.resize(faceCount + 1);
  faceLevels_[faceCount] = 0;
  int16_t* const levels = faceLevels_.data();
  const size_t perCell = static_cast<size_t>(samples.Grid().Count());
  size_t seen = 0;
  const size_t cellCount = samples.CellCount();
  for (size_t cell = samples.NextTouched(0); cell < cellCount;
       cell = samples.NextTouched(cell + 1)) {
    if (seenFaces_.size() < seen + perCell)
      seenFaces_.resize(seen + perCell);  // grows as push_back
    uint32_t* const list = seenFaces_.data();
    for (uint32_t faceNumber : samples.Faces(cell)) {
      const uint32_t face = faceNumber == 0 ? static_cast<uint32_t>(faceCount) : faceNumber - 1;
      const bool isNew = levels[face] == -1;
      levels[face] = 0;
      list[seen] = face;
      seen += isNew ? 1 : 0;
    }
  }
  seenFaces_.resize(seen);
  faceLevels_[faceCount] = -1;  // every level -1 between frames, as BeginSeenFaces expects
}

// The intensity (and, with `levels`, the ramp level) of every seen face.
void ShadeStage::ShadeSeenFaces(const Scene& scene, const ShadeView& view, const ShadePlan& plan,
                                bool levels, WorkerPool* pool) {
  // Step 1: n.s per seen face, with n turned towards the eye, in world space;
  // each worker's least and greatest.
  const Mat4& m = view.eyeFromWorld;
  const Vec3 s = plan.sunEye;
  const Vec3 sunWorld{m.At(0, 0) * s.x + m.At(1, 0) * s.y + m.At(2, 0) * s.z,
                      m.At(0, 1) * s.x + m.At(1, 1) * s.y + m.At(2, 1) * s.z,
                      m.At(0, 2) * s.x + m.At(1, 2) * s.y + m.At(2, 2) * s.z};
  const size_t count = seenFaces_.size();
  seenSunDots_.resize(count);
  workerDotRanges_.assign(pool != nullptr ? static_cast<size_t>(pool->Workers()) : 1,
                          {INFINITY, -INFINITY});
  ForRanges(pool, count, [&](int worker, size_t begin, size_t end) {
    double minDot = INFINITY, maxDot = -INFINITY;
    for (size_t i = begin; i < end; ++i) {
      if (i + kAhead < end) __builtin_prefetch(&scene.facePlanesWorld[seenFaces_[i + kAhead]]);
      const FacePlane& plane = scene.facePlanesWorld[seenFaces_[i]];
      const double dot =
          Dot(plane.normal, sunWorld) * (plane.FacesPoint(view.eyeWorld) ? 1.0 : -1.0);
      seenSunDots_[i] = dot;
      minDot = std::min(minDot, dot);
      maxDot = std::max(maxDot, dot);
    }
    workerDotRanges_[static_cast<size_t>(worker)] = {minDot, maxDot};
  });
  double minDot = INFINITY, maxDot = -INFINITY;
  for (const auto& [low, high] : workerDotRanges_) {
    minDot = std::min(minDot, low);
    maxDot = std::max(maxDot, high);
  }
  // Step 2: levels and intensities per face.
  const ShadeRamp& ramp = *plan.ramp;
  ForRanges(pool, count, [&](int, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const double shade = plan.mode == ShadeMode::kContrast
                               ? ContrastIntensity(seenSunDots_[i], minDot, maxDot, plan.ambient)
                               : LambertIntensity(seenSunDots_[i], plan.ambient);
      const double intensity = plan.darkInk ? 1.0 - shade : shade;
      if (levels) {
        faceLevels_[seenFaces_[i]] = static_cast<int16_t>(ramp.LevelFor(intensity));
      }
      const double clamped = std::isnan(intensity) ? 0.0 : std::clamp(intensity, 0.0, 1.0);
      faceIntensities_[seenFaces_[i]] = static_cast<uint8_t>(std::lround(255.0 * clamped));
    }
  });
}

// Cells [begin, end): level, intensity and ramp glyph of their face.
void ShadeStage::ShadeCellRange(const ShadePlan& plan, size_t begin, size_t end,
                                CellBuffer& cells) {
  const auto& faces = cells.FaceNumbers();
  auto& glyphs = cells.Glyphs();
  auto& levels = cells.Levels();
  auto& intensities = cells.Intensities();
  const ShadeRamp& ramp = *plan.ramp;  // in a register: the byte stores below may alias the plan
  for (size_t i = begin; i < end; ++i) {
    if (faces[i] == 0) continue;
    levels[i] = faceLevels_[faces[i] - 1];
    intensities[i] = faceIntensities_[faces[i] - 1];
    glyphs[i] = ramp.Glyph(levels[i]);
  }
}

// Unmarks the seen faces' levels; returns how many faces were seen.
int ShadeStage::EndSeenFaces() {
  for (const uint32_t f : seenFaces_) faceLevels_[f] = -1;
  return static_cast<int>(seenFaces_.size());
}

}  // namespace termshade
