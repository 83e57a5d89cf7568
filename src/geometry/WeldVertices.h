#pragma once

#include "geometry/Mesh.h"

namespace termshade {

/// Makes bit-identical positions one vertex (meshoptimizer's remap, first
/// occurrence first) and renumbers faces and segments, so faces that share a
/// corner in space share it in the mesh: what edge adjacency, closed-solid
/// and orientation tests need from importers that give each face its own
/// corners. Faces, their order and their corners' positions are unchanged.
void WeldExactPositions(Mesh& mesh);

/// WeldExactPositions, then NumberVerticesByFirstUse, in one step (a hash
/// table, no vertex copies): the vertices are the distinct positions the faces (then the
/// segments) use, numbered by first use; unused vertices are dropped. What
/// the own readers give for indexed formats, identical to the two steps.
void WeldAndNumberByFirstUse(Mesh& mesh);

}  // namespace termshade
