#pragma once

#include <string>
#include <vector>

#include "raster/SnapshotCompare.h"
#include "raster/SnapshotRender.h"

namespace termshade {

/// What `render --expect` prints on stderr: a line a view (how many samples
/// differ, of what kind, in how many cells, against the tolerance) and, for
/// each view beyond the tolerance, the golden and actual frames side by side
/// with the cells holding counted samples marked (FrameDiff.h). Escaped.
std::string SnapshotReport(const SnapshotOutcome& outcome, const std::vector<SnapshotFrame>& golden,
                           const std::vector<SnapshotFrame>& actual,
                           const SnapshotSettings& settings, const SnapshotTolerance& tolerance,
                           bool colour);

}  // namespace termshade
