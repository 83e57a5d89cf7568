#include "io/write/SnapshotReport.h"

#include <algorithm>

#include "io/write/FrameDiff.h"

namespace termshade {
namespace {

const SnapshotFrame* FindView(const std::vector<SnapshotFrame>& frames, const std::string& name) {
  const auto frame = std::find_if(frames.begin(), frames.end(),
                                  [&](const SnapshotFrame& f) { return f.view.name == name; });
  return frame != frames.end() ? &*frame : nullptr;
}

std::string Plural(int64_t count, const char* word) {
  return std::to_string(count) + " " + word + (count == 1 ? "" : "s");
}

}  // namespace

std::string SnapshotReport(const SnapshotOutcome& outcome, const std::vector<SnapshotFrame>& golden,
                           const std::vector<SnapshotFrame>& actual,
                           const SnapshotSettings& settings, const SnapshotTolerance& tolerance,
                           bool colour) {
  std::string out;
  for (const SnapshotViewOutcome& view : outcome.views) {
    const SnapshotDifference& d = view.difference;
    const std::vector<uint8_t> cells =
        CellsWithCountedSamples(d, settings.samples, settings.widthCells, settings.heightCells);
    const int64_t markedCells = std::count(cells.begin(), cells.end(), uint8_t{1});
    out += "view " + view.name + ": ";
    if (d.sizesDiffer) {
      out += "missing from the golden or the actual frames\n";
      continue;
    }
    out += Plural(d.countedSamples, "sample") + " of " + std::to_string(d.modelSamples) + " differ";
    if (d.countedSamples > 0) {
      out += " (" + std::to_string(d.countedSamples - d.shadeSamples) + " show another face, " +
             std::to_string(d.shadeSamples) + " a shade more than a step away) in " +
             Plural(markedCells, "cell");
    }
    out += ", tolerance " + tolerance.ToString() + " (" +
           Plural(tolerance.AllowedSamples(d.modelSamples), "sample") + ")";
    if (d.texturedCells > 0) {
      out += "; texture colours: " + Plural(d.textureCells, "cell") + " of " +
             std::to_string(d.texturedCells) + " differ (tolerance " +
             Plural(tolerance.AllowedSamples(d.texturedCells), "cell") + ")";
    }
    out += ": ";
    out += view.within ? "matches" : "DIFFERS";
    if (d.edgeSamples + d.isolatedSamples > 0) {
      out += "; forgiven: " + std::to_string(d.edgeSamples) + " along edges moved by one sample, " +
             std::to_string(d.isolatedSamples) + " lone";
    }
    out += "\n";
    if (view.within) continue;
    const SnapshotFrame* g = FindView(golden, view.name);
    const SnapshotFrame* a = FindView(actual, view.name);
    if (g == nullptr || a == nullptr) continue;
    out += SideBySideFrameDiff(g->textRows, a->textRows, cells, settings.widthCells, colour);
  }
  return out;
}

}  // namespace termshade
