#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "geometry/Mesh.h"
#include "io/read/FileBytes.h"
#include "io/read/LoadError.h"

namespace termshade {

/// The dedicated readers for the formats big scans come in: binary STL, PLY
/// and geometry-only OBJ, faster and smaller than Assimp and giving the same
/// mesh (Assimp stays the reference: see LoadOptions::importerOnly).
/// `format` is the lower-case extension. nullopt when none of them takes the
/// file (another format, ASCII STL, colours or materials), so the caller
/// imports it with Assimp. Positions are welded as on the Assimp path, and
/// the up axis is the format's convention (SPEC 10). owned, when given,
/// holds the bytes viewed: freed (empty) once a reader has taken the file
/// (as early as the reader can); left whole when the result is nullopt.
std::optional<Loaded<Mesh>> ReadWithOwnReader(std::string_view bytes, const std::string& format,
                                              const std::string& displayName,
                                              size_t memoryBudgetBytes, FileBytes* owned = nullptr);

}  // namespace termshade
