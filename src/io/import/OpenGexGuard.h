#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// For bytes about to go to Assimp as `format` (lower-case extension; empty:
/// Assimp sniffs the content). Assimp 5.2.5's OpenGEX importer takes content
/// with "Metric", "GeometryNode", "VertexArray (attrib" or "IndexArray" in
/// its first 200 bytes (any case) when no importer claims it by name, and
/// its OpenDDL parser reads past the end of its buffer on an unclosed
/// structure ("a{indexarray", "indexarray "; found by libFuzzer). Such
/// content must be closed: (), [] and {} balanced outside comments and
/// strings, and '}' its last significant byte. Why not, or nullopt.
std::optional<std::string> CheckOpenGexStructure(std::string_view bytes, const std::string& format);

}  // namespace termshade
