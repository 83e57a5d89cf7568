#pragma once

#include <string>

#include "geometry/Mesh.h"
#include "io/load/ModelLoader.h"
#include "io/read/FileBytes.h"
#include "io/read/LoadError.h"

namespace termshade {

/// LoadModelFile's load once the file is read or mapped: path names the
/// model (its extension, its folder for references). A mapped file found
/// shrunk while it was read gives an error, never a mesh.
Loaded<Mesh> LoadModelFileBytes(FileBytes bytes, const std::string& path,
                                const LoadOptions& options = {});

}  // namespace termshade
