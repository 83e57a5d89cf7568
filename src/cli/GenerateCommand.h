#pragma once

#include <string>

namespace termshade {

/// `termshade generate NAME [-o FILE]`: writes a shipped scene as .dat
/// (`all` with -o DIR writes every scene into DIR). Returns the exit code.
int RunGenerateCommand(const std::string& name, const std::string& outputPath);

}  // namespace termshade
