#pragma once

#include <string>
#include <string_view>

#include "geometry/Mesh.h"
#include "io/LoadError.h"

namespace termshade {

/// Parses the .dat format of SPEC 6. fileName is used in error locations and
/// as the mesh's name. Never throws on bad input; the first problem is returned
/// as file:line:column: what was expected.
Loaded<Mesh> ParseDat(std::string_view text, const std::string& fileName);

}  // namespace termshade
