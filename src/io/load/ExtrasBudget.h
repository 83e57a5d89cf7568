#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "geometry/Scene.h"

namespace termshade {

/// Bytes a prepared scene holds while its frames are drawn, from its counts
/// (EstimatePreparedBytes: vertices, triangles, planes, faces, the
/// renderer's buffers and a base).
size_t EstimateSceneBytes(const Scene& scene);

/// Whether an optional structure of a scene (the ray hierarchy, the levels of
/// detail: the frames are right without them) may be built: nullopt when its
/// extraBytes fit beside the scene and heldBytes already built within
/// budgetBytes; otherwise why not, for the user ("<what> skipped: ...").
std::optional<std::string> ExtraOverBudget(std::string_view what, size_t extraBytes,
                                           const Scene& scene, size_t heldBytes,
                                           size_t budgetBytes);

}  // namespace termshade
