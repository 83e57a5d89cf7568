#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// What well-known non-model content looks like ("PNG image", "PDF document",
/// "gzip-compressed data"), from its first bytes; nullopt when nothing is recognised.
std::optional<std::string> RecognisedNonModel(std::string_view bytes);

/// True when the bytes have the shape of a .dat model (SPEC 6): the first
/// non-blank line is a vertex line (a number and three coordinates) or 'Faces:'.
bool LooksLikeDat(std::string_view bytes);

/// The lower-case extension of a path's file name, without the dot ("" when none).
std::string LowerExtension(std::string_view path);

}  // namespace termshade
