#pragma once

#include <cstddef>
#include <span>

#include "geometry/EdgeAdjacency.h"
#include "geometry/FaceList.h"
#include "geometry/Mesh.h"
#include "geometry/Vec3.h"

namespace termshade {

/// Turns outward every closed part of the mesh (connected through shared
/// edges; every edge used by exactly two faces in opposite directions) whose
/// signed volume is negative, by reversing its faces' corner order (SPEC 10).
/// Open or non-manifold parts keep their winding. points: one per mesh
/// vertex, in any space that is a proper rotation plus shift of file space
/// (best centered, for the volume's rounding). Returns the faces reversed.
/// oneClosedPart, when given, is set to whether all faces form one part
/// with every edge closed, as given (before any reversal).
size_t OrientClosedPartsOutward(FaceList& faces, const EdgeAdjacency& edges,
                                std::span<const Vec3> points, bool* oneClosedPart = nullptr);

/// Reverses a face's corners in place, keeping its first corner and each
/// edge's hidden flag.
void ReverseFace(Mesh& mesh, size_t face);
void ReverseFace(FaceList& faces, size_t face);

}  // namespace termshade
