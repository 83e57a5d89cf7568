#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/Mesh.h"
#include "io/import/AssimpModuleInterface.h"
#include "io/read/LoadError.h"
#include "io/read/LoadOptions.h"

namespace termshade {

/// The import helper's file name, found where the module is (io/import/OwnFile.h).
inline constexpr const char* kImportHelperName = "termshade-import";

/// The helper's own heap beyond the budget (its libraries' data, the request
/// and wire buffers): the documented constant of the budget's promise.
inline constexpr uint64_t kHelperDataBytes = uint64_t{32} << 20;

/// What one import in the helper may take.
struct ImportLimits {
  uint64_t addressSpaceBytes = 0;  ///< the memory budget and 1 GiB for the helper itself
  /// What the importer may allocate (RLIMIT_DATA): the memory budget and
  /// kHelperDataBytes, so the helper's peak stays within them.
  uint64_t dataBytes = 0;
  uint64_t cpuSeconds = 0;  ///< options.importCpuSeconds, else 30 s and 1 s a MiB of file
};
ImportLimits ImportLimitsFor(size_t fileBytes, const LoadOptions& options);

/// Imports through Assimp in a child process, the import helper, so that
/// whatever the importer does with a hostile file (loops, huge allocations,
/// over-reads, crashes) stays there: it runs under ImportLimits, and its
/// mesh comes back over a pipe, checked whole (MeshWireProblem), before use.
/// Progress is forwarded; options.cancel stops it at once (the helper is
/// killed). A helper stopped by its limits, crashed or ended without a
/// result is a LoadError naming the file (in sanitizer builds, a crash or a
/// non-zero exit is thrown instead, so that tests report it).
Loaded<Mesh> ImportWithAssimpIsolated(const ImportSource& source, std::string bytes,
                                      const LoadOptions& options);

}  // namespace termshade
