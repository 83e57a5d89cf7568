#pragma once

#include "geometry/Mat4.h"
#include "geometry/ViewParams.h"

namespace termshade {

/// The viewing transform V of SPEC 2, as a matrix on column vectors (V transposed).
Mat4 EyeFromWorld(const ViewParams& view);

/// The eye E in world coordinates.
Vec3 EyePositionWorld(const ViewParams& view);

}  // namespace termshade
