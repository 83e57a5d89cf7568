#include "shade/GlyphMode.h"

#include <array>

namespace termshade {
namespace {

struct ModeInfo {
  GlyphMode mode;
  std::string_view name;
  SampleGrid grid;
};

constexpr std::array<ModeInfo, kGlyphModeCount> kModes{{
    {GlyphMode::kRamp, "ramp", {1, 1}},
    {GlyphMode::kAscii, "ascii", {2, 4}},
    {GlyphMode::kBlocks, "blocks", {1, 2}},
    {GlyphMode::kQuadrants, "quadrants", {2, 2}},
    {GlyphMode::kSextants, "sextants", {2, 3}},
    {GlyphMode::kBraille, "braille", {2, 4}},
}};

const ModeInfo& InfoOf(GlyphMode mode) {
  return kModes[static_cast<size_t>(mode)];
}

}  // namespace

std::string_view GlyphModeName(GlyphMode mode) {
  return InfoOf(mode).name;
}

std::optional<GlyphMode> ParseGlyphMode(std::string_view name) {
  for (const ModeInfo& info : kModes) {
    if (info.name == name) return info.mode;
  }
  return std::nullopt;
}

GlyphMode NextGlyphMode(GlyphMode mode) {
  return static_cast<GlyphMode>((static_cast<int>(mode) + 1) % kGlyphModeCount);
}

bool NeedsUtf8(GlyphMode mode) {
  return mode != GlyphMode::kRamp && mode != GlyphMode::kAscii;
}

GlyphMode PickGlyphMode(bool utf8, bool colour, std::string_view term,
                        std::string_view termProgram) {
  if (!utf8 || !colour) return GlyphMode::kAscii;
  static constexpr std::string_view kSextantTerms[] = {"kitty", "foot", "wezterm", "ghostty",
                                                       "contour"};
  for (std::string_view known : kSextantTerms) {
    if (term.find(known) != std::string_view::npos) return GlyphMode::kSextants;
  }
  static constexpr std::string_view kSextantPrograms[] = {"WezTerm", "ghostty"};
  for (std::string_view known : kSextantPrograms) {
    if (termProgram == known) return GlyphMode::kSextants;
  }
  return GlyphMode::kQuadrants;
}

SampleGrid ModeSampleGrid(GlyphMode mode) {
  return InfoOf(mode).grid;
}

SampleGrid ColourSubsamples(GlyphMode mode) {
  // Chosen by bench fidelity: each 8 samples a cell. Sextants gain too little
  // from more (0.001 blurred SSIM for 4x the samples) to pay for them.
  switch (mode) {
    case GlyphMode::kBlocks:
      return {2, 2};
    case GlyphMode::kQuadrants:
      return {1, 2};
    default:
      return {1, 1};
  }
}

}  // namespace termshade
