#pragma once

// The interface between the core and the Assimp import module
// (termshade-assimp.so, built from src/io/import/module): one exported C function
// returning a table of functions. C++ types cross it (ImportSource,
// LoadOptions, Loaded<Mesh>), so the module must come from the same build:
// the version and the build stamp (a hash of the headers whose types cross,
// the compiler and the project version) are checked before any call.
// No exception crosses: each function reports one as a status.

#include <cstdint>
#include <string>

#include "geometry/Mesh.h"
#include "io/read/LoadError.h"
#include "io/read/LoadOptions.h"

namespace termshade {

/// One model for the Open Asset Import Library, its bytes already read.
struct ImportSource {
  std::string displayName;  ///< the name messages use (the path as given, or "-")
  std::string importName;   ///< the name Assimp sees: absolute, with the format's extension
  std::string folder;       ///< canonical folder references must stay in; empty: none allowed
  std::string format;       ///< extension without the dot; empty: Assimp sniffs the content
};

/// Bumped when AssimpModuleApi changes.
inline constexpr uint32_t kAssimpModuleVersion = 1;

/// How a module function ended.
enum class ModuleStatus : int32_t {
  kDone = 0,         ///< the result is set (a mesh or a LoadError)
  kOutOfMemory = 1,  ///< std::bad_alloc was thrown
  kException = 2,    ///< another exception was thrown; its what() is in the text argument
};

/// What the module offers.
struct AssimpModuleApi {
  uint32_t version;        ///< kAssimpModuleVersion of the module's build
  const char* buildStamp;  ///< TERMSHADE_MODULE_STAMP of the module's build
  /// Imports one model with Assimp (see ImportWithAssimp in io/import/AssimpModule.h).
  ModuleStatus (*import)(const ImportSource& source, std::string& bytes, const LoadOptions& options,
                         Loaded<Mesh>& result, std::string& exceptionText) noexcept;
  /// Assimp's importer extensions: "*.3ds;*.obj;...".
  ModuleStatus (*extensionPatterns)(std::string& patterns, std::string& exceptionText) noexcept;
};

/// The module's one exported symbol.
inline constexpr const char* kAssimpModuleEntry = "termshade_assimp_module";
using AssimpModuleEntry = const AssimpModuleApi* (*)();

}  // namespace termshade
