#pragma once

#include <string>
#include <vector>

namespace termshade {

/// Extensions of the model files LoadModelFile reads, lower case, without
/// the dot, sorted: "dat" and every format the importer knows.
std::vector<std::string> ModelFileExtensions();

}  // namespace termshade
