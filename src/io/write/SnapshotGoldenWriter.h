#pragma once

#include <string>

#include "raster/SnapshotGolden.h"

namespace termshade {

/// Numbers as the golden writes them: the shortest text that reads back to
/// the same double (std::to_chars), locale-independent.
std::string SnapshotNumber(double value);

/// The golden as text (docs/snapshot-testing.md#the-golden-file): a header
/// with the options, then per view its text frame between `|` bars, its
/// samples' faces run-length coded a sample row a line (`=`: as the row
/// above), and the shade of each face seen (`face:shade`).
std::string FormatSnapshotGolden(const SnapshotGolden& golden);

}  // namespace termshade
