#pragma once

#include <string>
#include <string_view>

#include "io/read/LoadError.h"
#include "raster/SnapshotGolden.h"

namespace termshade {

/// Largest golden file read (a 4-view 512x170 golden of a dense model is ~20 MB).
constexpr size_t kMaxSnapshotGoldenBytes = size_t{256} << 20;
/// Most samples a snapshot view may hold (a 4x8 grid: 512 x 128 cells, or 80x24 at 4x8 is 61440).
constexpr int64_t kMaxSnapshotViewSamples = int64_t{1} << 22;

/// Parses a golden written by FormatSnapshotGolden; errors name the line
/// (`name:line: message`). Every number is range-checked before use.
Loaded<SnapshotGolden> ParseSnapshotGolden(std::string_view text, const std::string& name);

/// Reads and parses a golden file (a regular file only).
Loaded<SnapshotGolden> ReadSnapshotGolden(const std::string& path);

}  // namespace termshade
