#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "raster/SnapshotRender.h"
#include "raster/SnapshotSamples.h"
#include "shade/CellColour.h"

namespace termshade {

/// How many counted samples a view may differ by and still match
/// (`--tolerance N`, or `N%` of the samples showing the model).
struct SnapshotTolerance {
  double amount = 0.0;
  bool percent = false;

  /// The samples allowed for a view whose model covers `modelSamples`.
  int64_t AllowedSamples(int64_t modelSamples) const;
  /// "0", "12", "0.5%": as given on the command line.
  std::string ToString() const;
};

/// Parses `--tolerance`: a count of samples (12) or a share of the model's
/// samples (0.5%); nullopt when it is neither (or negative, or not finite).
std::optional<SnapshotTolerance> ParseSnapshotTolerance(std::string_view text);

/// One view compared, sample by sample (docs/snapshot-testing.md#the-tolerance-model).
/// A sample differs when its face differs, or its face is the same and its
/// shade is more than one step away. Differences are then forgiven in turn:
/// - edge: the golden's face (and shade, within a step) is among the actual's
///   3 x 3 neighbours of the sample and the actual's among the golden's: an
///   edge moved by at most one sample;
/// - isolated: a remaining difference with no remaining difference among
///   its 8 neighbours.
/// What is left is counted and measured against the tolerance.
struct SnapshotDifference {
  int64_t modelSamples = 0;      ///< samples showing a face in the golden or the actual
  int64_t differingSamples = 0;  ///< face differs, or shade by more than a step
  int64_t shadeStepSamples = 0;  ///< same face, shade one step away (not a difference)
  int64_t edgeSamples = 0;       ///< forgiven as an edge moved by at most one sample
  int64_t isolatedSamples = 0;   ///< forgiven as a lone sample
  int64_t countedSamples = 0;    ///< the rest
  int64_t shadeSamples = 0;      ///< counted samples whose face is the same (a shade change)
  std::vector<uint8_t> counted;  ///< per sample, 1 where counted (empty: sizes differ)
  bool sizesDiffer = false;      ///< the grids differ in size: every sample counts
  /// Texture colours, where the golden has them: cells textured in either,
  /// and those whose colour is gone, new, or off by more than kTextureColourStep.
  int64_t texturedCells = 0;
  int64_t textureCells = 0;

  bool Within(const SnapshotTolerance& tolerance) const {
    return !sizesDiffer && countedSamples <= tolerance.AllowedSamples(modelSamples) &&
           textureCells <= tolerance.AllowedSamples(texturedCells);
  }
};

/// Two texture colours of a cell look alike within this many sRGB steps a channel.
constexpr int kTextureColourStep = kAlbedoStepSeen;

/// Counts the cells whose texture colours differ (SnapshotDifference's texture
/// fields); nothing when the golden has none (a golden made before textures).
void CompareTextureColours(const std::vector<uint32_t>& golden, const std::vector<uint32_t>& actual,
                           SnapshotDifference& difference);

SnapshotDifference CompareSnapshotSamples(const SnapshotSamples& golden,
                                          const SnapshotSamples& actual);

/// One view of a snapshot compared.
struct SnapshotViewOutcome {
  std::string name;
  SnapshotDifference difference;
  bool within = false;  ///< within the tolerance
};

/// Every view of a snapshot compared with its golden, view by view (by name;
/// a view missing from either side fails).
struct SnapshotOutcome {
  std::vector<SnapshotViewOutcome> views;
  bool Passed() const;
};

SnapshotOutcome CompareSnapshotFrames(const std::vector<SnapshotFrame>& golden,
                                      const std::vector<SnapshotFrame>& actual,
                                      const SnapshotTolerance& tolerance);

/// Per cell of a widthCells x heightCells frame, 1 where a counted sample lies in it.
std::vector<uint8_t> CellsWithCountedSamples(const SnapshotDifference& difference, SampleGrid grid,
                                             int widthCells, int heightCells);

}  // namespace termshade
