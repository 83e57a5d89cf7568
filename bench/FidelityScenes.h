#pragma once

#include <string>
#include <vector>

#include "geometry/Scene.h"

namespace termshade {

/// A scene `bench fidelity` measures, by name.
struct NamedScene {
  std::string name;
  Scene scene;
};

/// The fidelity scenes: SPEC's generated scenes (read from dataDirectory),
/// a torus knot, a checkered textured globe and, where Debian's
/// assimp-testmodels is installed, the textured Collada duck.
std::vector<NamedScene> FidelityScenes(const std::string& dataDirectory);

}  // namespace termshade
