#include "io/ModelExtensions.h"

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <sstream>

namespace termshade {

std::vector<std::string> ModelFileExtensions() {
  std::string list;
  Assimp::Importer().GetExtensionList(list);  // "*.3ds;*.obj;..."
  std::vector<std::string> extensions{"dat"};
  std::istringstream patterns(list);
  for (std::string pattern; std::getline(patterns, pattern, ';');) {
    if (pattern.rfind("*.", 0) != 0 || pattern.size() < 3) continue;
    std::string extension = pattern.substr(2);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    extensions.push_back(extension);
  }
  std::sort(extensions.begin(), extensions.end());
  extensions.erase(std::unique(extensions.begin(), extensions.end()), extensions.end());
  return extensions;
}

}  // namespace termshade
