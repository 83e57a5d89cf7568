#pragma once

#include "geometry/Mesh.h"

namespace termshade {

/// Renumbers the vertices in the order the faces' corners (then the
/// segments) first use them, as a welding importer numbers them. Neighbouring
/// faces then mostly touch neighbouring vertices, which keeps scene
/// preparation and the frame in cache on files whose vertex list is in another
/// order. Vertices no face or segment uses are dropped. Faces, their order and
/// their corners' positions are unchanged.
void NumberVerticesByFirstUse(Mesh& mesh);

}  // namespace termshade
