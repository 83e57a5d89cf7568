#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// The problem with a header whose element counts (OFF vertices and faces,
/// PLY elements) could not fit in the bytes that follow it, before anything
/// is allocated for them; nullopt when the counts fit or the header is not understood.
std::optional<std::string> CheckHeaderCounts(std::string_view format, std::string_view bytes);

/// Peak bytes an import of fileBytes of the given format takes, measured on
/// generated meshes and rounded up (the importer's own structures included).
size_t EstimateImportBytes(std::string_view format, size_t fileBytes);

/// Peak bytes our own reader (OBJ, binary STL, PLY: OwnReaders.h) takes for
/// fileBytes of the format, through preparation and the first frame, for
/// files like the generated spheres; ReadWithOwnReader's caller checks the
/// real counts afterwards (EstimatePreparedBytes). nullopt for other formats.
std::optional<size_t> EstimateOwnReaderBytes(std::string_view format, size_t fileBytes);

/// The least any format's load of fileBytes takes: what a file must pass
/// before it is read.
size_t EstimateLeastLoadBytes(size_t fileBytes);

/// The largest file whose least load (EstimateLeastLoadBytes) fits in
/// budgetBytes: how much of a stream (standard input) may be held.
size_t LargestLoadableBytes(size_t budgetBytes);

/// Bytes a mesh of this size takes once loaded and prepared for rendering.
size_t EstimateMeshBytes(size_t vertices, size_t corners, size_t faces);

/// Peak bytes reading a mesh of this size from fileBytes of file (held
/// while it is read), preparing it and drawing its first frame take
/// (PrepareScene's arrays, the renderer's buffers); largestFaceCorners: the
/// corners of its largest face, whose triangulation needs work arrays of
/// its own (kTriangulateBytesPerCorner a corner).
size_t EstimatePreparedBytes(size_t fileBytes, size_t vertices, size_t corners, size_t faces,
                             size_t largestFaceCorners = 3);

/// Work bytes the triangulation of one face takes per corner (Triangulate.h:
/// the corners' positions, kept list, projected points, links, triangles).
inline constexpr double kTriangulateBytesPerCorner = 72;

/// The message for a model that needs more memory than the budget allows.
std::string OverBudgetMessage(double neededBytes, size_t budgetBytes);

/// Parses a byte count with an optional K, M, G or T suffix (powers of 1024,
/// optionally followed by "iB" or "B"): "4G", "512M", "1.5GiB", "1000000";
/// 1 byte to 64 TiB, else nullopt.
std::optional<size_t> ParseByteCount(std::string_view text);

}  // namespace termshade
