#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "geometry/Mesh.h"
#include "io/read/FileBytes.h"
#include "io/read/LoadError.h"

namespace termshade {

/// True when the bytes have the exact layout of a binary STL: an 80-byte
/// header, a little-endian uint32 triangle count n, then n records of 50 bytes.
bool IsBinaryStlLayout(std::string_view bytes);

/// For bytes that are neither a binary STL's exact layout nor an ASCII
/// STL's ("solid" first, as the importer tells them): the error saying how
/// the size misses the layout its triangle count gives (a file cut short,
/// or bytes after the last record). Nothing for every other file.
std::optional<LoadError> MisSizedBinaryStl(std::string_view bytes, const std::string& path);

/// True when the header asks for per-face colours (Materialise "COLOR="),
/// which the importer decodes; the fast reader leaves such files to it.
bool BinaryStlHasColours(std::string_view bytes);

/// Reads a binary STL of that layout into one face per triangle, in file
/// order. Exactly equal positions become one vertex (meshoptimizer's remap,
/// first occurrence first), so shared edges are shared in the mesh. owned,
/// when given, holds the bytes viewed: the records are copied out of it
/// (FileBytes::CopyOut: pread for a mapped file, whose pages are never
/// touched; held bytes handed back as they are read), and it is freed
/// (empty) once the mesh has the vertices.
/// The records are welded in runs, one a load thread, whose positions are
/// then numbered in file order (tables of 12-byte keys, not the records).
Loaded<Mesh> ReadBinaryStl(std::string_view bytes, const std::string& path,
                           FileBytes* owned = nullptr);

/// ReadBinaryStl in partCount runs of triangles, each on its own thread:
/// the same mesh for every partCount (what tests check).
Loaded<Mesh> ReadBinaryStlInParts(std::string_view bytes, const std::string& path, size_t partCount,
                                  FileBytes* owned = nullptr);

}  // namespace termshade
