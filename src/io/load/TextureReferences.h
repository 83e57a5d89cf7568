#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace termshade {

/// Where a texture a model names is: in the file itself, a file in the
/// model's folder, or somewhere termshade will not read.
enum class TextureWhere {
  kEmbedded,       ///< "*N": the file's own Nth image
  kInFolder,       ///< a regular file inside the model's folder
  kMissing,        ///< inside the folder, but no such regular file
  kOutsideFolder,  ///< an absolute path, or one that leaves the folder: not looked at
  kUri,            ///< a URI (file:, http://, data:): not looked at
  kNoFolder,       ///< the model came from standard input: no folder to look in
};

std::string_view TextureWhereName(TextureWhere where);

/// One texture name as the file writes it, and where it is.
struct TextureReference {
  std::string name;
  TextureWhere where = TextureWhere::kMissing;
};

/// Where each of a model's texture names points. Nothing is read: names
/// inside the model's folder are resolved (links and '..' included) and
/// looked up with stat; names outside it are not looked up at all.
/// modelPath "-": standard input.
std::vector<TextureReference> LocateTextures(const std::vector<std::string>& names,
                                             const std::string& modelPath);

}  // namespace termshade
