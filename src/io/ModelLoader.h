#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>

#include "geometry/Mesh.h"
#include "io/LoadError.h"

namespace termshade {

/// Largest model file read, so a wrong path to a huge file fails fast.
constexpr size_t kMaxModelFileBytes = size_t{512} << 20;

/// Limits and hooks for one load.
struct LoadOptions {
  /// Most memory the load may take, in bytes; a model needing more is refused
  /// with a message saying how much it needs.
  size_t memoryBudgetBytes = size_t{2} << 30;
  /// Polled while loading; once true, the load stops with a "cancelled" error.
  const std::atomic<bool>* cancel = nullptr;
  /// Called from the loading thread with the share done, in [0, 1], where known.
  std::function<void(double)> progress;
  /// Format extension without the dot ("stl") for content that cannot be
  /// sniffed (standard input); empty: by extension, then by content.
  std::string formatHint;
};

/// Loads a model file: .dat by our own reader (located errors), and the
/// common interchange formats (.obj, .stl, .ply, .off, .3ds, .dae, .gltf, ...)
/// through the Open Asset Import Library, keeping polygons untriangulated.
Loaded<Mesh> LoadModelFile(const std::string& path, const LoadOptions& options = {});

/// True for file names whose extension LoadModelFile hands to the importer.
bool UsesImporter(const std::string& path);

}  // namespace termshade
