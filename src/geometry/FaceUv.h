#pragma once

#include <array>
#include <cstdint>

#include "geometry/Scene.h"
#include "geometry/Vec3.h"

namespace termshade {

/// Fills scene.textures' per-triangle coordinates and the affine maps of its
/// big textured faces, once the triangles and planes are made (PrepareScene):
/// each face's corners sorted once, so a polygon of n corners costs n log n.
void BuildFaceUvs(Scene& scene);

/// The texture coordinates at a point on a textured face's plane (world
/// space): its barycentric weights in the face's triangle that holds it (or
/// comes nearest) applied to that triangle's corners' coordinates; on a face
/// of more than kMostScannedTriangles triangles, the face's fitted affine map.
std::array<double, 2> FaceUvAt(const Scene& scene, uint32_t face, Vec3 pWorld);

}  // namespace termshade
