#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "geometry/Mesh.h"

namespace termshade {

/// Interchange formats a mesh can be written in, for benchmarks and tests
/// against other viewers: ASCII OBJ, binary STL, binary little-endian PLY.
enum class ExportFormat { kDat, kObj, kStl, kPly };

/// The format named by a file's extension (.dat .obj .stl .ply); nullopt otherwise.
std::optional<ExportFormat> ExportFormatFromPath(std::string_view path);

/// Writes the mesh in the given format. OBJ and PLY keep polygons as they
/// are; STL (triangles only) fans each face from its first corner.
std::string ExportMesh(const Mesh& mesh, ExportFormat format);

}  // namespace termshade
