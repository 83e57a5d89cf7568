#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "geometry/Mesh.h"
#include "io/read/FileBytes.h"
#include "io/read/LoadError.h"

namespace termshade {

/// Reads a Wavefront OBJ's geometry straight into a mesh that keeps the
/// file's own vertex indexing: `v` positions and `f` polygons (v, v/vt,
/// v//vn, v/vt/vn, negative indices counting back), `l` two-corner lines as
/// segments; texture coordinates, normals, groups and smoothing are skipped.
/// Errors are located (file:line:column). The vertex and face counts are
/// taken in a first pass and checked against memoryBudgetBytes before
/// anything is allocated. nullopt when the file uses what the importer
/// decodes and this reader does not (materials, vertex colours, free-form
/// curves), so the caller hands it to Assimp.
/// Files of a few MB up are read in chunks of whole lines, one a core.
/// owned, when given, holds the text viewed: it is freed (empty) as soon as
/// the geometry is parsed, before the rest of the mesh is built.
std::optional<Loaded<Mesh>> ReadObj(std::string_view text, const std::string& path,
                                    size_t memoryBudgetBytes, FileBytes* owned = nullptr);

/// ReadObj with the text cut into chunkCount chunks of whole lines, each
/// read on its own thread; the mesh and any error are the same for every
/// chunkCount (what tests check).
std::optional<Loaded<Mesh>> ReadObjInChunks(std::string_view text, const std::string& path,
                                            size_t memoryBudgetBytes, size_t chunkCount,
                                            FileBytes* owned = nullptr);

}  // namespace termshade
