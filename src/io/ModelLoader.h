#pragma once

#include <string>

#include "geometry/Mesh.h"
#include "io/LoadError.h"

namespace termshade {

/// Largest model file read, so a wrong path to a huge file fails fast.
constexpr size_t kMaxModelFileBytes = size_t{512} << 20;

/// Loads a model file: .dat by our own reader (located errors), and the
/// common interchange formats (.obj, .stl, .ply, .off, .3ds, .dae, .gltf, ...)
/// through the Open Asset Import Library, keeping polygons untriangulated.
Loaded<Mesh> LoadModelFile(const std::string& path);

/// True for file names whose extension LoadModelFile hands to the importer.
bool UsesImporter(const std::string& path);

}  // namespace termshade
