#pragma once

#include <string>

namespace termshade {

/// Where one of this program's own files was found, or why not.
struct OwnFile {
  std::string path;     ///< empty when not found
  std::string problem;  ///< why not, naming the file and where it was looked for
};

/// One of this program's own files (the Assimp module, the import helper),
/// from a fixed place next to this program's own file (/proc/self/exe): the
/// installed layout's ../<libdir>/termshade/ first, else the program's own
/// folder (the build tree). Never from the working directory or a search
/// path. `what` names it in the problem ("the Assimp import module").
OwnFile FindOwnFile(const std::string& name, const std::string& what);

}  // namespace termshade
