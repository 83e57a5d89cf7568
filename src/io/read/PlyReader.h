#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "geometry/Mesh.h"
#include "io/read/LoadError.h"

namespace termshade {

/// Reads a PLY file (ascii, binary little- or big-endian) straight into a
/// mesh that keeps the file's own vertex indexing: vertex x, y, z of any
/// numeric type and the face element's vertex index lists, in file order;
/// other elements and properties are skipped. Counts are checked against the
/// file's size before anything is allocated; an index out of range is an
/// error. nullopt when the file carries what the importer decodes and this
/// reader does not (vertex or face colours, triangle strips), so the caller
/// hands it to Assimp.
/// A file whose mesh would need more than memoryBudgetBytes is refused with
/// a message saying how much it needs.
std::optional<Loaded<Mesh>> ReadPly(std::string_view bytes, const std::string& path,
                                    size_t memoryBudgetBytes);

/// For bytes about to go to Assimp under any name: its PLY importer takes any
/// content whose first line begins with "ply" (any case), and Assimp 5.2.5
/// loops forever on a header without 'end_header', and splits header lines
/// at NUL and form feed too. Such content must have a header this reader
/// accepts, in plain text lines; the located error otherwise, nullopt when
/// it has or is not PLY.
std::optional<LoadError> CheckPlyHeaderForImporter(std::string_view bytes, const std::string& path);

}  // namespace termshade
