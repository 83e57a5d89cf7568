#pragma once

#include <string>

#include "geometry/Mesh.h"

namespace termshade {

/// Writes a mesh in the .dat format of SPEC 6, vertices numbered from 1,
/// coordinates with 9 significant digits; hidden edges get a minus sign.
std::string WriteDat(const Mesh& mesh);

/// A coordinate as WriteDat prints it (no "-0").
std::string FormatCoordinate(double value);

}  // namespace termshade
