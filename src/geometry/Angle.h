#pragma once

#include <optional>
#include <string_view>

namespace termshade {

/// An angle as typed on the command line: radians (`0.3`, `0.3rad`) or
/// degrees (`30deg`); nullopt for anything else or a non-finite value.
std::optional<double> ParseAngleRadians(std::string_view text);

}  // namespace termshade
