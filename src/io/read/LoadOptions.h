#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// The memory budget when none is given: TERMSHADE_MEMORY_BUDGET ("4G",
/// "512M", bytes; see ParseByteCount in io/read/LoadBudget.h) if set and
/// valid, else 2 GiB (front ends refuse an invalid one: LoadEnvironmentProblem).
size_t DefaultMemoryBudgetBytes();

/// The import helper's processor time when none is given:
/// TERMSHADE_IMPORT_SECONDS (whole seconds, 1 to 86400) if set and valid,
/// else 0 (30 s and 1 s a MiB of file; io/import/IsolatedImport.h).
uint32_t DefaultImportCpuSeconds();

/// Why TERMSHADE_MEMORY_BUDGET or TERMSHADE_IMPORT_SECONDS holds a value
/// its option (--memory-budget, --import-seconds) would refuse: the
/// variable's name, the value (not yet escaped for a terminal) and what is
/// expected; nullopt when both are unset, empty or valid.
std::optional<std::string> LoadEnvironmentProblem();

/// Whole seconds 1 to 86400 (--import-seconds, TERMSHADE_IMPORT_SECONDS); nullopt otherwise.
std::optional<uint32_t> ParseImportSeconds(std::string_view text);

/// What a user sets for loads (--memory-budget, --import-seconds); 0: the default.
struct LoadLimits {
  size_t memoryBudgetBytes = 0;   ///< 0: DefaultMemoryBudgetBytes()
  uint32_t importCpuSeconds = 0;  ///< 0: DefaultImportCpuSeconds()
};

/// Limits and hooks for one load.
struct LoadOptions {
  LoadOptions() = default;
  /// The defaults, with what `limits` sets in their place.
  explicit LoadOptions(const LoadLimits& limits) {
    if (limits.memoryBudgetBytes > 0) memoryBudgetBytes = limits.memoryBudgetBytes;
    if (limits.importCpuSeconds > 0) importCpuSeconds = limits.importCpuSeconds;
  }

  /// Most memory the load may take, in bytes; a model needing more is refused
  /// with a message saying how much it needs. Checked before allocating: the
  /// file's size times what its format's import takes per byte, header counts
  /// against the bytes after the header, and the mesh's size before building it.
  size_t memoryBudgetBytes = DefaultMemoryBudgetBytes();
  /// Polled while loading; once true, the load stops with a "cancelled" error.
  const std::atomic<bool>* cancel = nullptr;
  /// Called from the loading thread with the share done, in [0, 1], where known.
  std::function<void(double)> progress;
  /// Format extension without the dot ("stl") for content that cannot be
  /// sniffed (standard input); empty: by extension, then by content.
  std::string formatHint;
  /// Assimp even where a dedicated reader exists (binary STL, PLY, OBJ): the
  /// reference those readers must agree with, for tests and benches.
  bool importerOnly = false;
  /// Assimp in this process rather than in the import helper
  /// (io/import/IsolatedImport.h): for the fuzzers, whose coverage must see it.
  bool importInProcess = false;
  /// Processor seconds the import helper may take; 0: 30 s and 1 s a MiB of file.
  uint32_t importCpuSeconds = DefaultImportCpuSeconds();
};

}  // namespace termshade
