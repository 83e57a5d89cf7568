#include "raster/SnapshotCompare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace termshade {
namespace {

// True when `samples` shows `face` with a shade within one step of `shade`
// at (x, y) or one of its 8 neighbours.
bool NearbyShows(const SnapshotSamples& samples, int x, int y, uint32_t face, int shade) {
  for (int dy = -1; dy <= 1; ++dy) {
    const int ny = y + dy;
    if (ny < 0 || ny >= samples.heightSamples) continue;
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx;
      if (nx < 0 || nx >= samples.widthSamples) continue;
      const size_t n = samples.Index(nx, ny);
      if (samples.faces[n] == face && std::abs(samples.shades[n] - shade) <= 1) return true;
    }
  }
  return false;
}

}  // namespace

int64_t SnapshotTolerance::AllowedSamples(int64_t modelSamples) const {
  if (!percent) return static_cast<int64_t>(std::floor(amount));
  return static_cast<int64_t>(std::floor(amount / 100.0 * static_cast<double>(modelSamples)));
}

std::string SnapshotTolerance::ToString() const {
  char text[64];
  std::snprintf(text, sizeof text, "%g%s", amount, percent ? "%" : "");
  return text;
}

std::optional<SnapshotTolerance> ParseSnapshotTolerance(std::string_view text) {
  SnapshotTolerance tolerance;
  if (!text.empty() && text.back() == '%') {
    tolerance.percent = true;
    text.remove_suffix(1);
  }
  if (text.empty() || text.size() > 32) return std::nullopt;
  const std::string copy(text);
  char* end = nullptr;
  tolerance.amount = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size() || !std::isfinite(tolerance.amount) ||
      tolerance.amount < 0.0 || (tolerance.percent && tolerance.amount > 100.0) ||
      tolerance.amount > 1e12) {
    return std::nullopt;
  }
  return tolerance;
}

SnapshotDifference CompareSnapshotSamples(const SnapshotSamples& golden,
                                          const SnapshotSamples& actual) {
  SnapshotDifference difference;
  if (golden.widthSamples != actual.widthSamples || golden.heightSamples != actual.heightSamples ||
      golden.faces.size() != actual.faces.size() || golden.shades.size() != golden.faces.size() ||
      actual.shades.size() != actual.faces.size()) {
    difference.sizesDiffer = true;
    difference.modelSamples =
        static_cast<int64_t>(std::max(golden.faces.size(), actual.faces.size()));
    difference.differingSamples = difference.countedSamples = difference.modelSamples;
    return difference;
  }
  const int width = golden.widthSamples, height = golden.heightSamples;
  // Step 1: differences, less those forgiven as an edge moved by one sample.
  std::vector<uint8_t> remaining(golden.faces.size(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = golden.Index(x, y);
      const uint32_t g = golden.faces[i], a = actual.faces[i];
      if (g != 0 || a != 0) ++difference.modelSamples;
      const int gs = golden.shades[i], as = actual.shades[i];
      if (g == a) {
        const int steps = std::abs(gs - as);
        if (steps == 1) ++difference.shadeStepSamples;
        if (steps <= 1) continue;
      }
      ++difference.differingSamples;
      if (g != a && NearbyShows(actual, x, y, g, gs) && NearbyShows(golden, x, y, a, as)) {
        ++difference.edgeSamples;
        continue;
      }
      remaining[i] = 1;
    }
  }
  // Step 2: lone samples forgiven; the rest counted.
  difference.counted.assign(golden.faces.size(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = golden.Index(x, y);
      if (remaining[i] == 0) continue;
      bool lone = true;
      for (int dy = -1; dy <= 1 && lone; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          if (remaining[golden.Index(nx, ny)] != 0) {
            lone = false;
            break;
          }
        }
      }
      if (lone) {
        ++difference.isolatedSamples;
        continue;
      }
      difference.counted[i] = 1;
      ++difference.countedSamples;
      if (golden.faces[i] == actual.faces[i]) ++difference.shadeSamples;
    }
  }
  return difference;
}

bool SnapshotOutcome::Passed() const {
  return std::all_of(views.begin(), views.end(),
                     [](const SnapshotViewOutcome& view) { return view.within; });
}

void CompareTextureColours(const std::vector<uint32_t>& golden, const std::vector<uint32_t>& actual,
                           SnapshotDifference& difference) {
  if (golden.empty()) return;
  for (size_t i = 0; i < golden.size(); ++i) {
    const uint32_t g = golden[i], a = i < actual.size() ? actual[i] : 0U;
    if (g == 0 && a == 0) continue;
    ++difference.texturedCells;
    if (!AlbedosAlike(g, a, kTextureColourStep)) ++difference.textureCells;
  }
}

SnapshotOutcome CompareSnapshotFrames(const std::vector<SnapshotFrame>& golden,
                                      const std::vector<SnapshotFrame>& actual,
                                      const SnapshotTolerance& tolerance) {
  SnapshotOutcome outcome;
  const SnapshotSamples none;
  for (const SnapshotFrame& expected : golden) {
    const auto match = std::find_if(actual.begin(), actual.end(), [&](const SnapshotFrame& frame) {
      return frame.view.name == expected.view.name;
    });
    SnapshotViewOutcome view;
    view.name = expected.view.name;
    view.difference =
        CompareSnapshotSamples(expected.samples, match != actual.end() ? match->samples : none);
    if (match != actual.end()) {
      CompareTextureColours(expected.textureColours, match->textureColours, view.difference);
    }
    view.within = view.difference.Within(tolerance);
    outcome.views.push_back(std::move(view));
  }
  for (const SnapshotFrame& frame : actual) {
    const bool known = std::any_of(golden.begin(), golden.end(), [&](const SnapshotFrame& g) {
      return g.view.name == frame.view.name;
    });
    if (known) continue;
    SnapshotViewOutcome view;
    view.name = frame.view.name;
    view.difference = CompareSnapshotSamples(none, frame.samples);
    outcome.views.push_back(std::move(view));
  }
  return outcome;
}

std::vector<uint8_t> CellsWithCountedSamples(const SnapshotDifference& difference, SampleGrid grid,
                                             int widthCells, int heightCells) {
  std::vector<uint8_t> cells(static_cast<size_t>(widthCells) * heightCells,
                             difference.sizesDiffer ? 1 : 0);
  if (difference.sizesDiffer) return cells;
  const int widthSamples = widthCells * grid.across;
  for (size_t i = 0; i < difference.counted.size(); ++i) {
    if (difference.counted[i] == 0) continue;
    const int x = static_cast<int>(i % widthSamples), y = static_cast<int>(i / widthSamples);
    const int col = x / grid.across, row = y / grid.down;
    if (col < widthCells && row < heightCells)
      cells[static_cast<size_t>(row) * widthCells + col] = 1;
  }
  return cells;
}

}  // namespace termshade
