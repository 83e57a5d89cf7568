#pragma once

#include "geometry/Camera.h"
#include "geometry/Scene.h"

namespace termshade {

/// How the projection is fitted. kSpec: the bounding sphere fills 9/10 of
/// the window's smaller half-extent (render's default; its dumps and the
/// goldens). kOrbit: the viewer's framing, `render --fit` (FitOrbitProjection):
/// as large as keeps every vertex inside the window at every orbit angle.
enum class Framing { kSpec, kOrbit };

/// The camera for a view of a scene in a widthCells x heightCells window. The
/// projection is fitted once, at the scene's default distance, so orbiting
/// never changes the model's size and a larger rho makes it smaller.
Camera FitCamera(const Scene& scene, const ViewParams& view, int widthCells, int heightCells,
                 double cellAspect, Framing framing = Framing::kSpec);

/// Like FitCamera, but fitted as if the eye were at distance fitRho (the
/// viewer's "refit" passes the current distance).
Camera FitCameraAt(const Scene& scene, const ViewParams& view, double fitRho, int widthCells,
                   int heightCells, double cellAspect, Framing framing = Framing::kSpec);

}  // namespace termshade
