#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace termshade {

/// -h/--help, --help-all, -V/--version, the viewer's keys under --help, and
/// the hidden --generate WHAT that writes the man page or a completion script.
void SetUpHelp(CLI::App& app, const std::string& version, std::string& generateWhat);

/// Puts every command's examples into its help footer (and so the man page).
void AddExamples(CLI::App& app);

/// Writes what --generate named to stdout: man, bash, zsh, fish, or
/// commands (every command's path, one a line); exit code.
int RunGenerate(const CLI::App& app, const std::string& version, const std::string& what);

/// After a parse error: "did you mean --method?" for the first unknown
/// option close to a known one of the command it was given to, else "".
std::string NearestOptionHint(const CLI::App& app);

}  // namespace termshade
