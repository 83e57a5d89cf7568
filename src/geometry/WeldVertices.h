#pragma once

#include "geometry/Mesh.h"

namespace termshade {

/// Makes bit-identical positions one vertex (meshoptimizer's remap, first
/// occurrence first) and renumbers faces and segments, so faces that share a
/// corner in space share it in the mesh: what edge adjacency, closed-solid
/// and orientation tests need from importers that give each face its own
/// corners. Faces, their order and their corners' positions are unchanged.
void WeldExactPositions(Mesh& mesh);

}  // namespace termshade
