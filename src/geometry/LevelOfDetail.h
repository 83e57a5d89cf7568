#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/Camera.h"
#include "geometry/Scene.h"

namespace termshade {

/// Whether a simplified copy of the model may be drawn in place of the exact one.
enum class DetailMode { kOff, kAuto };

std::string_view DetailModeName(DetailMode mode);
std::optional<DetailMode> ParseDetailMode(std::string_view name);

/// One simplified copy of a scene (meshoptimizer's edge collapse): the same
/// world space, fit and up axis as the exact scene, one face per triangle.
struct DetailLevel {
  Scene scene;
  /// Per face of `scene`: the exact scene's face it stands for (0-based); its colour too.
  std::vector<uint32_t> sourceFaces;
  /// How far the surface may have moved, model units (meshoptimizer's estimate).
  double errorModelUnits = 0.0;
};

/// The simplified copies of one scene, finest first: each has fewer triangles
/// than the one before (and than the exact scene).
struct DetailLevels {
  size_t exactTriangles = 0;
  std::vector<DetailLevel> levels;
  /// Why a scene big enough for levels has none (degenerate input); empty otherwise.
  std::string skippedBecause;
};

struct DetailBuildOptions {
  double reduction = 4.0;             ///< triangles of one level / the next
  size_t minSourceTriangles = 20000;  ///< smaller scenes get no levels
  size_t minTriangles = 1000;         ///< no level below this
  /// Largest deviation a level may have, relative to the model's extent.
  double maxRelativeError = 0.02;
  const std::atomic<bool>* cancel = nullptr;  ///< polled between steps and levels
};

/// Builds the levels of `exact` (none for a small scene, or when cancelled).
DetailLevels BuildDetailLevels(const Scene& exact, const DetailBuildOptions& options = {});

/// A coarse copy in one pass (vertex clustering): the vertices snapped to
/// the first vertex of their cell in a grid of cellModelUnits over the
/// bounding sphere (at most kMostClusterCellsAcross cells across), the
/// triangles left with three distinct corners kept. Much cheaper to build
/// than BuildDetailLevels' edge collapse, and coarser: `render --budget`'s.
DetailLevel BuildClusteredLevel(const Scene& exact, double cellModelUnits);
constexpr int kMostClusterCellsAcross = 128;

/// Peak bytes BuildDetailLevels takes beside the exact scene: meshoptimizer's
/// work arrays (per vertex of the scene, used or not) and the levels it keeps;
/// 0 for a scene too small for levels. Measured on generated spheres
/// (docs/load-and-memory.md), rounded up.
size_t EstimateDetailBuildBytes(const Scene& exact, const DetailBuildOptions& options = {});

/// How finely a frame needs the model: sample grid per cell and how large the
/// mean projected triangle may be.
struct DetailTarget {
  int samplesAcross = 1;  ///< per cell
  int samplesDown = 1;
  /// The mean projected triangle's area, in samples, that a level may reach.
  double samplesPerTriangle = 0.25;
  /// The largest projected deviation a level may have, in samples.
  double maxErrorSamples = 0.25;
};

/// Triangles the model needs in this view: its projected disc (front and
/// back surfaces both cover it, so twice its area) over samplesPerTriangle.
/// Infinite when the eye is near or inside the model's bounding sphere.
double TrianglesNeeded(const Scene& exact, const Camera& camera, const DetailTarget& target);

/// 0: the exact scene; i > 0: levels.levels[i - 1]. The coarsest level that
/// still has TrianglesNeeded triangles and a projected error within bounds.
size_t ChooseDetailLevel(const DetailLevels& levels, const Scene& exact, const Camera& camera,
                         const DetailTarget& target);

/// The scene of ChooseDetailLevel's answer.
const Scene& DetailScene(const DetailLevels& levels, const Scene& exact, size_t level);

}  // namespace termshade
