#pragma once

#include <cstddef>
#include <string>

namespace termshade {

/// `termshade generate NAME [-o FILE]`.
struct GenerateCommandOptions {
  std::string name;           ///< a shipped scene, `all`, or `sphere`
  std::string outputPath;     ///< file (its extension picks .dat .obj .stl .ply), DIR for `all`
  size_t triangles = 200000;  ///< for `sphere`
};

/// Writes a shipped scene (default .dat; .obj, binary .stl or binary .ply by
/// the output's extension), `all` shipped scenes into a directory, or a
/// `sphere` of about N triangles. Returns the exit code.
int RunGenerateCommand(const GenerateCommandOptions& options);

}  // namespace termshade
