#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// A terminal's answer to one of the start-up queries (TerminalQueries.h),
/// other than the DA1 answer: its background colour (OSC 11), whether it has
/// a capability (XTGETTCAP), its cell size in pixels (CSI 16 t), or an answer
/// the viewer has no use for (read so it never becomes keys).
struct TerminalReply {
  enum class Kind { kOther, kBackgroundColour, kCapability, kCellSize };
  Kind kind = Kind::kOther;
  double red = 0.0, green = 0.0, blue = 0.0;  ///< kBackgroundColour, each 0..1
  std::string capability;                     ///< kCapability: its name ("RGB")
  bool hasCapability = false;                 ///< kCapability: the terminal has it
  int cellWidthPx = 0, cellHeightPx = 0;      ///< kCellSize
};

/// An OSC string's body (between ESC ] and BEL or ST): `11;rgb:R/G/B` with
/// 1 to 4 hex digits a channel is a background colour, anything else kOther.
TerminalReply ReplyFromOsc(std::string_view body);
/// A DCS string's body (between ESC P and ST): `1+r` then hex name(=value)
/// is a capability the terminal has, `0+r` one it lacks, anything else kOther.
TerminalReply ReplyFromDcs(std::string_view body);
/// A CSI sequence's parameters and final byte: `6;H;W` `t` is the cell
/// size; nullopt for anything else.
std::optional<TerminalReply> ReplyFromCsi(std::string_view parameters, char finalByte);

}  // namespace termshade
