#pragma once

#include <string>

#include "geometry/Mesh.h"
#include "io/read/LoadError.h"
#include "io/read/LoadOptions.h"

namespace termshade {

/// Loads a model file: .dat by our own reader (located errors), and the
/// common interchange formats (.obj, .stl, .ply, .off, .3ds, .dae, .gltf, ...)
/// through the Open Asset Import Library, keeping polygons untriangulated.
/// path "-" reads standard input. The format comes from options.formatHint,
/// else the extension, else the content (.dat's shape, then Assimp's sniffing).
/// Only regular files are read, and files the model references only from
/// inside its own folder (SPEC 10). Every failure, out of memory included, is
/// a LoadError naming the file.
Loaded<Mesh> LoadModelFile(const std::string& path, const LoadOptions& options = {});

/// Loads a model from bytes in memory (standard input, fuzzing): as
/// LoadModelFile, with name in messages, the format from options.formatHint,
/// else name's extension, else the content; the model has no folder, so any
/// file it references is refused.
Loaded<Mesh> LoadModelBytes(std::string bytes, const std::string& name,
                            const LoadOptions& options = {});

/// True for file names whose extension LoadModelFile hands to the importer.
bool UsesImporter(const std::string& path);

}  // namespace termshade
