#pragma once

#include <string>

#include "geometry/Mesh.h"
#include "io/import/AssimpModuleInterface.h"
#include "io/read/LoadError.h"
#include "io/read/LoadOptions.h"

// Inside the Assimp import module (termshade-assimp.so) only; the core reaches
// these through io/import/AssimpModule.h.
namespace termshade {

/// Imports through Assimp with our confined IOSystem (regular files inside the
/// model's folder only), Assimp's data-structure validation, progress and
/// cancellation from options, and the budget checked before the mesh is built.
/// Fills faceColors (material diffuse or averaged vertex colours, when the file
/// gives them) and upAxisFile (the format's convention or what FBX and COLLADA declare).
Loaded<Mesh> RunAssimpImport(const ImportSource& source, std::string bytes,
                             const LoadOptions& options);

/// Assimp's importer extensions: "*.3ds;*.obj;...".
std::string AssimpExtensionPatterns();

}  // namespace termshade
