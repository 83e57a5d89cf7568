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

/// Bytes a mesh of this size takes once loaded and prepared for rendering.
size_t EstimateMeshBytes(size_t vertices, size_t corners, size_t faces);

/// The message for a model that needs more memory than the budget allows.
std::string OverBudgetMessage(double neededBytes, size_t budgetBytes);

/// Parses a byte count with an optional K, M, G or T suffix (powers of 1024,
/// optionally followed by "iB" or "B"): "4G", "512M", "1.5GiB", "1000000".
std::optional<size_t> ParseByteCount(std::string_view text);

}  // namespace termshade
