#pragma once

#include <string>
#include <vector>

#include "geometry/Mesh.h"
#include "io/import/AssimpModuleInterface.h"
#include "io/read/LoadError.h"
#include "io/read/LoadOptions.h"

namespace termshade {

/// The Assimp import module's file name. It is opened (dlopen, RTLD_NOW |
/// RTLD_LOCAL) on the first call that needs Assimp, from a fixed place next to
/// this program's own file (/proc/self/exe): the installed layout's
/// ../<libdir>/termshade/ first, else the build tree's own folder. Never from
/// the working directory or a search path.
inline constexpr const char* kAssimpModuleName = "termshade-assimp.so";

/// Imports through Assimp in the module, in this process (io/import/module/AssimpImport.h
/// says how; the loader runs it in a child, io/import/IsolatedImport.h). A module
/// that is missing or from another build is a LoadError naming it.
Loaded<Mesh> ImportWithAssimp(const ImportSource& source, std::string bytes,
                              const LoadOptions& options);

/// This build's stamp (a hash of the types that cross to the module and the helper).
const char* ModuleBuildStamp();

/// A module status other than kDone as the exception the call would have
/// thrown in-process: std::bad_alloc for kOutOfMemory, std::runtime_error
/// with the text for kException.
void RethrowModuleStatus(ModuleStatus status, const std::string& exceptionText);

/// True when Assimp has an importer for this extension (without the dot).
/// obj, stl and ply are answered without loading the module (Assimp reads
/// them all); other extensions load it (false when it cannot be loaded).
bool AssimpKnowsExtension(const std::string& format);

/// Assimp's extensions, lower case, without dots. Throws std::runtime_error
/// naming the module when it cannot be loaded.
std::vector<std::string> AssimpExtensions();

}  // namespace termshade
