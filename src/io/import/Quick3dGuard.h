#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace termshade {

/// For bytes about to go to Assimp: its Quick3D importer (content starting
/// "quick3Do" or "quick3Ds", any case, under any name) sizes its arrays from
/// the file's counts before reading (Assimp 5.2.5: a 27-byte file took
/// 2.4 GB; found by libFuzzer), and copies material names into a 1 KiB
/// aiString unchecked. The file's structure is walked as the importer walks
/// it: every count must fit the bytes left, every name 1023 bytes. Why
/// not, or nullopt (also when the content ends early: the importer's reader
/// is bounded and says so itself).
std::optional<std::string> CheckQuick3dCounts(std::string_view bytes);

}  // namespace termshade
