#pragma once

#include <string>

namespace termshade::test {

/// The goldens are to be rewritten: TERMSHADE_UPDATE_GOLDEN set, or
/// TERMSHADE_UPDATE=1 as for `render --expect` (docs/snapshot-testing.md).
bool UpdatingGoldens();

/// A text frame against its golden file, byte for byte; a failure prints the
/// side-by-side diff `render --expect` prints (io/write/FrameDiff.h). Writes
/// the file instead when UpdatingGoldens().
void ExpectTextGolden(const std::string& path, const std::string& actual);

}  // namespace termshade::test
