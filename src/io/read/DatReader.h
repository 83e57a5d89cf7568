#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <string_view>

#include "geometry/Mesh.h"
#include "io/read/LoadError.h"

namespace termshade {

/// Parses the .dat format of SPEC 6. fileName is used in error locations and
/// as the mesh's name. Never throws on bad input; the first problem is returned
/// as file:line:column: what was expected.
Loaded<Mesh> ParseDat(std::string_view text, const std::string& fileName);

/// As above, polling cancel (may be null; once true the parse stops with a
/// "loading cancelled" error) and reporting the share of the text read to
/// progress (may be empty) every few thousand lines.
Loaded<Mesh> ParseDat(std::string_view text, const std::string& fileName,
                      const std::atomic<bool>* cancel, const std::function<void(double)>& progress);

}  // namespace termshade
