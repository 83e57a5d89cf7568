#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "cli/CommandModel.h"

namespace termshade {

/// Shell completion scripts made from the command tree, so every option,
/// subcommand and choice CLI11 knows is completed without hand edits.
/// Model arguments complete to directories and files with `modelExtensions`.
void WriteBashCompletion(const CommandModel& root, const std::vector<std::string>& modelExtensions,
                         std::ostream& out);
void WriteZshCompletion(const CommandModel& root, const std::vector<std::string>& modelExtensions,
                        std::ostream& out);
void WriteFishCompletion(const CommandModel& root, const std::vector<std::string>& modelExtensions,
                         std::ostream& out);

}  // namespace termshade
