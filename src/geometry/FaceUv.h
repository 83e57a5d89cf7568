#pragma once

#include <array>
#include <cstdint>

#include "geometry/Scene.h"
#include "geometry/Vec3.h"

namespace termshade {

/// The texture coordinates at a point on a textured face's plane (world
/// space): its barycentric weights in the face's triangle that holds it (or
/// comes nearest), applied to that triangle's corners' coordinates.
std::array<double, 2> FaceUvAt(const Scene& scene, uint32_t face, Vec3 pWorld);

}  // namespace termshade
