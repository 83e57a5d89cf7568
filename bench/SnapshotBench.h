#pragma once

#include <string>
#include <vector>

namespace termshade {

/// `termshade bench snapshots`: how often `render --expect` catches one
/// vertex moved, against the size of the move (a share of the bounding-box
/// diagonal), for a few tolerances. The vertex is a corner of a face seen in
/// the default view, moved in a random direction; the golden is the model as
/// it was, with every view of a default snapshot (docs/snapshot-testing.md).
struct SnapshotBenchOptions {
  std::vector<std::string> modelPaths;  ///< empty: data/*.dat and a few corpus models
  std::string dataDirectory = "data";
  int trials = 20;  ///< moves per model and size
  int widthCells = 80;
  int heightCells = 24;
  std::vector<double> moveShares{1e-5, 1e-4, 1e-3, 3e-3, 1e-2, 3e-2};
  std::vector<std::string> tolerances{"0", "10", "100", "1%"};
};

int RunSnapshotBench(const SnapshotBenchOptions& options);

}  // namespace termshade
