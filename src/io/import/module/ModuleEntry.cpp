// termshade-assimp.so's one exported symbol: the function table of
// io/import/AssimpModuleInterface.h over RunAssimpImport and AssimpExtensionPatterns.
#include <exception>
#include <new>

#include "io/import/AssimpModuleInterface.h"
#include "io/import/module/AssimpImport.h"

namespace termshade {
namespace {

// Runs work, turning what it throws into a status: no exception leaves the module.
template <typename Work>
ModuleStatus Guarded(Work&& work, std::string& exceptionText) noexcept {
  try {
    work();
    return ModuleStatus::kDone;
  } catch (const std::bad_alloc&) {
    return ModuleStatus::kOutOfMemory;
  } catch (const std::exception& e) {
    try {
      exceptionText = e.what();
    } catch (...) {  // no memory left to copy the text: it stays empty
    }
    return ModuleStatus::kException;
  } catch (...) {
    return ModuleStatus::kException;  // not a std::exception: no text to give
  }
}

ModuleStatus Import(const ImportSource& source, std::string& bytes, const LoadOptions& options,
                    Loaded<Mesh>& result, std::string& exceptionText) noexcept {
  return Guarded([&] { result = RunAssimpImport(source, std::move(bytes), options); },
                 exceptionText);
}

ModuleStatus ExtensionPatterns(std::string& patterns, std::string& exceptionText) noexcept {
  return Guarded([&] { patterns = AssimpExtensionPatterns(); }, exceptionText);
}

constexpr AssimpModuleApi kApi{kAssimpModuleVersion, TERMSHADE_MODULE_STAMP, Import,
                               ExtensionPatterns};

}  // namespace
}  // namespace termshade

extern "C" __attribute__((visibility("default"))) const termshade::AssimpModuleApi*
termshade_assimp_module() {
  return &termshade::kApi;
}
