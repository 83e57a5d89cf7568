#pragma once

#include "geometry/Projection.h"
#include "geometry/ViewParams.h"

namespace termshade {

/// Everything that fixes a view of a scene: where the eye is and how eye space maps to cells.
struct Camera {
  ViewParams view;
  Projection projection;
};

}  // namespace termshade
