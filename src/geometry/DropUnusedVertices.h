#pragma once

#include "geometry/Mesh.h"

namespace termshade {

/// Removes vertices no face or segment uses, keeping the others' order, and
/// renumbers corners. Readers that keep a file's indexing call it so the
/// model's bounds (and so its centering and fit) are those of what is drawn,
/// as with importers that copy each face's corners.
void DropUnusedVertices(Mesh& mesh);

}  // namespace termshade
