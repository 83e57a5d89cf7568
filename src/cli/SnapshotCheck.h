#pragma once

#include <string>

#include "cli/RenderCommand.h"

namespace CLI {
class App;
}

namespace termshade {

/// `termshade render MODEL --expect GOLDEN [--update] [--tolerance N[%]] [--views LIST]`:
/// a snapshot test of a model (docs/snapshot-testing.md).
struct SnapshotCommandOptions {
  std::string expectPath;  ///< --expect: the golden file
  bool update = false;     ///< --update (or TERMSHADE_UPDATE=1): write the golden
  std::string tolerance;   ///< --tolerance: samples, or N% of the model's; empty: 0
  std::string views;       ///< --views: comma-separated names or `all`; empty: the golden's, or all

  bool Requested() const { return !expectPath.empty() || update; }
};

/// Adds --expect, --update, --tolerance and --views to the render command.
void AddSnapshotOptions(CLI::App& renderCommand, SnapshotCommandOptions& options);

/// Renders the model's snapshot and compares it with the golden, or writes
/// the golden. Exit codes: 0 match (or written), 1 a mismatch, a missing or
/// unreadable golden, or a bad model; 2 bad usage (including options that
/// contradict the golden). `renderCommand` tells which options were given.
int RunSnapshotCommand(const RenderCommandOptions& render, const SnapshotCommandOptions& snapshot,
                       const CLI::App& renderCommand);

}  // namespace termshade
