#pragma once

#include <optional>
#include <string>

#include "ThrottledLink.h"

namespace termshade {

/// `termshade bench terminal`: runs the real viewer in a pseudo-terminal and
/// measures what it sends to the terminal. The bench plays the terminal: it
/// answers the viewer's device attributes requests (DA1), through the link
/// when there is one.
struct TerminalBenchOptions {
  std::string viewerPath;  ///< the termshade binary to run
  std::string modelPath;   ///< empty: the demo scene
  int widthCells = 160;
  int heightCells = 48;
  int arrowPresses = 20;
  int heldKeyPresses = 60;  // queued at once, as a held key over a slow link
  double turntableSeconds = 4.0;
  double idleSeconds = 10.0;
  bool traceWrites = true;  ///< count write() calls with strace, if it is installed
  std::string lod;          ///< the viewer's --lod (auto, off); empty: its default
  /// After the first screen, read this long before measuring: a big model
  /// loads and its levels of detail are built.
  double settleSeconds = 0.0;
  std::string glyphs;  ///< the viewer's --glyphs; empty: picked for the terminal
  std::string colour;  ///< the viewer's --color; empty: auto
  /// A slow link between the viewer and the terminal (rate, delay each way):
  /// then settle, stop and quit times are measured instead.
  std::optional<LinkSpec> link;
  bool answer = true;  ///< false: a terminal that never answers DA1
};

/// Runs the measurement and prints the report; returns an exit code.
int RunTerminalBench(const TerminalBenchOptions& options);

}  // namespace termshade
