#include "tui/TerminalQueries.h"

#include <algorithm>
#include <cmath>

#include "shade/CellColour.h"

namespace termshade {

void TakeReply(const TerminalReply& reply, TerminalAnswers& answers) {
  switch (reply.kind) {
    case TerminalReply::Kind::kBackgroundColour:
      answers.background = BackgroundOfColour(reply.red, reply.green, reply.blue);
      break;
    case TerminalReply::Kind::kCapability:
      if (reply.hasCapability && (reply.capability == "RGB" || reply.capability == "Tc")) {
        answers.directColour = true;
      }
      break;
    case TerminalReply::Kind::kCellSize: {
      const double aspect = static_cast<double>(reply.cellHeightPx) / reply.cellWidthPx;
      if (aspect >= 0.5 && aspect <= 4.0) answers.cellAspect = aspect;
      break;
    }
    case TerminalReply::Kind::kOther:
      break;
  }
}

Background BackgroundOfColour(double red, double green, double blue) {
  const auto byte = [](double channel) {
    return static_cast<uint8_t>(std::lround(std::clamp(channel, 0.0, 1.0) * 255.0));
  };
  const Srgb8 colour{byte(red), byte(green), byte(blue)};
  const Srgb8 black{0, 0, 0}, white{255, 255, 255};
  return ContrastRatio(colour, black) > ContrastRatio(colour, white) ? Background::kLight
                                                                     : Background::kDark;
}

}  // namespace termshade
