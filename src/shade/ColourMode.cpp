#include "shade/ColourMode.h"

namespace termshade {

std::optional<ColourMode> ParseColourMode(std::string_view name) {
  if (name == "none") return ColourMode::kNone;
  if (name == "16") return ColourMode::k16;
  if (name == "256") return ColourMode::k256;
  if (name == "truecolor" || name == "24bit") return ColourMode::kTrueColour;
  if (name == "auto") return ColourMode::kAuto;
  return std::nullopt;
}

std::string_view ColourModeName(ColourMode mode) {
  switch (mode) {
    case ColourMode::kNone:
      return "none";
    case ColourMode::k16:
      return "16";
    case ColourMode::k256:
      return "256";
    case ColourMode::kTrueColour:
      return "truecolor";
    case ColourMode::kAuto:
      return "auto";
  }
  return "none";
}

ColourMode AutoColourMode(std::string_view noColor, std::string_view colorTerm, int terminfoColours,
                          bool terminfoDirect) {
  if (!noColor.empty()) return ColourMode::kNone;  // https://no-color.org
  if (colorTerm == "truecolor" || colorTerm == "24bit" || terminfoDirect) {
    return ColourMode::kTrueColour;
  }
  if (terminfoColours >= 256) return ColourMode::k256;
  return terminfoColours >= 8 ? ColourMode::k16 : ColourMode::kNone;
}

}  // namespace termshade
