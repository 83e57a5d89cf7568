#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "cli/CommandModel.h"

namespace termshade {

/// termshade(1) in roff (man(7) macros): synopsis, options and commands from
/// the command tree, the viewer's keys from its key table, model files,
/// environment, exit status and every command's examples.
void WriteManPage(const CommandModel& root, const std::string& version,
                  const std::vector<std::string>& modelExtensions, std::ostream& out);

}  // namespace termshade
