#pragma once

#include <string>

#include "geometry/Mesh.h"
#include "io/LoadError.h"
#include "io/ModelLoader.h"

namespace termshade {

/// One model for the Open Asset Import Library, its bytes already read.
struct ImportSource {
  std::string displayName;  ///< the name messages use (the path as given, or "-")
  std::string importName;   ///< the name Assimp sees: absolute, with the format's extension
  std::string folder;       ///< canonical folder references must stay in; empty: none allowed
  std::string format;       ///< extension without the dot; empty: Assimp sniffs the content
};

/// Imports through Assimp with our confined IOSystem (regular files inside the
/// model's folder only), Assimp's data-structure validation, progress and
/// cancellation from options, and the budget checked before the mesh is built.
/// Fills faceColors (material diffuse or averaged vertex colours, when the file
/// gives them) and upAxisFile (the format's convention or what FBX and COLLADA declare).
Loaded<Mesh> ImportWithAssimp(const ImportSource& source, std::string bytes,
                              const LoadOptions& options);

/// True when Assimp has an importer for this extension (without the dot).
bool AssimpKnowsExtension(const std::string& format);

}  // namespace termshade
